#!/usr/bin/python3
"""The render census: every POV-Ray example scene rendered by POV-Ray 3.7 and wardray, compared, and reported.

    tools/census.py build/wardray                     # all 396 scenes; writes docs/reports/census.md
    tools/census.py build/wardray --scenes 'objects/*' # only these (the report still lists every scene)
    tools/census.py build/wardray --fresh              # forget the cached results and redo everything
    tools/census.py build/wardray --check objects/blob.pov ... --expect-match   # the CTest mode

Each scene is rendered by both programs at 120x90, `-A`, linear Radiance HDR (`+FH`), one thread each (`+WT1`),
each bounded at 60 s, in a scratch copy of the scene's folder (POV-Ray writes only below its current folder, and
scenes read the data files beside them). The two images are compared as ../shared/docs/METRICS.md says (rRMSE,
bad-pixel fraction, non-finite pixels; POV-Ray is the reference) and each scene gets a category (see `classify`).
Scenes run in parallel, `--jobs` of them (default 2, one thread each).

Results are cached in `build/census/results.jsonl`, one JSON line per scene, keyed by the wardray binary's hash and
the scene's text with the files it includes from its own folder; POV-Ray's images are cached by the scene alone
(`build/census/povray/`). An interrupted run resumes where it stopped, and a rebuilt wardray re-renders only
wardray. The report is written from the cache after every run: scenes with no current result are listed as not
measured. Beside it, not committed: `build/census/index.html`, a contact sheet of every scene (POV-Ray, wardray,
difference), worst first.

Scenes with an `.ini` beside them (animations, the portfolio, benchmark, desk) are rendered without it, as
`povray scene.pov` would: one frame, clock 0, frame_number 0, in both programs alike. Where POV-Ray fails that
way (the portfolio scenes index arrays by frame_number), it renders the .ini's first frame instead (`scene.ini
+SF<n> +EF<n>` before the census's own options, which win); wardray reads no .ini and has no animation options,
so it gets only the .ini's `Declare=` values, and the scene carries a note saying so.
"""
import argparse
import concurrent.futures
import datetime
import fcntl
import fnmatch
import hashlib
import html
import json
import math
import os
import pathlib
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tools" / "compare"))

import gimetrics  # noqa: E402
import progress  # noqa: E402
import renderers  # noqa: E402
from povrewrite import RewriteError, find_blocks, mask_comments_and_strings  # noqa: E402

EXAMPLES = pathlib.Path("/usr/share/povray-3.7/scenes")
SIZE = (120, 90)
TIMEOUT = 60  # seconds, each renderer
# METRICS.md: a match is rRMSE <= 1 % and bad pixels <= 0.5 %; issue 13: more than 2 % with no warning is silent.
MATCH_RRMSE, MATCH_BAD, SILENT_RRMSE = 0.01, 0.005, 0.02
# Stochastic scenes (radiosity, jitter, crand) are compared at their own settings, one render each: the tolerance.
STOCHASTIC_RRMSE = 0.05
CATEGORIES = ("match", "differ-with-warning", "differ-silently", "differ-small", "blocked", "povray-fails")
# Bumped when what is stored per scene changes, so old cache lines are not reused.
RECORD_VERSION = 2


# ---------------------------------------------------------------------------------------------------------------
# What the scene text says: stochastic features and gamma hints.

def masked(text):
    try:
        return mask_comments_and_strings(text)
    except RewriteError:
        return text  # an unterminated comment: scan the raw text


def scene_files(scene):
    """[(name, text)] of the scene and, recursively, the files it includes from its own folder."""
    files, todo = {}, [(scene.name, scene.read_text(errors="replace"))]
    while todo:
        name, text = todo.pop(0)
        if name in files:
            continue
        files[name] = text
        todo += [(n, t) for n, t in renderers.local_includes(text, scene.parent) if n not in files]
    return list(files.items())


def read_ini(path):
    """What the census takes from a scene's .ini: its first frame, that frame's clock and its declarations.

    POV-Ray renders that one frame of the .ini (the portfolio scenes index arrays by frame_number and fail
    without it); wardray reads no .ini and has no animation options, so it gets only the declarations."""
    ini = {"file": path.name, "frame": 1, "clock": 0.0, "declares": []}
    for raw in path.read_text(errors="replace").splitlines():
        line = raw.split(";", 1)[0].strip()
        key, _, value = line.partition("=")
        key, value = key.strip().lower(), value.strip()
        try:
            if key == "initial_frame" and value:
                ini["frame"] = int(value)
                continue
            if key == "initial_clock" and value:
                ini["clock"] = float(value)
                continue
        except ValueError:
            continue
        for token in line.split():
            low = token.lower()
            if low.startswith("declare=") and low.count("=") >= 2:
                ini["declares"].append(token[len("declare="):])
            elif re.fullmatch(r"[+-]kfi-?\d+", low):
                ini["frame"] = int(low[4:])
            elif re.fullmatch(r"[+-]ki-?[\d.]+", low):
                ini["clock"] = float(low[3:])
    return ini


def ini_note(ini):
    return (f"POV-Ray rendered frame {ini['frame']} of {ini['file']} (clock {ini['clock']:g}); wardray reads no "
            ".ini and has no animation options (frame_number 0)")


def stochastic_features(texts):
    """The sources of randomness a scene uses: a global radiosity block, `jitter` (area lights, media), `crand`.

    An object's `radiosity { importance ... }` is not a radiosity block and does not count."""
    found = []
    for text in texts:
        m = masked(text)
        try:
            blocks = find_blocks(m, "radiosity")
        except RewriteError:
            blocks = []
        for open_at, close_at in blocks:
            body = re.sub(r"\bimportance\b\s*[\d.]*", "", m[open_at + 1:close_at]).strip()
            if body and "radiosity" not in found:
                found.append("radiosity")
        for word in ("jitter", "crand"):
            if re.search(rf"(?<![A-Za-z0-9_]){word}(?![A-Za-z0-9_])", m) and word not in found:
                found.append(word)
    return found


