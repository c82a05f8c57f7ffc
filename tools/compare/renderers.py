"""Runs POV-Ray and wardray on wrapper scenes, times them and caches converged references.

Both renderers write linear images at the requested size, antialiasing off, 2 threads, and run with their current
folder set to a scratch folder that holds the wrapper scene (POV-Ray writes only below its current folder);
`+L<scene folder>` lets the scene's own includes resolve. The images are OpenEXR (`+FE`, half floats: 11 bits of
mantissa a channel) unless the caller asks for Radiance HDR (`+FH`), whose 8-bit mantissa shared by the three
channels, truncated, adds about 0.6 % rRMSE between two images of the same scene (docs/reports/reference_seed.md):
too much for errors near 1 %.
"""
import hashlib
import json
import pathlib
import re
import resource
import shutil
import subprocess
import sys
import time

from povrewrite import mask_comments_and_strings

THREADS = 2

# Output formats: the switch and the file suffix.
FORMATS = {"exr": ("+FE", ".exr"), "hdr": ("+FH", ".hdr")}
DEFAULT_FORMAT = "exr"


class RenderFailed(RuntimeError):
    """A renderer exited with an error; the message holds the end of its output."""


def run_timed(cmd, cwd, timeout=None, attempts=10):
    """Runs `cmd`, returns its whole-process wall-clock seconds; raises RenderFailed on a non-zero exit.

    A binary that cannot be started (missing or being relinked: wardray is rebuilt in place) is retried a minute
    later, up to `attempts` times."""
    for attempt in range(1, attempts + 1):
        start = time.perf_counter()
        try:
            proc = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                  errors="replace", timeout=timeout)
            break
        except subprocess.TimeoutExpired as e:
            raise RenderFailed(f"{' '.join(cmd)} timed out after {timeout} s") from e
        except OSError as e:
            if attempt == attempts:
                raise RenderFailed(f"cannot start {cmd[0]}: {e}") from e
            print(f"\ncompare: cannot start {cmd[0]} ({e}); retrying in a minute", file=sys.stderr, flush=True)
            time.sleep(60)
    elapsed = time.perf_counter() - start
    if proc.returncode != 0:
        last = next((l.strip() for l in reversed(proc.stdout.splitlines()) if l.strip()), "no output")
        raise RenderFailed(f"{pathlib.Path(cmd[0]).name} exited with {proc.returncode}: {last}\n"
                           f"command: {' '.join(cmd)}\n{proc.stdout[-1500:]}")
    return elapsed


