#!/usr/bin/env python3
"""Checks that wardray's layers depend one way, downward: includes, CMake links and the heavy headers.

The layers, bottom to top, are LAYERS below. A source file in a layer's folder may include headers of its own layer
and of the layers below it, with one exception: the parser hands a scene::Scene upward and nothing but the
application includes a parser header or links the parser target (pbrt-v4's parser knows nothing below it, and the
renderer knows nothing of the parser). The heavy or system-specific headers stay in the folders that own them.
A test in tests/LAYER/ may include what LAYER may, plus the parser (tests build scenes from scene text) and the
tests' own helpers.

usage: tools/check_layers.py [ROOT]      exit status 0 when every rule holds, 1 with one line per violation
"""
import pathlib
import re
import sys

LAYERS = ["core", "function", "scene", "parser", "geometry", "texture", "media", "photons", "cache", "lighting",
          "camera", "render", "app"]
# The parser is read only by the application (and tests); the layers between it and app never see it.
PARSER_READERS = {"app"}
# Headers that only some folders may include: the prefix of the include, and the folders allowed.
HEAVY_HEADERS = {
    "embree3/": {"geometry"},
    "CGAL/": {"geometry"},
    "OpenImageIO/": {"render"},
    "boost/spirit": {"parser"},
    "mpi.h": {"app"},
}
# Single files allowed a heavy header besides its folders: the ray benchmark measures wardray against bare Embree.
HEAVY_HEADER_FILES = {"embree3/": {"tools/bench/ray_bench.cpp"}}
# Folders that are not layers but sit beside them, with the layer whose rules they follow.
TEST_FOLDERS = {"bad_input": "app", "fuzz": "parser"}
TOOL_LAYER = "app"

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)
LINK = re.compile(r"target_link_libraries\(\s*wardray_(\w+)([^)]*)\)", re.S)


def may_use(layer, other):
    """Whether code of `layer` may include headers of, or link, `other`."""
    if other == layer:
        return True
    if other == "parser":
        return layer in PARSER_READERS
    return LAYERS.index(other) < LAYERS.index(layer)


def source_files(root):
    for path in sorted(root.rglob("*")):
        if path.suffix in (".h", ".cpp") and "build" not in path.relative_to(root).parts[0]:
            yield path


def layer_of(root, path):
    """The layer whose rules a file follows, and whether it is a test; None for files outside every layer."""
    parts = path.relative_to(root).parts
    if parts[0] in LAYERS:
        return parts[0], False
    if parts[0] == "tests" and len(parts) > 2:
        return TEST_FOLDERS.get(parts[1], parts[1] if parts[1] in LAYERS else None), True
    if parts[0] == "tools":
        return TOOL_LAYER, False
    return None, False


def include_violations(root):
    for path in source_files(root):
        layer, is_test = layer_of(root, path)
        if layer is None:
            continue
        rel = path.relative_to(root)
        text = path.read_text(errors="replace")
        for m in INCLUDE.finditer(text):
            kind, name = m.groups()
            line = text.count("\n", 0, m.start()) + 1
            for prefix, owners in HEAVY_HEADERS.items():
                allowed = rel.as_posix() in HEAVY_HEADER_FILES.get(prefix, set())
                if name.startswith(prefix) and layer not in owners and not is_test and not allowed:
                    yield f"{rel}:{line}: includes <{name}>, which only {', '.join(sorted(owners))}/ may include"
            if kind != '"':
                continue
            other = name.split("/")[0]
            if other not in LAYERS or "/" not in name:
                continue
            if is_test and other == "parser":
                continue
            if not may_use(layer, other):
                yield f"{rel}:{line}: {layer}/ includes \"{name}\" from the layer above it ({other}/)"


def link_violations(root):
    for cmake in sorted(root.glob("*/CMakeLists.txt")):
        layer = cmake.parent.name
        if layer not in LAYERS:
            continue
        text = cmake.read_text()
        for m in LINK.finditer(text):
            target, args = m.groups()
            if target != layer:
                continue
            for other in re.findall(r"\bwardray_(\w+)", args):
                if other in LAYERS and not may_use(layer, other):
                    line = text.count("\n", 0, m.start()) + 1
                    yield f"{cmake.relative_to(root)}:{line}: wardray_{layer} links wardray_{other}, a layer above it"


def violations(root):
    return list(include_violations(root)) + list(link_violations(root))


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent)
    found = violations(root)
    for v in found:
        print(v)
    print(f"layers: {len(found)} violation(s)" if found else "layers: every dependency points downward")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
