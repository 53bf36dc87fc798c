"""Run one call and classify its outcome; run a target's strategy through hypothesis and count.

Examples
--------
>>> from fuzz.harness import Target, classify
>>> import hypothesis.strategies as st
>>> t = Target("float", float, st.just(((1.0,), {})))
>>> classify(t, ("2",), {}).outcome, classify(t, ("x",), {}).outcome
('ok', 'foreign')
"""
from __future__ import annotations

import contextlib
import dataclasses
import math
import signal
import time
import warnings
from collections import Counter
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from planargeo.errors import PlanargeoError

OK, PACKAGE, FOREIGN, NONFINITE, HANG, INCONSISTENT = (
    "ok", "package error", "foreign", "non-finite", "hang", "inconsistent")
OUTCOMES = (OK, PACKAGE, FOREIGN, NONFINITE, HANG, INCONSISTENT)
#: The outcomes that are defects.
BAD = (FOREIGN, NONFINITE, HANG, INCONSISTENT)


#: numpy's default floating-point error handling (underflow to zero or a subnormal is no defect).
NUMPY_ERRORS = dict(divide="warn", over="warn", invalid="warn", under="ignore")


class Hang(BaseException):
    """Raised by the alarm inside a call past its time limit (a BaseException: no ``except Exception`` stops it)."""


@dataclass
class Target:
    """One entry point: ``fn(*args, **kwargs)`` with ``(args, kwargs)`` drawn from ``strategy``.

    Attributes
    ----------
    name : str
        Shown in the table, e.g. ``"projective.join"``.
    fn : callable
    strategy : hypothesis strategy of ``(args, kwargs)``
    group : str
        The area (and engineer) it belongs to: geometry, screws, mechanics, kernels, scenes,
        simulate, cli, explorers, files.
    nonfinite_ok : callable ``(args, kwargs, result) -> bool``, optional
        True where a non-finite result is documented (points at infinity...).
    check : callable ``(args, kwargs, result) -> (outcome, detail) or None``, optional
        Classifies a returned result itself (e.g. the command line's status and output, an
        explorer's consistency); None: go on with the finiteness check.
    timeout : float
        Seconds before a call counts as a hang.
    weight : float
        Share of the calls of a run (relative to 1).
    """

    name: str
    fn: Callable
    strategy: Any
    group: str = "misc"
    nonfinite_ok: Callable | None = None
    check: Callable | None = None
    timeout: float = 5.0
    weight: float = 1.0


@dataclass
class Result:
    outcome: str
    detail: str = ""


@dataclass
class Tally:
    """Counts of one target's outcomes, the first example of each defect and the time spent."""

    counts: Counter = field(default_factory=Counter)
    examples: dict = field(default_factory=dict)
    seconds: float = 0.0

    @property
    def calls(self) -> int:
        return sum(self.counts.values())

    @property
    def defects(self) -> int:
        return sum(self.counts[o] for o in BAD)


@contextlib.contextmanager
def time_limit(seconds: float):
    """Raise :class:`Hang` in the main thread after ``seconds`` (SIGALRM; POSIX)."""
    def alarm(signum, frame):
        raise Hang(f"no answer within {seconds:g} s")

    old = signal.signal(signal.SIGALRM, alarm)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def _numbers(x, depth=0, seen=None):
    """Every float/complex value reachable in ``x`` (arrays, containers, dataclasses, simple objects)."""
    if seen is None:
        seen = set()
    if depth > 6 or id(x) in seen:
        return
    if isinstance(x, (bool, np.bool_, str, bytes, int, np.integer)) or x is None:
        return
    if isinstance(x, (float, complex, np.floating, np.complexfloating)):
        yield x
        return
    seen.add(id(x))
    if isinstance(x, np.ndarray):
        if x.dtype.kind in "fc":
            yield from x.ravel()[:10_000]
        elif x.dtype == object:
            for v in x.ravel()[:1000]:
                yield from _numbers(v, depth + 1, seen)
        return
    if isinstance(x, dict):
        for v in x.values():
            yield from _numbers(v, depth + 1, seen)
        return
    if isinstance(x, (list, tuple, set, frozenset)):
        for v in list(x)[:10_000]:
            yield from _numbers(v, depth + 1, seen)
        return
    if dataclasses.is_dataclass(x):
        for f in dataclasses.fields(x):
            yield from _numbers(getattr(x, f.name, None), depth + 1, seen)
        return
    arr = getattr(type(x), "array", None)
    if isinstance(arr, property):          # planargeo's thin classes (Point, Line, Twist, Inertia...)
        yield from _numbers(x.array, depth + 1, seen)


def all_finite(x) -> bool:
    """True when every number reachable in ``x`` is finite.

    >>> all_finite({"a": [1.0, (2, 3j)]}), all_finite([1.0, float("nan")])
    (True, False)
    """
    for v in _numbers(x):
        c = complex(v)
        if not (math.isfinite(c.real) and math.isfinite(c.imag)):
            return False
    return True


def _short(x, n: int = 160) -> str:
    with np.printoptions(threshold=12, edgeitems=2, precision=4):
        s = repr(x)
    return s if len(s) <= n else s[:n - 3] + "..."


def call_repr(name: str, args, kwargs) -> str:
    parts = [_short(a, 80) for a in args] + [f"{k}={_short(v, 80)}" for k, v in kwargs.items()]
    return f"{name}({', '.join(parts)})"


def classify(target: Target, args, kwargs) -> Result:
    """Call ``target.fn(*args, **kwargs)`` once and classify what happened."""
    try:
        with time_limit(target.timeout), warnings.catch_warnings(), np.errstate(**NUMPY_ERRORS):
            warnings.simplefilter("error")
            out = target.fn(*args, **kwargs)
    except Hang as exc:
        return Result(HANG, str(exc))
    except PlanargeoError:
        return Result(PACKAGE)
    except Exception as exc:  # noqa: BLE001 - the point: anything else is foreign
        return Result(FOREIGN, f"{type(exc).__module__}.{type(exc).__name__}: {str(exc)[:200]}")
    if target.check is not None:
        verdict = target.check(args, kwargs, out)
        if verdict is not None:
            return Result(*verdict)
    if not all_finite(out) and all_finite((args, kwargs)):
        if target.nonfinite_ok is None or not target.nonfinite_ok(args, kwargs, out):
            return Result(NONFINITE, f"returned {_short(out)}")
    return Result(OK)


def run_target(target: Target, examples: int, *, seed: int | None = None, tally: Tally | None = None,
               derandomize: bool = False) -> Tally:
    """Draw ``examples`` argument sets from ``target.strategy`` and classify each call."""
    from hypothesis import HealthCheck, Phase, given, settings

    tally = tally or Tally()

    @settings(max_examples=examples, database=None, deadline=None, derandomize=derandomize,
              phases=[Phase.generate], suppress_health_check=list(HealthCheck), print_blob=False)
    @given(target.strategy)
    def one(call):
        args, kwargs = call
        r = classify(target, args, kwargs)
        tally.counts[r.outcome] += 1
        if r.outcome in BAD and r.outcome not in tally.examples:
            tally.examples[r.outcome] = f"{call_repr(target.name, args, kwargs)} -> {r.detail}"

    t0 = time.perf_counter()
    if seed is not None and not derandomize:
        from hypothesis import seed as hseed

        one = hseed(seed)(one)
    one()
    tally.seconds += time.perf_counter() - t0
    return tally
