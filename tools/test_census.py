"""Self-test of the census's non-rendering parts: classification, the scene-text scans and the output parsers.
Runs in well under a second:

    /usr/bin/python3 -m unittest discover -s tools -p 'test_census.py'
"""
import pathlib
import sys
import tempfile
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))

import census  # noqa: E402


def record(rrmse=0.0, bad=0.0, features=(), stochastic=(), nan=0, gamma=("1.0",), version="3.7", pov="ok",
           ward="ok"):
    return {"povray": {"status": pov, "error": "Parse Error: x" if pov != "ok" else None},
            "wardray": {"status": ward, "features": list(features), "error": "s.pov:1:1: error: y" if ward != "ok"
                        else None, "exit": 0 if ward == "ok" else 1},
            "metrics": None if pov != "ok" or ward != "ok" else
            {"rrmse": rrmse, "bad": bad, "non_finite": nan, "non_finite_wardray": nan, "non_finite_povray": 0},
            "stochastic": list(stochastic), "assumed_gamma": list(gamma), "version": version}


class ClassifyTest(unittest.TestCase):
    def cat(self, **kw):
        return census.classify(record(**kw))[0]

    def test_failures_come_first(self):
        self.assertEqual(self.cat(pov="error", ward="error"), "povray-fails")
        self.assertEqual(self.cat(pov="timeout"), "povray-fails")
        self.assertEqual(self.cat(ward="error"), "blocked")
        self.assertEqual(self.cat(ward="timeout"), "blocked")
        self.assertEqual(census.classify(record(ward="error"))[1], "s.pov:1:1: error: y")

    def test_match_needs_both_figures(self):
        self.assertEqual(self.cat(rrmse=0.01, bad=0.005), "match")
        self.assertEqual(self.cat(rrmse=0.0101, bad=0.0), "differ-small")
        self.assertEqual(self.cat(rrmse=0.005, bad=0.006), "differ-small")
        self.assertEqual(self.cat(rrmse=0.02, bad=0.5), "differ-small")
        self.assertEqual(self.cat(rrmse=0.0201), "differ-silently")

    def test_a_warning_explains_a_difference_but_not_a_match(self):
        self.assertEqual(self.cat(rrmse=0.5, features=["fog"]), "differ-with-warning")
        self.assertEqual(self.cat(rrmse=0.015, features=["fog"]), "differ-with-warning")
        self.assertEqual(self.cat(rrmse=0.001, features=["fog"]), "match")
        self.assertEqual(census.classify(record(rrmse=0.5, features=["fog", "media"]))[1],
                         "not rendered: fog, media")

    def test_non_finite_pixels_never_match(self):
        self.assertEqual(self.cat(nan=1), "differ-silently")
        self.assertEqual(self.cat(nan=1, features=["fog"]), "differ-with-warning")
        self.assertIn("1 non-finite pixels", census.classify(record(nan=1))[1])

    def test_stochastic_scenes_use_their_tolerance_and_ignore_bad_pixels(self):
        self.assertEqual(self.cat(rrmse=0.04, bad=0.3, stochastic=["radiosity"]), "match")
        self.assertEqual(self.cat(rrmse=0.05, stochastic=["jitter"]), "match")
        self.assertEqual(self.cat(rrmse=0.06, stochastic=["radiosity"]), "differ-silently")
        self.assertEqual(self.cat(rrmse=0.06, stochastic=["radiosity"], features=["media"]),
                         "differ-with-warning")

    def test_gamma_hints(self):
        self.assertEqual(census.classify(record(rrmse=0.3, gamma=["2.2"]))[1], "assumed_gamma 2.2")
        self.assertEqual(census.classify(record(rrmse=0.3, gamma=[], version="3.6"))[1],
                         "#version 3.6 with no assumed_gamma")
        self.assertEqual(census.classify(record(rrmse=0.3, gamma=["1.0"], version="3.5"))[1], "#version 3.5")
        self.assertEqual(census.classify(record(rrmse=0.3, gamma=[], version=None))[1],
                         "no assumed_gamma, no #version")
        self.assertEqual(census.classify(record(rrmse=0.3))[1], "no hint in the scene text")


