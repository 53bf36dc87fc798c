"""The fuzz suite itself (issue 23): it reaches the computation, covers every explorer, and catches defects.

* :func:`test_small_run_reaches_the_computation_and_every_explorer` runs a small version of
  ``make fuzz`` (``tests/fuzz/run.py --calls 800``, in a fresh process) and asserts its shares and
  coverage: at least half of the calls computed, every explorer with at least 20 calls (200 at
  ``make fuzz``'s size, scaled down) through drags, slider jumps, the invariant check and, where
  it has Play, Play steps.  The failures it finds in today's code are printed, not asserted: the
  entry points belong to other parts of the package (``make fuzz`` reports them, non-zero).
* The other tests plant defects and check that the harness reports them as failed: explorers
  (defined here) whose state depends on their history, that show numpy's overflow text, that
  keep a value outside a slider's range, that hang, or whose picture cannot be drawn (the page asks for it
  after every action); an explorer whose far time takes several updates ("ask again") keeps the
  invariant, its fresh explorer asking again as the message says; functions that raise a foreign exception,
  return NaN from finite input, or wrap numpy's words in the package's error.  A clean explorer
  and a clean function must come out with no failure (the harness does not fail everything).
"""
from __future__ import annotations

import json
import math
import os
import subprocess
import sys
import time
from pathlib import Path

import hypothesis.strategies as st
import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from fuzz.explorers import fuzz_explorers, readout_difference  # noqa: E402
from fuzz.harness import FOREIGN, HANG, INCONSISTENT, NONFINITE, OK, PACKAGE, Target, run_target  # noqa: E402
from planargeo.errors import InputError, NumericOverflowError  # noqa: E402
from planargeo.widgets import EXPLORERS, Explorer  # noqa: E402
from planargeo.widgets.base import Step  # noqa: E402

RUN = Path(__file__).resolve().parent / "fuzz" / "run.py"
SMALL_CALLS = 800
#: ``make fuzz`` gives every explorer at least 200 calls; the small run at least this many.
SMALL_PER_EXPLORER = 20


@pytest.fixture(scope="module")
def small_run(tmp_path_factory):
    work = tmp_path_factory.mktemp("fuzz")
    out = work / "tallies.json"
    env = dict(os.environ, MPLBACKEND="Agg")
    r = subprocess.run([sys.executable, str(RUN), "--calls", str(SMALL_CALLS), "--seed", "1",
                        "--time-limit", "20", "--json", str(out)],
                       capture_output=True, text=True, timeout=900, env=env, cwd=work)
    assert out.exists(), r.stderr[-3000:]
    data = json.loads(out.read_text())
    failures = r.stdout[r.stdout.find("Failures"):] if "Failures" in r.stdout else ""
    print(f"\nsmall fuzz run (status {r.returncode}): {r.stdout.strip().splitlines()[-1]}\n{failures}")
    data["status"] = r.returncode
    return data


@pytest.mark.slow
def test_small_run_reaches_the_computation_and_every_explorer(small_run):
    s, eps = small_run["summary"], small_run["entry_points"]
    assert s["calls"] >= SMALL_CALLS * 0.9
    assert s["computed_share"] >= 0.5, s
    # every explorer of the package, each with its share of calls, through each path
    assert set(s["explorer_calls"]) == set(EXPLORERS)
    for name, n in s["explorer_calls"].items():
        assert n >= SMALL_PER_EXPLORER, (name, n)
        for action in ("set", "drag", "fresh"):
            assert sum(eps.get(f"{name}.{action}", {}).get("counts", {}).values()) >= 1, (name, action)
    played = [n for n in EXPLORERS if f"{n}.advance" in eps]
    assert len(played) >= 5, played                     # the explorers with Play were played
    # the functions are fuzzed too, most of their calls computed
    funcs = [e for e in eps.values() if e["group"] != "explorer actions"]
    assert len(funcs) >= 150
    computed = sum(e["counts"].get(OK, 0) for e in funcs)
    assert computed >= 0.5 * sum(sum(e["counts"].values()) for e in funcs)
    # the status says whether anything failed
    assert (small_run["status"] != 0) == (s["failed"] > 0)


