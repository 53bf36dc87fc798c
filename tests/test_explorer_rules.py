"""Rules every explorer follows (issue 22, issue 23): checked on the scene, the state and the readout.

Parametrised over every explorer of :data:`planargeo.widgets.EXPLORERS` (``display="agg"``):

* **controls do something**: every control, walked from the default state (a slider to both
  ends and a middle value, every option of a list, a checkbox toggled, a text field given its
  placeholder's numbers), changes the state, the readout or the drawn picture, or is disabled
  with a tooltip saying why;
* **Home / End**: both ends of every enabled slider give a state or a refusal that names the slider
  and leaves the shown state as it was; refusals are the exception (at most a quarter of the
  ends; the counts are printed);
* **Play plays**: 60 s of simulated time from the default state, through ``advance`` (the
  Play step API, so the test is not bound to the wall clock), without a refusal;
* **views fit**: across 200 seeded random states (a random walk, three controls at a time,
  slider ends and zeros often: folded chains, coincident points), the view holds every point of the mechanism
  (:meth:`~planargeo.widgets.base.Explorer.mechanism_points`) and never spans less than half
  the scene's scale;
* **one state per set of controls**: after a random history (sets, drags of every handle,
  Play steps, Reset) a fresh explorer built from ``ex.values`` shows the same readout (to
  1e-9) and the same view; Reset shows the default state's readout;
* **readable readout**: no code identifiers (``a_b``, ``qdd[1]``) in names or texts, a unit
  for every numeric row (``"—"`` for dimensionless), points far beyond the scene read "at
  infinity", round-off reads 0;
* **every symbol explained**: each readout name and each label drawn on the figure appears in
  ``explain()``.

"Changed" is judged on the readout texts and the state's numbers first; the picture's data
is compared only for display controls (overlays, key), which change nothing else.

Explorers that still break a rule carry ``xfail(strict=True)`` with the exact failure in
:data:`KNOWN`; a fixed explorer then fails its xfail, and its entry goes.
"""
from __future__ import annotations

import hashlib
import json
import math
import re
import warnings

import ipywidgets as W
import numpy as np
import pytest

from planargeo import widgets
from planargeo.widgets import EXPLORERS
from planargeo.widgets.readout import is_numeric, plain_symbol

NAMES = sorted(EXPLORERS)

#: (explorer, rule) -> the failure still shown (xfail, strict): remove an entry once it passes
KNOWN: dict[tuple[str, str], str] = {}

CODE_NAME = re.compile(r"\w_\w|[a-z]+\[\d\]")
NUMBER = re.compile(r"(?<![\w.])[-−+]?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?(?![\w.])")


def _params(rule: str):
    out = []
    for name in NAMES:
        why = KNOWN.get((name, rule))
        marks = [pytest.mark.xfail(strict=True, reason=why)] if why else []
        out.append(pytest.param(name, id=name, marks=marks))
    return out


def make(name: str, **values):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        return getattr(widgets, name)(display="agg", **values)


# --------------------------------------------------------------------------- fingerprints
def _numbers(x, depth: int = 0, out: list | None = None) -> list:
    """The numbers and words of a state, in a stable order (dicts, sequences, arrays, records)."""
    out = [] if out is None else out
    if depth > 6:
        return out
    if isinstance(x, (bool, np.bool_, str)) or x is None:
        out.append(repr(x))
    elif isinstance(x, (int, float, np.integer, np.floating)):
        out.append(float(x))
    elif isinstance(x, np.ndarray):
        if x.dtype.kind in "fiub":
            a = np.asarray(x, float).ravel()
            out.append(hashlib.sha1(np.round(a, 12).tobytes()).hexdigest())
        elif x.dtype == object:
            for v in x.ravel()[:1000]:
                _numbers(v, depth + 1, out)
    elif isinstance(x, dict):
        for k in sorted(x, key=repr):
            out.append(repr(k))
            _numbers(x[k], depth + 1, out)
    elif isinstance(x, (list, tuple)):
        for v in x[:1000]:
            _numbers(v, depth + 1, out)
    elif hasattr(x, "__dataclass_fields__"):
        for k in x.__dataclass_fields__:
            _numbers(getattr(x, k, None), depth + 1, out)
    return out


def _same_numbers(a: list, b: list) -> bool:
    if len(a) != len(b):
        return False
    for u, v in zip(a, b):
        if isinstance(u, float) and isinstance(v, float):
            if not (u == v or (math.isnan(u) and math.isnan(v))
                    or abs(u - v) <= 1e-12 * max(1.0, abs(u), abs(v))):
                return False
        elif u != v:
            return False
    return True


def _pixels(ex) -> str:
    """A fingerprint of what is drawn: the picture's data."""
    return hashlib.sha1(json.dumps(ex.picture(), sort_keys=True).encode()).hexdigest()