def gamma_facts(scene_text, texts):
    """(assumed_gamma values as written, the scene's first #version or None)."""
    gammas = []
    for text in texts:
        for g in re.findall(r"(?<![A-Za-z0-9_])assumed_gamma\s+([^\s}]+)", masked(text)):
            if g not in gammas:
                gammas.append(g)
    v = re.search(r"#\s*version\s+([0-9.]+)", masked(scene_text))
    return gammas, (v.group(1) if v else None)


def hints(rec):
    """Likely causes of a difference found in the scene text (wardray does not apply POV-Ray's gamma model yet)."""
    out = []
    other = []
    for g in rec.get("assumed_gamma", []):
        try:
            if abs(float(g) - 1.0) > 1e-9:
                out.append(f"assumed_gamma {g}")
        except ValueError:
            other.append(f"assumed_gamma {g}")
    out += other
    version = rec.get("version")
    try:
        old = version is not None and float(version) < 3.7
    except ValueError:
        old = False
    if old:
        out.append(f"#version {version}" + ("" if rec.get("assumed_gamma") else " with no assumed_gamma"))
    elif not rec.get("assumed_gamma"):
        out.append("no assumed_gamma" + ("" if version else ", no #version"))
    if rec.get("ini"):
        out.append(ini_note(rec["ini"]))
    if rec.get("metrics") and rec["metrics"].get("non_finite_wardray"):
        out.append(f"{rec['metrics']['non_finite_wardray']} non-finite pixels")
    return out


# ---------------------------------------------------------------------------------------------------------------
# Classification.

def tolerance(stochastic):
    """(match rRMSE, match bad-pixel fraction or None, silent rRMSE) for a scene."""
    if stochastic:
        # One render each at the scene's own settings: the noise makes a per-pixel test meaningless.
        return STOCHASTIC_RRMSE, None, STOCHASTIC_RRMSE
    return MATCH_RRMSE, MATCH_BAD, SILENT_RRMSE


def classify(rec):
    """(category, reason) of a scene's record.

    povray-fails: POV-Ray failed or timed out (no reference). blocked: wardray failed, timed out or wrote no image.
    match: rRMSE and bad pixels within the tolerance and no non-finite pixel. differ-with-warning: not a match and
    wardray warned that something is not rendered yet. differ-silently: no such warning and rRMSE above 2 % (5 %
    for a stochastic scene) or any non-finite pixel. differ-small: the rest (no warning, between match and 2 %)."""
    if rec["povray"]["status"] != "ok":
        return "povray-fails", rec["povray"].get("error") or rec["povray"]["status"]
    ward = rec["wardray"]
    if ward["status"] != "ok":
        return "blocked", (ward.get("error") or ward["status"]) + (f"; {ini_note(rec['ini'])}" if rec.get("ini")
                                                                   else "")
    m = rec["metrics"]
    match_rrmse, match_bad, silent_rrmse = tolerance(rec.get("stochastic"))
    finite = m["non_finite_wardray"] == 0 and m["non_finite"] == 0
    if finite and m["rrmse"] <= match_rrmse and (match_bad is None or m["bad"] <= match_bad):
        return "match", ""
    features = ward.get("features", [])
    if features:
        return "differ-with-warning", "not rendered: " + ", ".join(features)
    reason = "; ".join(hints(rec)) or "no hint in the scene text"
    if not finite or m["rrmse"] > silent_rrmse:
        return "differ-silently", reason
    return "differ-small", reason


# ---------------------------------------------------------------------------------------------------------------
# Rendering one scene.

class Interrupted(Exception):
    """The census was interrupted while this scene rendered: its result is not recorded."""


class Runner:
    """Runs commands, each in its own session so that ^C reaches only the census, which then kills them: a render
    cut short is never recorded as a failure."""

    def __init__(self):
        self.stop = threading.Event()
        self._running = set()
        self._lock = threading.Lock()

    def run(self, cmd, cwd, timeout):
        """{rc, seconds, stdout, stderr, timed_out} of a command run with stdin closed."""
        if self.stop.is_set():
            raise Interrupted()
        start = time.perf_counter()
        proc = subprocess.Popen(cmd, cwd=cwd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True, errors="replace", start_new_session=True)
        with self._lock:
            self._running.add(proc)
        timed_out = False
        try:
            try:
                out, err = proc.communicate(timeout=timeout)
            except subprocess.TimeoutExpired:
                timed_out = True
                self._kill(proc)
                out, err = proc.communicate()
        finally:
            with self._lock:
                self._running.discard(proc)
        if self.stop.is_set():
            raise Interrupted()
        return {"rc": None if timed_out else proc.returncode, "seconds": time.perf_counter() - start,
                "stdout": out or "", "stderr": err or "", "timed_out": timed_out}

    @staticmethod
    def _kill(proc):
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass

    def interrupt(self):
        self.stop.set()
        with self._lock:
            for proc in list(self._running):
                self._kill(proc)


def exit_text(rc):
    if rc is not None and rc < 0:
        try:
            return f"killed by {signal.Signals(-rc).name}"
        except ValueError:
            return f"killed by signal {-rc}"
    return f"exit status {rc}"


def scratch_copy(scene, work):
    """A fresh folder holding copies of the files beside the scene (subfolders linked, they are only read)."""
    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    for entry in scene.parent.iterdir():
        if entry.is_dir():
            (work / entry.name).symlink_to(entry.resolve(), target_is_directory=True)
        elif entry.is_file():
            shutil.copy(entry, work / entry.name)
    return work


