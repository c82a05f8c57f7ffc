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

    def test_a_coincident_surface_warning_is_not_silent_and_keeps_the_reason(self):
        rec = record(rrmse=0.3)
        rec["wardray"]["cautions"] = ["coincident surfaces"]
        category, reason = census.classify(rec)
        self.assertEqual(category, "differ-with-warning")
        self.assertTrue(reason.startswith("warned: coincident surfaces; "))
        self.assertIn("no assumed_gamma", census.classify(record(rrmse=0.3, gamma=()))[1])
        self.assertEqual(census.classify(record(rrmse=0.3))[0], "differ-silently")
        rec["metrics"]["rrmse"] = 0.0
        self.assertEqual(census.classify(rec)[0], "match")
        self.assertEqual(census.wardray_cautions("a.pov:1:1: warning: coincident surfaces: this box ..."),
                         ["coincident surfaces"])
        self.assertEqual(census.wardray_cautions("a.pov:1:1: warning: fog is not rendered yet"), [])

    def test_a_pattern_wrap_warning_is_not_silent(self):
        out = ("c.pov:25:3: warning: pattern wrap on a surface: this pigment changes abruptly exactly on the "
               "surface of the sphere at c.pov:79:4 ...")
        self.assertEqual(census.wardray_cautions(out), ["pattern wrap"])
        both = "a.pov:1:1: warning: coincident surfaces: this box ...\n" + out
        self.assertEqual(census.wardray_cautions(both), ["coincident surfaces", "pattern wrap"])
        rec = record(rrmse=0.3)
        rec["wardray"]["cautions"] = census.wardray_cautions(out)
        category, reason = census.classify(rec)
        self.assertEqual(category, "differ-with-warning")
        self.assertTrue(reason.startswith("warned: pattern wrap; "))

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

    def test_a_known_reason_names_the_difference_and_keeps_it_silent(self):
        rec = record(rrmse=0.3)
        rec["scene"] = "advanced/pawns.pov"
        category, reason = census.classify(rec)
        self.assertEqual(category, "differ-silently")
        self.assertTrue(reason.startswith("known: POV-Ray's own speckle"), reason)
        self.assertIn("advanced/pawns.pov", census.known_reasons())


    def test_a_trace_rounding_warning_is_not_silent(self):
        out = ("tracevines.pov:24:12: warning: the objects this scene builds from trace() change when trace()'s "
               "results move by 1e-12 of their distance (8246 objects against 10166): they hang on rounding")
        self.assertEqual(census.wardray_cautions(out), ["trace() rounding"])
        rec = record(rrmse=0.22)
        rec["wardray"]["cautions"] = census.wardray_cautions(out)
        self.assertEqual(census.classify(rec)[0], "differ-with-warning")


