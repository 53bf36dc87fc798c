"""Explorers fuzzed the way a user works them: action sequences, then the one-state invariant.

Each explorer (:data:`planargeo.widgets.EXPLORERS`, ``display="agg"``) is driven by seeded random
action sequences through the paths of the mouse and the page:

* ``set`` — slider jumps, dropdown and checkbox picks, text entries, 1-3 controls at once, with
  values from each control's documented domain (:func:`control_value`: both ends, one step inside
  them, 0 and ±1e-300 where in range, grid and off-grid values), and at times a value outside it
  (NaN, ±inf, past an end, another type: it must be refused, never kept);
* ``drag`` — :meth:`~planargeo.widgets.Explorer.drag` of every handle from where it is to points
  near it, across the view and far off it (10³ and 10⁶ view sizes away);
* ``advance`` — Play steps (at a random Play speed);
* ``reset`` — the *Reset* button;
* ``export`` — the *SVG* and *PNG* buttons (into a scratch folder) and a short GIF;
* ``simulate`` — an explorer's own long-running method (the chain's ``simulate(duration)``), with
  durations in and out of its domain (1e6, 1e300, inf, nan, -1, 0, 1e-300);
* ``fresh`` — after each sequence, the invariant: ``type(ex)(display="agg", **ex.values)`` shows the
  same readout numbers as ``ex`` (to 1e-9 relative, round-off below ``zero_tol · scale`` equal to 0).
  A time further than one update computes (the chain's and the slider-crank's time: a
  :class:`~planargeo.errors.SizeLimitError` saying "ask again") is reached the way its message says:
  the fresh explorer is made at its default time, then asked for that time again until it is
  computed (:func:`fresh_explorer`).

An action *failed* when an exception escaped it, when the explorer shows numpy's words
("overflow encountered", "invalid value encountered", "divide by zero"), a Python traceback, an
"internal error" or a failed export, when it kept a value outside a control's domain, when a
readout is NaN with no message, when it took longer than the time limit (a hang), or when the fresh
explorer disagrees or cannot be built.  It was *refused* when the explorer showed its own message
(the previous state kept) or raised a :class:`~planargeo.errors.PlanargeoError`, else *computed*.

>>> import random
>>> from planargeo.widgets import CarExplorer
>>> ex = CarExplorer(display="agg")
>>> v = control_value(random.Random(0), ex.controls["drive force (N)"], ex, valid=True)
>>> -6000.0 <= v <= 6000.0
True
"""
from __future__ import annotations

import math
import numbers
import random
import re
import tempfile
import time
import warnings
from pathlib import Path
from typing import Any, Callable

import numpy as np

from fuzz.harness import (FAILED_OUTCOMES, FOREIGN, HANG, INCONSISTENT, NUMPY_ERRORS, OK, PACKAGE, Hang,
                          Result, Tally, foreign_text, note_refusal, time_limit)
from planargeo.errors import PlanargeoError

#: Relative tolerance of the invariant (readout numbers of ``ex`` and of a fresh explorer).
RTOL = 1e-9


def _numbers_close(a, b, atol: float) -> bool:
    if isinstance(a, (bool, np.bool_)) or isinstance(b, (bool, np.bool_)):
        return bool(a) == bool(b)
    if isinstance(a, numbers.Number) and isinstance(b, numbers.Number):
        a, b = complex(a), complex(b)
        for x, y in ((a.real, b.real), (a.imag, b.imag)):
            if math.isnan(x) or math.isnan(y):
                if not (math.isnan(x) and math.isnan(y)):
                    return False
            elif not (x == y or math.isclose(x, y, rel_tol=RTOL, abs_tol=atol)):
                return False
        return True
    if isinstance(a, (np.ndarray, list, tuple)) or isinstance(b, (np.ndarray, list, tuple)):
        try:
            A, B = np.asarray(a), np.asarray(b)
        except Exception:  # noqa: BLE001 - ragged
            A = B = None
        if A is not None and A.dtype.kind in "biufc" and B.dtype.kind in "biufc":
            return A.shape == B.shape and all(_numbers_close(x, y, atol) for x, y in zip(A.ravel(), B.ravel()))
        if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
            return len(a) == len(b) and all(_numbers_close(x, y, atol) for x, y in zip(a, b))
        return False
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(_numbers_close(a[k], b[k], atol) for k in a)
    try:
        return bool(a == b)
    except Exception:  # noqa: BLE001
        return repr(a) == repr(b)


