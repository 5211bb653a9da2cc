"""Times the stages of a long command and prints each as it ends, so a user sees where time goes."""
import sys
import time
from contextlib import contextmanager


# Below this an estimate reads better in seconds than in fractions of a minute.
SECONDS_SHOWN_UP_TO = 90


def duration(seconds: float) -> str:
    """'45 s' or '12.5 min': how long a stage should take, as a person reads it."""
    return f"{seconds:.0f} s" if seconds < SECONDS_SHOWN_UP_TO else f"{seconds / 60:.1f} min"


class StageTimer:
    def __init__(self, stream=sys.stderr):
        self.seconds = {}
        self._stream = stream
        self._start = time.perf_counter()

    @contextmanager
    def stage(self, name: str, estimate_s: float = None):
        note = f" (estimate {duration(estimate_s)})" if estimate_s else ""
        print(f"[krp-train-map] stage '{name}' started{note}", file=self._stream, flush=True)
        t0 = time.perf_counter()
        yield
        self.seconds[name] = time.perf_counter() - t0
        print(f"[krp-train-map] stage '{name}' took {self.seconds[name]:.1f} s", file=self._stream, flush=True)

    def total(self) -> float:
        return time.perf_counter() - self._start
