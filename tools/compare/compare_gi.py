#!/usr/bin/env python3
"""Error against run time for global illumination, POV-Ray 3.7 and wardray side by side.

For every scene of the list, each renderer renders the scene over a ladder of radiosity quality settings
(tools/compare/ladder.json; every radiosity block of the scene's global_settings is overridden in a wrapper
scene), the two renderers' runs interleaved (POV-Ray, wardray, POV-Ray, ...), 2 threads each, N runs per point.
Each image is compared (rRMSE, bad pixels; docs/metrics.md) with the converged reference of its own
renderer: POV-Ray at count 3200, error_bound 0.07, pretrace_end 0.005, nearest_count 20; wardray's brute-force
`--gi=reference` of the cache mode's own image (`--gi-area-lights=grid`: the camera hits' area lights on POV-Ray's
grid, jittered as the ladder's renders jitter them, as POV-Ray's reference renders POV-Ray's grid), with its rays per
pixel raised until a second path seed (or, without a seed option, half the rays) changes the image by less than
0.3 % rRMSE (ladder.json's tolerance); and both against two common references: POV-Ray's converged render, and
the model reference (model_reference(): wardray's with the area lights' jitter averaged out, since POV-Ray's jitter
changes from run to run). Images are OpenEXR unless --format hdr.
Each scene is rendered at the size its line in the scene list gives (cornell 256x256), else 160x120; --size sets
one size for all. References are cached (build/compare-cache). Writes <out>/gi_comparison.csv, .json, .md and one
error-against-time plot per scene under <out>/gi_comparison/.

usage: tools/compare/compare_gi.py [--scenes FILE] [--size WxH] [--runs N] [--quick] [--out DIR]
                                   [--ladder-set full|extended|long] [--allow-unsupported]
                                   [--wardray PATH] [--renderers povray,wardray] [--format exr|hdr]
                                   [--report-only]
"""
import argparse
import json
import pathlib
import statistics
import sys
import tempfile
import time

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
sys.path.insert(0, str(HERE))

from gimetrics import image_error, read_linear_rgb  # noqa: E402
from povrewrite import RewriteError, rewrite_radiosity  # noqa: E402
from progress import Progress, format_seconds  # noqa: E402
from renderers import DEFAULT_FORMAT, FORMATS, PovRay, RenderCache, RenderFailed, Wardray, run_timed  # noqa: E402
import report  # noqa: E402


# A scene's image size when its line in the list gives none (issue 18: at 64x48 start-up dominates).
DEFAULT_SIZE = (160, 120)


def parse_size(text):
    w, _, h = text.lower().partition("x")
    if not (w.isdigit() and h.isdigit() and int(w) > 0 and int(h) > 0):
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT, got {text!r}")
    return int(w), int(h)


def parse_povray_reference(text):
    """`povray-reference=KEY:VALUE,...` of a scene list's line: the radiosity settings of POV-Ray's reference for that
    scene that differ from ladder.json's (for a scene where the common ones leave it far from converged)."""
    keys = ("pretrace_start", "pretrace_end", "count", "error_bound", "nearest_count")
    settings = {}
    for item in text.split(","):
        key, _, value = item.partition(":")
        if key not in keys:
            raise ValueError(f"expected one of {', '.join(keys)} in povray-reference=, got {key!r}")
        try:
            number = float(value)
        except ValueError:
            raise ValueError(f"expected a number for {key} in povray-reference=, got {value!r}") from None
        settings[key] = int(number) if key in ("count", "nearest_count") and number.is_integer() else number
    return settings


