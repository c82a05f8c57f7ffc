"""A one-line progress display on stderr for the whole comparison run, with an estimate of the time left.

The estimate prices every job still to do: a run at a quality point already timed on this scene costs what it
cost; otherwise what the same renderer and point cost on earlier scenes; otherwise the mean of everything finished.
Cached references count as done but teach the estimate nothing."""
import statistics
import sys
import time


def format_seconds(s):
    if s is None:
        return "?"
    s = int(round(s))
    return f"{s // 3600}h{s % 3600 // 60:02d}m" if s >= 3600 else f"{s // 60}m{s % 60:02d}s"


class Progress:
    def __init__(self, jobs, stream=sys.stderr):
        """`jobs` is the plan: a list of (scene, renderer, point) tuples, references having point None."""
        self.plan = list(jobs)
        self.done = 0
        self.times = {}  # (scene, renderer, point) -> [seconds]
        self.start = time.monotonic()
        self.stream = stream
        self.tty = stream.isatty()

    def _estimate(self, job):
        scene, renderer, point = job
        if self.times.get(job):
            return statistics.mean(self.times[job])
        same = [statistics.mean(v) for (s, r, p), v in self.times.items() if r == renderer and p == point]
        if same:
            return statistics.mean(same)
        finished = [t for v in self.times.values() for t in v]
        return statistics.mean(finished) if finished else None

    def left(self):
        remaining = self.plan[self.done:]
        estimates = [self._estimate(j) for j in remaining]
        if any(e is None for e in estimates):
            return None
        return sum(estimates)

    def show(self, scene, setting, renderer, run, runs):
        elapsed = time.monotonic() - self.start
        line = (f"[{self.done + 1}/{len(self.plan)}] {scene} | {setting} | {renderer} run {run}/{runs} | "
                f"elapsed {format_seconds(elapsed)} | left ~{format_seconds(self.left())}")
        if self.tty:
            self.stream.write("\r\x1b[K" + line)
        else:
            self.stream.write(line + "\n")
        self.stream.flush()

    def finish(self, job, seconds):
        """Records a finished job of the plan (jobs finish in plan order); seconds None for a cached one."""
        if seconds is not None:
            self.times.setdefault(job, []).append(seconds)
        self.done += 1

    def add(self, jobs):
        """Adds jobs found to be needed while running (another convergence check of a reference)."""
        self.plan[self.done:self.done] = list(jobs)

    def drop(self, scene, renderer):
        """Removes a renderer's remaining jobs on a scene from the plan (its reference failed)."""
        self.plan[self.done:] = [j for j in self.plan[self.done:] if j[0] != scene or j[1] != renderer]

    def note(self, message):
        self.stream.write(("\r\x1b[K" if self.tty else "") + message + "\n")
        self.stream.flush()
