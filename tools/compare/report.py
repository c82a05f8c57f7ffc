"""Writes the comparison's CSV, its error-against-time plots and the Markdown report from the measured data."""
import csv
import json
import pathlib

from gimetrics import crossing_time

TARGETS = (0.05, 0.02, 0.01)
LABELS = {"povray": "POV-Ray", "wardray": "wardray"}


def curve(scene, renderer, common=False):
    """(seconds, rRMSE) of `renderer`'s ladder points: against its own reference; with `common` True against
    POV-Ray's converged render (POV-Ray's own reference, so its curve is the same); with `common` "model" against the
    converged image of the shared model (compare_gi.model_reference), for both renderers."""
    if common == "model":
        key = "rrmse_vs_model_reference"
    else:
        key = "rrmse_vs_povray_reference" if common and renderer == "wardray" else "rrmse"
    return [(p["seconds"], p[key]) for p in scene["points"] if p["renderer"] == renderer and p.get(key) is not None]


def scene_size(scene, data):
    """The scene's image size: its own (per-scene sizes), or the run's for data written before they existed."""
    return tuple(scene.get("size") or data["size"])


def slowest(points):
    return max(points) if points else None


def best(points):
    return min(points, key=lambda p: p[1]) if points else None


def crossing(scene, renderer, target, common=False):
    """{'seconds', 'exact'} or {'seconds': None, 'slowest': (s, e)} when the curve never reaches the target."""
    pts = curve(scene, renderer, common)
    t, exact = crossing_time(pts, target)
    return {"seconds": t, "exact": exact, "slowest": slowest(pts), "best": best(pts), "measured": bool(pts)}


def compare_times(pov, ward):
    """(ratio text, which renderer is faster) for wardray time / POV-Ray time, with bounds where only one is known."""
    if not pov["measured"] or not ward["measured"]:
        return "—", "not measured"
    tp, tw = pov["seconds"], ward["seconds"]
    if tp is None and tw is None:
        return "—", "neither reaches it"
    if tw is None:
        bound = ward["slowest"][0] / tp
        return (f"> {bound:.2f}" if bound > 1 else "—"), "POV-Ray (wardray does not reach it)"
    if tp is None:
        bound = tw / pov["slowest"][0]
        return (f"< {bound:.2f}" if bound < 1 else "—"), "wardray (POV-Ray does not reach it)"
    r = tw / tp
    if pov["exact"] and ward["exact"]:
        return f"{r:.2f}", "wardray" if r < 1 else "POV-Ray"
    if not pov["exact"] and not ward["exact"]:
        return f"~{r:.2f}", "unclear (both reach it at their fastest point)"
    if ward["exact"]:
        # POV-Ray's time is only an upper bound (its fastest point already meets the target): r is a lower bound.
        return f"≥ {r:.2f}", "POV-Ray" if r >= 1 else "unclear"
    return f"≤ {r:.2f}", "wardray" if r <= 1 else "unclear"


def fmt_time(c):
    if not c["measured"]:
        return "—"
    if c["seconds"] is None:
        s, e = c["best"]
        return f"not reached (best {100 * e:.1f} % at {s:.2f} s)"
    return f"{c['seconds']:.2f}" if c["exact"] else f"≤ {c['seconds']:.2f}"


def pct(x, digits=2):
    return "—" if x is None else f"{100 * x:.{digits}f} %"