def povray_error(output):
    """POV-Ray's first error with its continuation lines, e.g. "Parse Error: Cannot open include file x.inc"."""
    lines = output.splitlines()

    def joined(i):
        text = lines[i].strip()
        for more in lines[i + 1:i + 3]:
            if more.startswith(" ") and more.strip() and not re.search(r"[Ee]rror", more):
                text += " " + more.strip()
            else:
                break
        return re.sub(r"^File '[^']*' ", "", text)

    possible = None
    for i, line in enumerate(lines):
        if "Possible Parse Error" in line:
            possible = i
        elif re.search(r"(Parse|Render|Fatal) [Ee]rror|^Error:|^Problem with option", line):
            text = joined(i)
            # "Fatal error in parser: Cannot open file." says little; the warning before it names the file.
            if line.startswith("Fatal") and possible is not None:
                text = joined(possible) + " " + text
            return text[:300]
    return None


def povray_warnings(output):
    lines, found = output.splitlines(), []
    for i, line in enumerate(lines):
        if "Warning:" in line and "Possible" not in line:
            text = line.strip()
            if i + 1 < len(lines) and lines[i + 1].startswith(" ") and lines[i + 1].strip():
                text += " " + lines[i + 1].strip()
            text = re.sub(r"^File '[^']*' line \d+: ", "", text)[:300]
            if text not in found:
                found.append(text)
    return found


def wardray_diagnostics(output):
    """(first error line, features not rendered yet in order of appearance, other warnings) from wardray's output."""
    error, features, warnings = None, [], []
    for line in output.splitlines():
        m = re.search(r"warning: (.*?) is not rendered yet", line)
        if m:
            if m.group(1) not in features:
                features.append(m.group(1))
            continue
        m = re.search(r"warning: (.*)", line)
        if m:
            w = m.group(1).strip()[:200]
            if w not in warnings:
                warnings.append(w)
        elif error is None and re.search(r"\berror\b", line):
            error = re.sub(r"^.*?/(?=[^/]*:\d+:\d+: )", "", line.strip())[:300]
    return error, features, warnings


