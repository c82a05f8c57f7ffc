#!/usr/bin/python3
"""Renders a scene scaled by 1e-6 ... 1e6 with wardray and with POV-Ray and prints a Markdown table of each
renderer's rRMSE against its own render at scale 1 (docs/metrics.md's definitions, through `wardray diff`).

The scene reads its scale from the float S (Declare=S=...), as scenes/stiff/scaled.pov does.

  tools/scale_report.py                              # scenes/stiff/scaled.pov, 160x120
  tools/scale_report.py --scene my.pov --scales 1e-3 1e3
  tools/scale_report.py --wardray-arg=--gi=reference  # extra wardray switches, repeatable
  tools/scale_report.py --wrap --scene scenes/parity/blob.pov --scales 1e-4 1e4
                                                     # a scene that does not read S: `scale S` is appended to
                                                     # its top-level camera, light sources, objects and media
  tools/scale_report.py --wrap --lengths --scene scenes/parity/ground_fog.pov --scales 1e-4 1e4
                                                     # and the lengths a transform does not reach are scaled too
  tools/scale_report.py --threads-only --scene scenes/parity/media_density.pov
                                                     # only whether +WT1 and +WT2 give the same bytes

What `--lengths` scales, wherever the block is (top level, #declare or macro), by rewriting the value that
follows the keyword (a number, identifier, parenthesised or <vector> expression with + - * /):
  - fog: `distance`, `fog_offset`, `fog_alt` times S; fog `turbulence` divided by S (POV-Ray looks the noise up
    at the world point times that vector, so it is a frequency). fog_type, color, up, turb_depth, octaves,
    omega and lambda are ratios or directions and stay.
  - media: the `absorption` and `emission` colours and the `scattering { type, colour }` colour divided by S
    (POV-Ray applies them per unit of world length, and an object's transform moves only the density
    patterns). extinction, eccentricity, samples, intervals, ratio, confidence, variance, jitter, aa_level and
    aa_threshold are ratios or counts and stay; densities follow their object, or for a scene-level media
    block its `scale S` from --wrap.
  - `fade_distance` (of interiors and of light sources) times S.
  - a cylinder light's `radius` and `falloff` times S (lengths from its axis that POV-Ray does not transform;
    a spotlight's are angles and stay).
  - photons: global_settings' `spacing` times S (the photons' `media max_steps, factor` is a ratio).
  - rainbow `distance` times S.
Not scaled: radiosity's distance_maximum, isosurface and parametric accuracy, blob thresholds, and other
lengths outside the atmosphere, media and lights.
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
          "superellipsoid", "light_group", "media"}


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
        if c == "}":
            inserts.append(i)  # closes a block a macro opened (`#macro Ball() sphere {`): placed too
            i += 1
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


_WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_NUMBER = re.compile(r"(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
# Colour keywords that may come before a colour's expression.
_COLOUR_WORDS = {"color", "colour", "rgb", "rgbf", "rgbt", "rgbft", "srgb", "srgbf", "srgbt", "srgbft"}


def _skip_space(masked, i):
    while i < len(masked) and masked[i].isspace():
        i += 1
    return i


def _closing(masked, i, open_c, close_c):
    depth = 0
    for j in range(i, len(masked)):
        if masked[j] == open_c:
            depth += 1
        elif masked[j] == close_c:
            depth -= 1
            if depth == 0:
                return j
    raise ValueError("unbalanced %r at offset %d" % (open_c, i))


def expression_extent(masked, i):
    """(start, end) of the float or vector expression at masked[i:]: operands (numbers, identifiers with optional
    (arguments) or .x, parenthesised groups, <vectors>) joined by + - * /, with unary signs."""
    i = _skip_space(masked, i)
    start = i
    while True:
        i = _skip_space(masked, i)
        while i < len(masked) and masked[i] in "+-":
            i = _skip_space(masked, i + 1)
        if masked.startswith("(", i):
            i = _closing(masked, i, "(", ")") + 1
        elif masked.startswith("<", i):
            i = _closing(masked, i, "<", ">") + 1
        else:
            m = _NUMBER.match(masked, i) or _WORD.match(masked, i)
            if not m:
                raise ValueError("no expression at offset %d: %r" % (i, masked[i:i + 30]))
            i = m.end()
            if m.re is _WORD and masked.startswith("(", _skip_space(masked, i)):
                i = _closing(masked, _skip_space(masked, i), "(", ")") + 1
        while masked.startswith(".", i) and _WORD.match(masked, i + 1):
            i = _WORD.match(masked, i + 1).end()
        j = _skip_space(masked, i)
        if j < len(masked) and masked[j] in "+-*/":
            i = j + 1
            continue
        return start, i


def colour_extent(masked, i):
    """(start, end) of a colour's expression after its optional `color` and `rgb...` keywords."""
    i = _skip_space(masked, i)
    m = _WORD.match(masked, i)
    while m and m.group() in _COLOUR_WORDS:
        i = _skip_space(masked, m.end())
        m = _WORD.match(masked, i)
    return expression_extent(masked, i)


def _blocks(masked, keyword):
    """(open, close) of every `keyword {` block, nested ones included."""
    out = []
    for m in re.finditer(r"(?<![A-Za-z0-9_#])" + keyword + r"\s*\{", masked):
        open_at = m.end() - 1
        out.append((open_at, _closing(masked, open_at, "{", "}")))
    return out