class Snapshot:
    """What a student sees of the shown state: readout texts, the state's numbers, the picture."""

    def __init__(self, ex, pixels: bool = False):
        self.ex = ex
        self.readout = dict(ex.readout_strings)
        self.state = _numbers(ex.state)
        self._pixels = _pixels(ex) if pixels else None      # drawn now, or when first needed

    @property
    def pixels(self):
        if self._pixels is None:
            self._pixels = _pixels(self.ex)
        return self._pixels

    def differs(self, other: "Snapshot") -> bool:
        if self.readout != other.readout or not _same_numbers(self.state, other.state):
            return True
        return self.pixels != other.pixels


# --------------------------------------------------------------------------- controls
def _options(w) -> list:
    return [o[1] if isinstance(o, tuple) else o for o in w.options]


def _slider_trials(w) -> list:
    lo, hi, v = w.min, w.max, w.value
    mid = (lo + hi) / 2
    if abs(mid - v) <= 1e-9 * max(1.0, abs(hi - lo)):
        mid = (lo + v) / 2
    out = [lo, mid, hi]
    if isinstance(w, W.IntSlider):
        out = [int(round(x)) for x in out]
    else:
        out = [float(x) for x in out]
    return [x for i, x in enumerate(out) if x != v and x not in out[:i]]


def _trials(w) -> list:
    """The values a walk gives a control (never its default)."""
    if isinstance(w, (W.FloatSlider, W.IntSlider)):
        return _slider_trials(w)
    if isinstance(w, W.Checkbox):
        return [not w.value]
    if isinstance(w, (W.Dropdown, W.ToggleButtons, W.RadioButtons, W.Select)):
        return [o for o in _options(w) if o != w.value]
    if isinstance(w, W.Text):
        nums = NUMBER.findall(w.placeholder or "")
        return [", ".join(n.replace("−", "-") for n in nums)] if nums else []
    return []


def _disabled_reason(w):
    """The tooltip of a disabled control ("" if it has none), or None when it is enabled."""
    if not getattr(w, "disabled", False):
        return None
    return str(getattr(w, "tooltip", None) or "").strip()


def _random_value(w, rng):
    if isinstance(w, (W.FloatSlider, W.IntSlider)):
        r = rng.random()
        if r < 0.15:
            x = w.min
        elif r < 0.3:
            x = w.max
        elif r < 0.4 and w.min <= 0.0 <= w.max:
            x = 0.0
        else:
            x = w.min + (w.max - w.min) * rng.random()
        return int(round(x)) if isinstance(w, W.IntSlider) else float(x)
    if isinstance(w, W.Checkbox):
        return bool(rng.random() < 0.5)
    if isinstance(w, (W.Dropdown, W.ToggleButtons, W.RadioButtons, W.Select)):
        opts = _options(w)
        return opts[int(rng.integers(len(opts)))]
    return None


def _random_set(ex, rng, k: int | None = None) -> dict:
    """Random values for ``k`` random controls (all when None), text fields left alone."""
    names = [n for n, w in ex.controls.items() if not isinstance(w, W.Text)]
    if k is not None:
        names = list(rng.choice(names, size=min(k, len(names)), replace=False))
    vals = {}
    for n in names:
        v = _random_value(ex.controls[n], rng)
        if v is not None:
            vals[n] = v
    return vals


def _view(ex) -> tuple[float, float, float, float]:
    """The box the picture shows."""
    x0, x1, y0, y1 = ex.picture()["box"]
    return (x0, x1, y0, y1)


# --------------------------------------------------------------------------- rules
@pytest.mark.parametrize("name", _params("controls"))
def test_every_control_does_something(name):
    ex = make(name)
    assert ex.message == "", ex.message
    base = Snapshot(ex, pixels=True)
    problems = []
    for k, w in list(ex.controls.items()):
        ex.reset()
        reason = _disabled_reason(ex.controls[k])
        if reason is not None:
            if not reason:
                problems.append(f"{k!r} is disabled without a reason")
            continue
        trials = _trials(ex.controls[k])
        need_each = isinstance(w, (W.Checkbox, W.Dropdown, W.ToggleButtons, W.RadioButtons,
                                   W.Select))
        moved = []
        for v in trials:
            ex.reset()
            ex.set(**{k: v})
            if ex.message:
                moved.append(False)
                if need_each:
                    problems.append(f"{k!r} = {v!r} is refused from the default state: {ex.message}")
                continue
            moved.append(Snapshot(ex).differs(base))
            if need_each and not moved[-1]:
                problems.append(f"{k!r} = {v!r} changes nothing")
        if trials and not need_each and not any(moved):
            problems.append(f"{k!r} changes nothing at {trials}")
    ex.reset()
    assert not problems, "; ".join(problems)