def children_cpu_seconds():
    """User plus system seconds of the processes this one has waited for."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


class ImageFormat:
    """The output format a renderer writes (a key of FORMATS), and what follows from it."""

    def __init__(self, image_format):
        if image_format not in FORMATS:
            raise ValueError(f"unknown image format {image_format!r} (expected one of {', '.join(FORMATS)})")
        self.image_format = image_format

    @property
    def format_switch(self):
        return FORMATS[self.image_format][0]

    @property
    def suffix(self):
        return FORMATS[self.image_format][1]


class PovRay(ImageFormat):
    name = "povray"
    label = "POV-Ray"

    def __init__(self, exe="povray", image_format=DEFAULT_FORMAT):
        super().__init__(image_format)
        self.exe = shutil.which(exe) or exe
        proc = subprocess.run([self.exe, "--version"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                              errors="replace")
        # The first lines may be complaints about a missing user configuration file.
        first = next((l for l in proc.stdout.splitlines() if l.startswith("POV-Ray")), None)
        if first is None:
            raise RuntimeError(f"{exe} does not look like POV-Ray: {proc.stdout[:200]!r}")
        self.version = first.strip()

    def command(self, scene_name, output, size, scene_dir, extra=()):
        w, h = size
        return [self.exe, f"+I{scene_name}", f"+O{output}", self.format_switch, f"+W{w}", f"+H{h}", "-A",
                "-D", "-V", f"+WT{THREADS}", f"+L{scene_dir}", *extra]


class Wardray(ImageFormat):
    name = "wardray"
    label = "wardray"

    def __init__(self, exe, gi_mode="cache", wait_minutes=10, image_format=DEFAULT_FORMAT, references_key=None):
        super().__init__(image_format)
        self.exe = pathlib.Path(exe).resolve()
        self.gi_mode = gi_mode
        # The binary may be missing or mid-rebuild: wait a minute at a time before giving up.
        deadline = time.monotonic() + 60 * wait_minutes
        while True:
            try:
                help_text = subprocess.run([str(self.exe), "--help"], stdout=subprocess.PIPE,
                                           stderr=subprocess.STDOUT, text=True, errors="replace", timeout=60).stdout
                version = subprocess.run([str(self.exe), "--version"], stdout=subprocess.PIPE,
                                         stderr=subprocess.STDOUT, text=True, errors="replace", timeout=60).stdout
                digest = self.digest()
                break
            except (OSError, subprocess.SubprocessError) as e:
                if time.monotonic() > deadline:
                    raise RuntimeError(f"wardray at {self.exe} is not usable ({e})") from e
                print(f"compare: {self.exe} not usable yet ({e}); retrying in a minute", file=sys.stderr, flush=True)
                time.sleep(60)
        self.help_text = help_text
        # The version string alone does not change on every rebuild; the binary's hash does.
        name = version.strip() or "wardray"
        self.version = f"{name} (binary sha256 {digest[:12]})"
        # The version the cached renders (references) are filed under: this binary's, or with --wardray-references-key
        # an earlier binary's, whose references the caller vouches for (its images of the scenes the same).
        self.cache_version = f"{name} (binary sha256 {(references_key or digest)[:12]})"
        self.has_reference = "reference" in help_text and "--gi-rays" in help_text
        self.has_seed = re.search(r"--seed\b", help_text) is not None
        # A reference of the cache mode's own image: the camera hits' area lights on POV-Ray's grid with the cache
        # mode's jitter, the seeds turning the paths alone (binaries since 2026-12-07).
        self.has_own_model_reference = "--gi-area-lights" in help_text and "--gi-path-seed" in help_text

    def digest(self):
        return hashlib.sha256(self.exe.read_bytes()).hexdigest()

    def rebuilt(self):
        """True when the binary is no longer the one measured at the start (or cannot be read)."""
        try:
            return self.digest()[:12] not in self.version
        except OSError:
            return True

    def command(self, scene_name, output, size, scene_dir, extra=()):
        w, h = size
        gi = [] if any(a.startswith("--gi=") for a in extra) else [f"--gi={self.gi_mode}"]
        return [str(self.exe), f"+I{scene_name}", f"+O{output}", self.format_switch, f"+W{w}", f"+H{h}",
                "-A", f"+WT{THREADS}", f"+L{scene_dir}", *gi, *extra]

    def reference_args(self, rays, seed=None):
        if self.gi_mode == "off":
            return []  # development without wardray's GI: the "reference" is just the direct-light image
        args = ["--gi=reference", "--gi-rays", str(rays)]
        if self.has_own_model_reference:
            # The image the cache mode converges to: its direct light at the camera hits exactly (POV-Ray's area
            # light grid, jittered as at the default seed), only the indirect light by brute force. The integral of
            # the area lights (the default, --gi-area-lights=fine) differs from it by the grid's jitter and bias,
            # about 0.8 % on cornell, which no radiosity setting changes (docs/reports/reference_seed.md).
            args.append("--gi-area-lights=grid")
            if seed is not None:
                args += ["--gi-path-seed", str(seed)]
        elif seed is not None:
            args += ["--seed", str(seed)]
        return args

    def check(self, scene_path, scene_dir):
        """(first error line or None, warning lines) from `wardray --check` on the scene."""
        proc = subprocess.run([str(self.exe), "--check", f"+L{scene_dir}", f"+I{scene_path}"],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors="replace")
        lines = proc.stdout.splitlines()
        warnings = warning_lines(lines)
        if proc.returncode == 0:
            return None, warnings
        errors = [l for l in lines if "error" in l]
        return (errors or lines or [f"exit status {proc.returncode}"])[0], warnings


def warning_lines(lines):
    """The warnings among `wardray --check`'s lines ("path:line:col: warning: message"), every path in them (the
    message may name other places) without its folders."""
    return [re.sub(r"(?<![\w.])/\S*/", "", l) for l in lines if re.search(r":\d+:\d+: warning: ", l)]


def local_includes(text, scene_dir):
    """Contents of the files a scene includes from its own folder, so that editing them invalidates the cache."""
    found = []
    masked = mask_comments_and_strings(text)
    for m in re.finditer(r"#\s*include\s*\"", masked):
        end = text.find('"', m.end())
        path = pathlib.Path(scene_dir) / text[m.end():end]
        if path.is_file():
            found.append((path.name, path.read_text(errors="replace")))
    return found


class RenderCache:
    """Rendered images kept by a hash of scene text, local includes, renderer version, options and size."""

    def __init__(self, folder):
        self.folder = pathlib.Path(folder)
        self.folder.mkdir(parents=True, exist_ok=True)

    def key(self, renderer, scene_text, scene_dir, size, extra):
        version = getattr(renderer, "cache_version", renderer.version)
        blob = json.dumps({"renderer": renderer.name, "version": version, "scene": scene_text,
                           "includes": local_includes(scene_text, scene_dir), "size": list(size),
                           "args": list(extra), "threads": THREADS}, sort_keys=True)
        # Radiance HDR keeps the keys it had before the format was a choice, so its cached references still serve.
        if renderer.image_format != "hdr":
            blob += f" format={renderer.image_format}"
        return hashlib.sha256(blob.encode()).hexdigest()

    def render(self, renderer, scene_text, scene_dir, size, extra, work, what):
        """The path of a cached image for this render and the seconds it took, rendering it when needed."""
        key = self.key(renderer, scene_text, scene_dir, size, extra)
        image, meta = self.folder / f"{key}{renderer.suffix}", self.folder / f"{key}.json"
        if image.is_file() and meta.is_file():
            seconds = json.loads(meta.read_text())["seconds"]
            print(f"compare: using cached {what} ({key[:12]}, rendered in {seconds:.1f} s)", file=sys.stderr,
                  flush=True)
            return image, seconds, True
        (work / "scene.pov").write_text(scene_text)
        written = work / f"cached{renderer.suffix}"
        written.unlink(missing_ok=True)
        cmd = renderer.command("scene.pov", written.name, size, scene_dir, extra)
        before = children_cpu_seconds()
        seconds = run_timed(cmd, work)
        # Processor time too: a long reference rendered on a busy machine has a wall time that says little.
        cpu_seconds = children_cpu_seconds() - before
        if not written.is_file():
            raise RenderFailed(f"{' '.join(cmd)} exited without writing its image")
        shutil.move(str(written), image)
        meta.write_text(json.dumps({"what": what, "seconds": seconds, "cpu_seconds": cpu_seconds, "command": cmd,
                                    "version": renderer.version,
                                    "created": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())}, indent=1))
        return image, seconds, False
