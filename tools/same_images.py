#!/usr/bin/env python3
"""Renders the same scenes with two wardray binaries and says whether every image is byte-identical.

For a change meant to leave behaviour alone (a restructuring, a speed-up that must not move a pixel): every scene
of scenes/ and a fixed set of POV-Ray's example scenes, each rendered by both binaries as linear HDR and as PNG,
with and without antialiasing; the files are compared byte for byte, and the wall times are given side by side.

usage: tools/same_images.py OLD_WARDRAY NEW_WARDRAY [--size 160x120] [--jobs 2] [--examples-only | --ours-only]
exit status: 0 when every image is identical, 1 otherwise.
"""
import argparse
import concurrent.futures
import hashlib
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
EXAMPLES = pathlib.Path("/usr/share/povray-3.7/scenes")
# Thirty example scenes that parse and render today, chosen to cover shapes, CSG, textures, lights, area lights,
# reflection and refraction, the language, and radiosity.
EXAMPLE_SCENES = [
    "objects/lathe2.pov", "objects/prism2.pov", "objects/primitiv.pov", "objects/superel1.pov", "objects/torus1.pov",
    "objects/sor1.pov", "objects/ttf1.pov", "objects/mesh2.pov", "objects/polygon.pov", "objects/quartic/helix.pov",
    "objects/quartic/steiner.pov", "objects/csg/cliptst2.pov", "objects/csg/intee1.pov",
    "textures/patterns/agate.pov", "textures/patterns/bozo.pov", "textures/patterns/brick.pov",
    "textures/patterns/crackle1.pov", "textures/finishes/metallicreflection.pov", "textures/normals/normal.pov",
    "lights/arealit1.pov", "lights/spotlite.pov", "lights/circular.pov", "lights/parallel_lights.pov",
    "interior/iortest.pov", "interior/atten1.pov", "language/trace.pov", "language/vturbulence.pov",
    "camera/orthographic.pov", "radiosity/cornell.pov", "radiosity/rad_def_test_37.pov",
]
VARIANTS = [("hdr", ["+FH", "-A"]), ("png", ["+FN", "+A0.3"])]


def scenes(args):
    out = []
    if not args.examples_only:
        out += sorted(p for p in (ROOT / "scenes").rglob("*.pov"))
    if not args.ours_only:
        out += [EXAMPLES / s for s in EXAMPLE_SCENES if (EXAMPLES / s).exists()]
    return out


def render(binary, scene, variant, flags, size, work):
    out = work / f"{binary.parent.name}-{variant}.{variant}"
    cmd = [str(binary), f"+I{scene}", f"+O{out}", f"+W{size[0]}", f"+H{size[1]}", "-D", "+WT1"] + flags
    start = time.perf_counter()
    proc = subprocess.run(cmd, cwd=scene.parent, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    elapsed = time.perf_counter() - start
    digest = hashlib.sha256(out.read_bytes()).hexdigest() if out.exists() else f"exit {proc.returncode}"
    return digest, elapsed


def compare(scene, old, new, size):
    rows = []
    with tempfile.TemporaryDirectory(prefix="same-") as tmp:
        work = pathlib.Path(tmp)
        for variant, flags in VARIANTS:
            (work / "old").mkdir(exist_ok=True)
            (work / "new").mkdir(exist_ok=True)
            a, ta = render(old, scene, variant, flags, size, work / "old")
            b, tb = render(new, scene, variant, flags, size, work / "new")
            # A render that failed is never "the same", even when both binaries fail alike.
            rows.append((variant, a == b and not a.startswith("exit"), a, b, ta, tb))
    return scene, rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("old", type=pathlib.Path)
    ap.add_argument("new", type=pathlib.Path)
    ap.add_argument("--size", default="160x120")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--examples-only", action="store_true")
    ap.add_argument("--ours-only", action="store_true")
    args = ap.parse_args()
    size = tuple(int(v) for v in args.size.split("x"))
    old, new = args.old.resolve(), args.new.resolve()
    todo = scenes(args)
    different = 0
    total_old = total_new = 0.0
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for scene, rows in pool.map(lambda s: compare(s, old, new, size), todo):
            for variant, same, a, b, ta, tb in rows:
                total_old += ta
                total_new += tb
                name = scene.relative_to(EXAMPLES) if EXAMPLES in scene.parents else scene.relative_to(ROOT)
                mark = "same" if same else ("FAILED" if a.startswith("exit") else "DIFFERENT")
                if not same:
                    different += 1
                print(f"{mark:9} {variant} {ta:6.2f} s {tb:6.2f} s  {name}" + ("" if same else f"  {a[:12]} {b[:12]}"))
    print(f"{len(todo) * len(VARIANTS) - different} of {len(todo) * len(VARIANTS)} images identical; "
          f"time new/old {total_new / total_old:.3f} ({total_new:.1f} s / {total_old:.1f} s)")
    return 1 if different else 0


if __name__ == "__main__":
    sys.exit(main())