def readout_difference(a: dict, b: dict, atol: float = 0.0) -> str | None:
    """The first readout entry where ``a`` and ``b`` differ (numbers to :data:`RTOL`), or None.

    >>> readout_difference({"E": 1.0, "case": "x"}, {"E": 1.0 + 1e-12, "case": "x"}) is None
    True
    >>> readout_difference({"E": 47.5}, {"E": 44.9})
    "'E': 47.5 here, 44.9 in a fresh explorer"
    """
    if list(a) != list(b):
        return f"entries {sorted(set(a) ^ set(b))[:3] or 'in another order'} differ"
    for k in a:
        if not _numbers_close(a[k], b[k], atol):
            return f"{k!r}: {_short(a[k])} here, {_short(b[k])} in a fresh explorer"
    return None


def _short(x, n=60) -> str:
    with np.printoptions(precision=6, threshold=6):
        s = repr(x)
    return s if len(s) <= n else s[:n - 3] + "..."


#: controls that hold a scene time (a far one may take several updates: "ask again")
TIME_CONTROLS = ("time (s)", "t (s)", "t")
#: updates a fresh explorer may ask for a far time before the invariant counts it as failed
MAX_ASKS = 40


def fresh_explorer(cls, values: dict):
    """``cls(display="agg", **values)``; a time beyond one update's work reached by asking again.

    A :class:`~planargeo.errors.SizeLimitError` whose message says "ask again" (a time further than
    one update computes) is not a refusal of the values: the explorer is made at its default time,
    then its time control is set to the value again, as the message says, until it is shown.

    Raises
    ------
    Exception
        What the constructor raised for any other reason, or the last refusal after
        :data:`MAX_ASKS` asks (as :class:`~planargeo.errors.PlanargeoError`).
    """
    from planargeo.errors import SizeLimitError

    try:
        return cls(display="agg", **values)
    except SizeLimitError as exc:
        if "ask again" not in str(exc):
            raise
        first = exc
    times = {k: v for k, v in values.items() if k in TIME_CONTROLS}
    if not times:
        raise first
    ref = cls(display="agg", **{k: v for k, v in values.items() if k not in times})
    for _ in range(MAX_ASKS):
        ref.set(**times)
        if all(_numbers_close(ref.values[k], v, 0.0) if isinstance(v, numbers.Number) else ref.values[k] == v
               for k, v in times.items()):
            return ref
        if "ask again" not in (ref.message or ""):
            raise PlanargeoError(f"a fresh explorer asked for {times} refuses it: {ref.message}")
    raise PlanargeoError(f"a fresh explorer asked {MAX_ASKS} times for {times} has not reached it: {ref.message}")


# ----------------------------------------------------------------------------- values
def _slider_values(w) -> tuple[list, float]:
    lo, hi = float(w.min), float(w.max)
    step = float(w.step or 0) or (hi - lo) / 100
    vals = [lo, hi, lo + step, hi - step, (lo + hi) / 2]
    if lo <= 0.0 <= hi:
        vals += [0.0, 1e-300, -1e-300, 5e-324, -5e-324, 1e-12, -1e-12]
    if lo > 0:
        vals += [lo * (1 + 1e-12), lo + 1e-300]
    vals += [hi - (hi - lo) * 1e-12, lo + (hi - lo) * 1e-12]
    return [v for v in vals if lo <= v <= hi], step