def load_scene_list(path):
    """[(scene path, size or None, options)]: one `.pov` path a line (absolute or relative to the repository),
    optionally followed by the image size it is compared at, `WIDTHxHEIGHT`, and by options for that scene alone:
    `povray-reference=KEY:VALUE,...`, its own settings for POV-Ray's reference (parse_povray_reference), and
    `wardray-max-rays=N`, a higher cap on its wardray reference's paths per pixel (a power of two). `options` maps
    "povray_reference" and "wardray_max_rays" to them, when given."""
    scenes = []
    for number, line in enumerate(pathlib.Path(path).read_text().splitlines(), 1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        words = line.split()
        size, options = None, {}
        try:
            for word in words[1:]:
                key, eq, value = word.partition("=")
                if eq and key == "povray-reference" and "povray_reference" not in options:
                    options["povray_reference"] = parse_povray_reference(value)
                elif eq and key == "wardray-max-rays" and "wardray_max_rays" not in options:
                    if not value.isdigit() or int(value) < 64 or int(value) & (int(value) - 1):
                        raise ValueError(f"expected a power of two of at least 64 in wardray-max-rays=, got {value!r}")
                    options["wardray_max_rays"] = int(value)
                elif size is None and not eq:
                    size = parse_size(word)
                else:
                    raise ValueError(f"expected a scene, at most a size and each option at most once, got {line!r}")
        except (ValueError, argparse.ArgumentTypeError) as e:
            raise ValueError(f"{path}:{number}: {e}") from None
        p = pathlib.Path(words[0])
        scenes.append((p if p.is_absolute() else (ROOT / p), size, options))
    return scenes


def scene_name(path):
    return path.stem


def next_rays(rays, change, tolerance, max_rays):
    """Rays per pixel for the next convergence check: noise falls as 1/sqrt(rays), so aim where `change` would be
    10 % under the tolerance, at least twice the current count, rounded up to a power of two, at most max_rays."""
    wanted = rays * (change / tolerance) ** 2 * 1.2
    n = 2 * rays
    while n < wanted:
        n *= 2
    return min(n, max_rays)


def wardray_reference(ward, text, scene_dir, size, work, cache, cfg, progress, name):
    """wardray's converged image, as pixels: brute force with enough rays that a second seed changes the image by
    less than the tolerance (docs/metrics.md), the mean of the two seeds; without a seed option, that halving the
    rays does."""
    if ward.gi_mode == "off":
        image, seconds, cached = cache.render(ward, text, scene_dir, size, [], work,
                                              f"wardray --gi=off image of {name}")
        progress.finish((name, "wardray", None), None if cached else seconds)
        return read_linear_rgb(image), {"rays": None, "seconds": seconds, "converged": False,
                       "check": "none: wardray ran with --gi=off (development mode)"}
    if not ward.has_reference:
        raise RenderFailed("this wardray has no --gi=reference with --gi-rays (see wardray --help)")

    def render(rays, seed):
        progress.show(name, f"reference {rays} rays" + (f" seed {seed}" if seed else ""), "wardray", 1, 1)
        image, seconds, cached = cache.render(ward, text, scene_dir, size, ward.reference_args(rays, seed), work,
                                              f"wardray reference of {name}, {rays} rays"
                                              + (f", seed {seed}" if seed else ""))
        progress.finish((name, "wardray", None), None if cached else seconds)
        return image, seconds

    rays, tolerance, max_rays = cfg["start_rays"], cfg["tolerance"], cfg["max_rays"]
    while True:
        # A pair of images whose difference measures the noise left at `rays`; the reference is the first one.
        if ward.has_seed:
            (ref, seconds), (other, _) = render(rays, 1), render(rays, 2)
        else:
            (ref, seconds), (other, _) = render(rays, None), render(rays // 2, None)
        change = image_error(read_linear_rgb(other), read_linear_rgb(ref))["rrmse"]
        how = (f"a second seed changes rRMSE by {100 * change:.2f} % at {rays} rays" if ward.has_seed else
               f"no seed option: {rays // 2} instead of {rays} rays changes rRMSE by {100 * change:.2f} %")
        converged = bool(change < tolerance)
        if converged or rays >= max_rays:
            image = read_linear_rgb(ref)
            if ward.has_seed:
                # The two seeds are independent estimates: their mean has half the variance of either, at no cost.
                image = 0.5 * (image + read_linear_rgb(other))
                how += "; the reference is the mean of the two seeds' images"
            return image, {"rays": rays, "seconds": seconds, "converged": converged, "check": how}
        rays = next_rays(rays, change, tolerance, max_rays)
        progress.add([(name, "wardray", None)] * 2)


def model_reference(ward, text, scene_dir, size, work, cache, own, cfg, progress, name):
    """The converged image of the model both renderers implement, as pixels, and how it was made; None when the
    scene's direct light does not depend on the seed (no jittered area light): then it is wardray's own reference.

    wardray's own-model reference `own` has converged indirect light and, at the camera hits, exactly the cache mode's
    direct light at the default seed: one jitter pattern of POV-Ray's area-light grid. Here that direct light (a
    `--gi=off` render) is replaced by its expectation over the jitter, the mean of `jitter_seeds` renders with other
    seeds. Against this image each renderer's error includes its own jitter pattern (POV-Ray's changes from run to
    run) and neither the other renderer's pattern nor the grid's bias against the integral over the lights."""
    seeds = int(cfg.get("jitter_seeds", 64))

    def direct(seed):
        what = f"wardray direct light of {name}" + (f", seed {seed}" if seed else "")
        progress.show(name, "direct light" + (f" seed {seed}" if seed else ""), "wardray", 1, 1)
        args = ["--gi=off"] + (["--seed", str(seed)] if seed else [])
        image, seconds, cached = cache.render(ward, text, scene_dir, size, args, work, what)
        progress.finish((name, "wardray", None), None if cached else seconds)
        return read_linear_rgb(image)

    progress.add([(name, "wardray", None)] * 2)
    pattern, other = direct(0), direct(1)
    if (pattern == other).all():
        return None, {"jitter_seeds": 0, "check": "the direct light is the same for every seed: no jitter to average"}
    progress.add([(name, "wardray", None)] * (seeds - 1))
    total = other.copy()
    for seed in range(2, seeds + 1):
        total += direct(seed)
    expectation = total / seeds
    spread = image_error(other, expectation)["rrmse"]
    return own - pattern + expectation, {
        "jitter_seeds": seeds,
        "pattern_vs_expectation": image_error(pattern, expectation)["rrmse"],
        "check": f"the direct light's mean over {seeds} jitter seeds; one pattern is {100 * spread:.2f} % rRMSE from "
                 f"it, so the mean's own noise is about {100 * spread / seeds ** 0.5:.3f} %"}


def measure_scene(path, renderers, points, cfg, size, runs, cache, progress, options=None):
    """References, then the ladder with interleaved runs; returns the scene's results as plain data.
    `options`: the scene list's options for this scene (load_scene_list), over cfg's."""
    options = options or {}
    povray_reference = options.get("povray_reference")
    name = scene_name(path)
    scene_dir = path.parent
    text = path.read_text(errors="replace")
    result = {"scene": name, "path": str(path.relative_to(ROOT) if path.is_relative_to(ROOT) else path),
              "size": list(size), "references": {}, "points": [], "failures": []}
    with tempfile.TemporaryDirectory(prefix=f"compare-{name}-") as tmp:
        work = pathlib.Path(tmp)
        pov_settings = {**cfg["povray_reference"], **(povray_reference or {})}
        if povray_reference:
            result["povray_reference_override"] = povray_reference
        # wardray's references (brute force: count and error_bound do not matter to them) keep the common settings.
        ref_text, _ = rewrite_radiosity(text, cfg["povray_reference"])
        pov_ref_text, _ = rewrite_radiosity(text, pov_settings)
        refs = {}
        for r in renderers:
            try:
                if r.name == "povray":
                    progress.show(name, "reference", r.label, 1, 1)
                    image, seconds, cached = cache.render(r, pov_ref_text, scene_dir, size, [], work,
                                                          f"POV-Ray reference of {name}")
                    progress.finish((name, r.name, None), None if cached else seconds)
                    info = {"settings": pov_settings, "seconds": seconds, "converged": True}
                    refs[r.name] = read_linear_rgb(image)
                else:
                    ward_cfg = dict(cfg["wardray_reference"])
                    if options.get("wardray_max_rays"):
                        ward_cfg["max_rays"] = options["wardray_max_rays"]
                        result["wardray_max_rays"] = options["wardray_max_rays"]
                    refs[r.name], info = wardray_reference(r, ref_text, scene_dir, size, work, cache, ward_cfg,
                                                           progress, name)
                result["references"][r.name] = info
            except RenderFailed as e:
                result["failures"].append(f"{r.label} reference: {e}")
                progress.note(f"compare: {name}: {r.label} reference failed: {str(e).splitlines()[0]}")
        if "povray" in refs and "wardray" in refs:
            result["reference_mismatch"] = image_error(refs["wardray"], refs["povray"])
        # The common reference of the shared model, where wardray's own converges the cache mode's image.
        model = None
        ward = next((r for r in renderers if r.name == "wardray"), None)
        if "wardray" in refs and getattr(ward, "has_own_model_reference", False) and ward.gi_mode != "off":
            try:
                model, info = model_reference(ward, ref_text, scene_dir, size, work, cache, refs["wardray"],
                                              cfg["wardray_reference"], progress, name)
                if model is None:
                    model = refs["wardray"]
                result["model_reference"] = info
                result["model_mismatch"] = {r: image_error(refs[r], model) for r in refs}
            except RenderFailed as e:
                result["failures"].append(f"model reference: {e}")
                model = None
        active = [r for r in renderers if r.name in refs]
        for r in renderers:
            if r not in active:
                progress.drop(name, r.name)
        for p_index, p in enumerate(points):
            wrapper, _ = rewrite_radiosity(text, p["radiosity"])
            (work / "scene.pov").write_text(wrapper)
            rows = {r.name: {"renderer": r.name, "label": p["label"], "settings": p["radiosity"],
                             "wardray_args": p.get("wardray_args", []), "times": [], "errors": []} for r in active}
            failed = set()
            for i in range(runs):
                for r in active:  # interleaved: A B A B ...
                    job = (name, r.name, p["label"])
                    if r.name in failed:
                        progress.finish(job, None)
                        continue
                    progress.show(name, p["label"], r.label, i + 1, runs)
                    extra = p.get("wardray_args", []) if r.name == "wardray" else []
                    # A fresh name per run, so an image left by an earlier run can never be read as this one's.
                    output = work / f"{r.name}-{p_index}-{i}{r.suffix}"
                    try:
                        seconds = run_timed(r.command("scene.pov", output.name, size, scene_dir, extra), work)
                        if not output.is_file():
                            raise RenderFailed(f"{r.label} exited without writing {output.name}")
                    except RenderFailed as e:
                        failed.add(r.name)
                        result["failures"].append(f"{r.label} at {p['label']}: {e}")
                        progress.note(f"compare: {name}: {r.label} failed at {p['label']}: {str(e).splitlines()[0]}")
                        progress.finish(job, None)
                        continue
                    progress.finish(job, seconds)
                    image = read_linear_rgb(output)
                    output.unlink()
                    err = image_error(image, refs[r.name])
                    if "povray" in refs:
                        err["rrmse_vs_povray_reference"] = image_error(image, refs["povray"])["rrmse"]
                    if model is not None:
                        err["rrmse_vs_model_reference"] = image_error(image, model)["rrmse"]
                    rows[r.name]["times"].append(seconds)
                    rows[r.name]["errors"].append(err)
            for r in active:
                row = rows[r.name]
                if r.name in failed or not row["times"]:
                    continue
                row["seconds"] = statistics.median(row["times"])
                for key in ("rrmse", "bad_fraction", "rrmse_vs_povray_reference", "rrmse_vs_model_reference"):
                    values = [e[key] for e in row["errors"] if key in e]
                    row[key] = statistics.median(values) if values else None
                row["non_finite"] = max(e["non_finite"] for e in row["errors"])
                result["points"].append(row)
    return result


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scenes", default=str(HERE / "scenes.txt"), help="scene list, one .pov per line")
    ap.add_argument("--ladder", default=str(HERE / "ladder.json"), help="quality ladders and reference settings")
    ap.add_argument("--size", type=parse_size, default=None,
                    help="image size WxH for every scene (default: each scene's size in the list, else "
                         f"{DEFAULT_SIZE[0]}x{DEFAULT_SIZE[1]})")
    ap.add_argument("--runs", type=int, default=3, help="timed runs per ladder point and renderer (default 3)")
    ap.add_argument("--quick", action="store_true",
                    help="smoke test: two ladder points and cheap, unconverged references")
    ap.add_argument("--ladder-set", default="full", help="which ladder of --ladder to run (full, extended, long)")
    ap.add_argument("--allow-unsupported", action="store_true",
                    help="also compare scenes for which wardray --check warns of features it does not render")
    ap.add_argument("--out", default=str(ROOT / "docs" / "reports"), help="folder for the report (docs/reports)")
    ap.add_argument("--wardray", default=str(ROOT / "build" / "wardray"), help="wardray binary")
    ap.add_argument("--povray", default="povray", help="POV-Ray binary")
    ap.add_argument("--renderers", default="povray,wardray", help="which renderers to run (default both)")
    ap.add_argument("--wardray-gi", choices=("cache", "off"), default="cache",
                    help="wardray's GI mode for the ladder; 'off' only to develop this tool before the cache exists")
    ap.add_argument("--cache", default=str(ROOT / "build" / "compare-cache"), help="folder for cached references")
    ap.add_argument("--wardray-references-key", metavar="SHA256", default=None,
                    help="file and find wardray's cached references under this binary digest (its first 12 hex "
                         "digits suffice) instead of --wardray's: reuse an earlier binary's references when the two "
                         "render the reference images alike (the report says so)")
    ap.add_argument("--format", choices=sorted(FORMATS), default=DEFAULT_FORMAT,
                    help="image format of every render: exr (half floats, the default) or hdr (Radiance RGBE, whose "
                         "shared truncated mantissa adds about 0.6 %% rRMSE between two images)")
    ap.add_argument("--report-only", action="store_true",
                    help="rewrite the report and plots from <out>/gi_comparison.json without rendering")
    args = ap.parse_args()
    if args.runs < 1:
        ap.error("--runs must be at least 1")

    out = pathlib.Path(args.out)
    data_path = out / "gi_comparison.json"
    if args.report_only:
        report.write_all(json.loads(data_path.read_text()), out)
        return 0

    ladder = json.loads(pathlib.Path(args.ladder).read_text())
    set_name = "quick" if args.quick else args.ladder_set
    if set_name not in ladder or not isinstance(ladder[set_name], list):
        ap.error(f"{args.ladder} has no ladder {set_name!r}")
    points = ladder[set_name]
    cfg = {"povray_reference": ladder["quick_povray_reference" if args.quick else "povray_reference"],
           "wardray_reference": ladder["quick_wardray_reference" if args.quick else "wardray_reference"]}
    wanted = [n.strip() for n in args.renderers.split(",") if n.strip()]
    if not wanted or set(wanted) - {"povray", "wardray"}:
        ap.error("--renderers takes povray, wardray or both")
    renderers = []
    if "povray" in wanted:
        renderers.append(PovRay(args.povray, image_format=args.format))
    if "wardray" in wanted:
        renderers.append(Wardray(args.wardray, gi_mode=args.wardray_gi, image_format=args.format,
                                 references_key=args.wardray_references_key))
        if not renderers[-1].has_reference and args.wardray_gi == "cache":
            print("compare: warning: wardray --help lists no --gi=reference/--gi-rays; its reference will fail",
                  file=sys.stderr)
    cache = RenderCache(args.cache)

    # Scenes a renderer cannot read are reported, not rendered.
    scenes, skipped = [], []
    try:
        listed = load_scene_list(args.scenes)
    except ValueError as e:
        ap.error(str(e))
    for path, listed_size, options in listed:
        size = args.size or listed_size or DEFAULT_SIZE
        # The smoke test keeps its cheap references: a scene's own finer ones are for the report.
        options = {} if args.quick else options
        if not path.is_file():
            skipped.append({"scene": str(path), "reason": "file not found"})
            continue
        try:
            rewrite_radiosity(path.read_text(errors="replace"), cfg["povray_reference"])
        except RewriteError as e:
            skipped.append({"scene": str(path), "reason": f"radiosity block cannot be rewritten: {e}"})
            continue
        ward = next((r for r in renderers if r.name == "wardray"), None)
        problem, warnings = ward.check(path, path.parent) if ward else (None, [])
        if problem:
            skipped.append({"scene": str(path), "reason": f"wardray --check: {problem}"})
            continue
        # A scene wardray renders without some of its features compares neither images nor times fairly.
        unsupported = [w for w in warnings if "not rendered" in w or "not supported" in w]
        if unsupported and not args.allow_unsupported:
            skipped.append({"scene": str(path), "reason": "wardray does not render all of it (use "
                            "--allow-unsupported to compare anyway): " + "; ".join(unsupported)})
            continue
        scenes.append((path, size, warnings, options))
    for s in skipped:
        print(f"compare: skipping {s['scene']}: {s['reason']}", file=sys.stderr)

    plan = []
    for path, _, _, _ in scenes:
        name = scene_name(path)
        for r in renderers:
            plan += [(name, r.name, None)] * (2 if r.name == "wardray" and r.gi_mode != "off" else 1)
        plan += [(name, r.name, p["label"]) for p in points for _ in range(args.runs) for r in renderers]
    progress = Progress(plan)
    started = time.monotonic()
    data = {
        "command": " ".join(["tools/compare/compare_gi.py"] + sys.argv[1:]),
        "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
        "size": list(args.size) if args.size else None, "runs": args.runs, "quick": args.quick, "ladder_set": set_name, "threads": 2,
        "format": args.format,
        "wall_seconds": 0.0,
        "renderers": {r.name: r.version for r in renderers},
        "wardray_references_key": args.wardray_references_key if "wardray" in wanted else None,
        "wardray_gi": args.wardray_gi if "wardray" in wanted else None,
        "wardray_has_seed": next((r.has_seed for r in renderers if r.name == "wardray"), None),
        "wardray_own_model_reference": next((getattr(r, "has_own_model_reference", False)
                                             for r in renderers if r.name == "wardray"), None),
        "ladder": points, "references": cfg, "scenes": [], "skipped": skipped,
    }
    out.mkdir(parents=True, exist_ok=True)
    for path, size, warnings, options in scenes:
        result = measure_scene(path, renderers, points, cfg, size, args.runs, cache, progress, options)
        result["wardray_warnings"] = warnings
        data["scenes"].append(result)
        ward = next((r for r in renderers if r.name == "wardray"), None)
        if ward and ward.rebuilt() and not data.get("rebuilt"):
            data["rebuilt"] = f"wardray was rebuilt while {result['scene']} was measured"
            progress.note(f"compare: warning: {data['rebuilt']}; later figures mix two builds")
        data["wall_seconds"] = time.monotonic() - started
        # Saved after every scene: an interrupted run still gives a report with --report-only.
        data_path.write_text(json.dumps(data, indent=1))
    progress.note(f"compare: rendering took {format_seconds(data['wall_seconds'])}")
    data_path.write_text(json.dumps(data, indent=1))
    report.write_all(data, out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
