"""Self-test of the comparison tool's non-rendering parts: the radiosity-block rewriter, the image errors and the
crossing-time interpolation. Runs in well under a second:

    /usr/bin/python3 -m unittest discover -s tools/compare -p 'test_*.py'
"""
import math
import pathlib
import sys
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))

import numpy as np  # noqa: E402

from gimetrics import crossing_time, image_error  # noqa: E402
from povrewrite import RewriteError, mask_comments_and_strings, rewrite_radiosity  # noqa: E402

LADDER = {"count": 400, "error_bound": 0.2, "pretrace_end": 0.01}


def settings_in(text, key):
    """Values given for `key` outside comments, in order."""
    masked = mask_comments_and_strings(text)
    import re
    return [m.group(1) for m in re.finditer(r"(?<![A-Za-z_])" + key + r"\s+([0-9.]+)", masked)]


class RewriteTest(unittest.TestCase):
    def test_replaces_simple_settings_and_keeps_the_others(self):
        scene = ("global_settings {\n  assumed_gamma 1.0\n  radiosity {\n    pretrace_start 0.08\n"
                 "    pretrace_end 0.04\n    count 35\n    nearest_count 5\n    error_bound 0.5\n"
                 "    recursion_limit 3\n  }\n}\nsphere { 0, 1 }\n")
        out, how = rewrite_radiosity(scene, LADDER)
        self.assertEqual(how, "replaced")
        self.assertEqual(settings_in(out, "count"), ["400"])
        self.assertEqual(settings_in(out, "error_bound"), ["0.2"])
        self.assertEqual(settings_in(out, "pretrace_end"), ["0.01"])
        self.assertEqual(settings_in(out, "recursion_limit"), ["3"])
        self.assertEqual(settings_in(out, "nearest_count"), ["5"])
        self.assertTrue(out.endswith("sphere { 0, 1 }\n"))

    def test_ignores_comments_strings_and_object_radiosity(self):
        scene = ('// radiosity { count 1 }\n#declare S = "global_settings { radiosity { count 2 } }";\n'
                 "global_settings {\n  /* radiosity { count 3 } /* nested */ still a comment } */\n"
                 "  radiosity { count 50 // count 4\n  }\n}\n"
                 "sphere { 0, 1 radiosity { importance 0.5 } }\n")
        out, _ = rewrite_radiosity(scene, LADDER)
        self.assertIn("// radiosity { count 1 }", out)
        self.assertIn('"global_settings { radiosity { count 2 } }"', out)
        self.assertIn("/* radiosity { count 3 } /* nested */ still a comment } */", out)
        self.assertIn("radiosity { importance 0.5 }", out)
        self.assertEqual(settings_in(out, "count"), ["400"])

    def test_appends_after_macros_and_expressions(self):
        # Settings from a macro or an expression cannot be removed textually; the appended ones come last and win.
        scene = "global_settings { radiosity {\n Rad_Settings(1, off, off)\n count 35*2\n adc_bailout 0.01/2\n } }\n"
        out, _ = rewrite_radiosity(scene, LADDER)
        body = out[out.index("radiosity {"):]
        self.assertIn("Rad_Settings(1, off, off)", body)
        self.assertIn("count 35*2", body)
        self.assertIn("adc_bailout 0.01/2", body)
        self.assertLess(body.index("count 35*2"), body.index("count 400"))
        self.assertEqual(out.count("{"), out.count("}"))

    def test_every_branch_of_a_switch_is_overridden(self):
        scene = ("global_settings {\n#switch (Q)\n#case (1)\n radiosity { count 50 }\n#break\n"
                 "#case (2)\n radiosity { count 120, 1000 error_bound 0.25 }\n#break\n#end\n}\n")
        out, _ = rewrite_radiosity(scene, LADDER)
        self.assertEqual(settings_in(out, "count"), ["400", "400"])
        self.assertNotIn("1000", out)
        self.assertIn("#case (2)", out)

    def test_injects_a_block_when_there_is_none(self):
        out, how = rewrite_radiosity("global_settings { assumed_gamma 1 }\n", {"count": 20})
        self.assertEqual(how, "injected")
        self.assertRegex(out, r"global_settings \{\s*radiosity \{[^}]*count 20[^}]*\}\s*assumed_gamma 1 \}")
        out, how = rewrite_radiosity("sphere { 0, 1 }\n", {"count": 20, "always_sample": False})
        self.assertEqual(how, "appended")
        self.assertRegex(out, r"global_settings \{\s*radiosity \{[^}]*count 20\s+always_sample off\s*\}\s*\}")

    def test_refuses_unbalanced_text(self):
        with self.assertRaises(RewriteError):
            rewrite_radiosity("global_settings { radiosity { count 3 }\n", LADDER)
        with self.assertRaises(RewriteError):
            rewrite_radiosity("/* open\nglobal_settings { }\n", LADDER)