class StabilityTest(unittest.TestCase):
    """The instability test: cameras turned in the scratch copy, and unstable scenes judged supersampled."""

    def test_every_camera_block_takes_the_turn(self):
        text = ('#declare C = camera { location <0, 1, -3> look_at 0 } // camera { x }\n'
                'camera { C }\nmesh_camera { 1 0 mesh { M } }\n#declare S = "camera { }";\n')
        new, n = census.stability.perturb_cameras(text)
        self.assertEqual(n, 2)
        self.assertEqual(new.count("rotate <0.0001000, 0.0001300, 0.0000700>"), 2)
        self.assertIn("look_at 0  rotate", new)
        self.assertIn("camera { C  rotate", new)
        self.assertIn("mesh_camera { 1 0 mesh { M } }", new)  # not a camera block
        self.assertIn('"camera { }"', new)  # nor a string

    def test_the_copy_turns_cameras_in_the_folder_and_says_when_it_cannot(self):
        with tempfile.TemporaryDirectory() as tmp:
            d = pathlib.Path(tmp)
            files = [("a.pov", "#include \"cam.inc\"\nsphere { 0, 1 }\n"), ("cam.inc", "camera { location -z }\n")]
            self.assertEqual(census.stability.perturbed_copy(files, d), ["cam.inc"])
            self.assertIn("rotate", (d / "cam.inc").read_text())
            self.assertFalse((d / "a.pov").exists())
        with self.assertRaisesRegex(census.RewriteError, "no camera block"):
            census.stability.perturbed_texts([("a.pov", "#include \"elsewhere.inc\"\nsphere { 0, 1 }\n")])
        with self.assertRaisesRegex(census.RewriteError, "sub/c.inc"):
            census.stability.perturbed_texts([("a.pov", "sphere { 0, 1 }"), ("sub/c.inc", "camera { }")])
        self.assertEqual(census.stability.supersampled_options(["w", "-A", "+FH"]), ["w", "+A0.0", "+R4", "-J", "+FH"])

    def test_moved_is_beyond_the_match_tolerance(self):
        m = {"rrmse": 0.005, "bad": 0.001, "non_finite": 0, "non_finite_wardray": 0}
        self.assertFalse(census.stability.moved(m, census.MATCH_RRMSE, census.MATCH_BAD))
        self.assertTrue(census.stability.moved({**m, "rrmse": 0.02}, census.MATCH_RRMSE, census.MATCH_BAD))
        self.assertTrue(census.stability.moved({**m, "bad": 0.02}, census.MATCH_RRMSE, census.MATCH_BAD))

    @staticmethod
    def unstable(rec, rrmse, bad=0.0, floor=None, moved=0.2):
        metrics = {"rrmse": moved, "bad": 0.05, "non_finite": 0, "non_finite_wardray": 0, "non_finite_povray": 0}
        rec["stability"] = {"moved": metrics, "unstable": True}
        rec["converged"] = {"kind": "unstable", "settings": "+A0.0 +R3 -J", "metrics":
                            {**metrics, "rrmse": rrmse, "bad": bad}, "floor": floor and {**metrics, **floor}}
        return census.classify(rec)

    def test_an_unstable_scene_is_judged_supersampled_within_povrays_own_movement(self):
        category, reason = self.unstable(record(rrmse=0.1), 0.008)
        self.assertEqual(category, "match")
        self.assertIn("unstable at one sample a pixel: POV-Ray's own image moves by 20.00 %", reason)
        self.assertIn("supersampled (+A0.0 +R3 -J): rRMSE 0.80 %", reason)
        self.assertIn("at one sample a pixel 10.00 %", reason)
        # Beyond the match tolerance but within what POV-Ray's own supersampled image moves: a match.
        self.assertEqual(self.unstable(record(rrmse=0.1), 0.03, floor={"rrmse": 0.04, "bad": 0.01})[0], "match")
        # Beyond both: still a difference, silent or small by the supersampled figure.
        self.assertEqual(self.unstable(record(rrmse=0.1), 0.05, floor={"rrmse": 0.04, "bad": 0.0})[0],
                         "differ-silently")
        self.assertEqual(self.unstable(record(rrmse=0.1), 0.015)[0], "differ-small")
        self.assertEqual(self.unstable(record(rrmse=0.1), 0.005, bad=0.02, floor={"rrmse": 0.0, "bad": 0.01})[0],
                         "differ-small")

    def test_a_stable_scene_keeps_its_verdict_and_says_it_is_stable(self):
        rec = record(rrmse=0.05)
        rec["stability"] = {"moved": {"rrmse": 0.0001, "bad": 0.0}, "unstable": False}
        category, reason = census.classify(rec)
        self.assertEqual(category, "differ-silently")
        self.assertIn("stable at one sample a pixel: POV-Ray's own image moves by 0.01 %", reason)
        rec["stability"] = {"error": "no camera block in the scene's folder"}
        self.assertIn("instability not measured: no camera block", census.classify(rec)[1])


