"""Tests of tools/check_house.py: the repository itself passes, and a long file or a long keyword chain is caught."""
import pathlib
import sys
import tempfile
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import check_house  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent


def chain(branches, literal=True):
    cond = (lambda i: f'w == "k{i}"') if literal else (lambda i: f"x > {i}")
    lines = [f"    if ({cond(0)}) a = {0};"] + [f"    else if ({cond(i)}) a = {i};" for i in range(1, branches)]
    return "void f() {\n" + "\n".join(lines) + "\n    g();\n}\n"


class CheckHouse(unittest.TestCase):
    def violations(self, files):
        with tempfile.TemporaryDirectory(prefix="house-") as tmp:
            for name, text in files.items():
                path = pathlib.Path(tmp) / name
                path.parent.mkdir(parents=True, exist_ok=True)
                path.write_text(text)
            return check_house.violations(pathlib.Path(tmp))

    def test_the_repository_keeps_the_rules(self):
        self.assertEqual(check_house.violations(ROOT), [])

    def test_a_long_file_is_caught(self):
        self.assertEqual(len(self.violations({"geometry/a.cpp": "int x;\n" * 601})), 1)
        self.assertEqual(self.violations({"geometry/a.cpp": "int x;\n" * 600}), [])

    def test_a_long_keyword_chain_is_caught_at_its_first_line(self):
        found = self.violations({"parser/a.cpp": chain(11)})
        self.assertEqual(len(found), 1)
        self.assertIn("parser/a.cpp:2:", found[0])
        self.assertEqual(self.violations({"parser/a.cpp": chain(10)}), [])

    def test_a_chain_of_numeric_tests_is_not_keyword_dispatch(self):
        self.assertEqual(self.violations({"parser/a.cpp": chain(14, literal=False)}), [])

    def test_braced_branches_count_as_one_chain(self):
        body = "void f() {\n    if (w == \"a\") {\n        x();\n"
        body += "".join(f"    }} else if (w == \"k{i}\") {{\n        y();\n" for i in range(11)) + "    }\n}\n"
        self.assertEqual(len(self.violations({"parser/a.cpp": body})), 1)


if __name__ == "__main__":
    unittest.main()