class ErrorTest(unittest.TestCase):
    def test_rrmse_and_bad_pixels(self):
        ref = np.ones((4, 5, 3))
        img = ref.copy()
        img[0, 0] = 2.0  # one pixel off by 100 %
        e = image_error(img, ref)
        self.assertAlmostEqual(e["rrmse"], math.sqrt(3 / 60))
        self.assertAlmostEqual(e["bad_fraction"], 1 / 20)
        self.assertEqual(e["non_finite"], 0)

    def test_non_finite_pixels_are_counted_apart(self):
        ref = np.ones((2, 2, 3))
        img = ref.copy()
        img[1, 1, 2] = np.nan
        e = image_error(img, ref)
        self.assertEqual(e["non_finite"], 1)
        self.assertEqual(e["rrmse"], 0.0)


class ReadTest(unittest.TestCase):
    def test_a_rewritten_file_is_read_anew(self):
        # Reading a file rewritten under the same name once returned the old pixels (in the full tool, not here).
        try:
            import OpenImageIO as oiio
        except ImportError:
            self.skipTest("no OpenImageIO Python bindings")
        import tempfile
        from gimetrics import read_linear_rgb
        with tempfile.TemporaryDirectory() as tmp:
            path = pathlib.Path(tmp) / "out.hdr"
            for value in (0.25, 2.0):
                buf = oiio.ImageBuf(oiio.ImageSpec(4, 3, 3, oiio.FLOAT))
                oiio.ImageBufAlgo.fill(buf, (value, value, value))
                self.assertTrue(buf.write(str(path)))
                image = read_linear_rgb(path)
                self.assertEqual(image.shape, (3, 4, 3))
                self.assertAlmostEqual(float(image.mean()), value, places=2)


class CrossingTest(unittest.TestCase):
    def test_interpolates_in_log_log_space(self):
        # Error falls as 1/sqrt(t): from 8 % at 1 s to 2 % at 16 s; 4 % is reached at 4 s.
        t, exact = crossing_time([(16.0, 0.02), (1.0, 0.08)], 0.04)
        self.assertTrue(exact)
        self.assertAlmostEqual(t, 4.0)

    def test_first_crossing_of_a_noisy_curve(self):
        t, exact = crossing_time([(1, 0.1), (2, 0.04), (4, 0.06), (8, 0.01)], 0.05)
        self.assertTrue(exact)
        self.assertLess(t, 2.0)
        self.assertGreater(t, 1.0)

    def test_not_reached_and_reached_at_once(self):
        self.assertEqual(crossing_time([(1, 0.1), (2, 0.06)], 0.05), (None, False))
        self.assertEqual(crossing_time([(3, 0.01), (5, 0.005)], 0.05), (3, False))
        self.assertEqual(crossing_time([], 0.05), (None, False))


