#!/usr/bin/python3
"""Times the parse of one scene with wardray and with POV-Ray, side by side in one run, and prints (or writes) a
Markdown report: each renderer's parse time per round, their medians and the ratio wardray / POV-Ray.

wardray's figure is the parse phase of `--stats`; POV-Ray's is the "Parse Time" it prints (in milliseconds).
Rounds alternate the two renderers so load on the machine falls on both. With tools/bench/parse_bench built, the
report adds wardray's first parse with every library declaration read in place (as --check reads them).

  tools/parse_time.py                                   # scenes/parse/texture_libraries.pov, 9 rounds
  tools/parse_time.py --rounds 15 --write docs/reports/parse_time.md
  tools/parse_time.py --scene my.pov --wardray build/wardray
"""
import argparse
import json
import pathlib
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent


def wardray_parse_seconds(wardray, scene, work):
    stats = work / "stats.json"
    result = subprocess.run([str(wardray), "--stats", str(stats), "+W16", "+H12", "-D", "-A",
                             "+O" + str(work / "w.png"), str(scene)], capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("wardray failed on %s:\n%s" % (scene, result.stderr))
    return json.loads(stats.read_text())["phases"]["parse"]


def povray_parse_seconds(scene, work):
    # POV-Ray writes only below its working folder: render a copy there.
    local = work / scene.name
    shutil.copyfile(scene, local)
    result = subprocess.run(["povray", "+I" + local.name, "+W16", "+H12", "-D", "-A", "+Op.png"], cwd=work,
                            capture_output=True, text=True)
    match = re.search(r"Parse Time:.*\(([0-9.]+) seconds\)", result.stderr + result.stdout)
    if result.returncode != 0 or not match:
        sys.exit("povray failed on %s:\n%s" % (scene, result.stderr[-2000:]))
    return float(match.group(1))


def eager_first_parse_seconds(bench, scene):
    result = subprocess.run([str(bench), "--eager", str(scene), "1"], capture_output=True, text=True)
    match = re.search(r"first ([0-9.]+) s", result.stdout)
    return float(match.group(1)) if result.returncode == 0 and match else None


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scene", type=pathlib.Path, default=ROOT / "scenes/parse/texture_libraries.pov")
    parser.add_argument("--wardray", type=pathlib.Path, default=ROOT / "build/wardray")
    parser.add_argument("--bench", type=pathlib.Path, default=ROOT / "build/tools/bench/parse_bench")
    parser.add_argument("--rounds", type=int, default=9)
    parser.add_argument("--write", type=pathlib.Path, help="write the report here instead of printing it")
    args = parser.parse_args()
    if shutil.which("povray") is None:
        sys.exit("povray is not installed")
    scene = args.scene.resolve()

    wardray, povray, eager = [], [], []
    with tempfile.TemporaryDirectory(prefix="wardray_parse_time_") as tmp:
        work = pathlib.Path(tmp)
        for i in range(args.rounds):
            wardray.append(wardray_parse_seconds(args.wardray, scene, work))
            povray.append(povray_parse_seconds(scene, work))
            if args.bench.exists():
                seconds = eager_first_parse_seconds(args.bench, scene)
                if seconds is not None:
                    eager.append(seconds)
            print("round %d/%d: wardray %.4f s, POV-Ray %.3f s" % (i + 1, args.rounds, wardray[-1], povray[-1]),
                  file=sys.stderr)

    w, p = statistics.median(wardray), statistics.median(povray)
    lines = [
        "# Parse time: wardray against POV-Ray",
        "",
        "Scene: `%s`. Command: `tools/parse_time.py --rounds %d`; rounds alternate the renderers."
        % (scene.relative_to(ROOT) if scene.is_relative_to(ROOT) else scene, args.rounds),
        "wardray: the parse phase of `--stats` (library declarations read at their first use). POV-Ray 3.7: the"
        " \"Parse Time\" it prints, to the millisecond.",
        "",
        "| round | wardray (s) | POV-Ray (s) |" + (" wardray, every declaration in place (s) |" if eager else ""),
        "|---|---|---|" + ("---|" if eager else ""),
    ]
    for i in range(args.rounds):
        row = "| %d | %.4f | %.3f |" % (i + 1, wardray[i], povray[i])
        if eager:
            row += " %.4f |" % eager[i]
        lines.append(row)
    lines += ["", "Median: wardray %.4f s, POV-Ray %.3f s; ratio wardray / POV-Ray = %.2f." % (w, p, w / p)]
    if eager:
        e = statistics.median(eager)
        lines.append("With every library declaration read in place (`parse_bench --eager`, the first parse in a "
                     "process, as `--check` reads): median %.4f s, ratio %.2f." % (e, e / p))
    report = "\n".join(lines) + "\n"
    if args.write:
        args.write.write_text(report)
        print("wrote %s" % args.write, file=sys.stderr)
    else:
        print(report)


if __name__ == "__main__":
    main()