def control_value(rng: random.Random, w, ex, *, valid: bool = True, name: str = "") -> Any:
    """A value for control ``w`` from its documented domain (``valid``), or from outside it.

    Sliders: an end, one step inside an end, 0 and ±1e-300 where in range, the end minus a
    relative 1e-12, a value on the grid, or any value in range; lists: an option; checkboxes: a
    bool; text boxes: what :func:`text_value` makes for the control.
    """
    import ipywidgets as W

    if isinstance(w, (W.FloatSlider, W.IntSlider)):
        integer = isinstance(w, W.IntSlider)
        lo, hi = w.min, w.max
        if not valid:
            return rng.choice([hi + (w.step or 1), lo - (w.step or 1), float("nan"), float("inf"),
                               -float("inf"), 1e300, -1e300, None, "1", True, 1 + 2j, [lo]]
                              + ([lo + 0.5] if integer and hi > lo else []))
        if integer:
            return rng.choice([lo, hi, min(lo + 1, hi), max(hi - 1, lo), rng.randint(lo, hi)])
        ends, step = _slider_values(w)
        r = rng.random()
        if r < 0.45:
            return rng.choice(ends)
        if r < 0.7 and step > 0:
            k = rng.randint(0, int(round((hi - lo) / step)))
            return min(hi, lo + k * step)
        return rng.uniform(lo, hi)
    if isinstance(w, (W.Dropdown, W.ToggleButtons, W.RadioButtons, W.Select)):
        options = [o[1] if isinstance(o, tuple) else o for o in w.options]
        if not valid:
            return rng.choice(["", "nope", None, 3, str(options[0]).upper() + " "])
        return rng.choice(options)
    if isinstance(w, W.Checkbox):
        if not valid:
            return rng.choice([None, "yes", 2, float("nan")])
        return rng.choice([True, False])
    if isinstance(w, W.Text):
        return text_value(rng, name, ex, valid=valid)
    if isinstance(w, (W.FloatText, W.IntText)):
        if not valid:
            return rng.choice([float("nan"), float("inf"), 1e300, -1e300])
        return rng.randint(-10, 10) if isinstance(w, W.IntText) else rng.uniform(-10, 10)
    return None


def _numbers_text(rng: random.Random, n: int, scale: float, extreme: bool) -> str:
    xs = []
    for _ in range(n):
        r = rng.random()
        if extreme and r < 0.3:
            xs.append(rng.choice([1e-300, -1e-300, 5e-324, 0.0, 1e150, -1e150, 1e300, -1e300, 1e6]))
        else:
            xs.append(rng.uniform(-scale, scale))
    return rng.choice([", ", ",", "; ", " , "]).join(rng.choice([f"{x:g}", f"{x!r}", f"{x:.3f}"]) for x in xs)


def text_value(rng: random.Random, name: str, ex, *, valid: bool = True) -> str:
    """Text for the text box ``name`` of ``ex``: lists of numbers (chain), polygons (percussion)."""
    if not valid:
        return rng.choice(["x", "1,,2", "nan", "inf, 1", "1e400", "[1, 2]", "1 2", "0,0; 1", "∞",
                           "1;2;3;4;5;6;7;8;9;10;11;12;13;14;15;16;17;18;19;20;21;22", "\0"])
    if name == "polygon":
        r = rng.random()
        if r < 0.4:
            k = rng.randint(3, 8)
            rad = rng.choice([0.05, 0.5, 1.0, 3.0])
            pts = [(rad * math.cos(2 * math.pi * i / k + 0.1), rad * math.sin(2 * math.pi * i / k + 0.1))
                   for i in range(k)]
        elif r < 0.7:
            w_, h_ = rng.uniform(0.01, 2.0), rng.uniform(0.01, 1.0)
            pts = [(0, -h_ / 2), (w_, -h_ / 2), (w_, h_ / 2), (0, h_ / 2)]
        elif r < 0.85:
            pts = [(0, 0), (1, 0), (0, 1)]
        else:                                   # extreme sizes, still polygons
            s = rng.choice([1e-6, 1e-150, 1e6, 1e150])
            pts = [(0, 0), (s, 0), (s, s), (0, s)]
        return "; ".join(f"{x:g}, {y:g}" for x, y in pts)
    n = int(ex.values.get("links", 1)) if "links" in ex.controls else rng.randint(1, 4)
    if rng.random() < 0.15:
        return ""                                              # the pattern controls again
    scale = {"joint speeds": 5.0, "joint torques": 50.0}.get(name, 90.0)
    return _numbers_text(rng, n, scale, extreme=rng.random() < 0.3)