class HeadlineTest(unittest.TestCase):
    @staticmethod
    def scene(name, pov, ward):
        points = [{"renderer": "povray", "seconds": t, "rrmse": e, "label": f"p{i}"} for i, (t, e) in enumerate(pov)]
        points += [{"renderer": "wardray", "seconds": t, "rrmse": e, "label": f"p{i}"} for i, (t, e) in enumerate(ward)]
        return {"scene": name, "points": points}

    def test_says_where_wardray_is_not_ahead(self):
        import report
        data = {"scenes": [
            # Same curve shape, wardray four times faster: ahead at every target it reaches.
            self.scene("fast", [(4, 0.08), (16, 0.04), (64, 0.015)], [(1, 0.08), (4, 0.04), (16, 0.015)]),
            # wardray's curve is POV-Ray's, twice as slow.
            self.scene("slow", [(1, 0.08), (4, 0.01)], [(2, 0.08), (8, 0.01)]),
            # wardray never gets below 3 %.
            self.scene("stuck", [(1, 0.08), (4, 0.01)], [(1, 0.08), (4, 0.03)]),
        ]}
        rows, not_ahead, measured = report.headline(data)
        self.assertEqual(measured, 9)
        self.assertEqual(len(rows), 9)
        self.assertIn("| fast | 5 % |", rows[0])
        self.assertTrue(rows[0].endswith("| 0.25 | wardray |"), rows[0])
        self.assertEqual(not_ahead["POV-Ray is faster"],
                         [f"slow at {t} (wardray/POV-Ray 2.00)" for t in ("5 %", "2 %", "1 %")]
                         + ["stuck at 5 % (wardray/POV-Ray 1.42)"])
        self.assertEqual(not_ahead["only POV-Ray reaches the target"],
                         ["stuck at 2 % (wardray/POV-Ray > 1.59)", "stuck at 1 %"])
        self.assertEqual(not_ahead["neither reaches the target"], ["fast at 1 %"])


    def test_against_the_common_reference_wardray_carries_the_model_difference(self):
        import report
        # Against its own reference wardray is 4 times faster everywhere; against POV-Ray's its error never falls
        # below the 1.5 % the two lighting models differ by.
        points = [{"renderer": "povray", "seconds": t, "rrmse": e, "label": f"p{i}"}
                  for i, (t, e) in enumerate([(4, 0.08), (16, 0.04), (64, 0.008)])]
        points += [{"renderer": "wardray", "seconds": t, "rrmse": e, "rrmse_vs_povray_reference": c,
                    "label": f"p{i}"} for i, (t, e, c) in enumerate([(1, 0.08, 0.081), (4, 0.04, 0.042),
                                                                      (16, 0.008, 0.015)])]
        data = {"scenes": [{"scene": "s", "points": points}]}
        own, own_not_ahead, _ = report.headline(data)
        common, common_not_ahead, measured = report.headline(data, common=True)
        self.assertEqual(measured, 3)
        self.assertTrue(own[2].endswith("| 0.25 | wardray |"), own[2])
        self.assertTrue(common[1].endswith("| wardray |"), common[1])
        self.assertEqual(sum(len(v) for v in own_not_ahead.values()), 0)
        self.assertEqual(common_not_ahead["only POV-Ray reaches the target"], ["s at 1 %"])
        self.assertIn("| s | 1 % |", common[2])
        self.assertIn("not reached (best 1.5 % at 16.00 s)", common[2])


