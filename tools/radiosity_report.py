#!/usr/bin/env python3
"""Measures wardray's radiosity against POV-Ray's and writes docs/reports/radiosity.md.

For each scene (POV-Ray's cornell.pov and the project's scenes/radiosity/*.pov):
  1. references: POV-Ray's converged render (the scene's radiosity block with count 1600, error_bound 0.1,
     pretrace_end 0.01, nearest_count 20 set, as docs/metrics.md says) and wardray's reference
     mode (--gi=reference) at N and 2N paths per pixel, whose difference shows how converged it is;
     both are cached by the scene's text, the settings and the size, and the report says when a cache was used;
  2. parity: rRMSE and bad pixels of wardray's reference (2N) against POV-Ray's converged render;
  3. the scene's own settings, 2 threads each, runs interleaved (POV-Ray, wardray, wardray without gradients):
     the median whole-process time, each render's rRMSE against its own renderer's reference, and the records;
All images are linear HDR with antialiasing off.

usage: tools/radiosity_report.py [--wardray build/wardray] [--runs 3] [--size 80x60] [--paths 1024]
                                 [--cache build/radiosity-report-cache] [--out docs/reports/radiosity.md]
                                 [scene.pov ...]
"""
import argparse
import hashlib
import json
import pathlib
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
# The comparison tool's radiosity-block rewriter, which knows about comments, strings and nested blocks.
sys.path.insert(0, str(ROOT / "tools" / "compare"))
from povrewrite import rewrite_radiosity  # noqa: E402
CONVERGED_SETTINGS = {"count": 1600, "error_bound": 0.1, "pretrace_end": 0.01, "nearest_count": 20}
CONVERGED = " ".join(f"{k} {v}" for k, v in CONVERGED_SETTINGS.items())


def default_scenes():
    scenes = [pathlib.Path("/usr/share/povray-3.7/scenes/radiosity/cornell.pov")]
    scenes += sorted((ROOT / "scenes" / "radiosity").glob("*.pov"))
    return scenes


def run(cmd, cwd):
    start = time.perf_counter()
    proc = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    elapsed = time.perf_counter() - start
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(map(str, cmd))} failed ({proc.returncode}):\n{proc.stdout[-2000:]}")
    return elapsed


def diff(wardray, image, reference):
    out = subprocess.run([str(wardray), "diff", str(image), str(reference), "--json"], stdout=subprocess.PIPE,
                         text=True, check=True)
    m = json.loads(out.stdout)
    return m["rrmse"], m["bad_pixel_fraction"], m["non_finite_pixels"]


class References:
    """Expensive renders kept in a folder, keyed by what decides them."""

    def __init__(self, folder):
        self.folder = pathlib.Path(folder)
        self.folder.mkdir(parents=True, exist_ok=True)

    def get(self, key_parts, render):
        key = hashlib.sha256("\0".join(key_parts).encode()).hexdigest()[:20]
        path = self.folder / f"{key}.hdr"
        if path.exists():
            print(f"  using cached reference {path}", file=sys.stderr)
            return path, True
        render(path)
        return path, False


def measure(scene, args, refs, wardray_version):
    text = scene.read_text()
    width, height = args.size
    size = [f"+W{width}", f"+H{height}", "-A", "+WT2"]
    row = {"scene": scene.name}
    with tempfile.TemporaryDirectory(prefix="radiosity-report-") as tmp:
        work = pathlib.Path(tmp)
        # POV-Ray writes only below its current folder and finds includes beside the scene.
        (work / scene.name).write_text(text)
        (work / "converged.pov").write_text(rewrite_radiosity(text, CONVERGED_SETTINGS)[0])
        lib = [f"+L{scene.parent}"]

        def povray_converged(out):
            print(f"  POV-Ray converged render of {scene.name} (slow)", file=sys.stderr)
            run(["povray", "+Iconverged.pov", "+Oconverged.hdr", "+FH", "-D", "-V"] + size + lib, work)
            shutil.copy(work / "converged.hdr", out)

        def wardray_reference(paths):
            def render(out):
                print(f"  wardray reference of {scene.name} with {paths} paths", file=sys.stderr)
                run([args.wardray, f"+I{scene.name}", "+Oreference.hdr", "--gi=reference", f"--gi-rays={paths}"]
                    + size + lib, work)
                shutil.copy(work / "reference.hdr", out)
            return render

        pov_ref, pov_cached = refs.get(["povray", text, CONVERGED, str(args.size)], povray_converged)
        our_ref_n, cached_n = refs.get(["wardray", wardray_version, text, str(args.size), str(args.paths)],
                                       wardray_reference(args.paths))
        our_ref, cached_2n = refs.get(["wardray", wardray_version, text, str(args.size), str(2 * args.paths)],
                                      wardray_reference(2 * args.paths))
        row["cached"] = pov_cached or cached_n or cached_2n
        row["ref_noise"] = diff(args.wardray, our_ref_n, our_ref)[0]
        row["parity"], row["parity_bad"], _ = diff(args.wardray, our_ref, pov_ref)

        # The scene's own settings, interleaved.
        times = {"povray": [], "wardray": [], "nograd": []}
        for i in range(args.runs):
            print(f"  {scene.name}: run {i + 1}/{args.runs}", file=sys.stderr)
            times["povray"].append(run(["povray", f"+I{scene.name}", "+Opovray.hdr", "+FH", "-D", "-V"] + size + lib,
                                       work))
            times["wardray"].append(run([args.wardray, f"+I{scene.name}", "+Owardray.hdr", "--stats", "on.json"]
                                        + size + lib, work))
            times["nograd"].append(run([args.wardray, f"+I{scene.name}", "+Onograd.hdr", "--gi-gradients=off",
                                        "--stats", "off.json"] + size + lib, work))
        for k, v in times.items():
            row[f"{k}_s"] = statistics.median(v)
        row["povray_err"], row["povray_bad"], _ = diff(args.wardray, work / "povray.hdr", pov_ref)
        row["wardray_err"], row["wardray_bad"], nf1 = diff(args.wardray, work / "wardray.hdr", our_ref)
        row["nograd_err"], row["nograd_bad"], nf2 = diff(args.wardray, work / "nograd.hdr", our_ref)
        row["non_finite"] = nf1 + nf2
        for k, f in (("records", "on.json"), ("nograd_records", "off.json")):
            row[k] = json.loads((work / f).read_text())["cache"]["records"]
    return row