# ----------------------------------------------------------------------------- actions
def _check_shown(ex) -> tuple[str, str] | None:
    """A failure visible on the explorer now: foreign words, a failed export, NaN without a message."""
    msg = ex.message or ""
    w = foreign_text(msg)
    if w:
        return FOREIGN, f"message shows {w!r}: {msg[:200]!r}"
    label = getattr(getattr(ex, "export_label", None), "value", "") or ""
    if "export failed" in label:
        return FOREIGN, f"export failed into a writable scratch folder: {re.sub('<[^>]+>', '', label)[:200]!r}"
    if not msg:
        for k, v in ex.readout_values.items():
            if isinstance(v, (float, np.floating)) and math.isnan(v):
                return INCONSISTENT, f"readout {k!r} is NaN with no message"
    return None


def _picture_failure(ex) -> tuple[str, str] | None:
    """The page draws the shown state after every action: :meth:`picture` must not raise."""
    try:
        ex.picture()
    except Exception as exc:  # noqa: BLE001 - the page would show nothing
        return FOREIGN, f"ex.picture() raised {type(exc).__name__}: {str(exc)[:200]}"
    return None


class ExplorerFuzzer:
    """Drive one explorer class with seeded action sequences and tally each action.

    Parameters
    ----------
    cls : type
        An :class:`~planargeo.widgets.Explorer` subclass.
    rng : random.Random
    time_limit : float
        Seconds after which one action counts as a hang.
    scratch : Path
        Folder for exports.
    hostile_share : float
        Share of ``set`` actions with one value from outside its control's domain.
    """

    WEIGHTS = {"set": 44, "drag": 26, "advance": 14, "reset": 4, "export": 3, "simulate": 4}

    def __init__(self, cls, rng: random.Random, time_limit: float, scratch: Path,
                 hostile_share: float = 0.12, log: Callable[[str], None] | None = None):
        self.cls, self.rng, self.limit, self.scratch = cls, rng, float(time_limit), scratch
        self.hostile_share = hostile_share
        self.name = cls.__name__
        self.tallies: dict[str, Tally] = {}
        self.stopped: set[str] = set()        # actions that hung once are not tried again
        self.ex = None
        self.log = log or (lambda s: None)
        #: the actions since the explorer was made: ``(text, replay(ex))`` (for reproducers)
        self.history: list[tuple[str, Callable]] = []
        self.minimize_budget = 30             # replays spent shortening reproducers, per fuzzer
        self.minimize_seconds = 20.0          # and seconds

    # -- bookkeeping
    def _tally(self, action: str) -> Tally:
        return self.tallies.setdefault(f"{self.name}.{action}", Tally())

    def _record(self, action: str, outcome: str, detail: str, seconds: float) -> None:
        t = self._tally(action)
        t.counts[outcome] += 1
        t.seconds += seconds
        note_refusal(t, Result(outcome, detail))
        if outcome in FAILED_OUTCOMES and outcome not in t.examples:
            if action == "new":
                t.examples[outcome] = detail
                return
            steps = list(self.history)
            if outcome == HANG:
                if action != "fresh" and steps and self._hangs(steps[-1:]):
                    steps = steps[-1:]                   # the last action alone hangs
                elif len(steps) > 12:
                    steps = [(f"... {len(steps) - 10} earlier actions ...", None)] + steps[-10:]
            else:
                steps = self._minimize(steps, fresh=(action == "fresh"))
            text = "; ".join(x for x, _ in steps)
            tail = f"; {self.name}(display='agg', **ex.values)" if action == "fresh" else ""
            t.examples[outcome] = f"ex = {self.name}(display='agg'); {text}{tail} -> {detail}"

    def _hangs(self, steps) -> bool:
        """Replay ``steps`` on a new explorer: does it hang again?"""
        if self.minimize_budget <= 0:
            return False
        self.minimize_budget -= 3
        ex = None
        try:
            ex = self.cls(display="agg", export_dir=self.scratch)
            with time_limit(self.limit), np.errstate(**NUMPY_ERRORS), warnings.catch_warnings():
                warnings.simplefilter("ignore")
                for _, fn in steps:
                    fn(ex)
        except Hang:
            return True
        except BaseException:  # noqa: BLE001
            return False
        return False

    def _reproduces(self, steps, fresh: bool) -> bool:
        """Replay ``steps`` on a new explorer: does it fail again (the invariant, or what it shows)?"""
        try:
            with time_limit(self.limit), np.errstate(**NUMPY_ERRORS), \
                    warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                ex = self.cls(display="agg", export_dir=self.scratch)
                for i, (_, fn) in enumerate(steps):
                    try:
                        fn(ex)
                    except PlanargeoError:
                        pass
                    except Exception:  # noqa: BLE001
                        return not fresh and i == len(steps) - 1
                if not fresh:
                    return _picture_failure(ex) is not None or _check_shown(ex) is not None or any(
                        issubclass(w.category, RuntimeWarning) for w in caught)
                try:
                    ref = fresh_explorer(self.cls, dict(ex.values))
                except Exception:  # noqa: BLE001
                    return True
                atol = float(getattr(ex, "zero_tol", 1e-9)) * float(getattr(ex, "scale", 1.0))
                return readout_difference(ex.readout_values, ref.readout_values, atol) is not None
        except BaseException:  # noqa: BLE001 - a hang or anything else: not this failure
            return False

    def _minimize(self, steps, fresh: bool):
        """A shorter list of steps that still fails (one step dropped at a time, within a budget).

        The last 1, 4, 16 actions are tried first (a long history replays slowly), then the
        whole history; then one action at a time is dropped while the failure stays.
        """
        for k in (1, 4, 16, len(steps)):
            if self.minimize_budget <= 0:
                return steps
            self.minimize_budget -= 1
            if k <= len(steps) and self._reproduces(steps[-k:], fresh):
                steps = steps[-k:]
                break
        else:
            return steps
        i, t0 = 0, time.perf_counter()
        while i < len(steps) and self.minimize_budget > 0 and \
                time.perf_counter() - t0 < self.minimize_seconds:
            if not fresh and i == len(steps) - 1:
                break                                    # the failing action itself stays
            trial = steps[:i] + steps[i + 1:]
            self.minimize_budget -= 1
            if self._reproduces(trial, fresh):
                steps = trial
            else:
                i += 1
        return steps

    def calls(self) -> int:
        return sum(t.calls for t in self.tallies.values())

    def _new(self) -> None:
        t0 = time.perf_counter()
        self.history = []
        try:
            with time_limit(self.limit), np.errstate(**NUMPY_ERRORS):
                self.ex = self.cls(display="agg", export_dir=self.scratch)
        except Hang as exc:
            self._record("new", HANG, f"{self.name}(display='agg') -> {exc}", time.perf_counter() - t0)
            raise
        self._record("new", OK, "", time.perf_counter() - t0)

    # -- one action
    def _run(self, action: str, fn: Callable[[Any], Any], text: str,
             check: Callable[[Any], tuple[str, str] | None] | None = None) -> None:
        """Apply ``fn(ex)`` (the action ``text``) under the time limit and tally what became of it."""
        ex = self.ex
        self.history.append((text, fn))
        before = (ex.n_updates, ex.message)
        t0 = time.perf_counter()
        try:
            with time_limit(self.limit), np.errstate(**NUMPY_ERRORS), \
                    warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                out = fn(ex)
                drawn = _picture_failure(ex)        # what the page asks next
        except Hang as exc:
            self._record(action, HANG, str(exc), time.perf_counter() - t0)
            self.stopped.add(action)
            self.ex = None                     # interrupted mid-update: not trusted any more
            self.log(f"  {self.name}.{action}: hang ({text}); not tried again")
            return
        except PlanargeoError as exc:
            self._record(action, PACKAGE, f"{type(exc).__name__}: {str(exc)[:160]}", time.perf_counter() - t0)
            return
        except Exception as exc:  # noqa: BLE001 - escaped the explorer: a failure
            self._record(action, FOREIGN, f"raised {type(exc).__name__}: {str(exc)[:200]}",
                         time.perf_counter() - t0)
            self.ex = None
            return
        dt = time.perf_counter() - t0
        numpy_words = [w for w in caught if issubclass(w.category, RuntimeWarning)]
        verdict = drawn or _check_shown(ex) or (check(out) if check else None) or (
            (FOREIGN, f"a warning reached the user: {numpy_words[0].category.__name__}: {numpy_words[0].message} "
                      f"({Path(numpy_words[0].filename).name}:{numpy_words[0].lineno})") if numpy_words else None)
        if verdict:
            self._record(action, *verdict, dt)
            if verdict is drawn:
                self.ex = None                 # its picture cannot be drawn: a new explorer
            return
        updated = ex.n_updates > before[0]
        # refused: no new state and a message (not one left from an earlier refusal; exports only fail)
        refused = action != "export" and bool(ex.message) and not updated and \
            (ex.message != before[1] or action == "set")
        self._record(action, PACKAGE if refused else OK, ex.message[:160] if refused else "", dt)

    def act(self) -> None:
        acts = dict(self.WEIGHTS)
        if not self.ex.has_play:
            acts.pop("advance")
            acts["export"] = 2
        if not callable(getattr(self.ex, "simulate", None)):
            acts.pop("simulate")
        for a in self.stopped:
            acts.pop(a, None)
        if not acts:
            return
        action = self.rng.choices(list(acts), weights=list(acts.values()))[0]
        getattr(self, f"_{action}")()

    def _set(self) -> None:
        import ipywidgets as W

        ex, rng = self.ex, self.rng
        names = [k for k in ex.controls if not getattr(ex.controls[k], "disabled", False)] or list(ex.controls)
        k = rng.choice([1, 1, 1, 2, 3])
        chosen = rng.sample(names, min(k, len(names)))
        hostile = rng.random() < self.hostile_share
        bad = rng.choice(chosen) if hostile else None
        vals = {n: control_value(rng, ex.controls[n], ex, valid=(n != bad), name=n) for n in chosen}

        def check(_out):
            if bad is None or isinstance(ex.controls[bad], W.Text):
                return None
            held, v = ex.values.get(bad), vals[bad]
            kept = held is v or (type(held) is type(v) and (
                _numbers_close(held, v, 0.0) if isinstance(v, numbers.Number) else held == v))
            if kept:
                return FOREIGN, f"{bad!r} = {v!r} (outside its domain) was kept"
            return None

        if bad is None and len(vals) == 1 and rng.random() < 0.4:     # the page: one widget's value
            (n, v), = vals.items()
            self._run("set", lambda e: setattr(e.controls[n], "value", v),
                      f"ex.controls[{n!r}].value = {v!r}")
            return
        self._run("set", lambda e: e.set(**dict(vals)), f"ex.set(**{vals!r})", check=check)

    def _view(self) -> tuple[float, float, float, float]:
        x0, x1, y0, y1 = self.ex.picture()["box"]      # the box the picture shows
        return x0, x1, y0, y1

    def _drag(self) -> None:
        ex, rng = self.ex, self.rng
        hs = ex.all_handles()
        if not hs:
            self._run("drag", lambda e: e.drag("nope", (0, 0), (1, 1)), "ex.drag('nope', (0, 0), (1, 1))")
            return
        live = []
        for h in hs:
            try:
                if h.where() is not None:
                    live.append(h)
            except Exception:  # noqa: BLE001 - found below, on the handle picked
                live.append(h)
        h = rng.choice(live if live and rng.random() < 0.9 else hs)
        try:
            where = h.where()
        except Exception as exc:  # noqa: BLE001
            self.history.append((f"[ex.all_handles() {h.name!r}].where()", lambda e: None))
            self._record("drag", FOREIGN, f"handle {h.name!r}: where() raised {type(exc).__name__}: {exc}", 0.0)
            self.ex = None
            return
        try:
            x0, x1, y0, y1 = self._view()
        except Exception as exc:  # noqa: BLE001 - found by the action before; never stop the run
            self.history.append(("ex.picture()", lambda e: e.picture()))
            self._record("drag", FOREIGN, f"ex.picture() raised {type(exc).__name__}: {str(exc)[:200]}", 0.0)
            self.ex = None
            return
        size = max(abs(x1 - x0), abs(y1 - y0), 1e-9)
        if where is None:
            start = (float(0.5 * (x0 + x1)), float(0.5 * (y0 + y1)))
        else:
            start = (float(where[0]), float(where[1]))
            if not all(map(math.isfinite, start)):
                start = (float(0.5 * (x0 + x1)), float(0.5 * (y0 + y1)))
        r = rng.random()
        if r < 0.08:
            end = start
        elif r < 0.12:                         # exactly onto the view's corner / centre
            end = rng.choice([(x0, y0), (x1, y1), (0.0, 0.0)])
        else:
            far = rng.choices([0.02, 0.2, 0.6, 3.0, 1e3, 1e6], weights=[20, 30, 25, 10, 8, 7])[0]
            ang = rng.uniform(0, 2 * math.pi)
            end = (start[0] + far * size * math.cos(ang), start[1] + far * size * math.sin(ang))
        end = (float(end[0]), float(end[1]))
        steps = rng.choice([1, 1, 2, 3, 5])
        name = h.name
        self._run("drag", lambda e: e.drag(name, start, end, steps),
                  f"ex.drag({h.name!r}, {start!r}, {end!r}, {steps})")

    def _advance(self) -> None:
        ex, rng = self.ex, self.rng
        pre = ""
        if ex.play_speed is not None and rng.random() < 0.25:
            opts = [o[1] if isinstance(o, tuple) else o for o in ex.play_speed.options]
            sp = rng.choice(opts)
            ex.play_speed.value = sp
            pre = f"ex.play_speed.value = {sp!r}; "
        n = rng.choice([1, 1, 2, 3, 5])
        speed = ex.play_speed.value if ex.play_speed is not None else None

        def advance(e):
            if speed is not None:
                e.play_speed.value = speed
            return e.advance(n)

        self._run("advance", advance, f"{pre}ex.advance({n})")

    def _reset(self) -> None:
        ex = self.ex
        self._run("reset", lambda e: e.reset_button.click(), "ex.reset_button.click()")

    def _export(self) -> None:
        ex, rng = self.ex, self.rng
        r = rng.random()
        if r < 0.5:
            self._run("export", lambda e: e.export_button.click(), "ex.export_button.click()")
        elif r < 0.85 or not ex.has_play:
            self._run("export", lambda e: e.export_png_button.click(), "ex.export_png_button.click()")
        else:
            p = self.scratch / f"{self.name}-{rng.randrange(10**6)}.gif"
            k = rng.choice([2, 3, 4])

            def check(path):
                return None if Path(path).is_file() and Path(path).stat().st_size > 0 else \
                    (FOREIGN, f"export_animation returned {path!r} but wrote nothing")

            self._run("export", lambda e: e.export_animation(p, frames=k),
                      f"ex.export_animation({str(p)!r}, frames={k})", check=check)
        for f in self.scratch.glob("*"):       # keep the scratch folder small
            if f.is_file():
                f.unlink()

    def _simulate(self) -> None:
        ex, rng = self.ex, self.rng
        valid = rng.random() < 0.5
        if valid:
            d = rng.choice([None, 1e-300, 0.05, 0.5, 1.0, 2.0, float(getattr(ex, "duration", 1.0) or 1.0)])
        else:
            d = rng.choice([1e6, 1e300, float("inf"), float("nan"), -1.0, 0.0])

        def check(_out):
            if not valid and not ex.message:
                return FOREIGN, f"simulate({d!r}) returned with no message (a duration outside the domain)"
            return None

        self._run("simulate", lambda e: e.simulate(d), f"ex.simulate({d!r})", check=check)

    # -- the invariant
    def fresh(self) -> None:
        ex = self.ex
        values = dict(ex.values)
        text = f"{self.name}(display='agg', **ex.values)"
        t0 = time.perf_counter()
        try:           # a far time may take a few asks (fresh_explorer): three actions' time
            with time_limit(3 * self.limit), np.errstate(**NUMPY_ERRORS), \
                    warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                ref = fresh_explorer(self.cls, values)
        except Hang as exc:
            self._record("fresh", HANG, f"{exc}", time.perf_counter() - t0)
            self.stopped.add("fresh")
            return
        except Exception as exc:  # noqa: BLE001 - the controls hold values a new explorer refuses
            self._record("fresh", INCONSISTENT, f"values {_short(values, 300)} shown, but a fresh "
                         f"explorer refuses them: {type(exc).__name__}: {str(exc)[:200]}",
                         time.perf_counter() - t0)
            return
        dt = time.perf_counter() - t0
        verdict = _check_shown(ref)
        numpy_words = [w for w in caught if issubclass(w.category, RuntimeWarning)]
        if verdict is None and numpy_words:
            verdict = (FOREIGN, f"a warning reached the user: {numpy_words[0].message}")
        if verdict is None:
            atol = float(getattr(ex, "zero_tol", 1e-9)) * float(getattr(ex, "scale", 1.0))
            diff = readout_difference(ex.readout_values, ref.readout_values, atol)
            if diff:
                verdict = (INCONSISTENT, f"readout differs: {diff}")
        self._record("fresh", *(verdict or (OK, "")), dt)

    # -- a run
    def run(self, n_calls: int, seq: tuple[int, int] = (3, 10)) -> dict[str, Tally]:
        """About ``n_calls`` calls: sequences of actions, each followed by the invariant check."""
        while self.calls() < n_calls:
            if self.ex is None:
                try:
                    self._new()
                except Hang:
                    break
            for _ in range(self.rng.randint(*seq)):
                if self.ex is None:
                    break
                self.act()
            if self.ex is not None and "fresh" not in self.stopped:
                self.fresh()
            if self.ex is not None and self.rng.random() < 0.15:   # a new explorer now and then
                self.ex = None
        return self.tallies