class SceneListTest(unittest.TestCase):
    def write(self, text):
        import tempfile
        f = tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False)
        f.write(text)
        f.close()
        self.addCleanup(pathlib.Path(f.name).unlink)
        return f.name

    def test_a_line_may_give_the_scene_its_size(self):
        from compare_gi import ROOT, load_scene_list
        listed = load_scene_list(self.write("# comment\n\n/abs/a.pov 256x256\nscenes/b.pov\n  c.pov   64x48  \n"))
        self.assertEqual(listed, [(pathlib.Path("/abs/a.pov"), (256, 256), {}), (ROOT / "scenes/b.pov", None, {}),
                                  (ROOT / "c.pov", (64, 48), {})])

    def test_a_line_may_give_its_scene_its_own_reference_settings(self):
        from compare_gi import ROOT, load_scene_list
        listed = load_scene_list(self.write("a.pov povray-reference=error_bound:0.018,count:3200 64x48\n"
                                            "b.pov wardray-max-rays=65536 povray-reference=pretrace_end:0.00125\n"))
        self.assertEqual(listed, [(ROOT / "a.pov", (64, 48), {"povray_reference": {"error_bound": 0.018,
                                                                                    "count": 3200}}),
                                  (ROOT / "b.pov", None, {"povray_reference": {"pretrace_end": 0.00125},
                                                          "wardray_max_rays": 65536})])
        with self.assertRaisesRegex(ValueError, r":1: expected one of .* got 'brightness'"):
            load_scene_list(self.write("a.pov povray-reference=brightness:2\n"))
        with self.assertRaisesRegex(ValueError, r":1: expected a number for count"):
            load_scene_list(self.write("a.pov povray-reference=count:many\n"))
        with self.assertRaisesRegex(ValueError, r":1: expected a power of two"):
            load_scene_list(self.write("a.pov wardray-max-rays=50000\n"))
        with self.assertRaisesRegex(ValueError, r":1: expected a scene, at most a size and each option"):
            load_scene_list(self.write("a.pov wardray-max-rays=4096 wardray-max-rays=8192\n"))
        with self.assertRaisesRegex(ValueError, r":1: expected a scene, at most a size and each option"):
            load_scene_list(self.write("a.pov colour=red\n"))

    def test_a_bad_size_or_extra_words_name_the_line(self):
        from compare_gi import load_scene_list
        with self.assertRaisesRegex(ValueError, r":2: expected WIDTHxHEIGHT"):
            load_scene_list(self.write("a.pov\nb.pov 256by256\n"))
        with self.assertRaisesRegex(ValueError, r":1: expected a scene, at most a size"):
            load_scene_list(self.write("a.pov 64x48 extra\n"))
        with self.assertRaisesRegex(ValueError, r":1: expected a scene, at most a size"):
            load_scene_list(self.write("a.pov 64x48 64x48\n"))

    def test_the_shipped_list_compares_cornell_at_256_and_the_rest_at_their_default(self):
        from compare_gi import DEFAULT_SIZE, HERE, load_scene_list
        listed = {path: size for path, size, _ in load_scene_list(HERE / "scenes.txt")}
        cornell = [size for path, size in listed.items() if path.name == "cornell.pov"]
        self.assertEqual(cornell, [(256, 256)])
        self.assertGreaterEqual(DEFAULT_SIZE, (160, 120))
        self.assertTrue(any(path.name == "stackerday.pov" for path in listed))
        self.assertTrue(any(path.name == "stackernight.pov" for path in listed))
        self.assertTrue(any(path.name == "mesh_terrain.pov" for path in listed))


class QuietProgress:
    """A stand-in for progress.Progress that shows nothing."""
    def show(self, *args):
        pass

    def finish(self, *args):
        pass

    def add(self, *args):
        pass