class Census:
    def __init__(self, wardray, povray, results, examples=EXAMPLES, size=SIZE, timeout=TIMEOUT):
        self.ward, self.pov = wardray, povray
        self.results = pathlib.Path(results)
        self.examples = pathlib.Path(examples)
        self.size, self.timeout = size, timeout
        self.runner = Runner()
        renderers.THREADS = 1  # the commands of tools/compare/renderers.py read this when they are built
        self.ward_digest = wardray.digest()
        for sub in ("povray", "images", "work"):
            (self.results / sub).mkdir(parents=True, exist_ok=True)

    def rel(self, scene):
        return scene.relative_to(self.examples).as_posix()

    @staticmethod
    def slug(rel):
        return re.sub(r"[^A-Za-z0-9_.-]", "_", rel[:-4] if rel.endswith(".pov") else rel)

    def keys(self, scene):
        """(POV-Ray's key, the record's key): hashes of what each render depends on."""
        files = scene_files(scene)
        ini = scene.with_suffix(".ini")
        if ini.is_file():
            files = files + [(ini.name, ini.read_text(errors="replace"))]
        scene_hash = hashlib.sha256(json.dumps(files).encode()).hexdigest()
        common = {"scene": self.rel(scene), "files": scene_hash, "size": list(self.size), "timeout": self.timeout,
                  "threads": 1, "record": RECORD_VERSION}
        pov = hashlib.sha256(json.dumps({**common, "povray": self.pov.version}, sort_keys=True).encode()).hexdigest()
        rec = hashlib.sha256(json.dumps({**common, "povray_key": pov, "wardray": self.ward_digest},
                                        sort_keys=True).encode()).hexdigest()
        return pov, rec, files

    def povray_render(self, scene, key, fresh):
        """POV-Ray's result for the scene, {status, seconds, error, warnings, ini}, and its image path, cached.

        A scene that fails without the .ini beside it is rendered again through the .ini (its first frame)."""
        meta, image = self.results / "povray" / f"{key}.json", self.results / "povray" / f"{key}.hdr"
        if not fresh and meta.is_file():
            result = json.loads(meta.read_text())
            if result["status"] != "ok" or image.is_file():
                return result, image
        result = self._povray_once(scene, image, None)
        ini = scene.with_suffix(".ini")
        if result["status"] == "error" and ini.is_file():
            first, result = result, self._povray_once(scene, image, read_ini(ini))
            if result["status"] == "ok":
                result["without_ini"] = first["error"]
            else:
                first["error"] += f" (through {ini.name}: {result['error']})"
                result = first
        meta.write_text(json.dumps(result, indent=1))
        return result, image

    def _povray_once(self, scene, image, ini):
        work = scratch_copy(scene, self.results / "work" / (self.slug(self.rel(scene)) + ".povray"))
        cmd = self.pov.command(scene.name, "census.hdr", self.size, scene.parent)
        if ini:
            # The .ini first, so the census's options after it win; one frame of its animation.
            cmd = [cmd[0], ini["file"], *cmd[1:], f"+SF{ini['frame']}", f"+EF{ini['frame']}"]
        r = self.runner.run(cmd, work, self.timeout)
        output = r["stdout"] + r["stderr"]
        # An animation frame is written as census<frame number>.hdr.
        written = sorted(work.glob("census*.hdr"))
        if written and not (work / "census.hdr").exists():
            written[0].rename(work / "census.hdr")
        result = {"seconds": r["seconds"], "warnings": povray_warnings(output), "command": cmd, "ini": ini}
        if r["timed_out"]:
            result.update(status="timeout", error=f"timed out after {self.timeout} s")
        elif r["rc"] != 0 or not (work / "census.hdr").is_file():
            result.update(status="error", error=povray_error(output) or
                          f"{exit_text(r['rc'])}{'' if r['rc'] else ', no image'}")
        else:
            result["status"] = "ok"
            shutil.move(str(work / "census.hdr"), image)
        shutil.rmtree(work, ignore_errors=True)
        return result

    def wardray_command(self, scene_name, output, declares=()):
        w, h = self.size
        return [str(self.ward.exe), f"+I{scene_name}", f"+O{output}", "+FH", f"+W{w}", f"+H{h}", "-A", "-D",
                f"+WT{renderers.THREADS}", *(f"Declare={d}" for d in declares)]

    def wardray_render(self, scene, image, ini):
        work = scratch_copy(scene, self.results / "work" / (self.slug(self.rel(scene)) + ".wardray"))
        cmd = self.wardray_command(scene.name, "census.hdr", ini["declares"] if ini else ())
        r = self.runner.run(cmd, work, self.timeout)
        error, features, warnings = wardray_diagnostics(r["stdout"] + "\n" + r["stderr"])
        result = {"exit": r["rc"], "seconds": r["seconds"], "features": features, "warnings": warnings[:20],
                  "error": error, "command": cmd}
        if r["timed_out"]:
            result.update(status="timeout", error=f"timed out after {self.timeout} s")
        elif r["rc"] != 0:
            result.update(status="error", error=error or exit_text(r["rc"]))
        elif not (work / "census.hdr").is_file():
            result.update(status="error", error="exit status 0 but no image written")
        else:
            result["status"] = "ok"
            shutil.move(str(work / "census.hdr"), image)
        shutil.rmtree(work, ignore_errors=True)
        return result

    def measure(self, scene, fresh=False):
        """Renders one scene with both programs and compares: the record that goes into results.jsonl."""
        pov_key, key, files = self.keys(scene)
        rel = self.rel(scene)
        texts = [t for _, t in files]
        gammas, version = gamma_facts(files[0][1], texts)
        rec = {"scene": rel, "key": key, "record": RECORD_VERSION, "stochastic": stochastic_features(texts),
               "assumed_gamma": gammas, "version": version,
               "measured": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")}
        images = self.results / "images" / self.slug(rel)
        images.mkdir(parents=True, exist_ok=True)
        for old in images.iterdir():
            old.unlink()
        rec["povray"], pov_image = self.povray_render(scene, pov_key, fresh)
        rec["ini"] = rec["povray"].get("ini")  # the .ini POV-Ray needed, or None
        rec["wardray"] = self.wardray_render(scene, images / "wardray.hdr", rec["ini"])
        rec["metrics"] = None
        ref = img = None
        if rec["povray"]["status"] == "ok":
            ref = gimetrics.read_linear_rgb(pov_image)
            write_png(images / "povray.png", srgb8(ref))
        if rec["wardray"]["status"] == "ok":
            img = gimetrics.read_linear_rgb(images / "wardray.hdr")
            write_png(images / "wardray.png", srgb8(img))
            if ref is not None and img.shape != ref.shape:
                rec["wardray"].update(status="error", error=f"image is {img.shape[1]}x{img.shape[0]}, "
                                                            f"POV-Ray's {ref.shape[1]}x{ref.shape[0]}")
        if ref is not None and rec["wardray"]["status"] == "ok":
            rec["metrics"] = compare(img, ref)
            write_png(images / "diff.png", difference8(img, ref))
        rec["category"], rec["reason"] = classify(rec)
        return rec


def compare(img, ref):
    """METRICS.md's figures of wardray's image against POV-Ray's, with each image's non-finite pixels."""
    m = gimetrics.image_error(img, ref)
    finite = np.isfinite(img).all(axis=2) & np.isfinite(ref).all(axis=2)
    if not np.isfinite(m["rrmse"]) and np.array_equal(img[finite], ref[finite]):
        m["rrmse"] = 0.0  # both black
    return {"rrmse": m["rrmse"], "bad": m["bad_fraction"], "non_finite": m["non_finite"],
            "non_finite_wardray": int((~np.isfinite(img).all(axis=2)).sum()),
            "non_finite_povray": int((~np.isfinite(ref).all(axis=2)).sum())}


# ---------------------------------------------------------------------------------------------------------------
# Thumbnails.


def srgb8(rgb):
    """Linear radiance to 8-bit sRGB, clipped at 1 (non-finite pixels magenta)."""
    x = np.nan_to_num(rgb, nan=0.0, posinf=1.0, neginf=0.0).clip(0.0, 1.0)
    x = np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)
    out = (x * 255 + 0.5).astype(np.uint8)
    out[~np.isfinite(rgb).all(axis=2)] = (255, 0, 255)
    return out


def difference8(img, ref):
    """The difference as METRICS.md sees it: grey up to half brightness as |dY| approaches the bad-pixel threshold,
    red for bad pixels (brighter the larger |dY| against the mean luminance), magenta for non-finite pixels."""
    finite = np.isfinite(img).all(axis=2) & np.isfinite(ref).all(axis=2)
    y_img = gimetrics.luminance(np.where(finite[..., None], img, 0.0))
    y_ref = gimetrics.luminance(np.where(finite[..., None], ref, 0.0))
    mean = max(float(y_ref[finite].mean()) if finite.any() else 0.0, 1e-12)
    dy = np.abs(y_img - y_ref)
    threshold = 0.1 * y_ref + 0.01 * mean
    bad = dy > threshold
    grey = 0.5 * np.clip(dy / np.maximum(threshold, 1e-12), 0.0, 1.0)
    red = 0.5 + 0.5 * np.clip(dy / mean, 0.0, 1.0)
    out = np.stack([np.where(bad, red, grey), np.where(bad, 0.0, grey), np.where(bad, 0.0, grey)], axis=2)
    out = (out * 255 + 0.5).astype(np.uint8)
    out[~finite] = (255, 0, 255)
    return out