class ConvergedTest(unittest.TestCase):
    def converged(self, rec, rrmse, bad=0.0, error=None):
        rec["converged"] = {"settings": "s", "error": error, "metrics": None if error else
                            {"rrmse": rrmse, "bad": bad, "non_finite": 0, "non_finite_wardray": 0,
                             "non_finite_povray": 0}}
        return census.classify(rec)

    def test_a_converged_comparison_is_judged_with_the_deterministic_tolerances(self):
        self.assertEqual(self.converged(record(rrmse=0.07, stochastic=["crand"]), 0.008)[0], "match")
        self.assertEqual(self.converged(record(rrmse=0.07, stochastic=["crand"]), 0.008, bad=0.01)[0],
                         "differ-small")
        self.assertEqual(self.converged(record(rrmse=0.03, stochastic=["jitter"]), 0.015)[0], "differ-small")
        # 3 % converged is silent although 3 % at the scene's own settings would be a stochastic match.
        category, reason = self.converged(record(rrmse=0.03, stochastic=["radiosity"]), 0.03)
        self.assertEqual(category, "differ-silently")
        self.assertIn("converged (s): rRMSE 3.00 %", reason)
        self.assertIn("own settings 3.00 %", reason)

    def test_a_failed_converged_render_keeps_the_one_render_verdict(self):
        category, reason = self.converged(record(rrmse=0.07, stochastic=["radiosity"]), 0, error="povray: timed out")
        self.assertEqual(category, "differ-silently")
        self.assertIn("no converged comparison: povray: timed out", reason)

    def test_the_copy_rewrites_only_global_radiosity_blocks_in_the_folder(self):
        with tempfile.TemporaryDirectory() as tmp:
            d = pathlib.Path(tmp)
            files = [("a.pov", "global_settings { radiosity { count 35 error_bound 1.8 } }\n"
                               "sphere { 0, 1 radiosity { importance 0.5 } }\n"),
                     ("b.inc", "sphere { 0, 1 radiosity { importance 0.5 } }\n"),
                     ("sub/c.inc", "global_settings { radiosity { count 10 } }\n")]
            self.assertEqual(census.converged_copy(files, d), ["a.pov"])
            text = (d / "a.pov").read_text()
            self.assertIn("count 1600", text)
            self.assertNotIn("count 35", text)
            self.assertIn("error_bound 0.1", text)
            self.assertIn("importance 0.5", text)
            self.assertFalse((d / "b.inc").exists())
        self.assertEqual(census.converged_options(["w", "-A", "+FH"], ["crand"]), ["w", "+A0.0", "+R6", "-J", "+FH"])
        self.assertEqual(census.converged_options(["w", "-A"], ["radiosity"]), ["w", "-A"])
        self.assertEqual(census.converged_options(["w", "-A"], ["focal blur"]), ["w", "-A"])

    def test_the_copy_converges_literal_blur_samples(self):
        with tempfile.TemporaryDirectory() as tmp:
            d = pathlib.Path(tmp)
            files = [("a.pov", "camera { aperture 1 blur_samples 37 }\n#case(1) blur_samples 7, 19 #break\n"),
                     ("b.inc", "#declare N = 5; camera { blur_samples N }\n")]
            self.assertEqual(census.converged_copy(files, d, ["focal blur"]), ["a.pov"])
            text = (d / "a.pov").read_text()
            self.assertEqual(text.count("blur_samples 4000, 4000"), 2)
            self.assertNotIn("37", text)
            self.assertNotIn("7, 19", text)
            self.assertFalse((d / "b.inc").exists())


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

    def test_randomness_of_the_parsed_scene(self):
        out = "scene: s.pov\nradiosity: off\nrandomness: area light jitter, crand, focal blur\nwarnings: 0\n"
        self.assertEqual(census.parsed_randomness_words(out), ["jitter", "crand", "focal blur"])
        self.assertEqual(census.parsed_randomness_words("randomness: none\n"), [])
        self.assertEqual(census.parsed_randomness_words("no such line"), [])

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


def blocked(message, file="s.pov", line=1, col=1, scene="r01/s.pov", status="error"):
    rec = record(ward=status)
    rec["scene"] = scene
    rec["wardray"]["location"] = {"file": file, "line": line, "col": col, "message": message} if message else None
    return rec


