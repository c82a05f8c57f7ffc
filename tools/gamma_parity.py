#!/usr/bin/env python3
"""Measures wardray's 8-bit PNG and linear HDR against POV-Ray's on the gamma demo scenes (issue 13).

The scenes are gamma/ and the woods, stones and metals demos of incdemo/ that wardray renders with no "not rendered"
warning. Each is rendered by both programs as PNG and as HDR, same size, same switches, one thread each. Reported
per scene: the fraction of pixels whose every channel is within one level of POV-Ray's PNG, and the HDR rRMSE and
bad-pixel fraction as docs/metrics.md defines them. A scene with randomness (radiosity, jitter, crand, focal blur, in
its text or, as `wardray --check` names it, in the parsed scene) is rendered converged by both, as tools/census.py
converges it (a scratch copy of its folder with converged radiosity and blur_samples, every pixel supersampled 6x6
without jitter where the randomness is per sample): at its own settings two renders differ by their noise.

usage: tools/gamma_parity.py WARDRAY [--size 160x120] [--switches "-A"] [--out DIR] [--only STEM ...]
exit status: 0 when every scene has at least 99 % of its PNG pixels within one level, 1 otherwise.
"""
import argparse
import pathlib
import subprocess
import sys
import tempfile

import numpy as np
import OpenImageIO as oiio

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import census  # noqa: E402  (the census's scene files, randomness and convergence)

EXAMPLES = pathlib.Path("/usr/share/povray-3.7/scenes")


def converged_folder(scene, stochastic, scratch):
    """A copy of the scene's folder in `scratch` (subfolders linked) with its randomness converged: the new scene
    path."""
    census.scratch_copy(scene, scratch)
    census.converged_copy(census.scene_files(scene), scratch, stochastic)
    return scratch / scene.name


def demo_scenes():
    out = sorted((EXAMPLES / "gamma").glob("*.pov"))
    for folder in ("woods", "stones", "metals"):
        out += sorted((EXAMPLES / "incdemo" / folder).glob("*.pov"))
    return out


def read(path):
    buf = oiio.ImageBuf(str(path))
    fmt = oiio.UINT8 if path.suffix == ".png" else oiio.FLOAT
    return np.asarray(buf.get_pixels(fmt), dtype=np.float64)[..., :3]


def hdr_figures(image, ref):
    rrmse = np.sqrt(np.mean((image - ref) ** 2)) / max(np.mean(ref), 1e-12)
    lum = lambda a: 0.2126 * a[..., 0] + 0.7152 * a[..., 1] + 0.0722 * a[..., 2]
    y_i, y_r = lum(image), lum(ref)
    bad = np.abs(y_i - y_r) > 0.1 * y_r + 0.01 * np.mean(y_r)
    return rrmse, np.mean(bad)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("wardray")
    ap.add_argument("--size", default="160x120")
    ap.add_argument("--switches", default="-A")
    ap.add_argument("--out", default="gamma_parity_out")
    ap.add_argument("--only", nargs="*", help="scene names (stems) to measure, all when not given")
    args = ap.parse_args()
    width, height = args.size.split("x")
    out = pathlib.Path(args.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    wardray = str(pathlib.Path(args.wardray).resolve())
    common = [f"+W{width}", f"+H{height}", "+WT1"] + args.switches.split()
    print(f"{'scene':28} {'PNG within 1':>12} {'HDR rRMSE':>10} {'HDR bad':>8}")
    failed = 0
    for scene in demo_scenes():
        if args.only and scene.stem not in args.only:
            continue
        name = f"{scene.parent.name}_{scene.stem}"
        check = subprocess.run([wardray, str(scene), "--check"], cwd=scene.parent, capture_output=True, text=True)
        if "not rendered" in check.stderr or check.returncode != 0:
            print(f"{name:28} {'skipped: a feature is not rendered yet':>32}")
            continue
        texts = [t for _, t in census.scene_files(scene)]
        stochastic = census.stochastic_features(texts)
        stochastic += [w for w in census.parsed_randomness_words(check.stdout) if w not in stochastic]
        with tempfile.TemporaryDirectory(prefix="gamma-parity-") as tmp:
            source, switches = scene, common
            if stochastic:
                source = converged_folder(scene, stochastic, pathlib.Path(tmp) / "scene")
                switches = census.converged_options(common, stochastic)
                name += " (converged)"
            for ext, fmt in (("png", "+FN"), ("hdr", "+FH")):
                # POV-Ray may only write below its working folder: run it in the output folder.
                subprocess.run(["povray", f"+I{source}", f"+L{source.parent}", f"+L{scene.parent}",
                                f"+O{scene.parent.name}_{scene.stem}.pov.{ext}", fmt, "-D", "-V", "-GA"] + switches,
                               cwd=out, capture_output=True)
                subprocess.run([wardray, str(source), "-o", str(out / f"{scene.parent.name}_{scene.stem}.wr.{ext}"),
                                fmt] + switches, cwd=source.parent, capture_output=True)
        name_file = f"{scene.parent.name}_{scene.stem}"
        try:
            png_w, png_p = read(out / f"{name_file}.wr.png"), read(out / f"{name_file}.pov.png")
            hdr_w, hdr_p = read(out / f"{name_file}.wr.hdr"), read(out / f"{name_file}.pov.hdr")
        except Exception as e:  # a renderer failed: say so and count it
            print(f"{name:28} failed: {e}")
            failed += 1
            continue
        within = np.mean(np.all(np.abs(png_w - png_p) <= 1, axis=-1))
        rrmse, bad = hdr_figures(hdr_w, hdr_p)
        failed += within < 0.99
        print(f"{name:28} {100 * within:11.2f}% {100 * rrmse:9.2f}% {100 * bad:7.2f}%", flush=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