# ----------------------------------------------------------------------------- planted defects
class _Plain(Explorer):
    """One slider x in [-5, 5]; the readout is y = 2 x (a clean explorer)."""

    title = "plain"
    limits = (-6.0, 6.0, -6.0, 6.0)

    def make_controls(self):
        return {"x": Step(-5.0, 5.0, 0.5, 1.0, "x").make("x")}

    def scene_picture(self, state, view=None):
        from planargeo.draw.picture import Picture

        pic = Picture(view or self.limits, size=self.figure_px)
        pic.marks("dot", [[state["y"] / 2, 0.0]], symbol="x", desc="the dot (1.1)")
        return pic

    def compute(self, values, changed):
        return {"y": 2.0 * values["x"]}

    def readout_of(self, state):
        return {"y": state["y"]}


class _Drifting(_Plain):
    """Its readout depends on how many updates it has seen: a fresh explorer disagrees."""

    def compute(self, values, changed):
        self.k = getattr(self, "k", 0) + 1
        return {"y": 2.0 * values["x"] + 0.001 * self.k}


class _Overflowing(_Plain):
    """Near the top of its range the computation overflows: numpy's words reach the message."""

    def compute(self, values, changed):
        big = np.float64(1e300) * (values["x"] > 4.0)
        return {"y": float(big * np.float64(1e300)) if big else 2.0 * values["x"]}


class _Lenient(_Plain):
    """Keeps any value of x, NaN and 1e300 included (a control that does not validate)."""

    def make_controls(self):
        import ipywidgets as W

        return {"x": W.FloatText(value=1.0, description="x")}

    def compute(self, values, changed):
        return {"y": 2.0 * float(values["x"]) if np.isfinite(float(values["x"])) else 0.0}


class _Slow(_Plain):
    """At the top of its range the computation never ends."""

    def compute(self, values, changed):
        if values["x"] >= 4.0:
            time.sleep(30)
        return super().compute(values, changed)


def _failed(tallies, outcome=None) -> dict:
    return {k: dict(t.counts) for k, t in tallies.items()
            if (t.counts[outcome] if outcome else t.failed)}


def test_clean_explorer_has_no_failure():
    tallies = fuzz_explorers(40, seed=3, hostile_share=0.4, classes={"_Plain": _Plain})
    assert sum(t.calls for t in tallies.values()) >= 40
    assert not _failed(tallies)
    assert tallies["_Plain.fresh"].counts[OK] >= 3
    assert tallies["_Plain.set"].counts[PACKAGE] >= 1        # values from outside the range: refused


def test_history_dependent_state_is_found():
    tallies = fuzz_explorers(40, seed=3, classes={"_Drifting": _Drifting})
    assert tallies["_Drifting.fresh"].counts[INCONSISTENT] >= 1
    assert "in a fresh explorer" in tallies["_Drifting.fresh"].examples[INCONSISTENT]


def test_numpy_words_in_the_message_are_found():
    tallies = fuzz_explorers(40, seed=3, classes={"_Overflowing": _Overflowing})
    assert tallies["_Overflowing.set"].counts[FOREIGN] >= 1
    assert "overflow encountered" in tallies["_Overflowing.set"].examples[FOREIGN]


def test_a_kept_value_outside_the_domain_is_found():
    tallies = fuzz_explorers(40, seed=3, hostile_share=0.5, classes={"_Lenient": _Lenient})
    assert _failed(tallies, FOREIGN), {k: t.examples for k, t in tallies.items()}


def test_a_hang_is_found_and_the_run_goes_on():
    t0 = time.perf_counter()
    tallies = fuzz_explorers(40, seed=3, time_limit=3.0, classes={"_Slow": _Slow})
    assert _failed(tallies, HANG)
    assert time.perf_counter() - t0 < 60                      # one hang per action, then it is left
    assert sum(t.counts[OK] for t in tallies.values()) >= 5   # the run went on with a new explorer