class SceneTextTest(unittest.TestCase):
    def test_stochastic_features(self):
        f = census.stochastic_features
        self.assertEqual(f(["global_settings { radiosity { count 100 } }"]), ["radiosity"])
        self.assertEqual(f(["#include \"rad_def.inc\"\nglobal_settings { radiosity { Rad_Settings(1,off,off) } }"]),
                         ["radiosity"])
        self.assertEqual(f(["sphere { 0, 1 radiosity { importance 0.5 } }"]), [])
        self.assertEqual(f(["// radiosity { count 1 } jitter\n/* crand */ sphere { 0, 1 }"]), [])
        self.assertEqual(f(["light_source { 0, 1 area_light x, y, 4, 4 jitter }", "finish { crand 0.1 }"]),
                         ["jitter", "crand"])
        self.assertEqual(f(["#declare jitter_amount = 1;"]), [])

    def test_gamma_facts(self):
        text = "// #version 3.1;\n#version 3.6;\nglobal_settings { assumed_gamma 2.2 }\n"
        self.assertEqual(census.gamma_facts(text, [text, "global_settings{assumed_gamma 1.0}"]),
                         (["2.2", "1.0"], "3.6"))
        self.assertEqual(census.gamma_facts("sphere{0,1}", ["sphere{0,1}"]), ([], None))

    def test_scene_files_follow_local_includes(self):
        with tempfile.TemporaryDirectory() as tmp:
            d = pathlib.Path(tmp)
            (d / "a.pov").write_text('#include "colors.inc"\n#include "b.inc"\n')
            (d / "b.inc").write_text('#include "c.inc"\n#include "b.inc"\n')
            (d / "c.inc").write_text("global_settings { radiosity { } }\n")
            self.assertEqual([n for n, _ in census.scene_files(d / "a.pov")], ["a.pov", "b.inc", "c.inc"])


class OutputTest(unittest.TestCase):
    def test_wardray_diagnostics(self):
        out = ("/tmp/w/x.wardray/scene.pov:12:3: warning: fog is not rendered yet\n"
               "scene.pov:14:1: warning: pigment pattern 'mandel' is not rendered yet\n"
               "scene.pov:15:1: warning: fog is not rendered yet\n"
               "scene.pov:16:1: warning: pattern function is not rendered yet (f evaluates to 0)\n"
               "scene.pov:17:1: warning: sphere is degenerate (zero size) and is not rendered\n"
               "/work/x/scene.pov:20:2: error: expected '}'\n"
               "scene.pov:21:1: error: second\n")
        error, features, warnings = census.wardray_diagnostics(out)
        self.assertEqual(features, ["fog", "pigment pattern 'mandel'", "pattern function"])
        self.assertEqual(warnings, ["sphere is degenerate (zero size) and is not rendered"])
        self.assertEqual(error, "scene.pov:20:2: error: expected '}'")

    def test_povray_error(self):
        out = ("==== [Parsing...] ====\n"
               "File 'prism3c.pov' line 15: Possible Parse Error: Cannot find file 'prism3.inc',\n"
               " even after trying to append file type extension.\n"
               "File 'prism3c.pov' line 15: Parse Error: Cannot open include file\n"
               " prism3.inc.\n"
               "Fatal error in parser: Cannot parse input.\n")
        self.assertEqual(census.povray_error(out), "line 15: Parse Error: Cannot open include file prism3.inc.")
        self.assertIsNone(census.povray_error("Render Statistics\n"))
        out = ("File 'sort.pov' line 82: Possible Parse Error: Cannot find file 'arial.ttf',\n"
               " even after trying to append file type extension.\n"
               "Fatal error in parser: Cannot open file.\n")
        self.assertEqual(census.povray_error(out), "line 82: Possible Parse Error: Cannot find file 'arial.ttf', "
                         "even after trying to append file type extension. Fatal error in parser: Cannot open file.")

    def test_read_ini(self):
        with tempfile.TemporaryDirectory() as tmp:
            p = pathlib.Path(tmp) / "a.ini"
            p.write_text("; Initial_Frame=9\nAntialias=On\nInitial_Frame=3\nFinal_Frame= 33\nInitial_Clock=1\n")
            self.assertEqual(census.read_ini(p), {"file": "a.ini", "frame": 3, "clock": 1.0, "declares": []})
            p.write_text("Input_File_Name=s.pov\n+kf0.1666 +kff20 +kc declare=fp=0\n+KFI2 +KI0.5\n")
            self.assertEqual(census.read_ini(p), {"file": "a.ini", "frame": 2, "clock": 0.5, "declares": ["fp=0"]})

    def test_an_ini_is_noted_in_the_reason(self):
        rec = record(ward="error")
        rec["ini"] = {"file": "t.ini", "frame": 1, "clock": 0.0, "declares": []}
        self.assertIn("frame 1 of t.ini", census.classify(rec)[1])

    def test_broken_cache_lines_are_skipped(self):
        with tempfile.TemporaryDirectory() as tmp:
            p = pathlib.Path(tmp) / "results.jsonl"
            p.write_text('{"scene": "a.pov", "key": "1"}\n{"scene": "a.pov", "key": "2"}\n{"scene": "b.p')
            self.assertEqual(census.load_results(p), {"a.pov": {"scene": "a.pov", "key": "2"}})


if __name__ == "__main__":
    unittest.main()
