#!/usr/bin/env python3
"""Checks the house rules that keep wardray's files small and its dispatch in tables.

- No source file (.h, .cpp, under the layers, tests/ and tools/) over MAX_LINES lines.
- No keyword dispatch as an if-chain of more than MAX_BRANCHES branches: an `if` followed by `else if`s at the same
  indentation whose conditions compare against string literals or keyword names (a table says it better and
  looks up faster).

usage: tools/check_house.py [ROOT]      exit status 0 when every rule holds, 1 with one line per violation
"""
import pathlib
import re
import sys

MAX_LINES = 600
MAX_BRANCHES = 10
FOLDERS = ["core", "function", "scene", "parser", "geometry", "texture", "media", "photons", "cache", "lighting",
           "camera", "render", "app", "tests", "tools"]

BRANCH = re.compile(r"^(\s*)(?:\}\s*)?(else\s+)?if\s*\((.*)")
# A condition that dispatches on a word: a string literal, or a keyword constant / keyword test.
KEYWORD_TEST = re.compile(r'"[A-Za-z_][A-Za-z_0-9]*"|\bKeyword::|\bkw_|is_keyword\(|\bkeyword\b')


def source_files(root):
    for folder in FOLDERS:
        base = root / folder
        if base.is_dir():
            yield from sorted(p for p in base.rglob("*") if p.suffix in (".h", ".cpp"))


def long_files(root):
    for path in source_files(root):
        n = path.read_text(errors="replace").count("\n")
        if n > MAX_LINES:
            yield f"{path.relative_to(root)}: {n} lines (at most {MAX_LINES})"


def keyword_chains(path):
    """(first line, branch count) of each if / else-if chain dispatching on keywords."""
    chain_start, chain_indent, branches = None, None, 0
    for number, line in enumerate(path.read_text(errors="replace").split("\n"), start=1):
        m = BRANCH.match(line)
        if m:
            indent, is_else, condition = len(m.group(1)), m.group(2), m.group(3)
            if is_else and chain_start is not None and indent == chain_indent:
                if KEYWORD_TEST.search(condition):
                    branches += 1
                continue
            if chain_start is not None and branches > MAX_BRANCHES:
                yield chain_start, branches
            chain_start, chain_indent = number, indent
            branches = 1 if KEYWORD_TEST.search(condition) else 0
            continue
        stripped = line.strip()
        if chain_start is None or not stripped or stripped.startswith("//"):
            continue
        indent = len(line) - len(line.lstrip())
        # A statement back at the chain's indentation that is not part of it ends the chain.
        if indent <= chain_indent and not stripped.startswith("}") and not stripped.startswith("else"):
            if branches > MAX_BRANCHES:
                yield chain_start, branches
            chain_start, branches = None, 0
    if chain_start is not None and branches > MAX_BRANCHES:
        yield chain_start, branches


def long_chains(root):
    for path in source_files(root):
        for line, branches in keyword_chains(path):
            yield (f"{path.relative_to(root)}:{line}: keyword dispatch as an if-chain of {branches} branches "
                   f"(at most {MAX_BRANCHES}; use a table)")


def violations(root):
    return list(long_files(root)) + list(long_chains(root))


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent)
    found = violations(root)
    for v in found:
        print(v)
    print(f"house: {len(found)} violation(s)" if found else "house: every file and dispatch within the rules")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
