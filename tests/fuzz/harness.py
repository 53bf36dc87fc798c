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

import dataclasses
import math
import re
import time
import warnings
from collections import Counter
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from _limits import Hang, time_limit  # noqa: F401  (the hang guard, shared with the tests)
from planargeo.errors import PlanargeoError

OK, PACKAGE, FOREIGN, NONFINITE, HANG, INCONSISTENT = (
    "ok", "package error", "foreign", "non-finite", "hang", "inconsistent")
OUTCOMES = (OK, PACKAGE, FOREIGN, NONFINITE, HANG, INCONSISTENT)
#: The outcomes that are defects (a call *failed*); ``ok`` is *computed*, ``package error`` *refused*.
BAD = FAILED_OUTCOMES = (FOREIGN, NONFINITE, HANG, INCONSISTENT)

#: Words of numpy, Python or the explorers' catch-all that must never reach a user.
FOREIGN_WORDS = ("overflow encountered", "invalid value encountered", "divide by zero",
                 "underflow encountered", "Traceback (most recent call last)", "internal error",
                 "drawing failed")
_TRACE = re.compile(r'File "[^"]+", line \d+')


def foreign_text(text: str) -> str | None:
    """The foreign phrase in a text shown to a user (numpy's words, a traceback), or None.

    >>> foreign_text("cannot compute this configuration: overflow encountered in scalar multiply")
    'overflow encountered'
    >>> foreign_text("joint speeds must be finite numbers") is None
    True
    """
    for w in FOREIGN_WORDS:
        if w in text:
            return w
    if _TRACE.search(text):
        return "a traceback"
    return None


#: numpy's default floating-point error handling (underflow to zero or a subnormal is no defect).
NUMPY_ERRORS = dict(divide="warn", over="warn", invalid="warn", under="ignore")


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


#: Key of :attr:`Tally.examples` holding the first refusals (why calls were refused).
REFUSALS = "refused"


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

    failed = defects

    @property
    def computed(self) -> int:
        return self.counts[OK]

    @property
    def refused(self) -> int:
        return self.counts[PACKAGE]


def note_refusal(tally: Tally, r: Result, keep: int = 3) -> None:
    """Keep the first ``keep`` distinct reasons of refusal (``run.py --refusals`` shows them)."""
    if r.outcome == PACKAGE and r.detail:
        seen = tally.examples.setdefault(REFUSALS, [])
        if len(seen) < keep and r.detail not in seen:
            seen.append(r.detail)


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


def classify(target: Target, args, kwargs, timeout: float | None = None) -> Result:
    """Call ``target.fn(*args, **kwargs)`` once and classify what happened (``timeout``: hang limit)."""
    try:
        with time_limit(timeout or target.timeout), warnings.catch_warnings(), np.errstate(**NUMPY_ERRORS):
            warnings.simplefilter("error")
            out = target.fn(*args, **kwargs)
    except Hang as exc:
        return Result(HANG, str(exc))
    except PlanargeoError as exc:
        w = foreign_text(str(exc))
        if w:
            return Result(FOREIGN, f"{type(exc).__name__} in numpy's or Python's words ({w!r}): {str(exc)[:200]}")
        return Result(PACKAGE, f"{type(exc).__name__}: {str(exc)[:160]}")
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
               derandomize: bool = False, timeout: float | None = None) -> Tally:
    """Draw ``examples`` argument sets from ``target.strategy`` and classify each call.

    ``timeout`` (seconds) overrides the target's hang limit; after a hang the target is not
    called again (its remaining examples are skipped), which keeps a run bounded.
    """
    from hypothesis import HealthCheck, Phase, given, settings

    tally = tally or Tally()

    @settings(max_examples=examples, database=None, deadline=None, derandomize=derandomize,
              phases=[Phase.generate], suppress_health_check=list(HealthCheck), print_blob=False)
    @given(target.strategy)
    def one(call):
        if tally.counts[HANG]:
            return
        args, kwargs = call
        r = classify(target, args, kwargs, timeout)
        tally.counts[r.outcome] += 1
        if r.outcome in BAD and r.outcome not in tally.examples:
            tally.examples[r.outcome] = f"{call_repr(target.name, args, kwargs)} -> {r.detail}"
        note_refusal(tally, r)

    t0 = time.perf_counter()
    if seed is not None and not derandomize:
        from hypothesis import seed as hseed

        one = hseed(seed)(one)
    one()
    tally.seconds += time.perf_counter() - t0
    return tally