def test_readout_comparison_is_relative():
    assert readout_difference({"E": 1.0, "s": "at rest"}, {"E": 1.0 + 1e-12, "s": "at rest"}) is None
    assert readout_difference({"E": 47.5}, {"E": 44.9})
    assert readout_difference({"E": 1e-300}, {"E": 0.0}, atol=1e-9) is None
    assert readout_difference({"p": np.array([1.0, 2.0])}, {"p": np.array([1.0, 2.0 + 1e-6])})
    assert readout_difference({"a": 1.0}, {"a": 1.0, "b": 2.0})
    assert readout_difference({"n": math.nan}, {"n": math.nan}) is None


def _kinds(fn, strategy, n=30):
    return dict(run_target(Target("f", fn, strategy), n, seed=0).counts)


def test_function_failures_are_found():
    finite = st.floats(-10, 10).map(lambda x: ((x,), {}))

    def foreign(x):
        raise ValueError("all input arrays must have the same shape")

    def nonfinite(x):
        return np.array([x, math.nan])

    def wrapped(x):
        raise NumericOverflowError("cannot compute: overflow encountered in scalar multiply")

    def clean(x):
        if x > 5:
            raise InputError("x must be at most 5")
        return 2 * x

    assert _kinds(foreign, finite).get(FOREIGN) == 30
    assert _kinds(nonfinite, finite).get(NONFINITE) == 30
    assert _kinds(wrapped, finite).get(FOREIGN) == 30
    c = _kinds(clean, finite)
    assert set(c) <= {OK, PACKAGE} and c.get(OK) and c.get(PACKAGE), c


class _Undrawable(_Plain):
    """Its picture cannot be drawn near the top of its range (the page would show nothing)."""

    def scene_picture(self, state, view=None):
        if state["y"] >= 8.0:
            raise ZeroDivisionError("float division by zero")
        return super().scene_picture(state, view)


def test_a_picture_that_cannot_be_drawn_is_found_and_the_run_goes_on():
    tallies = fuzz_explorers(60, seed=3, classes={"_Undrawable": _Undrawable})
    found = _failed(tallies, FOREIGN)
    assert found, {k: dict(t.counts) for k, t in tallies.items()}
    examples = " ".join(str(e) for t in tallies.values() for e in t.examples.values())
    assert "ex.picture() raised ZeroDivisionError" in examples
    assert sum(t.calls for t in tallies.values()) >= 60          # the run went on


class _FarTime(_Plain):
    """A time control whose far values take several updates: beyond 2 s past the time reached, the update
    is refused with the package's words ("ask again") and the time reached moves on 2 s (a budget)."""

    def make_controls(self):
        return {**super().make_controls(), "time (s)": Step(0.0, 10.0, 0.5, 0.0, "time (s)").make("time")}

    def compute(self, values, changed):
        from planargeo.errors import SizeLimitError

        reached = getattr(self, "reached", 0.0)
        t = float(values["time (s)"])
        if t > reached + 2.0:
            self.reached = reached + 2.0
            raise SizeLimitError(f"t = {t:g} s is more motion than one step computes; it is computed up to "
                                 f"t = {self.reached:g} s now: ask again to go on from there, or press Play")
        self.reached = max(reached, t)
        return {"y": 2.0 * values["x"] + t}


def test_a_far_time_is_reached_by_asking_again_in_the_fresh_check():
    """The invariant holds for a time that one update cannot reach: the fresh explorer asks again."""
    from fuzz.explorers import fresh_explorer

    ex = _FarTime(display="agg")
    for t in (2.0, 4.0, 6.0, 7.5):
        ex.set(**{"time (s)": t})
    assert ex.values["time (s)"] == 7.5 and ex.message == ""
    from planargeo.errors import SizeLimitError

    with pytest.raises(SizeLimitError, match="ask again"):
        _FarTime(display="agg", **ex.values)
    ref = fresh_explorer(_FarTime, dict(ex.values))
    assert ref.values["time (s)"] == 7.5 and ref.readout_values == ex.readout_values
    tallies = fuzz_explorers(60, seed=3, classes={"_FarTime": _FarTime})
    assert not _failed(tallies), {k: t.examples for k, t in tallies.items() if t.failed}