def write_png(path, pixels):
    import OpenImageIO as oiio

    h, w = pixels.shape[:2]
    out = oiio.ImageOutput.create(str(path))
    if out is None or not out.open(str(path), oiio.ImageSpec(w, h, 3, oiio.UINT8)):
        raise RuntimeError(f"cannot write {path}: {oiio.geterror()}")
    out.write_image(np.ascontiguousarray(pixels))
    out.close()


# ---------------------------------------------------------------------------------------------------------------
# The cache of results.

def load_jsonl(path):
    out = []
    if path.is_file():
        for line in path.read_text(errors="replace").splitlines():
            try:
                out.append(json.loads(line))
            except json.JSONDecodeError:
                continue
    return out


def load_results(path):
    """{scene: record} from results.jsonl, the last line of a scene winning; broken lines (an interrupt) skipped."""
    records = {}
    if path.is_file():
        for line in path.read_text(errors="replace").splitlines():
            try:
                rec = json.loads(line)
                records[rec["scene"]] = rec
            except (json.JSONDecodeError, KeyError, TypeError):
                continue
    return records


# ---------------------------------------------------------------------------------------------------------------
# The report and the contact sheet.

def pct(x, digits=2):
    if x is None:
        return ""
    if isinstance(x, float) and math.isinf(x):
        return "inf"
    return f"{100 * x:.{digits}f} %"


def secs(x):
    return "" if x is None else f"{x:.2f}"


def cell(text):
    return str(text).replace("|", "\\|").replace("\n", " ")


def severity(rec):
    """Sort key, worst first: compared scenes by rRMSE (non-finite first), then blocked, then POV-Ray failures."""
    if rec["category"] == "povray-fails":
        return (2, 0.0, rec["scene"])
    if rec["metrics"] is None:
        return (1, 0.0, rec["scene"])
    m = rec["metrics"]
    r = m["rrmse"] if not math.isnan(m["rrmse"]) else math.inf
    return (0, -(math.inf if m["non_finite_wardray"] else r), rec["scene"])


def parse_status(rec):
    w = rec["wardray"]
    if w["status"] == "ok":
        return "ok"
    if w["status"] == "timeout":
        return "timeout"
    return "fails" if w.get("exit") == 1 else exit_text(w.get("exit"))


def stochastic_cell(rec):
    if not rec.get("stochastic"):
        return ""
    return f"{', '.join(rec['stochastic'])} (tol. {pct(STOCHASTIC_RRMSE, 0)})"


CAUSE_GROUPS = ("gamma: assumed_gamma ≠ 1",
                "gamma: #version < 3.7 and no assumed_gamma (POV-Ray's gamma handling off)",
                "#version < 3.7 with assumed_gamma 1 (pre-3.7 semantics, not gamma)",
                "other: #version 3.7 (or none) and assumed_gamma 1")


def cause_group(rec):
    h = hints(rec)
    if any(x.startswith("assumed_gamma") for x in h):
        return CAUSE_GROUPS[0]
    if any(x.startswith("#version") and x.endswith("no assumed_gamma") for x in h):
        return CAUSE_GROUPS[1]
    if any(x.startswith("#version") for x in h):
        return CAUSE_GROUPS[2]
    return CAUSE_GROUPS[3]


def totals(records):
    counts = {c: 0 for c in CATEGORIES}
    for rec in records:
        counts[rec["category"]] += 1
    return counts


def headline_numbers(records):
    """(scenes that render with no not-rendered warning, how many of them match)."""
    clean = [r for r in records if r["povray"]["status"] == "ok" and r["wardray"]["status"] == "ok"
             and not r["wardray"]["features"]]
    return len(clean), sum(r["category"] == "match" for r in clean)