class FailureGroupTest(unittest.TestCase):
    """The grouping of parse failures by construct (a corpus's "why scenes do not parse")."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        d = pathlib.Path(self.tmp.name)
        self.repo, self.lib = d / "repo", d / "lib"
        (self.repo / "sub" / "inc").mkdir(parents=True)
        self.lib.mkdir()
        (self.lib / "textures.inc").write_text("#declare Jade =\n  pigment { rgb 1 }\n#declare Mirror = finish { }\n")
        (self.repo / "s.pov").write_text(
            "#declare Thing = union { sphere { 0, 1 } }\n"
            "#undef Arr[2]\n"
            '#include "x.inc";\n'
            "#macro M(A, B) A #end\n"
            "M(1, 2, )\n"
            "#macro F()\n#for (I, 0, 2)\n  #local Sum = I;\n#end\n  Sum\n#end\n")
        (self.repo / "sub" / "inc" / "a.inc").write_text('#include "inc/b.inc"\n')
        (self.repo / "sub" / "inc" / "b.inc").write_text("\n")
        self.look = census.SourceLookup(self.repo, self.lib)

    def tearDown(self):
        self.tmp.cleanup()

    def group(self, *args, **kw):
        return census.failure_group(blocked(*args, **kw), self.look)

    def test_identifiers_are_named_by_their_declared_kind(self):
        self.assertEqual(self.look.declared("Jade"), "pigment")
        self.assertEqual(self.look.declared("Thing"), "object")
        self.assertEqual(self.look.declared("M"), "macro")
        self.assertIsNone(self.look.declared("Nowhere"))
        self.assertEqual(self.group("expected pigment, finish, normal or a transform in texture but found 'Jade'",
                                    line=9, col=17), ("texture { PigmentIdentifier }", "s.pov:9"))
        self.assertEqual(self.group("expected pigment, finish, normal or a transform in texture but found 'Mirror'")[0],
                         "texture { FinishIdentifier }")
        self.assertEqual(self.group("expected pigment, finish, normal or a transform in texture but found "
                                    "'no_bump_scale'")[0], "texture { no_bump_scale }")
        self.assertEqual(self.group("expected a finish item but found 'ior'")[0], "finish { ior }")
        self.assertEqual(self.group("'Thing' cannot stand alone here; use object { Thing } for declared objects")[0],
                         "ObjectIdentifier without object { }")
        self.assertEqual(self.group("expected an object modifier or '}' but found 'Thing'")[0],
                         "ObjectIdentifier without object { }")

    def test_constructs_found_from_the_source_line(self):
        self.assertEqual(self.group("expected a statement but found '['", line=2, col=11)[0], "#undef A[i]")
        self.assertEqual(self.group("expected a statement but found ';'", line=3, col=17)[0],
                         "#include \"...\"; (a ';' after #include)")
        self.assertEqual(self.group("macro 'M' takes 2 parameter(s) but 3 were given", line=5)[0],
                         "macro call with an empty last argument ', )'")
        self.assertEqual(self.group("undeclared identifier 'Sum'", line=10)[0],
                         "macro returning one of its #local identifiers (the identifier alone before #end)")
        self.assertEqual(self.group("undeclared identifier 'Other'", line=10)[0], "undeclared identifier")

    def test_directives_and_keywords(self):
        self.assertEqual(self.group("'declare' cannot start a statement")[0], "declare without #")
        self.assertEqual(self.group("'now' is not supported yet")[0], "now")
        self.assertEqual(self.group("'image_width' is a reserved word and cannot be declared")[0],
                         "#declare of a reserved word (image_width)")

    def test_nested_include_relative_to_the_scene_folder(self):
        self.assertEqual(self.group("cannot open include file 'inc/b.inc': No such file or directory",
                                    file="sub/inc/a.inc", scene="r01/sub/s.pov")[0],
                         "nested #include path (relative to the scene's folder, not the including file's)")
        self.assertEqual(self.group("cannot open include file 'gone.inc': No such file or directory",
                                    scene="r01/s.pov")[0], "#include of a file not found")

    def test_other_messages_are_normalised(self):
        a = self.group("expected a float but found 'Foo' at 3 places")[0]
        b = self.group("expected a float but found 'Bar' at 4 places")[0]
        self.assertEqual(a, b)
        self.assertEqual(a, "expected a float but found 'Identifier' at <n> places")
        self.assertEqual(self.group(None, status="timeout")[0], "timed out after 60 s (parse or render)")
        rec = blocked(None)
        rec["wardray"].update(error="terminate called after throwing an instance of 'std::bad_alloc'", exit=-6)
        self.assertEqual(census.failure_group(rec, self.look)[0], "out of memory (address space bounded)")
        rec["wardray"].update(error=None)
        self.assertEqual(census.failure_group(rec, self.look)[0], "crash (killed by SIGABRT)")

    def test_groups_worst_first(self):
        recs = [{"g": "b"}, {"g": "a"}, {"g": "b"}, {"g": "c"}]
        self.assertEqual([(g, len(rs)) for g, rs in census.grouped(recs, lambda r: r["g"])],
                         [("b", 2), ("a", 1), ("c", 1)])

    def test_silent_groups_by_gamma_hints(self):
        self.assertEqual(census.silent_group(record(rrmse=0.3, gamma=["2.2"], version="3.6")),
                         "assumed_gamma 2.2; #version 3.6")
        self.assertEqual(census.silent_group(record(rrmse=0.3, gamma=[], version=None)),
                         "no assumed_gamma, no #version")
        self.assertEqual(census.silent_group(record(rrmse=0.3)),
                         "no gamma or #version hint (assumed_gamma 1, #version 3.7)")


class CorpusTest(unittest.TestCase):
    def test_manifest_ids_are_neutral(self):
        with tempfile.TemporaryDirectory() as tmp:
            d = pathlib.Path(tmp)
            for path in ("a+one/x/s.pov", "b+two/t.pov", "a+one/u.pov"):
                (d / path).parent.mkdir(parents=True, exist_ok=True)
                (d / path).write_text("")
            (d / "M.tsv").write_text("path\trepository\tcommit\na+one/x/s.pov\ta/one\tc1\nb+two/t.pov\tb/two\tc2\n"
                                     "a+one/u.pov\ta/one\tc1\n")
            m = census.Manifest(d, d / "M.tsv")
            self.assertEqual([m.rel(s) for s in m.scenes()], ["r01/x/s.pov", "r02/t.pov", "r01/u.pov"])
            self.assertEqual(m.repo_folder(d / "a+one/x/s.pov"), (d / "a+one").resolve())
            self.assertEqual(m.row(d / "b+two/t.pov")["commit"], "c2")
            self.assertEqual([m.rel(s) for s in census.find_scenes(d, ["r01/*"], m)], ["r01/x/s.pov", "r01/u.pov"])

    def test_resource_outliers(self):
        def rec(scene, pp, wp, pm, wm, ward="ok"):
            r = record(ward=ward)
            r["scene"] = scene
            r["povray"]["resources"] = {"parse": pp, "peak_kb": pm}
            r["wardray"]["resources"] = {"parse": wp, "peak_kb": wm}
            return r
        recs = [rec("a", 1.0, 1.9, 100, 150), rec("b", 1.0, 3.0, 100, 100), rec("c", 0.001, 0.01, 100, 100),
                rec("d", 1.0, 1.0, 100, 500), rec("e", 1.0, None, 100, None, ward="timeout")]
        out = census.resource_outliers(recs)
        self.assertEqual([(r["scene"], why) for r, why in out],
                         [("e", ["wardray timed out after 60 s"]), ("d", ["memory 5.0x"]), ("b", ["parse 3.0x"])])

    def test_time_file_and_parse_times(self):
        with tempfile.TemporaryDirectory() as tmp:
            p = pathlib.Path(tmp) / "t.txt"
            p.write_text("Command exited with non-zero status 1\n0.52 12345\n")
            self.assertEqual(census.read_time_file(p), {"wall": 0.52, "peak_kb": 12345})
            p.write_text("Command terminated by signal 6\n1.00 99\n")
            self.assertEqual(census.read_time_file(p), {"signal": 6, "wall": 1.0, "peak_kb": 99})
            self.assertEqual(census.read_time_file(pathlib.Path(tmp) / "none"), {})
        self.assertEqual(census.povray_parse_seconds("  Parse Time:       0 hours  0 minutes  6 seconds (6.428 "
                                                     "seconds)\n"), 6.428)
        self.assertIsNone(census.povray_parse_seconds("nothing"))

    def test_error_location_is_relative_to_the_repository(self):
        out = "../inc/x.inc:227:5: error: undeclared identifier 'A'\nscene.pov:3:1: error: later\n"
        self.assertEqual(census.error_location(out, "/tmp/w/repo", "/tmp/w/repo/Examples/One"),
                         {"file": "Examples/inc/x.inc", "line": 227, "col": 5,
                          "message": "undeclared identifier 'A'"})
        out = "/usr/share/povray-3.7/include/shapes.inc:10:2: error: boom\n"
        self.assertEqual(census.error_location(out, "/tmp/w/repo", "/tmp/w/repo")["file"],
                         "<povray include>/shapes.inc")
        self.assertIsNone(census.error_location("fine\n", "/tmp/w/repo", "/tmp/w/repo"))


if __name__ == "__main__":
    unittest.main()
