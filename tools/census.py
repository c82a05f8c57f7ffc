#!/usr/bin/python3
"""The render census: every POV-Ray example scene rendered by POV-Ray 3.7 and wardray, compared, and reported.

    tools/census.py build/wardray                     # all 396 scenes; writes docs/reports/census.md
    tools/census.py build/wardray --scenes 'objects/*' # only these (the report still lists every scene)
    tools/census.py build/wardray --fresh              # forget the cached results and redo everything
    tools/census.py build/wardray --check objects/blob.pov ... --expect-match   # the CTest mode
    tools/census.py build/wardray --corpus /work/wild --manifest /work/wild/MANIFEST.tsv --report docs/reports/wild.md
                                                      # another corpus (issue 23's scenes from the wild)

Each scene is rendered by both programs at 120x90, `-A`, linear Radiance HDR (`+FH`), one thread each (`+WT1`),
each bounded at 60 s, in a scratch copy of the scene's folder (POV-Ray writes only below its current folder, and
scenes read the data files beside them). The two images are compared as docs/metrics.md says (rRMSE,
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
way (the portfolio scenes index arrays by frame_number), both programs render the .ini's first frame instead, the
same way (`scene.ini +SF<n> +EF<n>` before the census's own options, which win), and the scene carries a note
saying so.

With `--corpus ROOT --manifest MANIFEST.tsv`, the scenes are the manifest's rows instead (`path` below ROOT, whose
first folder is the scene's repository, `repository`, `commit`), with their own results folder (default
`build/census-<corpus name>/`) and report. Scenes are named by a neutral id, `r<NN>/<path in its repository>`
(repositories numbered in the manifest's order), never by anything copied from them. Each render runs in a scratch
copy of the scene's whole repository under /tmp (POV-Ray's povray.conf permits reads below /tmp and the current
folder only), in the scene's folder, and is measured with /usr/bin/time (wall time, peak memory) and each program's
own parse time (POV-Ray's statistics, wardray's `--stats`); wardray's address space is bounded (`--memory-limit`)
so that a runaway parse cannot exhaust the machine. The report adds why scenes do not parse (the failures grouped
by the construct that fails), the silent differences grouped by their hints, and the scenes where wardray takes
more than twice POV-Ray's parse time or peak memory.
"""
import argparse
import concurrent.futures
import csv
import datetime
import fcntl
import fnmatch
import hashlib
import html
import json
import math
import os
import pathlib
import posixpath
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
from povrewrite import RewriteError, find_blocks, mask_comments_and_strings, rewrite_radiosity  # noqa: E402

import census_stability as stability  # noqa: E402

EXAMPLES = pathlib.Path("/usr/share/povray-3.7/scenes")
SIZE = (120, 90)
TIMEOUT = 60  # seconds, each renderer
# docs/metrics.md: a match is rRMSE <= 1 % and bad pixels <= 0.5 %; issue 13: more than 2 % with no warning is silent.
MATCH_RRMSE, MATCH_BAD, SILENT_RRMSE = 0.01, 0.005, 0.02
# Stochastic scenes (radiosity, jitter, crand) are compared at their own settings, one render each: the tolerance.
STOCHASTIC_RRMSE = 0.05
# A stochastic scene that does not match at its own settings is rendered again converged by both programs
# (docs/metrics.md): POV-Ray's converged radiosity settings in its global radiosity blocks, and every pixel
# supersampled 6x6 without jitter (crand, jittered area lights and media average over the 36 samples).
CONVERGED_RADIOSITY = {"count": 1600, "error_bound": 0.1, "pretrace_end": 0.01, "nearest_count": 20}
CONVERGED_AA = ("+A0.0", "+R6", "-J")
# Focal blur converges with many samples through the lens, not with supersampling: every `blur_samples` of the
# scene's folder is rewritten to this many, as both minimum and maximum (so confidence and variance no longer stop
# early). wardray's own noise at 4000 is about 0.5 % rRMSE on advanced/chess2.pov (two seeds).
CONVERGED_BLUR_SAMPLES = 4000
CONVERGED_TIMEOUT = 900  # seconds, each renderer
CATEGORIES = ("match", "differ-with-warning", "differ-silently", "differ-small", "blocked", "povray-fails")
# Bumped when what is stored per scene changes, so old cache lines are not reused.
RECORD_VERSION = 3


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

    Both programs render that one frame through the .ini (the portfolio scenes index arrays by frame_number and
    fail without it); the declarations are kept for the record."""
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
    return f"both rendered frame {ini['frame']} of {ini['file']} (clock {ini['clock']:g}) through the .ini"


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


def parsed_randomness_words(check_output):
    """stochastic_features' words for the `randomness:` line of `wardray --check`, and "focal blur"."""
    m = re.search(r"^randomness: (.*)$", check_output, re.M)
    if not m:
        return []
    words = {"radiosity": "radiosity", "area light jitter": "jitter", "crand": "crand", "focal blur": "focal blur"}
    return [words[w] for w in m.group(1).split(", ") if w in words]


def has_global_radiosity(text):
    """Whether the text has a radiosity block (other than `importance` alone) inside a global_settings block."""
    m = masked(text)
    try:
        for g_open, g_close in find_blocks(m, "global_settings"):
            for open_at, close_at in find_blocks(m, "radiosity", g_open + 1, g_close):
                if re.sub(r"\bimportance\b\s*[\d.]*", "", m[open_at + 1:close_at]).strip():
                    return True
    except RewriteError:
        return False
    return False


def needs_supersampling(stochastic):
    """Whether a scene's randomness is per sample (crand, jitter), which supersampling averages away; radiosity's
    is in its cache, which the converged radiosity settings take care of, and focal blur's in its lens samples."""
    return any(f not in ("radiosity", "focal blur") for f in stochastic)


BLUR_SAMPLES = re.compile(r"\bblur_samples\s+[0-9.]+(\s*,\s*[0-9.]+)?")


def converged_blur(text):
    """The text with every literal `blur_samples N[, M]` set to CONVERGED_BLUR_SAMPLES as minimum and maximum."""
    n = CONVERGED_BLUR_SAMPLES
    return BLUR_SAMPLES.sub(f"blur_samples {n}, {n} /* converged by tools/census.py */", text)


def converged_options(cmd, stochastic):
    """A render command with `-A` replaced by the converged supersampling where the scene needs it."""
    if not needs_supersampling(stochastic):
        return list(cmd)
    return [x for a in cmd for x in (CONVERGED_AA if a == "-A" else (a,))]


def converged_copy(files, work, stochastic=("radiosity",)):
    """Rewrites, in the scratch folder `work`, the global radiosity blocks of the scene's files (those directly in
    the folder; subfolders are links to the originals) with CONVERGED_RADIOSITY, and with focal blur their
    `blur_samples` (converged_blur). The names of the files rewritten."""
    done = []
    for name, text in files:
        if "/" in name:
            continue
        new = text
        if "radiosity" in stochastic and has_global_radiosity(text):
            new, _ = rewrite_radiosity(new, CONVERGED_RADIOSITY, marker="converged by tools/census.py")
        if "focal blur" in stochastic:
            new = converged_blur(new)
        if new != text:
            (work / name).unlink(missing_ok=True)  # never write through a link into the original
            (work / name).write_text(new)
            done.append(name)
    return done


def converged_label(stochastic):
    parts = []
    if "radiosity" in stochastic:
        parts.append(" ".join(f"{k} {v}" for k, v in CONVERGED_RADIOSITY.items()))
    if needs_supersampling(stochastic):
        parts.append(" ".join(CONVERGED_AA))
    if "focal blur" in stochastic:
        parts.append(f"blur_samples {CONVERGED_BLUR_SAMPLES}, {CONVERGED_BLUR_SAMPLES}")
    return ", ".join(parts)


def gamma_facts(scene_text, texts):
    """(assumed_gamma values as written, the scene's first #version or None)."""
    gammas = []
    for text in texts:
        for g in re.findall(r"(?<![A-Za-z0-9_])assumed_gamma\s+([^\s}]+)", masked(text)):
            if g not in gammas:
                gammas.append(g)
    v = re.search(r"#\s*version\s+([0-9.]+)", masked(scene_text))
    return gammas, (v.group(1) if v else None)