def write_report(path, records, missing, info):
    records = sorted(records, key=lambda r: r["scene"])
    counts = totals(records)
    stochastic = [r for r in records if r.get("stochastic")]
    clean, clean_match = headline_numbers(records)
    lines = [
        "# Render census: POV-Ray's example scenes, POV-Ray 3.7 against wardray",
        "",
        f"Produced by `{info['command']}` on {info['date']}. {info['runtime']}",
        "",
        f"- wardray: {info['commit']}, binary `{info['wardray']}` (sha256 {info['digest'][:12]}).",
        f"- POV-Ray: {info['povray']}.",
        f"- Scenes: the {info['total']} `.pov` files under `{info['examples']}` (Debian's povray-examples).",
        f"- Each scene rendered by both programs at {SIZE[0]}x{SIZE[1]}, `-A`, linear HDR (`+FH`), one thread each "
        f"(`+WT1`), {info['jobs']} scenes at a time, each program bounded at {TIMEOUT} s, in a scratch copy of the "
        "scene's folder. Scenes with an `.ini` beside them are rendered without it (one frame, clock 0, "
        "frame_number 0) by both; where POV-Ray fails that way (the portfolio), it renders the .ini's first frame "
        "(`scene.ini +SF<n> +EF<n>`, the census's options after it), and wardray, which reads no .ini and has no "
        "animation options, gets only the .ini's `Declare=` values; such scenes carry a note.",
        "- Compared as ../shared/docs/METRICS.md says, POV-Ray's image the reference: rRMSE, bad-pixel fraction, "
        "non-finite pixels.",
        f"- Categories: **match** rRMSE ≤ {pct(MATCH_RRMSE, 0)} and bad pixels ≤ {pct(MATCH_BAD, 1)}, no "
        "non-finite pixel; **differ-with-warning** not a match and wardray warned that a feature is not rendered "
        f"yet; **differ-silently** no such warning and rRMSE > {pct(SILENT_RRMSE, 0)} or non-finite pixels (the "
        f"worst outcome); **differ-small** no warning, not a match, rRMSE ≤ {pct(SILENT_RRMSE, 0)}; **blocked** "
        "wardray fails to parse or render (or times out); **povray-fails** POV-Ray fails or times out (no "
        "reference).",
        f"- **Stochastic** scenes (a global `radiosity` block, `jitter` in area lights or media, `crand`, found in "
        "the scene text and the files it includes from its folder) are rendered once at their own settings by "
        f"each program; their tolerance is rRMSE ≤ {pct(STOCHASTIC_RRMSE, 0)} for a match and for a silent "
        "difference, and the bad-pixel fraction is reported but not used (noise makes a per-pixel test "
        "meaningless at the scenes' settings). They are not converged renders.",
        "- Times are single whole-process wall-clock runs with two scenes running at once on a shared 2-core "
        "machine: indicative, not a benchmark.",
        "- Reasons are what can be found automatically: the features wardray reports as not rendered yet; for "
        "other differences, hints from the scene text (`assumed_gamma` ≠ 1, `#version` < 3.7, no "
        "`assumed_gamma`: wardray does not apply POV-Ray's gamma model yet). A hint is not a diagnosis.",
        "",
        "## Totals",
        "",
        "| category | scenes |",
        "|---|---:|",
    ]
    for c in CATEGORIES:
        lines.append(f"| {c} | {counts[c]} |")
    lines += [f"| total measured | {len(records)} |"]
    if missing:
        lines += [f"| not measured with this binary | {len(missing)} |"]
    n_stoch_match = sum(r["category"] == "match" for r in stochastic)
    lines += [
        f"| stochastic (included above) | {len(stochastic)} ({n_stoch_match} match) |",
        "",
        f"Of the {clean} scenes that render with no \"not rendered yet\" warning (and POV-Ray renders), "
        f"**{clean_match} match POV-Ray**; {counts['differ-silently']} scenes differ silently.",
        "",
    ]
    if missing:
        lines += ["Not measured with this binary: " + ", ".join(f"`{m}`" for m in missing[:50]) +
                  (" ..." if len(missing) > 50 else ""), ""]

    silent = sorted((r for r in records if r["category"] == "differ-silently"), key=severity)
    lines += ["## Silent differences, worst first", "",
              f"{len(silent)} scenes differ by more than {pct(SILENT_RRMSE, 0)} (stochastic: "
              f"{pct(STOCHASTIC_RRMSE, 0)}) with no \"not rendered yet\" warning.", ""]
    groups = {}
    for r in silent:
        groups.setdefault(cause_group(r), []).append(r["scene"])
    lines += ["By likely cause (from the scene text):", "", "| likely cause | scenes | which |", "|---|---:|---|"]
    for g in CAUSE_GROUPS:
        names = groups.get(g, [])
        shown = ", ".join(f"`{n}`" for n in names) if g not in CAUSE_GROUPS[:2] else ""
        lines.append(f"| {g} | {len(names)} | {shown} |")
    lines.append("")
    lines += ["| scene | rRMSE | bad | stochastic | hints |", "|---|---:|---:|---|---|"]
    for r in silent:
        lines.append(f"| {cell(r['scene'])} | {pct(r['metrics']['rrmse'])} | {pct(r['metrics']['bad'])} | "
                     f"{stochastic_cell(r)} | {cell(r['reason'])} |")
    lines.append("")

    features, alone = {}, {}
    for r in records:
        found = r["wardray"].get("features", [])
        for f in found:
            features[f] = features.get(f, 0) + 1
        if len(found) == 1 and r["category"] == "differ-with-warning":
            alone[found[0]] = alone.get(found[0], 0) + 1
    if features:
        lines += ["## Features not rendered yet, by scenes", "",
                  "\"alone\": scenes that differ with this feature as their only warning (what rendering it could win).",
                  "", "| feature | scenes | alone |", "|---|---:|---:|"]
        for f, n in sorted(features.items(), key=lambda kv: (-kv[1], kv[0])):
            lines.append(f"| {cell(f)} | {n} | {alone.get(f, 0)} |")
        lines.append("")

    lines += ["## Every scene", "",
              "| scene | parse | not rendered | rRMSE | bad | NaN/Inf | POV-Ray s | wardray s | stochastic | "
              "category | reason |",
              "|---|---|---|---:|---:|---:|---:|---:|---|---|---|"]
    for r in records:
        m = r["metrics"] or {}
        nf = "" if not m else str(m["non_finite_wardray"]) if not m["non_finite_povray"] else \
            f"{m['non_finite_wardray']} (POV-Ray {m['non_finite_povray']})"
        reason = r["reason"] if r["category"] != "differ-with-warning" else ""
        lines.append(
            f"| {cell(r['scene'])} | {parse_status(r)} | {cell(', '.join(r['wardray'].get('features', [])))} | "
            f"{pct(m.get('rrmse'))} | {pct(m.get('bad'))} | {nf} | {secs(r['povray'].get('seconds'))} | "
            f"{secs(r['wardray'].get('seconds'))} | {stochastic_cell(r)} | {r['category']} | {cell(reason)} |")
    lines += ["", f"The contact sheet (not committed): `{info['sheet']}`.", ""]
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines))


