"""Times the stages of a long command and prints each as it ends, so a user sees where time goes."""
import sys
import time
from contextlib import contextmanager


class StageTimer:
    def __init__(self, stream=sys.stderr):
        self.seconds = {}
        self._stream = stream
        self._start = time.perf_counter()

    @contextmanager
    def stage(self, name: str, estimate_s: float = None):
        note = f" (estimate {estimate_s / 60:.1f} min)" if estimate_s else ""
        print(f"[krp-train-map] stage '{name}' started{note}", file=self._stream, flush=True)
        t0 = time.perf_counter()
        yield
        self.seconds[name] = time.perf_counter() - t0
        print(f"[krp-train-map] stage '{name}' took {self.seconds[name]:.1f} s", file=self._stream, flush=True)

    def total(self) -> float:
        return time.perf_counter() - self._start
