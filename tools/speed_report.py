#!/usr/bin/env python3
"""Wall time of example scenes in POV-Ray 3.7 and in wardray, side by side, as the feature issues' speed lines ask.

    tools/speed_report.py build/wardray --group tools/speed_groups/shapes.txt --size 320x240 --runs 3
    tools/speed_report.py build/wardray --scene objects/blob.pov --scene camera/focalblur.pov

Each scene (a path below Debian's examples folder, /usr/share/povray-3.7/scenes) is rendered in a scratch copy of
its folder by both programs with the same switches: the size asked, `-A` (no antialiasing) unless `--aa` says
otherwise, `+WT<threads>`, PNG output, no display. The renders alternate, POV-Ray then wardray, `--runs` times, so
that a change in the machine's load falls on both alike; the report gives each program's median wall time (parse,
photons, pretrace and render: the whole run, as a user waits for it), their ratio, and the sum over the group.
A render that fails or takes longer than `--timeout` seconds is named and left out of the sums. `--baseline` names
an older wardray binary that renders each scene too, in the same alternation, to show what a change costs or saves
(a scene without a feature should take the same time as before it).

The numbers are wall times on a shared machine: quote them as ratios, and run the tool again before trusting a
ratio near 1.
"""
import argparse
import datetime
import pathlib
import platform
import shutil
import statistics
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tools"))
import census  # noqa: E402


def read_group(path):
    """The scenes a group file names: one path per line below the examples folder; `#` starts a comment."""
    scenes = []
    for line in pathlib.Path(path).read_text().splitlines():
        line = line.split("#", 1)[0].strip()
        if line:
            scenes.append(line)
    return scenes


def render(cmd, cwd, timeout):
    """(wall seconds, error text or None) of one render."""
    start = time.perf_counter()
    try:
        proc = subprocess.run(cmd, cwd=cwd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True, errors="replace", timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, f"took longer than {timeout} s"
    seconds = time.perf_counter() - start
    if proc.returncode != 0:
        text = (proc.stderr or proc.stdout).strip().splitlines()
        return None, f"exit status {proc.returncode}: {text[-1] if text else ''}"
    return seconds, None


def time_scene(scene, args, work_root):
    """{scene, povray: [seconds], wardray: [seconds], error} of one scene, the renders alternating."""
    source = census.EXAMPLES / scene
    work = census.scratch_copy(source, work_root / census.Census.slug(scene))
    width, height = args.size
    common = [f"+I{source.name}", f"+W{width}", f"+H{height}", f"+WT{args.threads}", "+FN", "-D", *args.aa.split()]
    commands = {"povray": [args.povray, *common, "+Opovray.png", "-V"],
                "wardray": [str(args.wardray), *common, "+Owardray.png"]}
    if args.baseline:
        commands["baseline"] = [str(args.baseline), *common, "+Obaseline.png"]
    result = {"scene": scene, "error": None, **{name: [] for name in commands}}
    for _ in range(args.runs):
        for name in commands:
            seconds, error = render(commands[name], work, args.timeout)
            if error:
                result["error"] = f"{name}: {error}"
                shutil.rmtree(work, ignore_errors=True)
                return result
            result[name].append(seconds)
    shutil.rmtree(work, ignore_errors=True)
    return result


def report(results, args, started):
    lines = [f"## {args.title}", "",
             f"{started:%Y-%m-%d %H:%M} UTC, `{' '.join(sys.argv[1:])}`: {args.size[0]}x{args.size[1]}, "
             f"`{args.aa}`, +WT{args.threads} each, {args.runs} alternating run(s), median wall seconds; "
             f"{platform.node()}, {len(results)} scene(s).", "",
             "| scene | POV-Ray s | wardray s | wardray / POV-Ray |" + (" baseline s | wardray / baseline |" if args.baseline else ""),
             "|---|---:|---:|---:|" + ("---:|---:|" if args.baseline else "")]
    total_pov = total_ward = total_base = 0.0
    slower, failed = [], []
    for r in results:
        if r["error"]:
            failed.append(r)
            lines.append(f"| {r['scene']} | | | {r['error']} |")
            continue
        pov, ward = statistics.median(r["povray"]), statistics.median(r["wardray"])
        total_pov += pov
        total_ward += ward
        if ward > pov:
            slower.append(r["scene"])
        row = f"| {r['scene']} | {pov:.2f} | {ward:.2f} | {ward / pov:.2f} |"
        if args.baseline:
            base = statistics.median(r["baseline"])
            total_base += base
            row += f" {base:.2f} | {ward / base:.2f} |"
        lines.append(row)
    timed = len(results) - len(failed)
    if timed:
        lines += ["", f"Sum over the {timed} timed scene(s): POV-Ray {total_pov:.2f} s, wardray {total_ward:.2f} s, "
                      f"ratio **{total_ward / total_pov:.2f}**. wardray slower on {len(slower)}: "
                      f"{', '.join(slower) if slower else 'none'}."]
        if args.baseline:
            lines += ["", f"Baseline `{args.baseline}`: {total_base:.2f} s; wardray / baseline **{total_ward / total_base:.2f}**."]
    if failed:
        lines += ["", f"Not timed ({len(failed)}): " + "; ".join(f"{r['scene']} ({r['error']})" for r in failed) + "."]
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("wardray", type=pathlib.Path)
    ap.add_argument("--povray", default="povray")
    ap.add_argument("--group", action="append", default=[], help="a file listing scenes (see read_group)")
    ap.add_argument("--scene", action="append", default=[], help="a scene below the examples folder")
    ap.add_argument("--size", default="320x240", type=lambda s: tuple(int(v) for v in s.split("x")))
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--baseline", type=pathlib.Path, help="an older wardray, timed alongside")
    ap.add_argument("--aa", default="-A", help="antialiasing switches given to both, e.g. '+A0.3'")
    ap.add_argument("--timeout", type=float, default=300)
    ap.add_argument("--title", default="Speed, side by side")
    ap.add_argument("--report", type=pathlib.Path, help="append the section to this markdown file")
    ap.add_argument("--work", type=pathlib.Path, default=pathlib.Path("/tmp/speed-report"))
    args = ap.parse_args()
    scenes = [s for g in args.group for s in read_group(g)] + args.scene
    if not scenes:
        ap.error("no scenes: give --group or --scene")
    missing = [s for s in scenes if not (census.EXAMPLES / s).is_file()]
    if missing:
        ap.error(f"not below {census.EXAMPLES}: {', '.join(missing)}")
    args.wardray = args.wardray.resolve()
    if args.baseline:
        args.baseline = args.baseline.resolve()
    started = datetime.datetime.now(datetime.timezone.utc)
    results = []
    for i, scene in enumerate(scenes, 1):
        r = time_scene(scene, args, args.work)
        results.append(r)
        shown = r["error"] or f"POV-Ray {statistics.median(r['povray']):.2f} s, wardray {statistics.median(r['wardray']):.2f} s"
        print(f"[{i}/{len(scenes)}] {scene}: {shown}", flush=True)
    text = report(results, args, started)
    print(text)
    if args.report:
        with args.report.open("a") as out:
            out.write("\n" + text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