def write_sheet(path, records, info):
    """index.html beside the images: every scene, POV-Ray | wardray | difference, worst first."""
    colours = {"match": "#2a7", "differ-with-warning": "#c80", "differ-silently": "#d22", "differ-small": "#a6a",
               "blocked": "#666", "povray-fails": "#999"}
    counts = totals(records)
    out = ["<!doctype html><meta charset=utf-8><title>wardray render census</title>",
           "<style>body{font:13px sans-serif;background:#222;color:#ddd} .s{display:inline-block;margin:6px;"
           "padding:6px;background:#333;vertical-align:top;width:760px} img{width:240px;height:180px;"
           "image-rendering:pixelated;background:#000;margin-right:4px} .c{padding:1px 5px;border-radius:3px;"
           "color:#fff} .n{height:180px;width:240px;display:inline-block;background:#111;color:#888;"
           "vertical-align:top;margin-right:4px;text-align:center;line-height:180px}</style>",
           f"<h1>wardray render census</h1><p>{html.escape(info['commit'].replace('`', ''))}, {html.escape(info['date'])}, "
           f"{SIZE[0]}x{SIZE[1]}, -A, +WT1. Left to right: POV-Ray, wardray, difference (grey up to the bad-pixel "
           "threshold, red bad pixels, magenta non-finite). Sorted by rRMSE, worst first; then blocked, then "
           "POV-Ray failures.</p><p>" +
           " ".join(f"<span class=c style='background:{colours[c]}'>{c} {counts[c]}</span>" for c in CATEGORIES)
           + "</p>"]

    def img(rec, name):
        f = path.parent / "images" / Census.slug(rec["scene"]) / name
        if f.is_file():
            return f"<img src='images/{html.escape(Census.slug(rec['scene']))}/{name}' alt='{name}'>"
        return "<span class=n>none</span>"

    for r in sorted(records, key=severity):
        m = r["metrics"] or {}
        figures = (f"rRMSE {pct(m['rrmse'])}, bad {pct(m['bad'])}, NaN/Inf {m['non_finite_wardray']}"
                   if m else "")
        times = (f"POV-Ray {secs(r['povray'].get('seconds'))} s, wardray {secs(r['wardray'].get('seconds'))} s")
        feats = ", ".join(r["wardray"].get("features", []))
        out.append(
            f"<div class=s><b>{html.escape(r['scene'])}</b> <span class=c style='background:"
            f"{colours[r['category']]}'>{r['category']}</span><br>{img(r, 'povray.png')}{img(r, 'wardray.png')}"
            f"{img(r, 'diff.png')}<br>{figures}{'; ' if figures else ''}{times}"
            + (f"<br>stochastic: {html.escape(stochastic_cell(r))}" if r.get("stochastic") else "")
            + (f"<br>not rendered: {html.escape(feats)}" if feats else "")
            + (f"<br>{html.escape(r['reason'])}" if r["reason"] and r["category"] != "differ-with-warning" else "")
            + "</div>")
    path.write_text("\n".join(out) + "\n")


# ---------------------------------------------------------------------------------------------------------------
# Driving.

class CensusProgress(progress.Progress):
    """tools/compare's progress line and estimate, for scenes that finish out of order, `jobs` at a time."""

    def __init__(self, scenes, jobs):
        super().__init__([(s, "census", None) for s in scenes])
        self.jobs = jobs

    def left(self):
        total = super().left()
        return None if total is None else total / self.jobs

    def scene_done(self, scene, seconds, text):
        self.finish((scene, "census", None), seconds)
        line = (f"[{self.done}/{len(self.plan)}] {scene}: {text} | elapsed "
                f"{progress.format_seconds(time.monotonic() - self.start)} | left ~"
                f"{progress.format_seconds(self.left())}")
        if self.tty:
            self.stream.write("\r\x1b[K" + line[:200])
        else:
            self.stream.write(line + "\n")
        self.stream.flush()


def summary(rec):
    m = rec["metrics"]
    figures = f" rRMSE {pct(m['rrmse'])} bad {pct(m['bad'])}" if m else ""
    return f"{rec['category']}{figures}" + (f" ({rec['reason']})" if rec["reason"] else "")


def wardray_commit(exe):
    """The commit of the source tree the binary was built from (CMakeCache.txt beside it), marked when dirty."""
    for folder in (exe.parent, exe.parent.parent):
        cache = folder / "CMakeCache.txt"
        if cache.is_file():
            m = re.search(r"^CMAKE_HOME_DIRECTORY:INTERNAL=(.*)$", cache.read_text(errors="replace"), re.M)
            if not m:
                break
            src = m.group(1).strip()
            try:
                head = subprocess.run(["git", "-C", src, "log", "-1", "--format=%h %s"], capture_output=True,
                                      text=True, check=True).stdout.strip()
                dirty = subprocess.run(["git", "-C", src, "status", "--porcelain", "--untracked-files=no"],
                                       capture_output=True, text=True, check=True).stdout.strip()
            except (OSError, subprocess.CalledProcessError):
                break
            return f"commit {head}" + (" (plus uncommitted changes in the source tree at census time)"
                                       if dirty else "") + f", source `{src}`"
    return "commit unknown (no CMakeCache.txt beside the binary)"


def shown_path(path):
    """A path relative to the checkout when it is inside it."""
    try:
        return str(pathlib.Path(path).resolve().relative_to(ROOT))
    except ValueError:
        return str(path)