def fuzz_explorers(calls_each: int, *, seed: int = 0, time_limit: float = 20.0,
                   names: list[str] | None = None, classes: dict[str, type] | None = None,
                   hostile_share: float = 0.12, log: Callable[[str], None] | None = None) -> dict[str, Tally]:
    """Fuzz every explorer (or ``classes``) with about ``calls_each`` calls; tallies per action.

    Parameters
    ----------
    calls_each : int
    seed : int
    time_limit : float
        Per-call hang limit in seconds.
    names : list of str, optional
        Only these explorers of :data:`planargeo.widgets.EXPLORERS`.
    classes : dict, optional
        ``{name: class}`` to fuzz instead (a test's own explorer).
    hostile_share : float
        Share of ``set`` actions with a value from outside its control's domain.
    log : callable, optional
        Progress lines.
    """
    if classes is None:
        from planargeo import widgets

        names = names if names is not None else list(widgets.EXPLORERS)
        classes = {n: getattr(widgets, n) for n in names}
    out: dict[str, Tally] = {}
    with tempfile.TemporaryDirectory(prefix="planargeo-fuzz-export-") as d:
        for i, (name, cls) in enumerate(classes.items()):
            t0 = time.perf_counter()
            fz = ExplorerFuzzer(cls, random.Random(f"{seed}-{name}"), time_limit, Path(d),
                                hostile_share=hostile_share, log=log)
            fz.run(calls_each)
            out.update(fz.tallies)
            if log:
                bad = sum(t.defects for t in fz.tallies.values())
                log(f"  {name}: {fz.calls()} calls, {bad} failed, {time.perf_counter() - t0:.1f} s")
    return out
