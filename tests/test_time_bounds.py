"""Every explorer's time, and Play, is bounded (issue 23, second pass): 1e6, 1e300, inf, nan, −1 and 0 under
a timeout, and the farthest time of each range asked in one update.

* A time outside its range (or not a number) is refused in the package's words, naming the control;
  the shown state stays (controls, readout agree); 0 is computed.
* The end of the range asked at once costs one bounded update: computed, or refused with the limit and
  what to do ("ask again", :class:`planargeo.widgets._motion.Budget`), the shown state kept.
* Play asked for a long run (``advance(seconds=...)``, ``advance(n_frames)``) names the limit.

The deadline is a hang guard (generous: the machine may be loaded), not a speed figure.
"""
from __future__ import annotations

import math

import ipywidgets as W
import pytest

from _limits import time_limit
from planargeo import widgets
from planargeo.errors import InputError

TIME_CONTROLS = ("time (s)", "t (s)", "t")
HOSTILE = (1e6, 1e300, math.inf, math.nan, -1.0)
#: explorers with Play and a time control (checked below against the classes themselves)
TIMED = ["ChainExplorer", "SliderCrankExplorer", "TreeExplorer", "ImpulseExplorer", "ArticulatedExplorer"]


def _time_control(ex) -> str:
    names = [k for k in TIME_CONTROLS if k in ex.controls]
    assert len(names) == 1, names
    return names[0]


def _shown_time(ex, name) -> float:
    return float(ex.values[name])


def test_the_list_of_timed_explorers_is_complete():
    found = []
    for name in widgets.EXPLORERS:
        ex = getattr(widgets, name)(display="agg")
        if ex.has_play and any(k in ex.controls for k in TIME_CONTROLS):
            found.append(name)
    assert sorted(found) == sorted(TIMED)


@pytest.mark.parametrize("name", TIMED)
def test_a_time_outside_its_range_is_refused_by_name_and_0_is_computed(name):
    ex = getattr(widgets, name)(display="agg")
    k = _time_control(ex)
    text = isinstance(ex.controls[k], W.Text)
    shown = dict(ex.readout_values)
    for v in HOSTILE:
        for given in ((v, repr(v)) if text else (v,)):
            with time_limit(60):
                ex.set(**{k: given})
            assert k in ex.message or "time t" in ex.message, (given, ex.message)   # the control named
            assert "overflow" not in ex.message and "invalid value" not in ex.message
            assert _shown_time(ex, k) == 0.0 and ex.readout_values == shown  # the shown state kept
    with time_limit(60):
        ex.set(**{k: "0" if text else 0.0})
    assert _shown_time(ex, k) == 0.0 and ex.readout_values == shown


@pytest.mark.parametrize("name", TIMED)
def test_the_end_of_the_time_range_is_one_bounded_update(name):
    ex = getattr(widgets, name)(display="agg")
    k = _time_control(ex)
    w = ex.controls[k]
    if isinstance(w, W.Text):
        import importlib

        end = getattr(importlib.import_module(type(ex).__module__), "T_END")
        value = f"{end:g}"
    else:
        end = float(w.max)
        value = end
    shown = dict(ex.readout_values)
    with time_limit(60):
        ex.set(**{k: value})
    if ex.message:                          # refused: the limit and what to do, the shown state kept
        assert "ask again" in ex.message and "evaluations of the dynamics" in ex.message, ex.message
        assert _shown_time(ex, k) == 0.0 and ex.readout_values == shown
    else:
        assert _shown_time(ex, k) == pytest.approx(end)
    # the readout's time is the control's
    t_read = next(v for r, v in ex.readout_values.items() if r in ("t", "t (s)", "time (s)", "time"))
    assert float(t_read) == pytest.approx(_shown_time(ex, k))


@pytest.mark.parametrize("name", TIMED)
def test_play_asked_for_a_long_run_names_the_limit(name):
    ex = getattr(widgets, name)(display="agg")
    for bad in (1e6, 1e300):
        with time_limit(60), pytest.raises(InputError, match=r"at most .*allow_long=True"):
            ex.advance(1, seconds=bad)
        with time_limit(60), pytest.raises(InputError, match=r"at most .*allow_long=True"):
            ex.advance(int(bad) if bad < 1e10 else 10 ** 300)
    for bad in (math.inf, math.nan, -1.0, 0.0):
        with time_limit(60), pytest.raises(InputError, match="seconds must be a positive finite number"):
            ex.advance(1, seconds=bad)
        with time_limit(60), pytest.raises(InputError, match="n_frames must be a positive integer"):
            ex.advance(bad)
    assert ex.message == "" and ex.readout_values["t" if "t" in ex.readout_values else next(
        r for r in ex.readout_values if r.startswith("t"))] == 0.0