def find_scenes(examples, patterns):
    scenes = sorted(examples.rglob("*.pov"), key=lambda p: p.relative_to(examples).as_posix())
    if patterns:
        scenes = [s for s in scenes if any(fnmatch.fnmatch(s.relative_to(examples).as_posix(), p)
                                           for p in patterns)]
    return scenes


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("wardray", help="the wardray binary, e.g. build/wardray")
    ap.add_argument("--povray", default="povray")
    ap.add_argument("--examples", default=str(EXAMPLES), help=f"the example scenes (default {EXAMPLES})")
    ap.add_argument("--results", default=str(ROOT / "build" / "census"), help="cache, images and contact sheet")
    ap.add_argument("--out", default=str(ROOT / "docs" / "reports" / "census.md"))
    ap.add_argument("--jobs", type=int, default=2, help="scenes rendered at once, one thread each (default 2)")
    ap.add_argument("--scenes", action="append", metavar="GLOB",
                    help="only scenes whose path below the examples matches (repeatable), e.g. 'objects/*'")
    ap.add_argument("--fresh", action="store_true", help="redo every chosen scene, POV-Ray's renders too")
    ap.add_argument("--check", nargs="+", metavar="SCENE",
                    help="render these scenes (paths below the examples) with no cache and no report; exit 1 "
                         "when one differs silently, is blocked or POV-Ray fails")
    ap.add_argument("--expect-match", action="store_true", help="with --check: every scene must match")
    args = ap.parse_args()

    examples = pathlib.Path(args.examples)
    ward = renderers.Wardray(args.wardray)
    pov = renderers.PovRay(args.povray)

    if args.check:
        with tempfile.TemporaryDirectory(prefix="census-check-") as tmp:
            census = Census(ward, pov, tmp, examples)
            scenes = [examples / s for s in args.check]
            failed = 0
            with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
                for scene, rec in zip(scenes, pool.map(census.measure, scenes)):
                    bad = rec["category"] in ("differ-silently", "blocked", "povray-fails") or \
                        (args.expect_match and rec["category"] != "match")
                    failed += bad
                    print(f"{'FAIL' if bad else 'ok'}  {rec['scene']}: {summary(rec)}", flush=True)
        sys.exit(1 if failed else 0)

    results = pathlib.Path(args.results)
    results.mkdir(parents=True, exist_ok=True)
    lock = (results / "lock").open("w")  # two runs on one folder would delete each other's scratch folders
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        sys.exit(f"census: another census is running on {results}")
    shutil.rmtree(results / "work", ignore_errors=True)  # scratch folders of renders an interrupt cut short
    census = Census(ward, pov, results, examples)
    jsonl = results / "results.jsonl"  # appended to; a scene's last line wins, so --fresh needs no deletion
    cached = load_results(jsonl)
    all_scenes = find_scenes(examples, None)
    chosen = find_scenes(examples, args.scenes)
    todo = [s for s in chosen if args.fresh or
            cached.get(census.rel(s), {}).get("key") != census.keys(s)[1]]
    print(f"census: {len(chosen)} scenes, {len(chosen) - len(todo)} cached, {len(todo)} to render, "
          f"{args.jobs} at a time", file=sys.stderr, flush=True)

    started = time.monotonic()
    record_lock = threading.Lock()
    bar = CensusProgress([census.rel(s) for s in todo], args.jobs)
    problem = []

    def one(scene):
        if ward.rebuilt():
            problem.append(f"{ward.exe} changed during the census; re-run to measure the new binary")
            census.runner.interrupt()
        t0 = time.monotonic()
        try:
            rec = census.measure(scene, fresh=args.fresh)
        except Interrupted:
            return None
        with record_lock:
            if census.runner.stop.is_set():
                return None
            with jsonl.open("a") as f:
                f.write(json.dumps(rec) + "\n")
            bar.scene_done(rec["scene"], time.monotonic() - t0, summary(rec))
        return rec

    pool = concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs)
    futures = [pool.submit(one, s) for s in todo]
    try:
        for fut in concurrent.futures.as_completed(futures):
            fut.result()
    except KeyboardInterrupt:
        problem.append("interrupted; finished scenes are kept, re-run to resume")
        census.runner.interrupt()
    except BaseException:
        census.runner.interrupt()
        raise
    finally:
        pool.shutdown(wait=True, cancel_futures=True)
    interrupted = bool(problem)
    if bar.tty:
        sys.stderr.write("\n")
    for p in problem[:1]:
        print(f"census: {p}", file=sys.stderr)
    elapsed = time.monotonic() - started
    if bar.tty:
        sys.stderr.write("\n")

    cached = load_results(jsonl)
    current, missing = [], []
    for s in all_scenes:
        rec = cached.get(census.rel(s))
        if rec and rec.get("key") == census.keys(s)[1]:
            current.append(rec)
        else:
            missing.append(census.rel(s))
    for rec in current:
        rec["category"], rec["reason"] = classify(rec)  # the stored category may predate a change of the rules
    with (results / "runs.jsonl").open("a") as f:
        f.write(json.dumps({"date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
                            "argv": sys.argv, "wardray": census.ward_digest, "jobs": args.jobs,
                            "rendered": bar.done, "seconds": elapsed,
                            "interrupted": interrupted}) + "\n")
    shown = shown_path(args.wardray)
    full = [r for r in load_jsonl(results / "runs.jsonl") if r.get("rendered") == len(all_scenes)
            and not r.get("interrupted") and r.get("wardray") == census.ward_digest]
    runtime = (f"The last run that rendered all {len(all_scenes)} scenes with this binary (finished "
               f"{full[-1]['date'][:16].replace('T', ' ')} UTC) took {progress.format_seconds(full[-1]['seconds'])} of wall time." if full else "")
    info = {"runtime": runtime, "command": shlex.join(["tools/census.py", *sys.argv[1:]]),
            "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
            "commit": wardray_commit(ward.exe), "wardray": str(shown), "digest": census.ward_digest,
            "povray": pov.version, "examples": str(examples), "total": len(all_scenes), "jobs": args.jobs,
            "sheet": shown_path(results / "index.html")}
    write_report(pathlib.Path(args.out), current, missing, info)
    write_sheet(results / "index.html", current, info)
    counts = totals(current)
    print(f"census: {bar.done} scenes rendered in {progress.format_seconds(elapsed)}; "
          + ", ".join(f"{c} {counts[c]}" for c in CATEGORIES)
          + (f", not measured {len(missing)}" if missing else "")
          + f"\ncensus: wrote {args.out} and {results / 'index.html'}", file=sys.stderr)
    sys.exit(130 if interrupted else 0)


if __name__ == "__main__":
    main()