def write_csv(data, path):
    fields = ["scene", "renderer", "kind", "point", "settings", "wardray_args", "runs", "seconds_median",
              "seconds_runs", "rrmse_median", "bad_fraction_median", "non_finite_max",
              "rrmse_vs_povray_reference_median", "rrmse_vs_model_reference_median", "note"]
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        for s in data["scenes"]:
            for name, ref in s["references"].items():
                note = ref.get("check", "")
                mismatch = s.get("reference_mismatch")
                w.writerow({"scene": s["scene"], "renderer": name, "kind": "reference", "point": "reference",
                            "settings": json.dumps(ref.get("settings", {"rays": ref.get("rays")})),
                            "seconds_median": f"{ref['seconds']:.4f}",
                            "rrmse_vs_povray_reference_median":
                                f"{mismatch['rrmse']:.6f}" if mismatch and name == "wardray" else "",
                            "note": note})
            for p in s["points"]:
                w.writerow({"scene": s["scene"], "renderer": p["renderer"], "kind": "ladder", "point": p["label"],
                            "settings": json.dumps(p["settings"]), "wardray_args": " ".join(p["wardray_args"]),
                            "runs": len(p["times"]), "seconds_median": f"{p['seconds']:.4f}",
                            "seconds_runs": ";".join(f"{t:.4f}" for t in p["times"]),
                            "rrmse_median": f"{p['rrmse']:.6f}", "bad_fraction_median": f"{p['bad_fraction']:.6f}",
                            "non_finite_max": p["non_finite"],
                            "rrmse_vs_povray_reference_median":
                                "" if p.get("rrmse_vs_povray_reference") is None
                                else f"{p['rrmse_vs_povray_reference']:.6f}",
                            "rrmse_vs_model_reference_median":
                                "" if p.get("rrmse_vs_model_reference") is None
                                else f"{p['rrmse_vs_model_reference']:.6f}"})


def plot_scene(scene, data, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    floor = 1e-5  # log axes: an error of exactly 0 (identical images) is drawn at 0.001 %
    fig, ax = plt.subplots(figsize=(6.4, 4.4), dpi=100)
    styles = {"povray": dict(color="tab:blue", marker="o"), "wardray": dict(color="tab:red", marker="s")}
    for name in ("povray", "wardray"):
        pts = sorted(curve(scene, name))
        if not pts:
            continue
        xs, ys = [t for t, _ in pts], [100 * max(e, floor) for _, e in pts]
        ax.plot(xs, ys, label=f"{LABELS[name]} vs its own reference", **styles[name])
        labels = {p["seconds"]: p["label"] for p in scene["points"] if p["renderer"] == name}
        for x, y in zip(xs, ys):
            ax.annotate(labels.get(x, ""), (x, y), textcoords="offset points", xytext=(4, 4), fontsize=6,
                        color=styles[name]["color"])
    cross = sorted((p["seconds"], p["rrmse_vs_povray_reference"]) for p in scene["points"]
                   if p["renderer"] == "wardray" and p.get("rrmse_vs_povray_reference") is not None)
    if cross:
        ax.plot([t for t, _ in cross], [100 * max(e, floor) for _, e in cross], color="tab:red", linestyle="--",
                linewidth=0.8, alpha=0.6, label="wardray vs POV-Ray's reference")
    mismatch = scene.get("reference_mismatch")
    if mismatch:
        ax.axhline(100 * max(mismatch["rrmse"], floor), color="black", linestyle="--", linewidth=1,
                   label=f"references differ: {100 * mismatch['rrmse']:.2f} %")
    for t in TARGETS:
        ax.axhline(100 * t, color="gray", linestyle=":", linewidth=0.8)
        ax.annotate(f"{100 * t:g} %", (1, 100 * t), xycoords=("axes fraction", "data"), xytext=(-22, 2),
                    textcoords="offset points", fontsize=7, color="gray")
    ax.set_xscale("log")
    ax.set_yscale("log")
    plain = matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}")
    for axis, (lo, hi) in ((ax.xaxis, ax.get_xlim()), (ax.yaxis, ax.get_ylim())):
        axis.set_major_locator(matplotlib.ticker.LogLocator(base=10, subs=(1, 2, 5)))
        axis.set_major_formatter(plain)
        # Within less than a decade there may be no major tick: label the minor ones too.
        axis.set_minor_formatter(plain if hi / lo < 10 else matplotlib.ticker.NullFormatter())
    ax.tick_params(which="minor", labelsize=6)
    ax.set_xlabel("wall-clock time per render (s), median, 2 threads")
    ax.set_ylabel("rRMSE (%)")
    w, h = scene_size(scene, data)
    ax.set_title(f"{scene['scene']}: error against time ({w}x{h})")
    ax.grid(True, which="both", linewidth=0.3, alpha=0.5)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def headline(data, common=False):
    """Rows of the headline table, and the scene and target pairs where wardray is not ahead, by reason; with
    `common`, each renderer's error is taken against the common reference instead of its own."""
    rows = []
    not_ahead = {"POV-Ray is faster": [], "only POV-Ray reaches the target": [], "neither reaches the target": [],
                 "unclear (a time is only a bound)": []}
    measured = 0
    for s in data["scenes"]:
        for target in TARGETS:
            pov, ward = crossing(s, "povray", target, common), crossing(s, "wardray", target, common)
            ratio, faster = compare_times(pov, ward)
            rows.append(f"| {s['scene']} | {pct(target, 0)} | {fmt_time(pov)} | {fmt_time(ward)} | {ratio} "
                        f"| {faster} |")
            if not (pov["measured"] and ward["measured"]):
                continue
            measured += 1
            where = f"{s['scene']} at {pct(target, 0)}" + (f" (wardray/POV-Ray {ratio})" if ratio != "—" else "")
            if faster == "POV-Ray":
                not_ahead["POV-Ray is faster"].append(where)
            elif faster.startswith("POV-Ray"):
                not_ahead["only POV-Ray reaches the target"].append(where)
            elif faster.startswith("neither"):
                not_ahead["neither reaches the target"].append(where)
            elif faster.startswith("unclear"):
                not_ahead["unclear (a time is only a bound)"].append(where)
    return rows, not_ahead, measured


