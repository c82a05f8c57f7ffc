#!/usr/bin/env python3
"""Every example scene that ships an INI file, rendered through that INI by POV-Ray 3.7 and by wardray, compared.

    tools/ini_census.py build/wardray                  # all INI files; writes docs/reports/ini_census.md
    tools/ini_census.py build/wardray --ini 'animations/*'

Issue 19 asks that each example INI renders through wardray with the same images as through POV-Ray, frames
compared as stills. For each INI file below the examples folder both programs render its first, middle and last
frame (`file.ini +SF<n> +EF<n>`, the INI's own animation range; one frame for an INI without one) at the census's
size and settings given after the INI (120x90, `-A`, one thread, linear HDR), each in a scratch copy of the INI's
folder, and the frames are compared as docs/metrics.md says (tools/census.py's compare and tolerances: rRMSE ≤ 1 %
and bad pixels ≤ 0.5 % for a match, rRMSE ≤ 5 % where the scene is stochastic). A frame wardray renders with a
"not rendered yet" warning is counted apart, as in the census.
"""
import argparse
import concurrent.futures
import datetime
import fnmatch
import pathlib
import re
import subprocess
import sys
import time

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "tools" / "compare"))
import census  # noqa: E402
import gimetrics  # noqa: E402


def ini_settings(path):
    """(input file, first frame, last frame) the INI asks for; frames 1..1 without an animation range."""
    scene, first, last = None, None, None
    for raw in path.read_text(errors="replace").splitlines():
        line = raw.split(";", 1)[0].strip()
        key, sep, value = line.partition("=")
        key, value = key.strip().lower(), value.strip()
        if sep:
            if key == "input_file_name":
                scene = value.strip('"')
            elif key == "initial_frame" and re.fullmatch(r"-?\d+", value):
                first = int(value)
            elif key == "final_frame" and re.fullmatch(r"-?\d+", value):
                last = int(value)
            continue
        for token in line.split():
            low = token.lower()
            if re.fullmatch(r"[+-]kfi-?\d+", low):
                first = int(low[4:])
            elif re.fullmatch(r"[+-]kff-?\d+", low):
                last = int(low[4:])
            elif low.startswith("+i") and len(low) > 2:
                scene = token[2:]
    if scene is None:
        scene = path.with_suffix(".pov").name
    if first is None:
        first = 1
    if last is None or last < first:
        last = first
    return scene, first, last


