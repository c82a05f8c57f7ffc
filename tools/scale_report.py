#!/usr/bin/python3
"""Renders a scene scaled by 1e-6 ... 1e6 with wardray and with POV-Ray and prints a Markdown table of each
renderer's rRMSE against its own render at scale 1 (docs/metrics.md's definitions, through `wardray diff`).

The scene reads its scale from the float S (Declare=S=...), as scenes/stiff/scaled.pov does.

  tools/scale_report.py                              # scenes/stiff/scaled.pov, 160x120
  tools/scale_report.py --scene my.pov --scales 1e-3 1e3
  tools/scale_report.py --wardray-arg=--gi=reference  # extra wardray switches, repeatable
  tools/scale_report.py --wrap --scene scenes/parity/blob.pov --scales 1e-4 1e4
                                                     # a scene that does not read S: `scale S` is appended to
                                                     # its top-level camera, light sources and objects
"""
import argparse
import json
import math
import re
import pathlib
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tools" / "compare"))

from povrewrite import mask_comments_and_strings, matching_brace  # noqa: E402

# What `--wrap` scales: the blocks at the top level of a scene that are placed in space.
PLACED = {"camera", "light_source", "object", "union", "intersection", "difference", "merge", "sphere", "box",
          "cylinder", "cone", "plane", "torus", "disc", "triangle", "smooth_triangle", "polygon", "mesh", "mesh2",
          "blob", "isosurface", "parametric", "height_field", "julia_fractal", "bicubic_patch", "sphere_sweep",
          "ovus", "lemon", "poly", "polynomial", "cubic", "quartic", "quadric", "lathe", "sor", "prism", "text",
          "superellipsoid", "light_group"}


def wrap_in_scale(text):
    """The scene text with `scale S` before the closing brace of every top-level camera, light source and object
    (not those being declared): the whole scene scaled by S, as its own camera sees it."""
    masked = mask_comments_and_strings(text)
    inserts, i, n = [], 0, len(masked)
    word = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
    while i < n:
        c = masked[i]
        if c == "{":
            i = matching_brace(masked, i) + 1  # a block that is not placed: skip it whole
            continue
        m = word.match(masked, i)
        if not m:
            i += 1
            continue
        j = m.end()
        while j < n and masked[j].isspace():
            j += 1
        before = masked[:m.start()].rstrip()
        declared = before.endswith("=")
        if m.group() in PLACED and j < n and masked[j] == "{" and not declared:
            close = matching_brace(masked, j)
            inserts.append(close)
            i = close + 1
        else:
            i = m.end()
    for at in sorted(inserts, reverse=True):
        text = text[:at] + " scale S " + text[at:]
    return text


def scale_name(s):
    return "1" if s == 1 else "1e%d" % round(math.log10(s))


def run(command, cwd):
    result = subprocess.run(command, cwd=cwd, capture_output=True, text=True, errors="replace")
    return result.returncode, result.stderr + result.stdout


def render_wardray(args, scene, out, scale, cwd):
    command = [args.wardray, str(scene), "+W%d" % args.width, "+H%d" % args.height, "-A", "+FH", "-o", str(out),
               "Declare=S=%r" % scale] + args.wardray_arg
    status, output = run(command, cwd)
    return status == 0, output


def render_povray(args, scene, out, scale, cwd):
    # POV-Ray writes only under its working folder: render there, with the scene beside it.
    command = [args.povray, "+I" + scene.name, "+O" + out.name, "+W%d" % args.width, "+H%d" % args.height,
               "-A", "-D", "+FH", "+WT2", "Declare=S=%r" % scale] + args.povray_arg
    status, output = run(command, cwd)
    return status == 0 and out.exists(), output


def diff(args, image, reference):
    status, output = run([args.wardray, "diff", str(image), str(reference), "--json"], None)
    if status != 0:
        return None
    return json.loads(output[output.index("{"):])


