#!/usr/bin/python3
"""Measures wardray's two record-radius limits that POV-Ray 3.7 lacks (issue 18), each on and off, or
(`--set spacing`) its two record spacings, `--gi-spacing=harmonic` and `hessian`, or (`--set record-pass`) its
record passes off and on (each row also has the share of the records the final pass made), or (`--set adaptive`)
adaptive hemisphere sampling (`--gi-adaptive`) off and on.

For one scene: a brute-force reference (`--gi=reference --gi-rays N`, seeds 1 and 2, their mean), then the ladder
points of tools/compare/ladder.json with the four configurations (both limits on, neighbour clamping off, the
E/|grad E| cap off, both off) rendered in turn, A B C D, 2 threads, linear HDR, `-A`. Each render's records, gather
and shadow rays (from --stats), rRMSE and bad-pixel fraction against the reference (docs/metrics.md), the rRMSE with
the reference's own noise taken out in quadrature, and its time over the default's at the same point are
appended to a JSON-lines file (with `--seeds N`, each configuration is rendered with `--seed 1` .. `--seed N` in
turn and the report takes the mean records and rays and the root-mean-square error over the seeds, so that one
record placement's luck does not decide a comparison); `--report` turns that file into the Markdown table of docs/reports/radiosity.md,
with each configuration's error over the default's at the same record count and at the same gather rays
(log-log interpolation on the default's curve over the ladder; values outside its range are marked, not averaged).

  tools/compare/record_limits.py SCENE.pov [--size 160x120] [--rays 512] [--points c40/e0.7,c80/e0.5]
                                 [--set limits|spacing|record-pass|adaptive] [--seeds N [--first-seed S]]
  tools/compare/record_limits.py --report build/record-limits/rows.jsonl
"""
import argparse
import collections
import json
import math
import pathlib
import subprocess
import sys
import time

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from gimetrics import image_error, read_linear_rgb  # noqa: E402
from povrewrite import rewrite_radiosity  # noqa: E402

# Each set's first configuration is the baseline the others are compared with.
CONFIG_SETS = {
    "limits": {
        "both on": [],
        "clamp off": ["--gi-neighbour-clamp=off"],
        "cap off": ["--gi-gradient-cap=off"],
        "both off": ["--gi-neighbour-clamp=off", "--gi-gradient-cap=off"],
    },
    "spacing": {
        "harmonic": ["--gi-spacing=harmonic"],
        "hessian": ["--gi-spacing=hessian"],
        "hessian, cap off": ["--gi-spacing=hessian", "--gi-gradient-cap=off"],
    },
    "record-pass": {
        "record pass off": ["--gi-record-pass=off"],
        "record pass on": ["--gi-record-pass=on"],
    },
    "adaptive": {
        "adaptive off": ["--gi-adaptive=off"],
        "adaptive on": ["--gi-adaptive=on"],
    },
}
CONFIGS = CONFIG_SETS["limits"]


def configs_of(names):
    """The configuration set whose names are `names` (the limits' when none matches)."""
    for configs in CONFIG_SETS.values():
        if set(names) <= set(configs):
            return configs
    return CONFIG_SETS["limits"]


def render(exe, scene, output, size, scene_dir, extra, cwd, stats=None):
    """Renders `scene` in `cwd`; returns the whole-process wall-clock seconds."""
    w, h = size
    cmd = [str(exe), f"+I{scene}", f"+O{output}", "+FH", f"+W{w}", f"+H{h}", "-A", "+WT2", f"+L{scene_dir}", *extra]
    if stats:
        cmd += ["--stats", str(stats)]
    start = time.perf_counter()
    proc = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if proc.returncode:
        raise RuntimeError(f"{' '.join(cmd)}\n{proc.stdout[-800:]}")
    return time.perf_counter() - start