def known_reasons(path=None):
    """Scene -> the reason it differs, from tools/census_reasons.tsv (found by looking and measuring)."""
    path = path or pathlib.Path(__file__).resolve().parent / "census_reasons.tsv"
    out = {}
    if path.exists():
        for line in path.read_text().splitlines():
            if line.strip() and not line.startswith("#") and "\t" in line:
                scene, reason = line.split("\t", 1)
                out[scene.strip()] = reason.strip()
    return out


KNOWN_REASONS = known_reasons()


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
    m, stochastic = rec["metrics"], rec.get("stochastic")
    conv, conv_note = rec.get("converged"), ""
    match_rrmse, match_bad, silent_rrmse = tolerance(stochastic)
    if conv and conv.get("kind") == "unstable" and conv.get("metrics"):
        # Unstable at one sample a pixel: supersampled against supersampled, within POV-Ray's own movement.
        m, stochastic = conv["metrics"], None
        match_rrmse, match_bad = stability.supersampled_tolerance(conv.get("floor"), MATCH_RRMSE, MATCH_BAD)
        silent_rrmse = max(SILENT_RRMSE, match_rrmse)
        conv_note = unstable_note(rec)
    elif conv and conv.get("kind") == "unstable":
        conv_note = unstable_note(rec)
    elif conv and conv.get("metrics"):
        # Converged against converged: the deterministic tolerances apply.
        m, stochastic = conv["metrics"], None
        conv_note = (f"converged ({conv['settings']}): rRMSE {pct(m['rrmse'])}, bad {pct(m['bad'])}; at the "
                     f"scene's own settings {pct(rec['metrics']['rrmse'])}")
        match_rrmse, match_bad, silent_rrmse = tolerance(stochastic)
    elif conv:
        conv_note = f"no converged comparison: {conv.get('error')}"
    elif rec.get("stability") and rec["stability"].get("error"):
        conv_note = f"instability not measured: {rec['stability']['error']}"
    elif rec.get("stability"):
        moved = rec["stability"]["moved"]
        conv_note = (f"stable at one sample a pixel: POV-Ray's own image moves by {pct(moved['rrmse'])} rRMSE "
                     f"(bad {pct(moved['bad'])}) with its {stability.turn_label()}")
    finite = m["non_finite_wardray"] == 0 and m["non_finite"] == 0
    if finite and m["rrmse"] <= match_rrmse and (match_bad is None or m["bad"] <= match_bad):
        return "match", conv_note
    features = ward.get("features", [])
    if features:
        return "differ-with-warning", "not rendered: " + ", ".join(features)
    reason = "; ".join(hints(rec)) or "no hint in the scene text"
    if rec.get("scene") in KNOWN_REASONS:
        reason = "known: " + KNOWN_REASONS[rec["scene"]] + "; " + reason
    if conv_note:
        reason = conv_note + "; " + reason
    # Warned that the picture may differ (surfaces on one another): not silent, whatever the cause; the reason
    # still says what was measured.
    if ward.get("cautions"):
        return "differ-with-warning", "warned: " + ", ".join(ward["cautions"]) + "; " + reason
    if not finite or m["rrmse"] > silent_rrmse:
        return "differ-silently", reason
    return "differ-small", reason


def unstable_note(rec):
    """What the reason says of a scene found unstable at one sample a pixel."""
    conv, st = rec["converged"], rec["stability"]
    head = (f"unstable at one sample a pixel: POV-Ray's own image moves by {pct(st['moved']['rrmse'])} rRMSE "
            f"(bad {pct(st['moved']['bad'])}) with its {stability.turn_label()}")
    if not conv.get("metrics"):
        return f"{head}; no supersampled comparison: {conv.get('error')}"
    m, floor = conv["metrics"], conv.get("floor")
    text = (f"{head}; supersampled ({conv['settings']}): rRMSE {pct(m['rrmse'])}, bad {pct(m['bad'])}")
    if floor:
        text += f", POV-Ray's own supersampled movement {pct(floor['rrmse'])} (bad {pct(floor['bad'])})"
    return text + f"; at one sample a pixel {pct(rec['metrics']['rrmse'])}"


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


# wardray's warnings of a tie that rounding decides (POV-Ray's random speckle), and the caution each counts as.
TIE_WARNINGS = (("coincident surfaces:", "coincident surfaces"), ("pattern wrap on a surface:", "pattern wrap"),
                ("the objects this scene builds from trace() change", "trace() rounding"))


def wardray_cautions(output):
    """What wardray warned may make its picture differ from POV-Ray's although it renders everything the scene
    says: "coincident surfaces" when it found surfaces lying on one another, "pattern wrap" when a texture jumps
    exactly on a surface (both POV-Ray's random speckle), "trace() rounding" when the objects the scene builds from
    parse-time trace() calls change with the last bits of their results, in that order."""
    return [caution for text, caution in TIE_WARNINGS if re.search(r"warning: " + re.escape(text), output)]


def read_time_file(path):
    """{wall, peak_kb[, signal]} from `/usr/bin/time -f '%e %M' -o path`; {} when it wrote nothing (killed)."""
    out = {}
    try:
        lines = path.read_text(errors="replace").splitlines()
    except OSError:
        return out
    for line in lines:
        m = re.match(r"Command terminated by signal (\d+)", line)
        if m:
            out["signal"] = int(m.group(1))
        m = re.fullmatch(r"\s*([\d.]+) (\d+)\s*", line)
        if m:
            out.update(wall=float(m.group(1)), peak_kb=int(m.group(2)))
    return out


def povray_parse_seconds(output):
    """POV-Ray's own parse time from its statistics ("Parse Time: ... (0.123 seconds)"), or None."""
    m = re.search(r"Parse Time:.*\(\s*([\d.]+) seconds\)", output)
    return float(m.group(1)) if m else None


def wardray_parse_seconds(stats_path):
    try:
        return float(json.loads(stats_path.read_text())["phases"]["parse"])
    except (OSError, ValueError, KeyError, TypeError):
        return None


POVRAY_INCLUDE = pathlib.Path("/usr/share/povray-3.7/include")


def error_location(output, repo, cwd):
    """{file, line, col, message} of wardray's first error, the file relative to the repository copy `repo`
    (`<povray include>/x.inc` for POV-Ray's library), or None."""
    for line in output.splitlines():
        m = re.match(r"^(.*?):(\d+):(\d+): error: (.*)$", line.strip())
        if not m:
            continue
        file = pathlib.Path(m.group(1))
        full = pathlib.Path(os.path.normpath(file if file.is_absolute() else pathlib.Path(cwd) / file))
        for base, prefix in ((pathlib.Path(repo), ""), (POVRAY_INCLUDE, "<povray include>/")):
            try:
                shown = prefix + full.relative_to(base).as_posix()
                break
            except ValueError:
                continue
        else:
            shown = file.name
        return {"file": shown, "line": int(m.group(2)), "col": int(m.group(3)), "message": m.group(4).strip()}
    return None


class Manifest:
    """A corpus of scenes listed in a manifest (issue 23's scenes from the wild), as the census sees it.

    MANIFEST.tsv has a header line and tab-separated columns, at least `path` (below the corpus root; its first
    folder holds the scene's repository) and `repository` (owner/name); `commit` and the rest are kept as given.
    A scene's neutral id is `r<NN>/<path in the repository>`, the repositories numbered from 01 in the order they
    first appear in the manifest."""

    def __init__(self, root, manifest):
        self.root = pathlib.Path(root).resolve()
        self.manifest = pathlib.Path(manifest)
        with self.manifest.open(newline="", errors="replace") as f:
            self.rows = [r for r in csv.DictReader(f, delimiter="\t") if r.get("path")]
        self.repos = {}  # repository folder below the root -> rNN
        self.by_path = {}
        for row in self.rows:
            folder = row["path"].split("/", 1)[0]
            self.repos.setdefault(folder, f"r{len(self.repos) + 1:02d}")
            self.by_path[row["path"]] = row
        self.digits = max(2, len(str(len(self.repos))))

    def scenes(self):
        return [self.root / r["path"] for r in self.rows]

    def path(self, scene):
        """The scene's path below the corpus root, as the manifest writes it."""
        return pathlib.Path(scene).resolve().relative_to(self.root).as_posix()

    def repo_folder(self, scene):
        return self.root / self.path(scene).split("/", 1)[0]

    def neutral(self, corpus_path):
        """`a+b/sub/x.pov` -> `r07/sub/x.pov`."""
        folder, _, rest = corpus_path.partition("/")
        return f"{self.repos.get(folder, folder)}/{rest}"

    def rel(self, scene):
        return self.neutral(self.path(scene))

    def row(self, scene):
        return self.by_path.get(self.path(scene), {})


