"""Tests of tools/check_layers.py: the repository itself passes, and each kind of upward dependency is caught."""
import pathlib
import sys
import tempfile
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import check_layers  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent


def tree(files):
    """A temporary source tree holding `files` (path -> text)."""
    tmp = tempfile.TemporaryDirectory(prefix="layers-")
    for name, text in files.items():
        path = pathlib.Path(tmp.name) / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return tmp


class CheckLayers(unittest.TestCase):
    def violations(self, files):
        with tree(files) as root:
            return check_layers.violations(pathlib.Path(root))

    def test_the_repository_depends_only_downward(self):
        self.assertEqual(check_layers.violations(ROOT), [])

    def test_a_downward_include_is_allowed(self):
        self.assertEqual(self.violations({"lighting/a.cpp": '#include "geometry/shape.h"\n#include "core/vec3.h"\n'}),
                         [])

    def test_an_upward_include_is_caught_with_its_line(self):
        found = self.violations({"geometry/a.cpp": '// x\n#include "lighting/integrator.h"\n'})
        self.assertEqual(len(found), 1)
        self.assertIn("geometry/a.cpp:2:", found[0])

    def test_only_the_application_reads_the_parser(self):
        self.assertEqual(len(self.violations({"render/a.cpp": '#include "parser/parse.h"\n'})), 1)
        self.assertEqual(self.violations({"app/a.cpp": '#include "parser/parse.h"\n'}), [])
        self.assertEqual(self.violations({"tests/lighting/a_test.cpp": '#include "parser/parse.h"\n'}), [])

    def test_a_test_follows_its_folder(self):
        self.assertEqual(len(self.violations({"tests/cache/a_test.cpp": '#include "render/film.h"\n'})), 1)

    def test_heavy_headers_stay_in_their_folder(self):
        self.assertEqual(len(self.violations({"lighting/a.cpp": "#include <embree3/rtcore.h>\n"})), 1)
        self.assertEqual(len(self.violations({"geometry/a.cpp": "#include <OpenImageIO/imageio.h>\n"})), 1)
        self.assertEqual(self.violations({"geometry/a.cpp": "#include <embree3/rtcore.h>\n"}), [])

    def test_an_upward_link_is_caught(self):
        cmake = "add_library(wardray_cache STATIC a.cpp)\ntarget_link_libraries(wardray_cache PUBLIC wardray_lighting)\n"
        found = self.violations({"cache/CMakeLists.txt": cmake})
        self.assertEqual(len(found), 1)
        self.assertIn("wardray_lighting", found[0])
        self.assertEqual(len(self.violations({"geometry/CMakeLists.txt":
                                              "target_link_libraries(wardray_geometry PUBLIC wardray_parser)\n"})), 1)


if __name__ == "__main__":
    unittest.main()