def frames_of(first, last):
    return sorted({first, (first + last) // 2, last})


def render(cmd, cwd, timeout):
    start = time.monotonic()
    try:
        proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout, errors="replace")
        return proc.returncode, proc.stdout + proc.stderr, time.monotonic() - start
    except subprocess.TimeoutExpired:
        return None, "timed out", time.monotonic() - start


def produced(folder, stem):
    """The one image a render wrote as `stem.hdr` or, for an animation frame, `stem<digits>.hdr`."""
    found = sorted(p for p in folder.glob(f"{stem}*.hdr") if re.fullmatch(rf"{stem}\d*\.hdr", p.name))
    return found[0] if found else None


def measure(ini, frame, wardray, povray, work_root, timeout):
    rel = ini.relative_to(census.EXAMPLES)
    scene_name, first, last = ini_settings(ini)
    work = census.scratch_copy(ini, work_root / (str(rel).replace("/", "+") + f"-{frame}"))
    common = [f"+SF{frame}", f"+EF{frame}", f"+W{census.SIZE[0]}", f"+H{census.SIZE[1]}", "-A", "+WT1", "+FH"]
    rec = {"ini": str(rel), "frame": frame, "range": [first, last], "scene": scene_name}
    rc, out, secs = render([povray, ini.name] + common + ["+Opov.hdr", "-D", "-V"], work, timeout)
    rec["povray_seconds"] = secs
    ref_path = produced(work, "pov")
    if rc != 0 or ref_path is None:
        rec["category"] = "povray-fails"
        rec["reason"] = census.povray_error(out) or ("timed out" if rc is None else f"exit {rc}")
        return rec
    rc, out, secs = render([wardray, ini.name] + common + ["+Oward.hdr"], work, timeout)
    rec["wardray_seconds"] = secs
    error, features, _ = census.wardray_diagnostics(out)
    img_path = produced(work, "ward")
    if rc != 0 or img_path is None:
        rec["category"] = "blocked"
        rec["reason"] = error or ("timed out" if rc is None else f"exit {rc}")
        return rec
    img, ref = gimetrics.read_linear_rgb(img_path), gimetrics.read_linear_rgb(ref_path)
    if img.shape != ref.shape:
        rec["category"] = "blocked"
        rec["reason"] = f"image size {img.shape[1]}x{img.shape[0]}, POV-Ray's {ref.shape[1]}x{ref.shape[0]}"
        return rec
    m = census.compare(img, ref)
    texts = [t for _, t in census.scene_files(work / scene_name)] if (work / scene_name).is_file() else []
    stochastic = bool(census.stochastic_features(texts))
    limit = census.STOCHASTIC_RRMSE if stochastic else 0.01
    rec.update(rrmse=m["rrmse"], bad=m["bad"], non_finite=m["non_finite"], stochastic=stochastic,
               features=features)
    ok = m["rrmse"] <= limit and (stochastic or m["bad"] <= 0.005) and m["non_finite"] == 0
    if ok:
        rec["category"] = "match"
    elif features:
        rec["category"] = "differ-with-warning"
        rec["reason"] = ", ".join(features)
    else:
        rec["category"] = "differ"
    if rec["category"] != "match":
        scene_rel = str((rel.parent / scene_name))
        known = census.KNOWN_REASONS.get(f"{rel}:{frame}") or census.KNOWN_REASONS.get(scene_rel)
        if known:
            rec["reason"] = "; ".join(x for x in (rec.get("reason"), "known: " + known) if x)
    return rec


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("wardray")
    ap.add_argument("--povray", default="povray")
    ap.add_argument("--ini", default="*", help="glob of INI files below the examples folder")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--report", default=str(ROOT / "docs" / "reports" / "ini_census.md"))
    ap.add_argument("--work", default="/tmp/ini-census")
    args = ap.parse_args()
    wardray = str(pathlib.Path(args.wardray).resolve())
    inis = sorted(p for p in census.EXAMPLES.rglob("*.ini")
                  if fnmatch.fnmatch(str(p.relative_to(census.EXAMPLES)), args.ini))
    jobs = [(ini, f) for ini in inis for f in frames_of(*ini_settings(ini)[1:])]
    work_root = pathlib.Path(args.work)
    work_root.mkdir(parents=True, exist_ok=True)
    started = time.monotonic()
    records = []
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = [pool.submit(measure, ini, f, wardray, args.povray, work_root, census.TIMEOUT) for ini, f in jobs]
        for i, fut in enumerate(concurrent.futures.as_completed(futures), 1):
            rec = fut.result()
            records.append(rec)
            figure = f" rRMSE {census.pct(rec['rrmse'])} bad {census.pct(rec['bad'])}" if "rrmse" in rec else ""
            print(f"[{i}/{len(jobs)}] {rec['ini']} frame {rec['frame']}: {rec['category']}{figure}", flush=True)
    records.sort(key=lambda r: (r["ini"], r["frame"]))
    write_report(pathlib.Path(args.report), records, args, time.monotonic() - started)


def write_report(path, records, args, seconds):
    counts = {}
    for r in records:
        counts[r["category"]] = counts.get(r["category"], 0) + 1
    by_ini = {}
    for r in records:
        by_ini.setdefault(r["ini"], []).append(r)
    all_match = sum(1 for rs in by_ini.values() if all(r["category"] == "match" for r in rs))
    stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    lines = [
        "# The example INI files, rendered through their INI by POV-Ray 3.7 and wardray",
        "",
        f"Produced by `tools/ini_census.py {args.wardray}` on {stamp} ({seconds / 60:.1f} min of wall time).",
        "",
        "Each INI file below the examples folder is rendered by both programs through the INI at its first, middle",
        "and last frame (`file.ini +SF<n> +EF<n>`; one frame without an animation range), the census's settings after",
        "it (120x90, `-A`, `+WT1`, linear HDR), in a scratch copy of its folder, and compared as docs/metrics.md says:",
        "match at rRMSE ≤ 1 % and bad pixels ≤ 0.5 % (rRMSE ≤ 5 % where the scene is stochastic); "
        "differ-with-warning where wardray says what it does not render.",
        "",
        f"**{len(by_ini)} INI files, {len(records)} frames**: " +
        ", ".join(f"{k} {v}" for k, v in sorted(counts.items())) +
        f". INI files whose every frame matches: **{all_match} of {len(by_ini)}**. Reasons marked \"known\" are"
        " measured ones from tools/census_reasons.tsv (keyed by the scene, or by `file.ini:frame`).",
        "",
        "| INI | frames | frame | category | rRMSE | bad | POV-Ray s | wardray s | note |",
        "|---|---|---:|---|---:|---:|---:|---:|---|",
    ]
    for r in records:
        rr = census.pct(r["rrmse"]) if "rrmse" in r else ""
        bad = census.pct(r["bad"]) if "bad" in r else ""
        note = r.get("reason", "") + (" (stochastic)" if r.get("stochastic") else "")
        lines.append(f"| {r['ini']} | {r['range'][0]}-{r['range'][1]} | {r['frame']} | {r['category']} | {rr} | "
                     f"{bad} | {r.get('povray_seconds', 0):.2f} | {r.get('wardray_seconds', 0):.2f} | "
                     f"{census.cell(note)} |")
    path.write_text("\n".join(lines) + "\n")
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