class Census:
    def __init__(self, wardray, povray, results, examples=EXAMPLES, size=SIZE, timeout=TIMEOUT, corpus=None,
                 work_root=None, memory_limit=None, converge=True):
        """`corpus`: a Manifest, or None for the example scenes below `examples`. With a corpus, renders run in
        copies of the scene's repository below `work_root` and are timed (wall, peak memory, parse time), and
        wardray's address space is bounded at `memory_limit` bytes (None: unbounded)."""
        self.ward, self.pov = wardray, povray
        self.results = pathlib.Path(results)
        self.examples = pathlib.Path(examples)
        self.size, self.timeout = size, timeout
        self.corpus = corpus
        self.timed = corpus is not None
        self.memory_limit = memory_limit
        self.converge = converge  # stochastic scenes that differ at their settings are compared converged too
        self.work_root = pathlib.Path(work_root) if work_root else self.results / "work"
        self.runner = Runner()
        renderers.THREADS = 1  # the commands of tools/compare/renderers.py read this when they are built
        self.ward_digest = wardray.digest()
        for sub in ("povray", "images"):
            (self.results / sub).mkdir(parents=True, exist_ok=True)
        self.work_root.mkdir(parents=True, exist_ok=True)

    def rel(self, scene):
        if self.corpus:
            return self.corpus.rel(scene)
        return scene.relative_to(self.examples).as_posix()

    def scratch(self, scene, suffix):
        """(the scratch folder to delete afterwards, the folder to render in) for one render of the scene."""
        work = self.work_root / (self.slug(self.rel(scene)) + suffix)
        if not self.corpus:
            return work, scratch_copy(scene, work)
        if work.exists():
            shutil.rmtree(work)
        work.mkdir(parents=True)
        repo = self.corpus.repo_folder(scene)
        shutil.copytree(repo, work / "repo", symlinks=True)
        return work, work / "repo" / scene.resolve().parent.relative_to(repo.resolve())

    def timed_command(self, cmd, work):
        """The command run under /usr/bin/time (wall seconds, peak resident kilobytes to work/time.txt), and for
        wardray in a bounded address space."""
        if not self.timed:
            return cmd
        if self.memory_limit and cmd[0] == str(self.ward.exe):
            cmd = ["prlimit", f"--as={int(self.memory_limit)}", "--", *cmd]
        return ["/usr/bin/time", "-o", str(work / "time.txt"), "-f", "%e %M", *cmd]

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
        if self.corpus:
            common.update(corpus=self.corpus.row(scene).get("commit"), timed=True)
        pov = hashlib.sha256(json.dumps({**common, "povray": self.pov.version}, sort_keys=True).encode()).hexdigest()
        extra = {"memory_limit": self.memory_limit} if self.corpus else {}
        if self.converge:
            extra["converged"] = [CONVERGED_RADIOSITY, CONVERGED_AA, CONVERGED_TIMEOUT]
            extra["stability"] = [stability.CAMERA_TURN, stability.SUPERSAMPLED_AA]
        rec = hashlib.sha256(json.dumps({**common, **extra, "povray_key": pov, "wardray": self.ward_digest},
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

    def povray_converged(self, scene, key, ini, stochastic, fresh):
        """POV-Ray's converged render of a stochastic scene (see CONVERGED_RADIOSITY), cached like the others."""
        tag = hashlib.sha256(json.dumps([CONVERGED_RADIOSITY, CONVERGED_AA, CONVERGED_TIMEOUT]).encode()
                             ).hexdigest()[:8]
        if "focal blur" in stochastic:
            tag += f"-blur{CONVERGED_BLUR_SAMPLES}"
        return self.povray_variant(scene, f"{key}-converged-{tag}", ini, fresh, converged=stochastic)

    def povray_variant(self, scene, name, ini, fresh, **how):
        """POV-Ray's render `name` of the scene, made by _povray_once(**how), cached like the others."""
        meta = self.results / "povray" / f"{name}.json"
        image = meta.with_suffix(".hdr")
        if not fresh and meta.is_file():
            result = json.loads(meta.read_text())
            if result["status"] != "ok" or image.is_file():
                return result, image
        result = self._povray_once(scene, image, ini, **how)
        meta.write_text(json.dumps(result, indent=1))
        return result, image

    def _povray_once(self, scene, image, ini, converged=(), perturbed=False, supersampled=False):
        """`converged`: the scene's stochastic features, to render it converged (see CONVERGED_RADIOSITY);
        `perturbed`: with its cameras turned (census_stability); `supersampled`: with SUPERSAMPLED_AA."""
        root, work = self.scratch(scene, ".povray")
        # In a corpus, the copy of the scene's folder: POV-Ray may not read the original.
        cmd = self.pov.command(scene.name, "census.hdr", self.size, work if self.corpus else scene.parent)
        if ini:
            # The .ini first, so the census's options after it win; one frame of its animation.
            cmd = [cmd[0], ini["file"], *cmd[1:], f"+SF{ini['frame']}", f"+EF{ini['frame']}"]
        timeout = self.timeout
        if converged:
            converged_copy(scene_files(scene), work, converged)
            cmd, timeout = converged_options(cmd, converged), CONVERGED_TIMEOUT
        if perturbed:
            stability.perturbed_copy(scene_files(scene), work)
        if supersampled:
            cmd, timeout = stability.supersampled_options(cmd), CONVERGED_TIMEOUT
        r = self.runner.run(self.timed_command(cmd, root), work, timeout)
        output = r["stdout"] + r["stderr"]
        # An animation frame is written as census<frame number>.hdr.
        written = sorted(work.glob("census*.hdr"))
        if written and not (work / "census.hdr").exists():
            written[0].rename(work / "census.hdr")
        result = {"seconds": r["seconds"], "warnings": povray_warnings(output), "command": cmd, "ini": ini}
        if self.timed:
            result["resources"] = {**read_time_file(root / "time.txt"), "parse": povray_parse_seconds(output)}
        if r["timed_out"]:
            result.update(status="timeout", error=f"timed out after {timeout} s")
        elif r["rc"] != 0 or not (work / "census.hdr").is_file():
            result.update(status="error", error=povray_error(output) or
                          f"{exit_text(r['rc'])}{'' if r['rc'] else ', no image'}")
        else:
            result["status"] = "ok"
            shutil.move(str(work / "census.hdr"), image)
        shutil.rmtree(root, ignore_errors=True)
        return result

    def wardray_command(self, scene_name, output, declares=()):
        w, h = self.size
        return [str(self.ward.exe), f"+I{scene_name}", f"+O{output}", "+FH", f"+W{w}", f"+H{h}", "-A", "-D",
                f"+WT{renderers.THREADS}", *(f"Declare={d}" for d in declares)]

    def wardray_render(self, scene, image, ini, converged=(), supersampled=False, perturbed=False):
        root, work = self.scratch(scene, ".wardray")
        cmd = self.wardray_command(scene.name, "census.hdr")
        if ini:
            # As POV-Ray got it: the .ini first, so the census's options after it win; one frame of its animation.
            cmd = [cmd[0], ini["file"], *cmd[1:], f"+SF{ini['frame']}", f"+EF{ini['frame']}"]
        timeout = self.timeout
        if converged:
            converged_copy(scene_files(scene), work, converged)
            cmd, timeout = converged_options(cmd, converged), CONVERGED_TIMEOUT
        if perturbed:
            stability.perturbed_copy(scene_files(scene), work)
        if supersampled:
            cmd, timeout = stability.supersampled_options(cmd), CONVERGED_TIMEOUT
        # The scratch copy lies below /tmp, which Debian's povray.conf lets both programs read (wardray's default
        # read permissions are that file's): users' scenes include `../common.inc`.
        if self.timed:
            cmd += ["--stats", str(root / "stats.json")]
        r = self.runner.run(self.timed_command(cmd, root), work, timeout)
        # An animation frame is written as census<frame number>.hdr.
        written = sorted(work.glob("census*.hdr"))
        if written and not (work / "census.hdr").exists():
            written[0].rename(work / "census.hdr")
        output = r["stdout"] + "\n" + r["stderr"]
        error, features, warnings = wardray_diagnostics(output)
        result = {"exit": r["rc"], "seconds": r["seconds"], "features": features, "warnings": warnings[:20],
                  "error": error, "command": cmd, "cautions": wardray_cautions(output)}
        if self.timed:
            result["resources"] = {**read_time_file(root / "time.txt"), "parse": wardray_parse_seconds(
                root / "stats.json")}
            result["location"] = error_location(output, root / "repo", work)
            if "signal" in result["resources"] and r["rc"] is not None:
                result["exit"] = r["rc"] = -result["resources"]["signal"]  # /usr/bin/time's status is 128 + signal
        if r["timed_out"]:
            result.update(status="timeout", error=f"timed out after {timeout} s")
        elif r["rc"] != 0:
            result.update(status="error", error=error or exit_text(r["rc"]))
        elif not (work / "census.hdr").is_file():
            result.update(status="error", error="exit status 0 but no image written")
        else:
            result["status"] = "ok"
            shutil.move(str(work / "census.hdr"), image)
        shutil.rmtree(root, ignore_errors=True)
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
        cautioned_only = rec["category"] == "differ-with-warning" and not rec["wardray"].get("features")
        if self.converge and (rec["category"] in ("differ-silently", "differ-small") or cautioned_only):
            stochastic = rec["stochastic"]
            if not stochastic:
                # Randomness the scene text does not show (a grainy finish from a library include, focal blur):
                # wardray names what the parsed scene uses. Judged converged only: the tolerance at its own settings
                # stays.
                rec["stochastic_hidden"] = stochastic = self.parsed_randomness(scene, rec["ini"])
            if stochastic:
                rec["converged"] = self.converged(scene, pov_key, rec["ini"], images, stochastic, fresh)
            else:
                rec["stability"] = self.stability(scene, pov_key, rec["ini"], ref, fresh)
                if rec["stability"].get("unstable"):
                    rec["converged"] = self.supersampled(scene, pov_key, rec["ini"], images, fresh)
            rec["category"], rec["reason"] = classify(rec)
        return rec

    def stability(self, scene, pov_key, ini, ref, fresh):
        """POV-Ray's image of a deterministic scene against its image with the cameras turned
        (census_stability): {moved: metrics, unstable}, or {error} when the cameras cannot be turned."""
        try:
            stability.perturbed_texts(scene_files(scene))
        except RewriteError as e:
            return {"error": str(e)}
        result, image = self.povray_variant(scene, f"{pov_key}-perturbed-{self.stability_tag()}", ini, fresh,
                                            perturbed=True)
        if result["status"] != "ok":
            return {"error": f"POV-Ray with its camera turned: {result.get('error') or result['status']}"}
        turned = gimetrics.read_linear_rgb(image)
        if turned.shape != ref.shape:
            return {"error": "POV-Ray's image with its camera turned differs in size"}
        m = compare(turned, ref)
        return {"moved": m, "unstable": stability.moved(m, MATCH_RRMSE, MATCH_BAD)}

    @staticmethod
    def stability_tag():
        return hashlib.sha256(json.dumps([stability.CAMERA_TURN, stability.SUPERSAMPLED_AA, CONVERGED_TIMEOUT]
                                         ).encode()).hexdigest()[:8]

    def supersampled(self, scene, pov_key, ini, images, fresh):
        """Both programs' supersampled renders of a scene unstable at one sample a pixel, each with the cameras
        turned (so that no sample sits exactly on a tie, where the two programs' last bits decide), compared, with
        POV-Ray's own supersampled movement under the turn (turned against not) as the floor:
        {kind, settings, metrics, floor, ...}."""
        out = {"kind": "unstable", "settings": " ".join(stability.SUPERSAMPLED_AA) + ", cameras turned",
               "metrics": None, "floor": None}
        tag = self.stability_tag()
        out["povray"], pov_image = self.povray_variant(scene, f"{pov_key}-supersampled-perturbed-{tag}", ini, fresh,
                                                       supersampled=True, perturbed=True)
        out["wardray"] = self.wardray_render(scene, images / "wardray-supersampled.hdr", ini, supersampled=True,
                                             perturbed=True)
        ref = compare_pair(out, pov_image, images, "supersampled")
        if ref is None:
            return out
        plain, plain_image = self.povray_variant(scene, f"{pov_key}-supersampled-{tag}", ini, fresh,
                                                 supersampled=True)
        if plain["status"] == "ok":
            floor = gimetrics.read_linear_rgb(plain_image)
            if floor.shape == ref.shape:
                out["floor"] = compare(floor, ref)
        return out

    def parsed_randomness(self, scene, ini):
        """The randomness of the scene as wardray parses it (`--check`'s `randomness:` line), in
        stochastic_features' words: radiosity, jitter, crand, focal blur."""
        root, work = self.scratch(scene, ".check")
        cmd = [str(self.ward.exe), f"+I{scene.name}", "--check", *([ini["file"]] if ini else [])]
        r = self.runner.run(cmd, work, self.timeout)
        shutil.rmtree(root, ignore_errors=True)
        return parsed_randomness_words(r["stdout"]) if r["rc"] == 0 else []

    def converged(self, scene, pov_key, ini, images, stochastic, fresh):
        """Both programs' converged renders of a stochastic scene, compared: {settings, povray, wardray, metrics}."""
        out = {"settings": converged_label(stochastic), "metrics": None}
        if "radiosity" in stochastic and not any(has_global_radiosity(t) for n, t in scene_files(scene)
                                                 if "/" not in n):
            out["error"] = "its radiosity block is not in a global_settings of the scene's folder"
            return out
        out["povray"], pov_image = self.povray_converged(scene, pov_key, ini, stochastic, fresh)
        out["wardray"] = self.wardray_render(scene, images / "wardray-converged.hdr", ini, converged=stochastic)
        compare_pair(out, pov_image, images, "converged")
        return out


def compare(img, ref):
    """docs/metrics.md's figures of wardray's image against POV-Ray's, with each image's non-finite pixels."""
    m = gimetrics.image_error(img, ref)
    finite = np.isfinite(img).all(axis=2) & np.isfinite(ref).all(axis=2)
    if not np.isfinite(m["rrmse"]) and np.array_equal(img[finite], ref[finite]):
        m["rrmse"] = 0.0  # both black
    return {"rrmse": m["rrmse"], "bad": m["bad_fraction"], "non_finite": m["non_finite"],
            "non_finite_wardray": int((~np.isfinite(img).all(axis=2)).sum()),
            "non_finite_povray": int((~np.isfinite(ref).all(axis=2)).sum())}


# ---------------------------------------------------------------------------------------------------------------
# Thumbnails.


def compare_pair(out, pov_image, images, label):
    """A second comparison of a scene (`label`: converged, supersampled), both renders in `out` ("povray",
    "wardray", the latter's image `images/wardray-<label>.hdr`): fills out["metrics"], writes the three PNGs of the
    contact sheet and returns POV-Ray's image; or sets out["error"] and returns None."""
    for who in ("povray", "wardray"):
        if out[who]["status"] != "ok":
            out["error"] = f"{who}: {out[who].get('error') or out[who]['status']}"
            return None
    ref = gimetrics.read_linear_rgb(pov_image)
    img = gimetrics.read_linear_rgb(images / f"wardray-{label}.hdr")
    if img.shape != ref.shape:
        out["error"] = f"{label} images differ in size"
        return None
    out["metrics"] = compare(img, ref)
    write_png(images / f"povray-{label}.png", srgb8(ref))
    write_png(images / f"wardray-{label}.png", srgb8(img))
    write_png(images / f"diff-{label}.png", difference8(img, ref))
    return ref


def srgb8(rgb):
    """Linear radiance to 8-bit sRGB, clipped at 1 (non-finite pixels magenta)."""
    x = np.nan_to_num(rgb, nan=0.0, posinf=1.0, neginf=0.0).clip(0.0, 1.0)
    x = np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)
    out = (x * 255 + 0.5).astype(np.uint8)
    out[~np.isfinite(rgb).all(axis=2)] = (255, 0, 255)
    return out


def difference8(img, ref):
    """The difference as docs/metrics.md sees it: grey up to half brightness as |dY| approaches the bad-pixel threshold,
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


def judged_metrics(rec):
    """The figures a scene's category was decided on: the converged comparison where there is one."""
    conv = rec.get("converged")
    return conv["metrics"] if conv and conv.get("metrics") else rec["metrics"]


def severity(rec):
    """Sort key, worst first: compared scenes by rRMSE (non-finite first), then blocked, then POV-Ray failures."""
    if rec["category"] == "povray-fails":
        return (2, 0.0, rec["scene"])
    if rec["metrics"] is None:
        return (1, 0.0, rec["scene"])
    m = judged_metrics(rec)
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
    st = rec.get("stability") or {}
    if st.get("unstable"):
        return f"unstable at one sample a pixel (POV-Ray moves {pct(st['moved']['rrmse'])}): judged supersampled"
    if rec.get("stochastic_hidden"):
        return f"{', '.join(rec['stochastic_hidden'])} (in the parsed scene: converged only)"
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


# ---------------------------------------------------------------------------------------------------------------
# Why scenes do not parse, and what silent differences have in common (a corpus's report).

OBJECT_WORDS = {"union", "difference", "intersection", "merge", "object", "sphere", "box", "cylinder", "cone",
                "plane", "torus", "quadric", "quartic", "poly", "cubic", "polynomial", "mesh", "mesh2", "lathe", "sor",
                "prism", "text", "blob", "superellipsoid", "height_field", "isosurface", "parametric", "disc",
                "triangle", "smooth_triangle", "polygon", "julia_fractal", "sphere_sweep", "bicubic_patch", "ovus",
                "lemon", "light_source", "light_group"}
ITEM_WORDS = {"pigment", "texture", "finish", "normal", "interior", "material", "media", "density", "color_map",
              "colour_map", "pigment_map", "normal_map", "texture_map", "slope_map", "density_map", "camera",
              "spline", "function", "array", "transform"}
COLOUR_WORDS = {"color", "colour", "rgb", "rgbf", "rgbt", "rgbft", "srgb", "srgbf", "srgbt", "srgbft", "red", "green",
                "blue"}


class SourceLookup:
    """What a failure's grouping needs from the scene's sources: the text of a line, and the kind of value an
    identifier is declared as (read from the files of the scene's repository, then POV-Ray's include files).
    Used to name the failing construct only; nothing of the text goes into the report."""

    SOURCE_SUFFIXES = {".pov", ".inc", ".mcr", ".povray"}

    def __init__(self, repo, library=POVRAY_INCLUDE):
        self.repo = pathlib.Path(repo) if repo else None
        self.library = pathlib.Path(library) if library else None
        self._texts = None

    def texts(self):
        """[(path, masked text)] of the repository's scene files, then the library's."""
        if self._texts is None:
            self._texts = []
            for base in (self.repo, self.library):
                if base is None or not base.is_dir():
                    continue
                for f in sorted(base.rglob("*")):
                    if f.suffix.lower() in self.SOURCE_SUFFIXES and f.is_file():
                        self._texts.append((f, masked(f.read_text(errors="replace"))))
        return self._texts

    def line(self, file, number):
        """Line `number` (from 1) of `file` (relative to the repository, or `<povray include>/x.inc`), or ''."""
        if file.startswith("<povray include>/"):
            path = self.library / file[len("<povray include>/"):] if self.library else None
        else:
            path = self.repo / file if self.repo else None
        try:
            return path.read_text(errors="replace").splitlines()[number - 1]
        except (OSError, IndexError, AttributeError):
            return ""

    def file_text(self, file):
        try:
            return (self.repo / file).read_text(errors="replace")
        except (OSError, TypeError):
            return ""

    def declared(self, name, depth=0):
        """The kind `name` is declared as: 'pigment', 'texture', 'object', 'colour', 'float', 'vector', 'macro',
        'string', ... or None when no declaration is found."""
        if not re.fullmatch(r"[A-Za-z_]\w*", name) or depth > 3:
            return None
        decl = re.compile(rf"#\s*(?:declare|local)\s+{re.escape(name)}\s*=\s*([A-Za-z_]\w*|<|\"|[-+\d.(])")
        macro = re.compile(rf"#\s*macro\s+{re.escape(name)}\s*\(")
        for _, text in self.texts():
            if macro.search(text):
                return "macro"
            m = decl.search(text)
            if not m:
                continue
            word = m.group(1)
            if word in ITEM_WORDS:
                return word.replace("colour", "color")
            if word in COLOUR_WORDS:
                return "color"
            if word in OBJECT_WORDS:
                return "object"
            if word == "<":
                return "vector"
            if word == '"' or word in ("concat", "str", "chr", "substr", "strupr", "strlwr"):
                return "string"
            if re.fullmatch(r"[-+\d.(]", word) or word in ("int", "floor", "ceil", "abs", "sqrt", "pow", "sin",
                                                          "cos", "rand", "seed", "true", "false", "yes", "no",
                                                          "on", "off", "pi", "clock", "vlength", "vdot"):
                return "float"
            return self.declared(word, depth + 1) or "identifier"
        return None


def token_label(token, lookup):
    """How a failing token is named in a group: a declared identifier by its kind ('PigmentIdentifier'), a number
    as <number>, a keyword or punctuation as itself."""
    if re.fullmatch(r"[-+]?[\d.]+(e[-+]?\d+)?", token, re.I):
        return "<number>"
    kind = lookup.declared(token) if lookup else None
    if kind:
        return kind.capitalize().replace("_map", "Map") + "Identifier"
    if re.fullmatch(r"[A-Z_]\w*", token) and token != token.lower():
        return "Identifier"  # capitalised and declared nowhere we can see: an identifier, not a keyword
    return token


DIRECTIVES = {"declare", "local", "include", "macro", "if", "ifdef", "ifndef", "else", "end", "while", "for",
              "switch", "case", "break", "default", "undef", "version", "debug", "warning", "error", "fopen",
              "fclose", "read", "write", "range", "elseif"}


def failure_group(rec, lookup):
    """(construct, location) of a blocked scene: what fails, named from wardray's first error message (its text
    and the token it names, the token by its declared kind) and the source line where it points.

    Known constructs get a short name ("texture { PigmentIdentifier }", "#undef A[i]", "declare without #",
    "nested #include path", ...); any other message is its text with identifiers, numbers and names replaced by
    their kinds, so that scenes failing the same way fall in one group."""
    w = rec["wardray"]
    loc = w.get("location")
    where = f"{loc['file']}:{loc['line']}" if loc else ""
    if w["status"] == "timeout":
        return f"timed out after {TIMEOUT} s (parse or render)", where
    resources = w.get("resources") or {}
    if not loc:
        err = w.get("error") or ""
        if re.search(r"bad_alloc|out of memory|cannot allocate", err, re.I):
            return "out of memory (address space bounded)", where
        if w.get("exit") is not None and w["exit"] < 0:
            return f"crash ({exit_text(w['exit'])})", where
        if resources.get("signal"):
            return f"crash (killed by signal {resources['signal']})", where
        return re.sub(r"\d+", "<n>", err) or "no error message", where
    msg = loc["message"]
    line = lookup.line(loc["file"], loc["line"]) if lookup else ""
    before = line[:max(loc["col"] - 1, 0)]
    found = re.search(r"(?:found|but found) '([^']*)'", msg)
    token = found.group(1) if found else None
    label = token_label(token, lookup) if token is not None else None

    if re.search(r"#\s*undef\b", before):
        return "#undef A[i]", where
    if re.match(r"\s*#\s*include\b", line) and token == ";":
        return "#include \"...\"; (a ';' after #include)", where
    m = re.search(r"cannot open include file '([^']+)'", msg)
    if m:
        name = m.group(1)
        scene_dir = posixpath.dirname(rec["scene"].split("/", 1)[-1])
        if lookup and lookup.repo and posixpath.dirname(loc["file"]) != scene_dir and \
                (lookup.repo / scene_dir / name).is_file():
            return "nested #include path (relative to the scene's folder, not the including file's)", where
        return "#include of a file not found", where
    m = re.search(r"'(\w+)' cannot start a statement", msg)
    if m:
        word = m.group(1)
        return (f"{word} without #" if word in DIRECTIVES else f"statement starting with '{token_label(word, lookup)}'"), where
    m = re.search(r"'(\w+)' is a reserved word and cannot be declared", msg)
    if m:
        return f"#declare of a reserved word ({m.group(1)})", where
    m = re.search(r"'(\w+)' (?:is not supported yet|is not implemented)", msg)
    if m:
        return f"{m.group(1)}", where
    m = re.search(r"'(\w+)' cannot stand alone here", msg)
    if m or (label == "ObjectIdentifier" and "object modifier" in msg):
        return "ObjectIdentifier without object { }", where
    m = re.search(r"macro '\w+' takes (\d+) parameter\(s\) but (\d+) were given", msg)
    if m:
        if re.search(r",\s*\)", line):
            return "macro call with an empty last argument ', )'", where
        return "macro called with the wrong number of arguments", where
    m = re.search(r"undeclared identifier '(\w+)'", msg)
    if m:
        name = m.group(1)
        text = masked(lookup.file_text(loc["file"])) if lookup else ""
        head = "\n".join(text.splitlines()[:loc["line"] - 1])
        if line.strip() == name and re.search(rf"#\s*local\s+{re.escape(name)}\b", head):
            return "macro returning one of its #local identifiers (the identifier alone before #end)", where
        return "undeclared identifier", where
    m = re.search(r"in (\w+) but found", msg) or re.search(r"expected an? (\w+) item but found", msg)
    if m and label is not None:
        return f"{m.group(1)} {{ {label} }}", where
    m = re.search(r"expected an object in '(\w+)' but found", msg)
    if m and label is not None:
        return f"{m.group(1)} {{ {label} }}", where
    m = re.search(r"expected an? (\w+) pattern or modifier but found", msg)
    if m and label is not None:
        return f"{m.group(1)} {{ ... {label} }}", where
    generic = msg
    if token is not None:
        generic = generic.replace(f"'{token}'", f"'{label}'")
    generic = re.sub(r"'[A-Za-z_]\w*'", lambda t: "'" + token_label(t.group(0)[1:-1], lookup) + "'", generic)
    generic = re.sub(r"(?<![\w'])\d+(\.\d+)?(?![\w'])", "<n>", generic)
    return generic, where


def silent_group(rec):
    """A silent difference's group: the scene-text hints on gamma and #version."""
    h = [x for x in hints(rec) if x.startswith(("assumed_gamma", "#version", "no assumed_gamma"))]
    return "; ".join(h) or "no gamma or #version hint (assumed_gamma 1, #version 3.7)"


def grouped(records, key):
    """[(group, [records])] worst group first: the most scenes, then by name."""
    groups = {}
    for r in records:
        groups.setdefault(key(r), []).append(r)
    return sorted(groups.items(), key=lambda kv: (-len(kv[1]), kv[0]))


PARSE_FLOOR = 0.05  # seconds: below this in wardray, a parse-time ratio is noise (POV-Ray reports milliseconds)


def mb(kb):
    return "" if kb is None else f"{kb / 1024:.0f}"


def ratio(a, b):
    return None if a is None or b is None or b <= 0 else a / b


def resource_outliers(records):
    """[(record, reasons)] of scenes where wardray takes more than twice POV-Ray's parse time (wardray's at least
    PARSE_FLOOR s) or more than twice its peak memory, or times out while POV-Ray renders; worst first."""
    out = []
    for r in records:
        if r["povray"]["status"] != "ok":
            continue
        p, w = r["povray"].get("resources") or {}, r["wardray"].get("resources") or {}
        reasons = []
        if r["wardray"]["status"] == "timeout":
            reasons.append(f"wardray timed out after {TIMEOUT} s")
        pr = ratio(w.get("parse"), p.get("parse") if p.get("parse") else 0.001)
        if pr is not None and pr > 2 and w["parse"] >= PARSE_FLOOR:
            reasons.append(f"parse {pr:.1f}x")
        mr = ratio(w.get("peak_kb"), p.get("peak_kb"))
        if mr is not None and mr > 2:
            reasons.append(f"memory {mr:.1f}x")
        if reasons:
            out.append((r, reasons))

    def worst(item):
        r, _ = item
        p, w = r["povray"].get("resources") or {}, r["wardray"].get("resources") or {}
        timeout = r["wardray"]["status"] == "timeout"
        return (not timeout, -max(ratio(w.get("parse"), max(p.get("parse") or 0, 0.001)) or 0,
                                  ratio(w.get("peak_kb"), p.get("peak_kb")) or 0), r["scene"])
    return sorted(out, key=worst)


def corpus_sections(records, lookup_for, memory_limit=None):
    """The corpus report's own sections: why scenes do not parse, silent differences by hint, and parse time and
    peak memory against POV-Ray's. `lookup_for(record)` gives the SourceLookup of the scene's repository."""
    lines = []
    ok_pov = [r for r in records if r["povray"]["status"] == "ok"]
    blocked = [r for r in records if r["category"] == "blocked"]
    parsed = [r for r in ok_pov if r["wardray"]["status"] == "ok"]
    lines += ["## Why scenes do not parse", "",
              f"{len(parsed)} of the {len(ok_pov)} scenes POV-Ray renders ({pct(len(parsed) / max(len(ok_pov), 1), 0)}) "
              f"parse and render in wardray; {len(blocked)} are blocked. They are grouped by the construct named by "
              "wardray's first error (its message and the token it names, a declared identifier by its kind, and "
              "the source line it points at), worst group first; the example is the group's first scene and the "
              "error's location (`r<NN>/` the repository, then the file's path in it).", "",
              "| construct | scenes | example scene | at |", "|---|---:|---|---|"]
    for group, rs in grouped(blocked, lambda r: failure_group(r, lookup_for(r))[0]):
        first = sorted(rs, key=lambda r: r["scene"])[0]
        where = failure_group(first, lookup_for(first))[1]
        if where and not where.startswith("<"):
            where = first["scene"].split("/", 1)[0] + "/" + where
        lines.append(f"| {cell(group)} | {len(rs)} | `{cell(first['scene'])}` | {('`' + cell(where) + '`') if where else ''} |")
    lines.append("")

    silent = sorted((r for r in records if r["category"] == "differ-silently"), key=severity)
    lines += ["## Silent differences by hint", "",
              f"{len(silent)} scenes differ silently, grouped by what the scene text says about gamma "
              "(`assumed_gamma`, `#version`; wardray does not apply POV-Ray's gamma model yet), worst group first; "
              "the example is the group's worst scene.", "",
              "| hints | scenes | example scene | its rRMSE |", "|---|---:|---|---:|"]
    for group, rs in grouped(silent, silent_group):
        first = sorted(rs, key=severity)[0]
        lines.append(f"| {cell(group)} | {len(rs)} | `{cell(first['scene'])}` | {pct(first['metrics']['rrmse'])} |")
    lines.append("")

    timed = [r for r in ok_pov if r["wardray"]["status"] == "ok" and (r["povray"].get("resources") or {}).get(
        "peak_kb") and (r["wardray"].get("resources") or {}).get("peak_kb")]
    both_parse = [r for r in timed if r["wardray"]["status"] == "ok" and r["povray"]["resources"].get("parse")
                  is not None and r["wardray"]["resources"].get("parse") is not None]

    def median(xs):
        xs = sorted(xs)
        return xs[len(xs) // 2] if xs else None

    mem = median([r["wardray"]["resources"]["peak_kb"] / r["povray"]["resources"]["peak_kb"] for r in timed])
    parse_w = sum(r["wardray"]["resources"]["parse"] for r in both_parse)
    parse_p = sum(r["povray"]["resources"]["parse"] for r in both_parse)
    outliers = resource_outliers(records)
    n_parse = sum(any(x.startswith("parse") for x in why) for _, why in outliers)
    n_mem = sum(any(x.startswith("memory") for x in why) for _, why in outliers)
    n_timeout = sum(any("timed out" in x for x in why) for _, why in outliers)
    lines += ["## Parse time and peak memory against POV-Ray", "",
              "Each process run under `/usr/bin/time -f '%e %M'` (wall seconds, peak resident memory) while "
              "rendering the census's 120x90 image with one thread; parse time as each program reports it "
              "(POV-Ray's statistics \"Parse Time\", wardray's `--stats` `phases.parse`). Single runs, two scenes "
              "at once on a shared machine: ratios, not benchmarks. Peak memory is the whole process's (parse and "
              f"render); wardray's address space is bounded at {info_gb(memory_limit)} so a runaway parse fails instead "
              "of exhausting the machine.", "",
              f"- Scenes both render, measured: {len(timed)}; median peak-memory ratio wardray/POV-Ray "
              f"{mem:.2f}." if mem is not None else "- No scene with both measured.",
              f"- Parse time summed over the {len(both_parse)} scenes both parse: POV-Ray {parse_p:.2f} s, wardray "
              f"{parse_w:.2f} s.",
              f"- More than twice POV-Ray's parse time (wardray's at least {PARSE_FLOOR:g} s): {n_parse} scenes; "
              f"more than twice its peak memory: {n_mem}; wardray timed out where POV-Ray rendered: {n_timeout}.",
              ""]
    if outliers:
        lines += ["| scene | POV-Ray parse s | wardray parse s | POV-Ray peak MB | wardray peak MB | POV-Ray wall s | "
                  "wardray wall s | why listed |", "|---|---:|---:|---:|---:|---:|---:|---|"]
        for r, why in outliers:
            p, w = r["povray"].get("resources") or {}, r["wardray"].get("resources") or {}
            lines.append(f"| `{cell(r['scene'])}` | {fmt3(p.get('parse'))} | {fmt3(w.get('parse'))} | "
                         f"{mb(p.get('peak_kb'))} | {mb(w.get('peak_kb'))} | {secs(r['povray'].get('seconds'))} | "
                         f"{secs(r['wardray'].get('seconds'))} | {cell(', '.join(why))} |")
        lines.append("")
    return lines


def fmt3(x):
    return "" if x is None else f"{x:.3f}"


def info_gb(limit):
    return f"{limit / 2**30:g} GiB" if limit else "no limit"


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


def write_report(path, records, missing, info, extra=()):
    """The report; `extra`, lines of more sections, goes before the table of every scene."""
    records = sorted(records, key=lambda r: r["scene"])
    counts = totals(records)
    stochastic = [r for r in records if r.get("stochastic")]
    clean, clean_match = headline_numbers(records)
    lines = [
        info.get("title", "# Render census: POV-Ray's example scenes, POV-Ray 3.7 against wardray"),
        "",
        f"Produced by `{info['command']}` on {info['date']}. {info['runtime']}",
        "",
        f"- wardray: {info['commit']}, binary `{info['wardray']}` (sha256 {info['digest'][:12]}).",
        f"- POV-Ray: {info['povray']}.",
        info.get("scenes_line", f"- Scenes: the {info['total']} `.pov` files under `{info['examples']}` (Debian's "
                 "povray-examples)."),
        f"- Each scene rendered by both programs at {SIZE[0]}x{SIZE[1]}, `-A`, linear HDR (`+FH`), one thread each "
        f"(`+WT1`), {info['jobs']} scenes at a time, each program bounded at {TIMEOUT} s, in a scratch copy of the "
        f"{info.get('scratch', 'scene' + chr(39) + 's folder')}. Scenes with an `.ini` beside them are rendered without it (one frame, clock 0, "
        "frame_number 0) by both; where POV-Ray fails that way (the portfolio), it renders the .ini's first frame "
        "(`scene.ini +SF<n> +EF<n>`, the census's options after it), and wardray, which reads no .ini and has no "
        "animation options, gets only the .ini's `Declare=` values; such scenes carry a note.",
        "- Compared as docs/metrics.md says, POV-Ray's image the reference: rRMSE, bad-pixel fraction, "
        "non-finite pixels.",
        f"- Categories: **match** rRMSE ≤ {pct(MATCH_RRMSE, 0)} and bad pixels ≤ {pct(MATCH_BAD, 1)}, no "
        "non-finite pixel; **differ-with-warning** not a match and wardray warned that a feature is not rendered "
        "yet, or that its picture may differ from POV-Ray's (surfaces that lie on one another, or a texture that "
        "jumps exactly on a surface, where POV-Ray shows either at random; the reason then still says what the "
        "measured difference comes from); "
        f"**differ-silently** no such warning and rRMSE > {pct(SILENT_RRMSE, 0)} or non-finite pixels (the "
        f"worst outcome); **differ-small** no warning, not a match, rRMSE ≤ {pct(SILENT_RRMSE, 0)}; **blocked** "
        "wardray fails to parse or render (or times out); **povray-fails** POV-Ray fails or times out (no "
        "reference).",
        f"- **Stochastic** scenes (a global `radiosity` block, `jitter` in area lights or media, `crand`, found in "
        "the scene text and the files it includes from its folder) are rendered once at their own settings by "
        f"each program; their tolerance is rRMSE ≤ {pct(STOCHASTIC_RRMSE, 0)} for a match and for a silent "
        "difference, and the bad-pixel fraction is reported but not used (noise makes a per-pixel test "
        "meaningless at the scenes' settings). One that does not match so is rendered again converged by both "
        f"programs (`{converged_label(['radiosity', 'crand'])}`: POV-Ray's converged radiosity in the global "
        "radiosity blocks of the scene's folder for scenes with radiosity, and every pixel supersampled without "
        f"jitter for scenes with crand or jitter), each bounded at {CONVERGED_TIMEOUT} s, and judged on that comparison "
        "with the tolerances of the other scenes; the tables then show the converged figures and the reason "
        "says so. A scene whose text shows no randomness but does not match is asked of wardray (`--check` names "
        "the randomness of the parsed scene, such as a `crand` finish from a library include, or focal blur); if it "
        "has some, it is judged on a converged comparison alone, keeping the deterministic tolerance at its own "
        f"settings. Focal blur converges with `blur_samples {CONVERGED_BLUR_SAMPLES}, {CONVERGED_BLUR_SAMPLES}` "
        "written over the literal `blur_samples` of the scene's folder.",
        "- **Unstable** scenes: a deterministic scene that does not match (or matches only with a caution) is "
        "rendered by POV-Ray a second time with every camera block of the scene's folder turned by a tiny angle "
        f"(`rotate <{', '.join(f'{a:g}' for a in stability.CAMERA_TURN)}>` degrees appended inside the block, a "
        "declared camera and a `camera { Name }` alike: about 2e-6 radians, 2e-4 of a pixel, moving the camera "
        "by about 2e-6 of its distance from the origin). If POV-Ray's own image moves by more than the match "
        "tolerance, its picture at one sample a pixel hangs on rounding (pixel centres exactly on edges, textures "
        "chaotic at the scale of a pixel), and the scene is judged instead on supersampled renders of both "
        f"programs (`{' '.join(stability.SUPERSAMPLED_AA)}`, each bounded at {CONVERGED_TIMEOUT} s), both with the "
        "cameras turned (so that no sample sits exactly on a tie, where each program's last bits decide), a match "
        "being within the match tolerance or within POV-Ray's own supersampled movement under the same turn, "
        "whichever is larger (a renderer that differs from POV-Ray no more than POV-Ray differs from itself "
        "cannot be told apart from it). The reason gives POV-Ray's own movement at one sample and supersampled. "
        "Where the cameras cannot be turned (no camera block in the folder's own files: the default camera, or "
        "one from an include file elsewhere or in a subfolder), the scene keeps its verdict and the reason says "
        "so. A scene whose parse-time trace() calls build different objects when their results move by 1e-12 is "
        "warned about by wardray and counts as a caution (\"trace() rounding\").",
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
    n_silent_known = sum(r["category"] == "differ-silently" and r["scene"] in KNOWN_REASONS for r in records)
    lines += [
        f"| stochastic (included above) | {len(stochastic)} ({n_stoch_match} match) |",
        "",
        f"Of the {clean} scenes that render with no \"not rendered yet\" warning (and POV-Ray renders), "
        f"**{clean_match} match POV-Ray**; {counts['differ-silently']} scenes differ silently, "
        f"{n_silent_known} of them with a measured reason in tools/census_reasons.tsv (a tie, randomness, or "
        f"POV-Ray's own quirk) and {counts['differ-silently'] - n_silent_known} unexplained.",
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
        lines.append(f"| {cell(r['scene'])} | {pct(judged_metrics(r)['rrmse'])} | {pct(judged_metrics(r)['bad'])} | "
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

    lines += list(extra)
    lines += ["## Every scene", "",
              "| scene | parse | not rendered | rRMSE | bad | NaN/Inf | POV-Ray s | wardray s | stochastic | "
              "category | reason |",
              "|---|---|---|---:|---:|---:|---:|---:|---|---|---|"]
    for r in records:
        m = judged_metrics(r) or {}
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
    m = judged_metrics(rec)
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


def find_scenes(examples, patterns, corpus=None):
    if corpus:
        return [s for s in corpus.scenes() if not patterns or any(
            fnmatch.fnmatch(corpus.rel(s), p) or fnmatch.fnmatch(corpus.path(s), p) for p in patterns)]
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
    ap.add_argument("--corpus", metavar="ROOT", help="another corpus of scenes, listed by --manifest, instead of "
                    "the examples (issue 23's scenes from the wild)")
    ap.add_argument("--manifest", metavar="TSV", help="with --corpus: its MANIFEST.tsv (default ROOT/MANIFEST.tsv)")
    ap.add_argument("--memory-limit", type=float, default=8.0, metavar="GIB",
                    help="with --corpus: wardray's address space, GiB (default 8; 0 for none)")
    ap.add_argument("--results", help="cache, images and contact sheet (default build/census, with --corpus "
                    "build/census-<corpus folder name>)")
    ap.add_argument("--out", "--report", dest="out", help="the report (default docs/reports/census.md, with "
                    "--corpus docs/reports/<corpus folder name>.md)")
    ap.add_argument("--jobs", type=int, default=2, help="scenes rendered at once, one thread each (default 2)")
    ap.add_argument("--scenes", action="append", metavar="GLOB",
                    help="only scenes whose path below the examples matches (repeatable), e.g. 'objects/*'")
    ap.add_argument("--fresh", action="store_true", help="redo every chosen scene, POV-Ray's renders too")
    ap.add_argument("--check", nargs="+", metavar="SCENE",
                    help="render these scenes (paths below the examples) with no cache and no report; exit 1 "
                         "when one differs silently, is blocked or POV-Ray fails")
    ap.add_argument("--expect-match", action="store_true", help="with --check: every scene must match")
    ap.add_argument("--no-converge", dest="converge", action="store_false",
                    help="compare stochastic scenes only at their own settings (no converged renders)")
    args = ap.parse_args()

    examples = pathlib.Path(args.examples)
    corpus = None
    if args.corpus:
        corpus = Manifest(args.corpus, args.manifest or pathlib.Path(args.corpus) / "MANIFEST.tsv")
        name = corpus.root.name
        args.results = args.results or str(ROOT / "build" / f"census-{name}")
        args.out = args.out or str(ROOT / "docs" / "reports" / f"{name}.md")
    elif args.manifest:
        ap.error("--manifest needs --corpus")
    args.results = args.results or str(ROOT / "build" / "census")
    args.out = args.out or str(ROOT / "docs" / "reports" / "census.md")
    memory_limit = int(args.memory_limit * 2**30) if corpus and args.memory_limit > 0 else None
    # The census's images are Radiance HDR (its cached references and thresholds are).
    ward = renderers.Wardray(args.wardray, image_format="hdr")
    pov = renderers.PovRay(args.povray, image_format="hdr")

    def work_root(results):
        # POV-Ray reads only below /tmp and its current folder: a corpus is rendered from copies below /tmp.
        if not corpus:
            return None
        tag = hashlib.sha256(str(pathlib.Path(results).resolve()).encode()).hexdigest()[:8]
        return pathlib.Path(tempfile.gettempdir()) / f"wardray-census-{corpus.root.name}-{tag}"

    if args.check:
        with tempfile.TemporaryDirectory(prefix="census-check-") as tmp:
            census = Census(ward, pov, tmp, examples, corpus=corpus, work_root=work_root(tmp),
                            memory_limit=memory_limit, converge=args.converge)
            scenes = [examples / s for s in args.check] if not corpus else find_scenes(examples, args.check, corpus)
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
    census = Census(ward, pov, results, examples, corpus=corpus, work_root=work_root(results),
                    memory_limit=memory_limit, converge=args.converge)
    # Scratch folders of renders an interrupt cut short.
    shutil.rmtree(census.work_root, ignore_errors=True)
    census.work_root.mkdir(parents=True)
    jsonl = results / "results.jsonl"  # appended to; a scene's last line wins, so --fresh needs no deletion
    cached = load_results(jsonl)
    all_scenes = find_scenes(examples, None, corpus)
    chosen = find_scenes(examples, args.scenes, corpus)
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
    extra = []
    if corpus:
        info.update(
            title=f"# Render census of a corpus: {corpus.root.name}, POV-Ray 3.7 against wardray",
            scenes_line=f"- Scenes: the {info['total']} scenes of `{corpus.manifest}` ({len(corpus.repos)} public "
                        "repositories; the corpus is not committed), each named by a neutral id, `r<NN>/<path in "
                        "its repository>`, the repositories numbered in the manifest's order. Figures only: "
                        "nothing of the scenes is copied here.",
            scratch="scene's whole repository below /tmp, rendered in the scene's folder (POV-Ray with "
                    "`+L<that folder>`, as the census gives it)")
        folders = {rid: corpus.root / folder for folder, rid in corpus.repos.items()}
        lookups = {}

        def lookup_for(rec):
            rid = rec["scene"].split("/", 1)[0]
            if rid not in lookups:
                lookups[rid] = SourceLookup(folders.get(rid))
            return lookups[rid]
        for rec in current:
            if rec["category"] == "blocked":
                # The construct, not wardray's message, which quotes the scene's own names.
                group, where = failure_group(rec, lookup_for(rec))
                rec["reason"] = group + (f" at {where}" if where else "")
        extra = corpus_sections(current, lookup_for, memory_limit)
        census.work_root.rmdir() if census.work_root.is_dir() and not any(census.work_root.iterdir()) else None
    write_report(pathlib.Path(args.out), current, missing, info, extra)
    write_sheet(results / "index.html", current, info)
    counts = totals(current)
    print(f"census: {bar.done} scenes rendered in {progress.format_seconds(elapsed)}; "
          + ", ".join(f"{c} {counts[c]}" for c in CATEGORIES)
          + (f", not measured {len(missing)}" if missing else "")
          + f"\ncensus: wrote {args.out} and {results / 'index.html'}", file=sys.stderr)
    sys.exit(130 if interrupted else 0)


if __name__ == "__main__":
    main()