@pytest.mark.parametrize("name", _params("home_end"))
def test_home_end_of_every_slider(name, capsys):
    ex = make(name)
    base = Snapshot(ex)
    ends = refused = 0
    problems, refusals = [], []
    for k, w in list(ex.controls.items()):
        if not isinstance(w, (W.FloatSlider, W.IntSlider)):
            continue
        ex.reset()
        if ex.controls[k].disabled:                 # no Home/End on a disabled slider
            continue
        for end in (ex.controls[k].min, ex.controls[k].max):
            ex.reset()
            if end == ex.controls[k].value:
                continue
            ends += 1
            ex.set(**{k: end})
            if ex.message:
                refused += 1
                refusals.append(f"{k} = {end:g}: {ex.message}")
                if k not in ex.message:
                    problems.append(f"the refusal of {k} = {end:g} does not name it: {ex.message}")
                if ex.values != ex.shown_values or ex.readout_strings != base.readout:
                    problems.append(f"the refusal of {k} = {end:g} changed the shown state")
            elif ex.values[k] != end:
                problems.append(f"{k} = {end:g} shows {ex.values[k]!r}")
    ex.reset()
    with capsys.disabled():
        print(f"\n{name}: Home/End {ends} slider ends, {refused} refused"
              + "".join(f"\n    {r}" for r in refusals))
    assert 4 * refused <= ends, f"{refused} of {ends} slider ends refused: {refusals}"
    assert not problems, "; ".join(problems)


@pytest.mark.parametrize("name", _params("play"))
def test_play_runs_60_seconds(name):
    ex = make(name)
    if not ex.has_play:
        pytest.skip(f"{name} has no Play")
    origin = dict(ex.values)
    played, restarts = 0.0, 0
    while played < 60.0 - 1e-9:
        before = dict(ex.values)
        ex.advance(1, seconds=1.0)
        assert ex.message == "", f"after {played:g} s of Play: {ex.message}"
        if ex.values == before:           # Play ended: start again, as Play with "loop" does
            restarts += 1
            assert restarts <= 10, f"Play ends without moving after {played:g} s"
            ex.set(**origin)
            assert ex.message == "", ex.message
        else:
            played += 1.0


@pytest.mark.parametrize("name", _params("views"))
def test_views_fit_200_random_states(name):
    ex = make(name)
    rng = np.random.default_rng(22)
    shown, problems = 0, []
    for i in range(200):                  # a random walk: three controls at a time
        vals = _random_set(ex, rng, k=3)
        ex.set(**vals)
        if ex.message:
            continue
        shown += 1
        pts = ex.mechanism_points()
        x0, x1, y0, y1 = _view(ex)
        w, h = x1 - x0, y1 - y0
        if len(pts):
            size = float(np.max(np.ptp(pts, axis=0)))
            tol = 1e-9 * max(w, h)
            out = pts[(pts[:, 0] < x0 - tol) | (pts[:, 0] > x1 + tol)
                      | (pts[:, 1] < y0 - tol) | (pts[:, 1] > y1 + tol)]
            if len(out):
                problems.append(f"state {i}: {len(out)} point(s) out of the view "
                                f"{(x0, x1, y0, y1)}, e.g. {tuple(out[0])}")
        else:
            size = 0.0
        floor = max(size, 0.5 * float(ex.scale))
        if min(w, h) < floor * (1 - 1e-9):
            problems.append(f"state {i}: the view spans {w:.3g} × {h:.3g}, less than {floor:.3g}")
        if len(problems) >= 5:
            break
    assert shown >= 20, f"only {shown} of 200 random states shown"
    assert not problems, "; ".join(problems)


def _history(ex, rng, n: int = 10) -> list[str]:
    done = []
    for _ in range(n):
        r = rng.random()
        if r < 0.4:
            vals = _random_set(ex, rng, k=2)
            ex.set(**vals)
            done.append(f"set {vals}")
        elif r < 0.7:
            hs = [h for h in ex.all_handles() if h.where() is not None]
            if not hs:
                continue
            h = hs[int(rng.integers(len(hs)))]
            a = np.asarray(h.where(), float)
            b = a + rng.normal(0.0, 0.3 * float(ex.scale), 2)
            ex.drag(h.name, tuple(a), tuple(b), steps=3)
            done.append(f"drag {h.name} to {tuple(np.round(b, 3))}")
        elif r < 0.9 and ex.has_play:
            ex.advance(3)
            done.append("play 3 frames")
        else:
            ex.reset()
            done.append("reset")
    return done