def _top_level_words(masked, open_at, close_at):
    """(word, start, end) of each word directly inside the block (not inside a nested block)."""
    i, depth = open_at + 1, 0
    while i < close_at:
        c = masked[i]
        if c == "{":
            depth += 1
        elif c == "}":
            depth -= 1
        elif depth == 0:
            m = _WORD.match(masked, i)
            if m and (i == 0 or not (masked[i - 1].isalnum() or masked[i - 1] in "_#.")):
                yield m.group(), m.start(), m.end()
                i = m.end()
                continue
        i += 1


def scale_lengths(text):
    """The scene text with the lengths (times S) and per-length coefficients (divided by S) that a `scale S`
    transform does not reach rewritten, as the module docstring lists."""
    masked = mask_comments_and_strings(text)
    edits = []  # (start, end, "*S" or "/S")

    def value(at, how, colour=False):
        a, b = (colour_extent if colour else expression_extent)(masked, at)
        edits.append((a, b, how))

    for open_at, close_at in _blocks(masked, "fog"):
        for w, _, end in _top_level_words(masked, open_at, close_at):
            if w in ("distance", "fog_offset", "fog_alt"):
                value(end, "*S")
            elif w == "turbulence":
                value(end, "/S")
    for open_at, close_at in _blocks(masked, "media"):
        for w, _, end in _top_level_words(masked, open_at, close_at):
            if w in ("absorption", "emission"):
                value(end, "/S", colour=True)
    for open_at, close_at in _blocks(masked, "scattering"):
        comma = masked.index(",", open_at)
        value(comma + 1, "/S", colour=True)
    for m in re.finditer(r"(?<![A-Za-z0-9_])fade_distance(?![A-Za-z0-9_])", masked):
        value(m.end(), "*S")
    for open_at, close_at in _blocks(masked, "light_source"):
        words = list(_top_level_words(masked, open_at, close_at))
        if any(w == "cylinder" for w, _, _ in words):
            for w, _, end in words:
                if w in ("radius", "falloff"):
                    value(end, "*S")
    for g_open, g_close in _blocks(masked, "global_settings"):
        for open_at, close_at in _blocks(masked[:g_close], "photons"):
            if open_at > g_open:
                for w, _, end in _top_level_words(masked, open_at, close_at):
                    if w == "spacing":
                        value(end, "*S")
    for open_at, close_at in _blocks(masked, "rainbow"):
        for w, _, end in _top_level_words(masked, open_at, close_at):
            if w == "distance":
                value(end, "*S")
    for a, b, how in sorted(edits, reverse=True):
        text = text[:a] + "((" + text[a:b] + ")" + how + ")" + text[b:]
    return text


def scale_name(s):
    return "1" if s == 1 else "1e%d" % round(math.log10(s))


def run(command, cwd):
    result = subprocess.run(command, cwd=cwd, capture_output=True, text=True, errors="replace")
    return result.returncode, result.stderr + result.stdout


def render_wardray(args, scene, out, scale, cwd, threads=None):
    command = [args.wardray, str(scene), "+W%d" % args.width, "+H%d" % args.height, "-A", "+FH", "-o", str(out),
               "Declare=S=%r" % scale] + (["+WT%d" % threads] if threads else []) + args.wardray_arg
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
                   "top-level camera, light sources, objects and media")
    p.add_argument("--lengths", action="store_true", help="with --wrap: also scale the lengths and per-length "
                   "coefficients of fog, media and lights that a transform does not reach (see above)")
    p.add_argument("--threads", action="store_true", help="also render wardray with +WT1 and +WT2 at each scale "
                   "and say whether the two files are the same bytes")
    args = p.parse_args()
    if args.lengths and not args.wrap:
        p.error("--lengths goes with --wrap")

    work = pathlib.Path(tempfile.mkdtemp(prefix="wardray-scale-"))
    scene = work / args.scene.name
    shutil.copy(args.scene, scene)
    if args.wrap:
        text = wrap_in_scale(scene.read_text())
        scene.write_text(scale_lengths(text) if args.lengths else text)
    # Included files next to the scene are found by both renderers through +L.
    args.povray_arg.append("+L" + str(args.scene.resolve().parent))

    renderers = [("wardray", render_wardray)] + ([] if args.no_povray else [("POV-Ray", render_povray)])
    images = {}
    same = {}
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
            if name == "wardray" and args.threads:
                outs = [work / ("wardray_%s_wt%d.hdr" % (scale_name(s), t)) for t in (1, 2)]
                done = [render_wardray(args, scene, o, s, work, t)[0] for o, t in zip(outs, (1, 2))]
                same[s] = all(done) and outs[0].read_bytes() == outs[1].read_bytes()

    def compare(name, s):
        image, reference = images.get((name, s)), images.get((name, 1.0))
        return diff(args, image, reference) if image and reference else None

    header = "| scale | wardray rRMSE | wardray bad pixels | wardray NaN/inf |"
    rule = "|---|---|---|---|"
    if args.threads:
        header += " wardray +WT1 = +WT2 |"
        rule += "---|"
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
        if args.threads:
            row += " %s |" % ("same bytes" if same.get(s) else "DIFFERENT")
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
