#!/usr/bin/env python3
"""How far wardray's brute-force reference is from converged: the rRMSE between two seeds at a ladder of paths.

Renders the scene with `--gi=reference --gi-rays N --seed S` for each N and two seeds, antialiasing off, and prints a
Markdown table of the rRMSE between the two seeds (docs/METRICS.md) and each render's whole-process wall time. With
--direct, also the same pair with `--gi=off`: the part of the difference that more paths cannot remove (area-light
jitter at the first hit), and with --format both, the same images as half-float EXR and as Radiance HDR, whose
8-bit shared-exponent mantissa is itself a floor of about 0.3 %.

usage: /usr/bin/python3 tools/compare/reference_seed.py WARDRAY SCENE [--size 128x128] [--rays 256 1024]
       [--seeds 1 2] [--threads 2] [--format hdr|exr|both] [--direct] [--out DIR]
"""
import argparse
import pathlib
import subprocess
import sys
import tempfile
import resource
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import gimetrics  # noqa: E402


def render(wardray, scene, out, args, extra):
    width, height = args.size.split("x")
    cmd = [wardray, f"+I{scene}", f"+O{out}", f"+W{width}", f"+H{height}", "-A", f"+WT{args.threads}",
           f"+L{pathlib.Path(scene).resolve().parent}"] + extra
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    run = subprocess.run(cmd, capture_output=True, text=True)
    seconds = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if run.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed:\n{run.stderr[-2000:]}")
    # CPU time (user + system, all threads) compares on a loaded machine; wall time does not.
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return seconds, cpu


def pair(wardray, scene, out_dir, args, label, extra, fmt):
    """Renders `extra` with each seed; returns (wall, CPU) times and the rRMSE between the first two seeds."""
    flag = "+FH" if fmt == "hdr" else "+FE"
    images, times = [], []
    for seed in args.seeds:
        out = out_dir / f"{label}_seed{seed}.{fmt}"
        times.append(render(wardray, scene, out, args, extra + [flag, "--seed", str(seed)]))
        images.append(gimetrics.read_linear_rgb(out))
    error = gimetrics.image_error(images[0], images[1])
    return times, error


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("wardray")
    p.add_argument("scene")
    p.add_argument("--size", default="128x128")
    p.add_argument("--rays", type=int, nargs="+", default=[256, 1024])
    p.add_argument("--seeds", type=int, nargs=2, default=[1, 2])
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--format", choices=["hdr", "exr", "both"], default="hdr")
    p.add_argument("--direct", action="store_true", help="also the --gi=off pair (the jitter floor)")
    p.add_argument("--out", help="keep the images here (default: a temporary folder)")
    p.add_argument("--extra", default="", help="more wardray arguments for every render, e.g. '--gi-light-picks 0'")
    args = p.parse_args()
    formats = ["hdr", "exr"] if args.format == "both" else [args.format]
    out_dir = pathlib.Path(args.out or tempfile.mkdtemp(prefix="reference_seed_"))
    out_dir.mkdir(parents=True, exist_ok=True)
    s1, s2 = args.seeds
    print(f"{pathlib.Path(args.scene).name}, {args.size}, -A, {args.threads} threads, seeds {s1} and {s2}")
    print()
    print(f"| mode | format | rRMSE seed {s1} vs {s2} | bad pixels | wall s (seed {s1}, seed {s2}) | CPU s |")
    print("|---|---|---|---|---|---|")
    runs = [("--gi=off", "direct", ["--gi=off"])] if args.direct else []
    runs += [(f"--gi=reference --gi-rays {n}", f"ref{n}", ["--gi=reference", "--gi-rays", str(n)]) for n in args.rays]
    for mode, label, extra in runs:
        for fmt in formats:
            times, error = pair(args.wardray, args.scene, out_dir, args, label, extra + args.extra.split(), fmt)
            print(f"| `{mode}` | {fmt} | {100 * error['rrmse']:.3f} % | {100 * error['bad_fraction']:.2f} % | "
                  f"{times[0][0]:.1f}, {times[1][0]:.1f} | {times[0][1]:.2f}, {times[1][1]:.2f} |", flush=True)
    print()
    print(f"images in {out_dir}")


if __name__ == "__main__":
    main()