def _close(a, b) -> bool:
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(_close(a[k], b[k]) for k in a)
    if is_numeric(a) and is_numeric(b):
        x = np.asarray(a, float).ravel()
        y = np.asarray(b, float).ravel()
        return x.shape == y.shape and bool(np.all(
            (x == y) | (np.isnan(x) & np.isnan(y)) | (np.abs(x - y) <= 1e-9 * np.maximum(
                1.0, np.maximum(np.abs(x), np.abs(y))))))
    if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
        return len(a) == len(b) and all(_close(u, v) for u, v in zip(a, b))
    return bool(a == b) if not isinstance(a, np.ndarray) else False


@pytest.mark.parametrize("name", _params("fresh"))
def test_a_fresh_explorer_shows_the_same_state(name):
    default = make(name)
    for seed in range(3):
        ex = make(name)
        steps = _history(ex, np.random.default_rng(seed))
        fresh = make(name, **ex.values)
        assert fresh.message == "", (steps, fresh.message)
        assert _close(ex.readout_values, fresh.readout_values), (
            steps, {k: (v, fresh.readout_values.get(k)) for k, v in ex.readout_values.items()
                    if not _close(v, fresh.readout_values.get(k))})
        assert np.allclose(_view(ex), _view(fresh), rtol=1e-9, atol=1e-9), (
            steps, _view(ex), _view(fresh))
        ex.reset()
        assert ex.values == default.values and _close(ex.readout_values, default.readout_values), (
            "Reset", steps)


def _readout_problems(ex) -> list[str]:
    out = []
    scale = float(ex.scale)
    for k, v in ex.readout_values.items():
        if str(k).startswith("_"):
            continue
        text = ex.readout_strings.get(str(k), "")
        if CODE_NAME.search(str(k)):
            out.append(f"readout name {k!r} is a code identifier")
        if CODE_NAME.search(text):
            out.append(f"readout {k!r} reads {text!r}, a code identifier")
        if is_numeric(v) and k not in ex.units:
            out.append(f"readout {k!r} = {text!r} has no unit (give '—' if dimensionless)")
        for tok in NUMBER.findall(text):
            x = abs(float(tok.replace("−", "-")))
            if 0 < x < 1e-6 * scale:
                out.append(f"readout {k!r} reads {text!r}: round-off must read 0")
                break
            if x >= 1e9 * scale and text.endswith(" m"):
                out.append(f"readout {k!r} reads {text!r}: a point that far reads 'at infinity'")
                break
    return out


@pytest.mark.parametrize("name", _params("readout"))
def test_readout_is_readable(name):
    ex = make(name)
    rng = np.random.default_rng(7)
    problems = _readout_problems(ex)
    for _ in range(5):
        ex.set(**_random_set(ex, rng, k=3))
        if not ex.message:
            problems += [p for p in _readout_problems(ex) if p not in problems]
    assert not problems, "; ".join(problems)


def _labels(ex) -> set[tuple[str, ...]]:
    """The symbols labelled in the picture (placed labels, not fixed texts, messages or the key).

    Each label is a tuple of the names it may go by: its text's symbol and its element's
    thesis symbol (one of them must be explained).
    """
    out = set()
    texts = [(part["text"], el.get("symbol") or "") for el in ex.picture()["elements"]
             if el["id"] != "figure message" and not el["id"].startswith("key ")
             for part in el["parts"] if part["p"] == "text" and not part.get("hidden")
             and not part.get("fixed")]
    for text, symbol in texts:
        s = plain_symbol(text).strip()
        if " = " in s:
            s = s.split(" = ")[0].strip()
        s = re.sub(r"\s*\((?:off view|line at ∞)\)$", "", s)     # where it is, not what it is
        s = s.removesuffix(" at ∞").strip()      # an ideal element's label names its symbol
        if not s or re.fullmatch(r"[-−+\d.,e ]+\s*[A-Za-zµ°/·²]*", s):   # a number, "1 m", "30°"
            continue
        out.add((s, plain_symbol(symbol).strip()) if symbol else (s,))
    return out


@pytest.mark.parametrize("name", _params("explain"))
def test_every_symbol_is_explained(name):
    ex = make(name)
    boxes = {k: True for k, w in ex.controls.items() if isinstance(w, W.Checkbox) and k != "key"}
    missing = set()
    for vals in ({}, boxes):
        if vals:
            ex.set(**vals)
            if ex.message:                      # all overlays at once refused: one at a time
                ex.reset()
                continue
        meanings = dict(ex.explain())
        text = " ".join(plain_symbol(f"{k} {v}") for k, v in meanings.items())
        missing |= {f"readout {k!r}" for k in ex.readout_values
                    if not str(k).startswith("_") and k not in meanings}
        missing |= {f"label {names[0]!r}" for names in _labels(ex)
                    if not any(n and n in text for n in names)}
    assert not missing, f"not in explain(): {', '.join(sorted(missing))}"