class ReferenceRaysTest(unittest.TestCase):
    def test_aims_past_the_tolerance_in_powers_of_two(self):
        from compare_gi import next_rays
        self.assertEqual(next_rays(64, 0.006, 0.005, 8192), 128)    # nearly there: just double
        self.assertEqual(next_rays(64, 0.05, 0.005, 8192), 8192)    # 100x the noise power: 7680 -> 8192
        self.assertEqual(next_rays(64, 0.05, 0.005, 4096), 4096)    # capped
        self.assertEqual(next_rays(64, 0.02, 0.005, 8192), 2048)    # 16 x 1.2 x 64 = 1229 -> 2048

    def test_the_reference_is_the_mean_of_the_two_seeds(self):
        import compare_gi

        class Ward:
            gi_mode, has_reference, has_seed = "cache", True, True

            def reference_args(self, rays, seed):
                return [rays, seed]

        class Cache:
            def render(self, renderer, text, scene_dir, size, extra, work, what):
                return tuple(extra), 1.0, True  # stands for the image's path

        # Seed 2 differs from seed 1 by 2 % at 64 rays and by 0.2 % at 2048 (next_rays' aim): the loop stops there.
        pixels = {(64, 1): 1.00, (64, 2): 1.02, (2048, 1): 1.000, (2048, 2): 1.002}
        saved = compare_gi.read_linear_rgb
        compare_gi.read_linear_rgb = lambda key: np.full((2, 2, 3), pixels[key])
        try:
            image, info = compare_gi.wardray_reference(Ward(), "", None, (2, 2), None, Cache(),
                                                       {"start_rays": 64, "tolerance": 0.005, "max_rays": 8192},
                                                       QuietProgress(), "scene")
        finally:
            compare_gi.read_linear_rgb = saved
        self.assertEqual(info["rays"], 2048)
        self.assertTrue(info["converged"])
        np.testing.assert_allclose(image, 1.001)


class ModelReferenceTest(unittest.TestCase):
    def _run(self, direct_by_seed, seeds):
        import compare_gi

        class Cache:
            def render(self, renderer, text, scene_dir, size, extra, work, what):
                assert extra[0] == "--gi=off"
                return (extra[2] if len(extra) > 1 else "0"), 1.0, True  # stands for the image's path

        own = np.full((2, 2, 3), 5.0)
        saved = compare_gi.read_linear_rgb
        compare_gi.read_linear_rgb = lambda key: np.full((2, 2, 3), direct_by_seed(int(key)))
        try:
            return compare_gi.model_reference(None, "", None, (2, 2), None, Cache(), own, {"jitter_seeds": seeds},
                                              QuietProgress(), "scene")
        finally:
            compare_gi.read_linear_rgb = saved

    def test_the_direct_light_becomes_its_mean_over_the_jitter_seeds(self):
        # Seed 0's pattern is 1.0; seeds 1..4 give 2, 3, 4, 5 (mean 3.5): own 5 - 1 + 3.5.
        image, info = self._run(lambda seed: 1.0 if seed == 0 else 1.0 + seed, 4)
        np.testing.assert_allclose(image, 7.5)
        self.assertEqual(info["jitter_seeds"], 4)

    def test_a_scene_without_jitter_keeps_wardrays_reference(self):
        image, info = self._run(lambda seed: 2.0, 4)
        self.assertIsNone(image)
        self.assertEqual(info["jitter_seeds"], 0)


class ReferenceArgsTest(unittest.TestCase):
    def _ward(self, own_model):
        import renderers
        ward = renderers.Wardray.__new__(renderers.Wardray)
        ward.gi_mode, ward.has_own_model_reference = "cache", own_model
        return ward

    def test_the_reference_converges_the_cache_modes_own_direct_light(self):
        args = self._ward(True).reference_args(16384, 2)
        self.assertEqual(args[:3], ["--gi=reference", "--gi-rays", "16384"])
        self.assertIn("--gi-area-lights=grid", args)
        # The seed turns the paths alone: the area lights' jitter stays that of the ladder's renders.
        self.assertEqual(args[args.index("--gi-path-seed") + 1], "2")
        self.assertNotIn("--seed", args)

    def test_an_older_binary_keeps_its_reference(self):
        self.assertEqual(self._ward(False).reference_args(64, 1), ["--gi=reference", "--gi-rays", "64", "--seed", "1"])