def measure(args):
    ladder = json.loads((HERE / "ladder.json").read_text())
    configs = CONFIG_SETS[args.set]
    size = tuple(int(x) for x in args.size.split("x"))
    path = pathlib.Path(args.scene).resolve()
    text = path.read_text(errors="replace")
    work = pathlib.Path(args.out) / f"{path.stem}-{args.size}"
    work.mkdir(parents=True, exist_ok=True)
    # The reference: brute force on the scene at POV-Ray's converged settings (recursion_limit etc. as the scene's).
    (work / "ref.pov").write_text(rewrite_radiosity(text, ladder["povray_reference"])[0])
    refs = []
    for seed in (1, 2):
        image = work / f"ref{args.rays}_s{seed}.hdr"
        if not image.exists():
            render(args.wardray, "ref.pov", image.name, size, path.parent,
                   ["--gi=reference", "--gi-rays", str(args.rays), "--seed", str(seed)], work)
        refs.append(read_linear_rgb(image))
    # The two seeds differ by sqrt(2) times one's noise; their mean has half the difference's.
    noise = image_error(refs[1], refs[0])["rrmse"] / 2
    reference = (refs[0] + refs[1]) / 2
    print(f"# {path.stem} {args.size}: reference {args.rays} paths x 2 seeds, noise of their mean {100 * noise:.2f} %")
    points = [p for p in ladder["full"] if p["label"] in args.points.split(",")]
    seeds = list(range(args.first_seed, args.first_seed + args.seeds)) if args.seeds > 1 else [0]
    rows = []
    for p in points:
        (work / "scene.pov").write_text(rewrite_radiosity(text, p["radiosity"])[0])
        for seed, (config, extra) in ((s, c) for s in seeds for c in configs.items()):  # in turn: comparable times
            seed_args = ["--seed", str(seed)] if seed else []
            seconds = render(args.wardray, "scene.pov", "image.hdr", size, path.parent, [*extra, *seed_args], work,
                             work / "stats.json")
            stats = json.loads((work / "stats.json").read_text())
            err = image_error(read_linear_rgb(work / "image.hdr"), reference)
            per_pass = stats["cache"]["records_per_pass_and_depth"]
            final_share = sum(per_pass[-1]) / max(sum(map(sum, per_pass)), 1)
            rows.append({"final_share": final_share,
                         "scene": path.stem, "size": args.size, "point": p["label"], "config": config,
                         "time": seconds, "records": stats["cache"]["records"], "gather": stats["rays"]["gather"],
                         "shadow": stats["rays"]["shadow"], "rrmse": err["rrmse"], "bad": err["bad_fraction"],
                         "corr": math.sqrt(max(err["rrmse"] ** 2 - noise ** 2, 0.0)), "noise": noise,
                         "seed": seed, "rays_ref": args.rays})
            if len(rows) % len(configs) == 0:
                base = rows[-len(configs)]["time"]
                for r in rows[-len(configs):]:
                    r["ratio"] = r["time"] / base
        for r in rows[-len(configs) * len(seeds):]:
            print(f"{r['scene']}\t{r['point']}\t{r['config']}\t{r['records']}\t{r['gather']}\t"
                  f"{100 * r['corr']:.2f} %\t{r['ratio']:.2f}\tfinal pass {100 * r['final_share']:.1f} %", flush=True)
    with open(pathlib.Path(args.out) / f"rows{'' if args.set == 'limits' else '-' + args.set}.jsonl", "a") as f:
        for r in rows:
            f.write(json.dumps(r) + "\n")


def interpolate(curve, x, key):
    """The default's error at cost `x` (log-log, straight lines between ladder points); and whether x lies
    outside the curve's range (then the nearest segment is extended)."""
    pts = sorted((c[key], c["corr"]) for c in curve)
    outside = x < pts[0][0] * 0.98 or x > pts[-1][0] * 1.02
    if x <= pts[0][0]:
        a, b = pts[0], pts[1]
    elif x >= pts[-1][0]:
        a, b = pts[-2], pts[-1]
    else:
        a, b = next((p, q) for p, q in zip(pts, pts[1:]) if p[0] <= x <= q[0])
    if a[0] == b[0] or a[1] <= 0 or b[1] <= 0:
        return a[1], outside
    slope = math.log(b[1] / a[1]) / math.log(b[0] / a[0])
    return a[1] * (x / a[0]) ** slope, outside