def common_targets(data, common, name, intro, heading=None):
    """The section of times to target with every renderer's error against one reference (`common` as curve() takes
    it, `name` as the verdict names it); no lines when no point has that error."""
    rows, not_ahead, measured = headline(data, common=common)
    if not measured:
        return []
    count = sum(len(v) for v in not_ahead.values())
    return [f"## Time to reach a target error against the {heading or name}", "", intro, "",
            "| scene | target rRMSE | POV-Ray (s) | wardray (s) | wardray / POV-Ray | faster |",
            "|---|---:|---:|---:|---:|---|"] + rows + [
        "",
        f"**Against the {name}, wardray is not ahead on {count} of the {measured} scene and target pairs "
        "measured.**" if count else f"Against the {name}, wardray is ahead on all {measured} scene and target pairs.",
        ""]


def markdown(data, plot_dir):
    sizes = sorted({scene_size(s, data) for s in data["scenes"]}) or ([tuple(data["size"])] if data["size"] else [])
    size_text = (f"at {sizes[0][0]}x{sizes[0][1]}" if len(sizes) == 1 else
                 "at the size the scene list gives it (" + ", ".join(
                     f"{s['scene']} {scene_size(s, data)[0]}x{scene_size(s, data)[1]}" for s in data["scenes"]) + ")")
    lines = ["# Global illumination: error against run time, wardray and POV-Ray", ""]
    if data["quick"]:
        lines += ["**Smoke test (`--quick`)**: two ladder points and cheap, unconverged references. Nothing here is a "
                  "measurement of either renderer; run without `--quick` for the report.", ""]
    if data.get("wardray_gi") == "off":
        lines += ["**wardray ran with `--gi=off`** (development of this tool before wardray's cache existed): its "
                  "curve shows direct light only and means nothing.", ""]
    if data.get("rebuilt"):
        lines += [f"**{data['rebuilt']}**: figures from that scene on may mix two builds of wardray.", ""]
    lines += [
        f"Produced by `{data['command']}` on {data['date']} (rendering took {data['wall_seconds'] / 60:.1f} min).",
        "",
        f"Each scene is rendered {size_text}, antialiasing off, "
        + {"exr": "linear OpenEXR (`+FE`)", "hdr": "linear Radiance HDR (`+FH`; its truncated shared mantissa adds "
           "about 0.6 % rRMSE between two images)"}[data.get("format", "hdr")]
        + ", 2 threads per renderer, over a ladder of "
        f"radiosity settings (ladder `{data.get('ladder_set', 'full')}` of `tools/compare/ladder.json`; each point "
        "overrides `count`, `error_bound`, `pretrace_start`, `pretrace_end` and `nearest_count` of every radiosity "
        "block in the scene's "
        "`global_settings`, everything else stays as the scene has it; wardray follows the same block). "
        f"Times are whole-process wall clock, the median of {data['runs']} run{'s' if data['runs'] != 1 else ''}, "
        "the two renderers' runs interleaved "
        "(POV-Ray, wardray, POV-Ray, ...). Each image's rRMSE and bad-pixel fraction (docs/metrics.md) are "
        "taken against the converged reference of its own renderer: POV-Ray's at "
        + ", ".join(f"`{k} {v}`" for k, v in data["references"]["povray_reference"].items())
        + "; wardray's is its brute-force mode (`--gi=reference`, no cache"
        + (", `--gi-area-lights=grid`: the camera hits' area lights on POV-Ray's grid with the jitter of the ladder's "
           "renders, so that the reference converges the cache mode's own image, as POV-Ray's converges POV-Ray's "
           "(whose jitter pattern, though, changes from run to run: its errors carry the difference of two patterns, "
           "wardray's none; the model reference below treats both alike); the seeds turn the paths alone"
           if data.get("wardray_own_model_reference") else
           "; its camera hits' area lights integrated finely, so wardray's errors include its grid's jitter and "
           "bias, which POV-Ray's, against its own grid, do not")
        + ") with the rays per pixel raised until "
        + {True: "a second seed",
           False: "halving the rays (wardray has no seed option; if the two renders share their first paths, this "
                  "check is up to 1.4 times more lenient than a second seed would be)"}.get(
            data.get("wardray_has_seed"), "a second seed (or, without a seed option, halving the rays)")
        + f" changes the image by less than {100 * data['references']['wardray_reference']['tolerance']:g} % "
        "rRMSE" + (" (the reference is then the mean of the two seeds' images, whose own noise is about half that "
                   "change)" if data.get("wardray_has_seed") else "")
        + ". The rRMSE between the two references shows how much of any difference is the lighting model rather "
        "than noise or cache error.",
        "",
        "Renderers: " + "; ".join(v if v.lower().startswith(LABELS[k].lower()) else f"{LABELS[k]} {v}"
                                  for k, v in data["renderers"].items()) + "."
        + (f" wardray's references are the cached ones filed under binary sha256 {data['wardray_references_key'][:12]}"
           " (`--wardray-references-key`): an earlier binary's, reused as rendering those images alike."
           if data.get("wardray_references_key") else ""),
        "",
        "These machines are shared and noisy: read the ratios, measured side by side, not the absolute seconds.",
        "",
        "## Time to reach a target error",
        "",
        "Time each renderer needs to reach rRMSE 5 %, 2 % and 1 % against its own reference, interpolated on its "
        "error-against-time curve (straight lines between ladder points in log-log space, first crossing). "
        "\"≤ t\" means the fastest ladder point already meets the target; \"not reached\" gives the lowest error "
        "measured. The ratio is wardray's time over POV-Ray's: below 1, wardray is faster.",
        "",
        "| scene | target rRMSE | POV-Ray (s) | wardray (s) | wardray / POV-Ray | faster |",
        "|---|---:|---:|---:|---:|---|",
    ]
    rows, not_ahead, measured = headline(data)
    lines += rows + [""]
    fastest = {name: min((p["seconds"] for s in data["scenes"] for p in s["points"] if p["renderer"] == name),
                         default=None) for name in ("povray", "wardray")}
    if all(fastest.values()):
        lines += [f"Fastest render measured: POV-Ray {fastest['povray']:.2f} s, wardray {fastest['wardray']:.2f} s "
                  "(whole process; at small sizes mostly start-up). A renderer cannot be quicker than that at any "
                  "target, so where a target is met at the cheapest point the ratio measures start-up, not "
                  "global illumination.", ""]
    count = sum(len(v) for v in not_ahead.values())
    if count:
        lines += [f"**wardray is not ahead on {count} of the {measured} scene and target pairs measured.**", ""]
        for reason, where in not_ahead.items():
            if where:
                lines.append(f"- {reason}: " + "; ".join(where) + ".")
        lines.append("")
    elif measured:
        lines += [f"wardray is ahead on all {measured} scene and target pairs measured.", ""]

    # The same targets against one reference for both: what a user comparing with POV-Ray's converged image sees.
    lines += common_targets(data, True, "common reference",
                            "As above, but each renderer's error taken against the same image, POV-Ray's converged "
                            "render: wardray's curve then includes the difference between the two lighting models "
                            "(the references' rRMSE below), so a target under that difference is out of its reach.")

    # Both against the converged image of the model they share: converged indirect light, and the direct light's
    # expectation over the area lights' jitter.
    model_lines = common_targets(
        data, "model", "model reference",
        "As above, but each renderer's error taken against one image that both converge to in expectation: "
        "wardray's brute-force indirect light, and at the camera hits the direct light of POV-Ray's area-light grid "
        "averaged over its jitter (the mean of "
        + ", ".join(f"{s['scene']} {s['model_reference']['jitter_seeds']}" for s in data["scenes"]
                    if s.get("model_reference"))
        + " direct-light renders with other seeds; 0: no jittered area light, the image is wardray's reference). "
        "Each renderer then carries its own jitter pattern (POV-Ray's differs from run to run, wardray's is fixed by "
        "its seed), and neither the other's pattern nor the grid's bias against the integral over the lights.",
        heading="converged model reference")
    lines += model_lines
    if model_lines:
        for s in data["scenes"]:
            mm = s.get("model_mismatch")
            if mm:
                lines.append(f"- {s['scene']}: the model reference is "
                             + " and ".join(f"{pct(v['rrmse'])} from {LABELS.get(k, k)}'s reference"
                                            for k, v in mm.items()) + ".")
        lines.append("")

    lines += ["## References", "",
              "| scene | POV-Ray reference (s) | wardray reference (s) | wardray rays/pixel | wardray convergence | "
              "rRMSE, wardray's reference against POV-Ray's | bad pixels, same | non-finite pixels |",
              "|---|---:|---:|---:|---|---:|---:|---:|"]
    loose = []
    for s in data["scenes"]:
        pr, wr, mm = s["references"].get("povray"), s["references"].get("wardray"), s.get("reference_mismatch")
        lines.append(f"| {s['scene']} | {pr['seconds']:.1f} |" if pr else
                     f"| {s['scene']} | {'failed' if 'povray' in data['renderers'] else 'not run'} |")
        lines[-1] += (f" {wr['seconds']:.1f} | {wr['rays']} | {wr['check']}"
                      + ("" if wr["converged"] else " (**not converged**)") + " |") if wr else \
            (" failed | — | — |" if "wardray" in data["renderers"] else " not run | — | — |")
        lines[-1] += (f" {pct(mm['rrmse'])} | {pct(mm['bad_fraction'])} | {mm['non_finite']} |" if mm
                      else " — | — | — |")
        if mm and mm["rrmse"] > min(TARGETS):
            loose.append(f"{s['scene']} ({pct(mm['rrmse'])})")
    lines.append("")
    own = [s for s in data["scenes"] if s.get("povray_reference_override")]
    if own:
        lines += ["POV-Ray's reference is rendered at the scene list's own settings on "
                  + "; ".join(f"{s['scene']} ("
                              + ", ".join(f"`{k} {v}`" for k, v in s["povray_reference_override"].items())
                              + ")" for s in own)
                  + ", the rest as above: at the common settings it is far from converged there.", ""]
    capped = [s for s in data["scenes"] if s.get("wardray_max_rays")]
    if capped:
        lines += ["wardray's reference may take up to the scene list's own number of paths per pixel on "
                  + ", ".join(f"{s['scene']} ({s['wardray_max_rays']})" for s in capped) + ".", ""]
    if loose:
        lines += ["The two references differ by more than the 1 % target on " + ", ".join(loose) + ": there, "
                  "reaching a target against its own reference says nothing about agreeing with the other renderer "
                  "(the last column of each scene's table below gives wardray's error against POV-Ray's reference).",
                  ""]

    unconverged = [s["scene"] for s in data["scenes"]
                   if s["references"].get("wardray") and not s["references"]["wardray"]["converged"]]
    if unconverged:
        lines += ["wardray's reference is **not converged** on " + ", ".join(unconverged) + ": an image's error "
                  "against it cannot fall below the reference's own noise (with a seed option, about half the change "
                  "quoted above: the reference is the mean of the two seeds), so wardray's low targets may read "
                  "\"not reached\" for that reason alone. Raise `max_rays` in "
                  "`tools/compare/ladder.json` (cached references are kept) to converge them.", ""]

    unsupported = [s for s in data["scenes"] if s.get("wardray_warnings")]
    if unsupported:
        lines += ["wardray warns of scene features it does not render (yet) on "
                  + ", ".join(f"{s['scene']} ({len(s['wardray_warnings'])})" for s in unsupported)
                  + "; there the references differ by design, not only by noise. The warnings are listed under "
                  "each scene below.", ""]

    lines += ["## Per scene", ""]
    for s in data["scenes"]:
        w, h = scene_size(s, data)
        lines += [f"### {s['scene']}", "", f"`{s['path']}`, {w}x{h}", "",
                  f"![{s['scene']}: error against time]({plot_dir.name}/{s['scene']}.png)", "",
                  "| point | renderer | time (s) | rRMSE | bad pixels | non-finite | rRMSE vs POV-Ray reference "
                  "| rRMSE vs model reference |",
                  "|---|---|---:|---:|---:|---:|---:|---:|"]
        for p in s["points"]:
            lines.append(f"| {p['label']} | {LABELS[p['renderer']]} | {p['seconds']:.2f} | {pct(p['rrmse'])} | "
                         f"{pct(p['bad_fraction'])} | {p['non_finite']} | {pct(p.get('rrmse_vs_povray_reference'))} "
                         f"| {pct(p.get('rrmse_vs_model_reference'))} |")
        non_finite = [p for p in s["points"] if p["non_finite"]]
        if non_finite:
            lines += ["", "**Non-finite pixels** (a failure whatever the errors say): "
                      + ", ".join(f"{LABELS[p['renderer']]} at {p['label']}" for p in non_finite) + "."]
        if s.get("wardray_warnings"):
            lines += ["", "`wardray --check` warnings:", ""] + [f"- `{w}`" for w in s["wardray_warnings"]]
        if s["failures"]:
            lines += ["", "Failures:", ""] + [f"- {f.splitlines()[0]}" for f in s["failures"]]
        lines.append("")

    if data["skipped"]:
        lines += ["## Scenes not compared", ""] + [f"- `{s['scene']}`: {s['reason']}" for s in data["skipped"]] + [""]
    lines += ["## Ladder", "", "| point | settings | wardray options |", "|---|---|---|"]
    for p in data["ladder"]:
        settings = ", ".join(f"{k} {v}" for k, v in p["radiosity"].items())
        lines.append(f"| {p['label']} | {settings} | {' '.join(p.get('wardray_args', [])) or '—'} |")
    lines.append("")
    return "\n".join(lines)


def write_all(data, out):
    out = pathlib.Path(out)
    plot_dir = out / "gi_comparison"
    plot_dir.mkdir(parents=True, exist_ok=True)
    write_csv(data, out / "gi_comparison.csv")
    for s in data["scenes"]:
        plot_scene(s, data, plot_dir / f"{s['scene']}.png")
    (out / "gi_comparison.md").write_text(markdown(data, plot_dir))
    print(f"compare: wrote {out / 'gi_comparison.md'}, {out / 'gi_comparison.csv'} and {len(data['scenes'])} plots "
          f"in {plot_dir}")