class WarningLinesTest(unittest.TestCase):
    def test_every_path_loses_its_folders_and_the_message_stays_whole(self):
        import renderers
        lines = ["/usr/share/povray-3.7/scenes/radiosity/patio-radio_37.pov:128:2: warning: coincident surfaces: "
                 "this box and the box at /usr/share/povray-3.7/scenes/radiosity/patio-radio_37.pov:283:2 have flat "
                 "faces that lie on one another; move or resize one of them by a small amount (a 1/2 step)",
                 "warnings: 1", "objects: 12"]
        self.assertEqual(renderers.warning_lines(lines), [
            "patio-radio_37.pov:128:2: warning: coincident surfaces: this box and the box at "
            "patio-radio_37.pov:283:2 have flat faces that lie on one another; move or resize one of them by a small "
            "amount (a 1/2 step)"])


class FormatTest(unittest.TestCase):
    def _renderer(self, image_format):
        import renderers

        class Stub(renderers.ImageFormat):
            name, version = "wardray", "stub"

        return Stub(image_format)

    def test_renders_are_openexr_unless_hdr_is_asked(self):
        import renderers
        ward = renderers.Wardray.__new__(renderers.Wardray)
        ward.exe, ward.gi_mode = pathlib.Path("/bin/wardray"), "cache"
        ward.image_format = renderers.DEFAULT_FORMAT
        self.assertEqual(renderers.DEFAULT_FORMAT, "exr")
        self.assertIn("+FE", ward.command("scene.pov", "out.exr", (4, 3), "/scenes"))
        ward.image_format = "hdr"
        cmd = ward.command("scene.pov", "out.hdr", (4, 3), "/scenes")
        self.assertIn("+FH", cmd)
        self.assertNotIn("+FE", cmd)

    def test_the_format_changes_the_cache_key_and_hdr_keeps_its_old_keys(self):
        import hashlib
        import json
        import tempfile
        import renderers
        with tempfile.TemporaryDirectory() as tmp:
            cache = renderers.RenderCache(tmp)
            exr = cache.key(self._renderer("exr"), "scene", tmp, (4, 3), ["--gi=reference"])
            hdr = cache.key(self._renderer("hdr"), "scene", tmp, (4, 3), ["--gi=reference"])
        self.assertNotEqual(exr, hdr)
        # The key an HDR render had before the format was a choice.
        old = json.dumps({"renderer": "wardray", "version": "stub", "scene": "scene", "includes": [], "size": [4, 3],
                          "args": ["--gi=reference"], "threads": renderers.THREADS}, sort_keys=True)
        self.assertEqual(hdr, hashlib.sha256(old.encode()).hexdigest())


class ReferencesKeyTest(unittest.TestCase):
    def test_references_are_filed_under_the_given_digest_and_the_ladder_keeps_its_own(self):
        import hashlib
        import os
        import tempfile
        import renderers
        with tempfile.TemporaryDirectory() as tmp:
            exe = pathlib.Path(tmp) / "wardray"
            exe.write_text("#!/bin/sh\ncase \"$1\" in --version) echo 'wardray 0.1.0';; "
                           "*) echo '--gi=reference --gi-rays --seed';; esac\n")
            os.chmod(exe, 0o755)
            digest = hashlib.sha256(exe.read_bytes()).hexdigest()
            plain = renderers.Wardray(exe)
            reusing = renderers.Wardray(exe, references_key="0123456789abcdef")
            # The report names the binary measured either way.
            self.assertEqual(plain.version, f"wardray 0.1.0 (binary sha256 {digest[:12]})")
            self.assertEqual(reusing.version, plain.version)
            cache = renderers.RenderCache(tmp)
            args = ("scene", tmp, (4, 3), ["--gi=reference"])
            self.assertNotEqual(cache.key(reusing, *args), cache.key(plain, *args))

            # The key is the one a binary with that digest files its references under.
            class Earlier(renderers.ImageFormat):
                name, version = "wardray", "wardray 0.1.0 (binary sha256 0123456789ab)"

            self.assertEqual(cache.key(reusing, *args), cache.key(Earlier(renderers.DEFAULT_FORMAT), *args))


if __name__ == "__main__":
    unittest.main()