def merge_seeds(rows):
    """One row per scene, point and configuration: mean records, rays and time ratio, RMS error over the seeds."""
    groups = collections.defaultdict(list)
    for r in rows:
        groups[(r["scene"], r["size"], r["point"], r["config"])].append(r)
    merged = []
    for g in groups.values():
        m = dict(g[0])
        for key in ("records", "gather", "shadow", "time", "ratio", "bad"):
            m[key] = sum(r[key] for r in g) / len(g)
        for key in ("records", "gather"):
            m[key] = round(m[key])
        for key in ("rrmse", "corr"):
            m[key] = math.sqrt(sum(r[key] ** 2 for r in g) / len(g))
        m["seeds"] = len(g)
        merged.append(m)
    return merged


def report(rows_file):
    rows = merge_seeds([json.loads(line) for line in open(rows_file)])
    labels = [p["label"] for p in json.loads((HERE / "ladder.json").read_text())["full"]]
    by = collections.defaultdict(list)
    for r in sorted(rows, key=lambda r: labels.index(r["point"]) if r["point"] in labels else len(labels)):
        by[(r["scene"], r["config"])].append(r)
    order = list(dict.fromkeys(r["scene"] for r in rows))
    configs = configs_of({r["config"] for r in rows})
    base_name = next(iter(configs))
    print("| scene | point | limits | records | gather rays | rRMSE | bad pixels | time / default's | "
          "error / default's at equal records | at equal gather rays |")
    print("|---|---|---|---:|---:|---:|---:|---:|---:|---:|")
    summary = collections.defaultdict(list)
    per_scene = collections.defaultdict(list)
    for scene in order:
        base = by[(scene, base_name)]
        for config in configs:
            for r in by[(scene, config)]:
                cells = []
                for key in ("records", "gather"):
                    if config == base_name:
                        cells.append("1")
                        continue
                    e, outside = interpolate(base, r[key], key)
                    ratio = r["corr"] / e if e > 0 else float("inf")
                    if not outside:
                        summary[(config, key)].append(ratio)
                        per_scene[(scene, config, key)].append(ratio)
                    cells.append(f"{ratio:.2f}" + (" (outside)" if outside else ""))
                print(f"| {scene} {r['size']} | {r['point']} | {config} | {r['records']:,} | {r['gather']:,} | "
                      f"{100 * r['corr']:.2f} % | {100 * r['bad']:.2f} % | {r['ratio']:.2f} | {cells[0]} | {cells[1]} |")
    print()
    def mean(v):
        return math.exp(sum(math.log(x) for x in v) / len(v)) if v else float("nan")
    others = list(configs)[1:]
    print("| scene | " + " | ".join(f"{c}: records | gather rays" for c in others) + " |")
    print("|---|" + "---:|---:|" * len(others))
    for scene in order:
        cells = [f"{mean(per_scene[(scene, c, k)]):.2f}" for c in others for k in ("records", "gather")]
        print(f"| {scene} | " + " | ".join(cells) + " |")
    print()
    for (config, key), v in summary.items():
        print(f"- {config}, at equal {'records' if key == 'records' else 'gather rays'}: error over the default's "
              f"{mean(v):.2f} (geometric mean of {len(v)} points); {sum(x < 0.95 for x in v)} point(s) more than 5 % "
              f"lower, {sum(x > 1.05 for x in v)} more than 5 % higher")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scene", nargs="?")
    ap.add_argument("--size", default="160x120")
    ap.add_argument("--rays", type=int, default=512, help="reference paths per pixel, per seed")
    ap.add_argument("--points", default="c40/e0.7,c80/e0.5,c150/e0.35", help="labels of ladder.json's 'full'")
    ap.add_argument("--wardray", default=str(HERE.parent.parent / "build" / "wardray"))
    ap.add_argument("--seeds", type=int, default=1, help="render each configuration with seeds 1..N (1: no --seed)")
    ap.add_argument("--first-seed", type=int, default=1, help="with --seeds: the first seed (more seeds later)")
    ap.add_argument("--set", choices=sorted(CONFIG_SETS), default="limits",
                    help="the configurations: the radius limits on and off, the two record spacings, "
                         "the record passes off and on, or adaptive hemisphere sampling off and on")
    ap.add_argument("--out", default=str(HERE.parent.parent / "build" / "record-limits"))
    ap.add_argument("--report", metavar="ROWS", help="print the table of a rows.jsonl and stop")
    args = ap.parse_args()
    if args.report:
        report(args.report)
    elif args.scene:
        measure(args)
    else:
        ap.error("a scene or --report ROWS")


if __name__ == "__main__":
    main()