def pct(x):
    return f"{100 * x:.2f} %"


def write_report(rows, args, out):
    w, h = args.size
    lines = [
        "# Radiosity: wardray against POV-Ray 3.7",
        "",
        f"Produced by `tools/radiosity_report.py --size {w}x{h} --runs {args.runs} --paths {args.paths}` "
        "(docs/metrics.md: linear HDR, antialiasing off, 2 threads each, whole-process times, median of "
        "the runs, the renderers' runs interleaved). Times are from a shared 2-core machine: read them as ratios.",
        "",
        "## Converged against converged",
        "",
        "POV-Ray's converged render is the scene with `" + CONVERGED + "` set in its radiosity block; "
        f"wardray's is `--gi=reference --gi-rays {2 * args.paths}`. *Reference noise* is the rRMSE between "
        f"wardray's references at {args.paths} and {2 * args.paths} paths.",
        "",
        "| scene | parity rRMSE | bad pixels | reference noise |",
        "|---|---|---|---|",
    ]
    for r in rows:
        lines.append(f"| {r['scene']} | {pct(r['parity'])} | {pct(r['parity_bad'])} | {pct(r['ref_noise'])} |")
    lines += [
        "",
        "## At the scene's own radiosity settings",
        "",
        "Each renderer's rRMSE is against its own converged reference (above); wardray with gradients (the "
        "default) and with `--gi-gradients=off` (POV-Ray 3.7's plain weighted average, same records otherwise).",
        "",
        "| scene | POV-Ray rRMSE | wardray rRMSE | no gradients rRMSE | POV-Ray s | wardray s | "
        "time ratio | records (grad / none) |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append(
            f"| {r['scene']} | {pct(r['povray_err'])} | {pct(r['wardray_err'])} | {pct(r['nograd_err'])} | "
            f"{r['povray_s']:.2f} | {r['wardray_s']:.2f} | {r['wardray_s'] / r['povray_s']:.2f} | "
            f"{r['records']} / {r['nograd_records']} |")
    lines += ["", "Non-finite pixels in wardray's renders: " + str(sum(r["non_finite"] for r in rows)) + ".", ""]
    notes = []
    for r in rows:
        if r["wardray_err"] >= r["povray_err"]:
            notes.append(f"- {r['scene']}: wardray's error is not lower than POV-Ray's at the scene's settings.")
        if r["wardray_s"] >= r["povray_s"]:
            notes.append(f"- {r['scene']}: wardray is not faster than POV-Ray at the scene's settings.")
        if r["wardray_err"] >= r["nograd_err"]:
            notes.append(f"- {r['scene']}: gradients did not lower the error here.")
    if notes:
        lines += ["## Where wardray is not ahead", ""] + notes + [""]
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text("\n".join(lines) + kept_sections(out, lines))


def kept_sections(out, lines):
    """The sections of an existing report that this script does not write (dated measurements appended by hand),
    so that a new run keeps them after its own."""
    if not out.is_file():
        return ""
    own = {line for line in lines if line.startswith("## ")}
    kept, keep = [], False
    for line in out.read_text().splitlines():
        if line.startswith("## "):
            keep = line not in own and line != "## Where wardray is not ahead"
        if keep:
            kept.append(line)
    return "\n" + "\n".join(kept) + "\n" if kept else ""


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--wardray", default=str(ROOT / "build" / "wardray"))
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--size", default="80x60", type=lambda s: tuple(int(v) for v in s.lower().split("x")))
    ap.add_argument("--paths", type=int, default=1024, help="reference paths per pixel (the check uses twice)")
    ap.add_argument("--cache", default=str(ROOT / "build" / "radiosity-report-cache"))
    ap.add_argument("--out", default=str(ROOT / "docs" / "reports" / "radiosity.md"))
    ap.add_argument("scenes", nargs="*", type=pathlib.Path)
    args = ap.parse_args()
    # References depend on the code that made them: key them by the binary's bytes.
    version = hashlib.sha256(pathlib.Path(args.wardray).read_bytes()).hexdigest()
    refs = References(args.cache)
    rows = []
    for scene in args.scenes or default_scenes():
        print(f"{scene}:", file=sys.stderr)
        rows.append(measure(scene.resolve(), args, refs, version))
    write_report(rows, args, pathlib.Path(args.out))
    print(pathlib.Path(args.out).read_text())


if __name__ == "__main__":
    main()