def cell(d, key, percent):
    if d is None:
        return "failed"
    v = d[key]
    return "%.3f %%" % (100 * v) if percent else str(v)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--scene", type=pathlib.Path, default=ROOT / "scenes" / "stiff" / "scaled.pov")
    p.add_argument("--scales", type=float, nargs="+", default=[1e-6, 1e-3, 1e3, 1e6])
    p.add_argument("--width", type=int, default=160)
    p.add_argument("--height", type=int, default=120)
    p.add_argument("--wardray", default=str(ROOT / "build" / "wardray"))
    p.add_argument("--povray", default="povray")
    p.add_argument("--wardray-arg", action="append", default=[],
                   help="an extra wardray switch such as --gi=reference (repeatable)")
    p.add_argument("--povray-arg", action="append", default=[], help="an extra POV-Ray switch (repeatable)")
    p.add_argument("--no-povray", action="store_true", help="render with wardray only")
    p.add_argument("--keep", type=pathlib.Path, help="keep the images in this folder")
    p.add_argument("--wrap", action="store_true", help="the scene does not read S: append `scale S` to its "
                   "top-level camera, light sources and objects")
    args = p.parse_args()

    work = pathlib.Path(tempfile.mkdtemp(prefix="wardray-scale-"))
    scene = work / args.scene.name
    shutil.copy(args.scene, scene)
    if args.wrap:
        scene.write_text(wrap_in_scale(scene.read_text()))
    # Included files next to the scene are found by both renderers through +L.
    args.povray_arg.append("+L" + str(args.scene.resolve().parent))

    renderers = [("wardray", render_wardray)] + ([] if args.no_povray else [("POV-Ray", render_povray)])
    images = {}
    notes = []
    for name, render in renderers:
        for s in [1.0] + [s for s in args.scales if s != 1.0]:
            out = work / ("%s_%s.hdr" % ("wardray" if name == "wardray" else "povray", scale_name(s)))
            ok, output = render(args, scene, out, s, work)
            if not ok:
                print("%s at scale %s failed:\n%s" % (name, scale_name(s), output[-2000:]), file=sys.stderr)
                reason = [line.strip() for line in output.splitlines() if "rror" in line][:1]
                notes.append("- %s at scale %s failed: %s" % (name, scale_name(s), reason[0] if reason else "?"))
            images[name, s] = out if ok else None

    def compare(name, s):
        image, reference = images.get((name, s)), images.get((name, 1.0))
        return diff(args, image, reference) if image and reference else None

    header = "| scale | wardray rRMSE | wardray bad pixels | wardray NaN/inf |"
    rule = "|---|---|---|---|"
    if not args.no_povray:
        header += " POV-Ray rRMSE | POV-Ray bad pixels | wardray vs POV-Ray rRMSE |"
        rule += "---|---|---|"
    extra = " ".join(args.wardray_arg)
    print("Scene %s, %dx%d, rRMSE of each scale against the same renderer at scale 1%s.\n"
          % (args.scene.name, args.width, args.height, (", wardray " + extra) if extra else ""))
    print(header)
    print(rule)
    for s in [1.0] + [s for s in args.scales if s != 1.0]:
        w = compare("wardray", s)
        row = "| %s | %s | %s | %s |" % (scale_name(s), cell(w, "rrmse", True), cell(w, "bad_pixel_fraction", True),
                                          cell(w, "non_finite_pixels", False))
        if not args.no_povray:
            v = compare("POV-Ray", s)
            both = (diff(args, images["wardray", s], images["POV-Ray", s])
                    if images.get(("wardray", s)) and images.get(("POV-Ray", s)) else None)
            row += " %s | %s | %s |" % (cell(v, "rrmse", True), cell(v, "bad_pixel_fraction", True),
                                        cell(both, "rrmse", True))
        print(row)
    if notes:
        print("\n" + "\n".join(notes))

    if args.keep:
        args.keep.mkdir(parents=True, exist_ok=True)
        for f in work.glob("*.hdr"):
            shutil.copy(f, args.keep / f.name)
    shutil.rmtree(work)


if __name__ == "__main__":
    main()
