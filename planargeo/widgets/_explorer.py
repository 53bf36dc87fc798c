"""What several explorers share, written once: handles named by their controls, a view grown to
hold points, sliders that span a chain of ``n`` bodies (:class:`ChainBodies`), a scene time kept
as text (:class:`SceneTime`), readout rows described as data (:class:`Described`,
``planargeo/data/quantities.toml``).

Examples
--------
>>> grown_view((0.0, 1.0, 0.0, 1.0), [[2.0, 0.5], [-1.0, 0.5]], 0.5)
(-1.5, 2.5, -1.5, 2.5)
"""
from __future__ import annotations

import math

import ipywidgets as W
import numpy as np
import traitlets

from planargeo.draw.pictures._words import words_data
from planargeo.errors import DegenerateGeometryError, InputError
from planargeo.widgets._motion import Budget, refusal_on_picture
from planargeo.widgets.controls import cached, number_text
from planargeo.widgets.handles import Handle


def shown(ex) -> dict:
    """The control values on show (the values themselves before the first state is shown)."""
    return ex.shown_values or ex.values


def xy_handle(ex, name: str, kx: str, ky: str, when=None) -> Handle:
    """A handle at ``(values[kx], values[ky])`` that sets both; not draggable while ``when()`` is false."""
    def where():
        v = shown(ex)
        return (v[kx], v[ky]) if when is None or when() else None

    return Handle(name, where, lambda x, y: {kx: x, ky: y})


def state_handle(ex, name: str, at, drag) -> Handle:
    """A handle at ``at(state)`` of the state shown; not draggable before the first state or where
    ``at`` gives None."""
    def where():
        p = None if ex.state is None else at(ex.state)
        return None if p is None else tuple(p)

    return Handle(name, where, drag)


def arrow_handle(ex, name: str, kx: str, ky: str, kangle: str, ksize: str | None = None, *,
                 arm: float = 1.0, per: float | None = None, flip: bool = False, when=None) -> Handle:
    """The tip of an arrow from ``(values[kx], values[ky])`` along ``values[kangle]`` (degrees).

    The arrow is ``arm`` long, or ``per × values[ksize]`` (then a drag sets the size too);
    ``flip``: a negative size points it the other way.
    """
    def sense(v):
        return -1.0 if flip and v[ksize] < 0 else 1.0

    def where():
        v = shown(ex)
        if when is not None and not when():
            return None
        length = per * v[ksize] if per is not None else sense(v) * arm
        a = math.radians(v[kangle])
        return (v[kx] + length * math.cos(a), v[ky] + length * math.sin(a))

    def drag(x, y):
        v = shown(ex)
        d = np.array([x - v[kx], y - v[ky]]) * sense(v)
        n = float(np.hypot(*d))
        if not n > 1e-9:
            # said in words, the size by its symbol as its slider shows it ("F", not a key)
            zero = ""
            if per is not None:
                label = str(getattr(ex.controls.get(ksize), "description", "") or ksize)
                zero = f"{label.split(' (')[0].strip()} would be 0 and "
            raise DegenerateGeometryError(f"{name} cannot be on the arrow's foot: {zero}the arrow "
                                          "would have no direction; drag it away from the foot")
        out = {kangle: math.degrees(math.atan2(d[1], d[0]))}
        if per is not None:
            out[ksize] = n / per
        return out

    return Handle(name, where, drag)


def grown_view(box, pts, margin: float, sized=None, extra: float | None = None) -> tuple:
    """``box`` ``(x0, x1, y0, y1)`` grown to hold ``pts`` with ``margin``, no side shorter than their extent.

    The least side is the extent of ``sized`` (default ``pts``) plus ``extra`` (default twice
    the margin), grown about the middle.
    """
    x0, x1, y0, y1 = box
    pts = np.asarray(pts, dtype=float).reshape(-1, 2)
    if not len(pts):
        return tuple(box)
    x0, x1 = min(x0, pts[:, 0].min() - margin), max(x1, pts[:, 0].max() + margin)
    y0, y1 = min(y0, pts[:, 1].min() - margin), max(y1, pts[:, 1].max() + margin)
    sized = pts if sized is None else np.asarray(sized, dtype=float).reshape(-1, 2)
    size = float(np.max(np.ptp(sized, axis=0))) + (2 * margin if extra is None else extra)
    if x1 - x0 < size:
        x0, x1 = x0 - (size - (x1 - x0)) / 2, x1 + (size - (x1 - x0)) / 2
    if y1 - y0 < size:
        y0, y1 = y0 - (size - (y1 - y0)) / 2, y1 + (size - (y1 - y0)) / 2
    return (float(x0), float(x1), float(y0), float(y1))


#: the table of an explorer in ``planargeo/data/quantities.toml`` (its words kept as data)
explorer_data = words_data


def readouts(explorer: str) -> tuple[dict, dict, dict]:
    """``(units, meanings, symbols)`` of ``explorer``'s readout rows and picture, from its data.

    Examples
    --------
    >>> units, meanings, symbols = readouts("impulse")
    >>> units["ω after the blow"], meanings["ω after the blow"]
    ('rad/s', 'angular velocity of the body just after the blow (5.64)')
    """
    table = explorer_data(explorer)
    rows = table.get("rows", {})
    units = {k: tuple(u) if isinstance(u, list) else u for k, (u, _m) in rows.items() if u}
    return units, {k: m for k, (_u, m) in rows.items()}, dict(table.get("symbols", {}))


class Described:
    """An explorer whose readout rows and symbols are data (:func:`readouts` of its ``slug``)."""

    def __init_subclass__(cls, **kw):
        super().__init_subclass__(**kw)
        if "rows" in explorer_data(cls.__dict__.get("slug", "")):
            cls.row_units, cls.meanings, cls.symbols = readouts(cls.slug)
            if "units" not in cls.__dict__:
                cls.units = cls.row_units

    def explain(self):
        return {**self.symbols, **self.meanings}


class HeldView:
    """A view fitted to the state (``_fitted_view(state)``), held while a handle is dragged, so that the
    pointer's place in the page keeps its meaning (re-fitted at each step, the view would move under the
    pointer and the handle run away from it); the release, or any update that is not a drag's, fits it
    again.  Handles' drags go through :meth:`holding`; ``compute`` starts with :meth:`drag_or_fit`; the
    picture is drawn in ``self.held_view or self._fitted_view(state)``.
    """

    held_view = None
    _drag_update = False

    def holding(self, drag):
        """``drag`` (a handle's ``(x, y) -> values``), holding the view shown when the drag began."""
        def held(x, y):
            vals = drag(x, y)                       # a refused step (raised) holds nothing
            if self.held_view is None and self.state is not None:
                self._hold_view(self.state)
            self._drag_update = True
            return vals
        return held

    def _hold_view(self, state) -> None:
        self.held_view = self._fitted_view(state)

    def _unhold_view(self) -> None:
        self.held_view = None

    def drag_or_fit(self) -> None:
        """At the start of an update: a drag's keeps the held view, any other fits the view again."""
        dragged, self._drag_update = self._drag_update, False
        if not dragged:
            self._unhold_view()

    def _release(self):
        # the end of a drag (HandleMixin): the view fits the state again, as a fresh explorer's
        self._unhold_view()
        self._drag_update = False
        super()._release()


class ChainBodies:
    """What explorers of a chain of ``bodies n`` (mass 1, joints ``L = 1`` apart) share."""

    #: ``(control, offset, widest)``: it spans up to ``n + offset`` (while ``n`` is set, ``widest``)
    spans: tuple[str, int, int] = ("", 0, 0)

    def __repr__(self) -> str:
        return f"{type(self).__name__}(...)"

    def _model(self, n, rho, g=0.0):
        from planargeo.scenes.articulated import bent_chain_model

        return cached(self._cache("_models"), (n, rho, g),
                      lambda: bent_chain_model(n, rho, 1.0, 1.0, g))

    def _span(self, n: int, *, widest: bool = False) -> None:
        """The spanned slider up to ``n + offset`` (or its widest range), its value kept."""
        name, offset, most = self.spans
        w, top = self.controls[name], most if widest else n + offset
        if w.max != top and (widest or w.value <= top):
            with self._quietly():
                w.max = top

    def set(self, **values):
        if "bodies n" not in values:
            return super().set(**values)
        self._span(0, widest=True)   # any value the widest range allows (checked against n by adjust)
        try:
            return super().set(**values)
        finally:
            self._span(int(shown(self)["bodies n"]))

    def mechanism_points(self):
        st = self.state
        return np.zeros((0, 2)) if st is None else np.asarray(st["joints"], dtype=float).reshape(-1, 2)

    def _tip_handle(self, bend_for_tip, base: str | None = None) -> Handle:
        """The chain's tip: dragged, it sets the bend ``φ`` that brings it nearest (``bend_for_tip``; the
        first body at the angle control ``base``)."""
        def drag(x, y):
            v = self.values
            phi = bend_for_tip((x, y), int(v["bodies n"]), math.radians(v[base]) if base else 0.0)
            return {"bend φ (deg)": float(np.clip(math.degrees(phi), -180.0, 180.0))}

        def tip(st):
            return st["joints"][-1] if len(st["joints"]) >= 3 else None

        return state_handle(self, "tip", tip, drag)


def time_text(t: float) -> str:
    """The scene time ``t`` (s) as the read-only time field holds it: to the nanosecond, no trailing zeros.

    Examples
    --------
    >>> time_text(0.0), time_text(0.1 + 0.2), time_text(59.99999999999873)
    ('0', '0.3', '60')
    """
    text = f"{round(float(t), 9):.9f}".rstrip("0").rstrip(".")
    return "0" if text in ("", "-0") else text


def time_shown(text, widget=None) -> str:
    """The time field's ``text`` as the page shows it: to the millisecond (other text as it is).

    The field keeps the exact time (the state's time, :func:`time_text`); the student reads it
    rounded, as Play's clock.

    Examples
    --------
    >>> time_shown("0.325875691"), time_shown("2.9725"), time_shown("0"), time_shown("soon")
    ('0.326', '2.973', '0.000', 'soon')
    """
    try:
        t = float(text)
    except (TypeError, ValueError):
        return text
    return f"{t:.3f}" if math.isfinite(t) else text


class TimeField(W.Text):
    """The read-only scene time field: its value is the exact time (``ex.values``: the state at a
    time depends on that time alone), the page shows it to the millisecond (:func:`time_shown`)."""

    value = traitlets.Unicode(help="String value").tag(sync=True, to_json=time_shown)


def time_value(text, limit: float) -> float:
    """The scene time (s) of the time field's ``text`` (at most ``limit``), or an InputError.

    The refusal is said in words, the time by its symbol as the field shows it (``t``).

    Examples
    --------
    >>> time_value("1.5", 3.0)
    1.5
    >>> time_value(" ", 3.0)
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: the time t is empty: type a time in seconds, from 0 to 3 s
    """
    said = str(text if text is not None else "").strip()
    if not said:
        raise InputError(f"the time t is empty: type a time in seconds, from 0 to {number_text(limit)} s")
    try:
        t = float(said)
    except (TypeError, ValueError):
        raise InputError(f"the time t must be a number of seconds, from 0 to {number_text(limit)} s, "
                         f"got “{said}”") from None
    if not 0.0 <= t <= limit + 1e-9:
        raise InputError(f"the time t must lie between 0 and {number_text(limit)} s, got {said} s")
    return t


def run_to(run: dict, t: float, checkpoint: float, step, budget=None):
    """``(state, drift, events)`` at scene time ``t`` of ``run``, its checkpoints extended in place.

    ``run`` holds ``ck`` (the state every ``checkpoint`` s), ``drift`` (the largest residual up to
    each) and ``events``.  From the last checkpoint before ``t`` to ``t``: the same operations
    whatever the history.  ``step(state, h, t0) -> (state, residual, events)``; a spent
    ``budget`` refuses the next checkpoint.
    """
    ck = run["ck"]
    k = int(math.floor(t / checkpoint + 1e-9))
    while len(ck) <= k:
        n = len(ck) - 1
        if budget is not None and budget.spent:
            raise budget.refusal(t, n * checkpoint)
        state, res, events = step(ck[n], checkpoint, n * checkpoint)
        ck.append(state)
        run["drift"].append(max(run["drift"][-1], res))
        run["events"] += events
    state, drift = ck[k], run["drift"][k]
    events = [e for e in run["events"] if e[0] <= k * checkpoint]
    rest = t - k * checkpoint
    if rest > 1e-12:
        state, res, more = step(state, rest, k * checkpoint)
        drift, events = max(drift, res), events + more
    return state, drift, events


def time_step(values: dict, dt: float, name: str, end: float) -> dict | None:
    """Play's step of a time control ``name``: ``dt`` on, at most ``end`` (None once there)."""
    t = float(values[name])
    return None if t >= end else {name: min(t + float(dt), end)}


class SceneTime:
    """Play advances a scene time kept as text in ``"t (s)"`` up to :attr:`t_end`; a change of a
    control in :attr:`initial` starts it again."""

    initial: tuple[str, ...] = ()
    t_end: float = 60.0
    _SET_BY_PLAY = "set by Play (a new initial state starts it at 0)"

    def time_control(self) -> W.Text:
        """The read-only time field."""
        return TimeField(value="0", description="t (s)", disabled=True, tooltip=self._SET_BY_PLAY)

    def disabled(self, values):
        return {"t (s)": self._SET_BY_PLAY}

    def adjust(self, values, changed):
        if set(changed) & set(self.initial) and "t (s)" not in changed and values["t (s)"] != "0":
            return {"t (s)": "0"}
        return {}

    def play_step(self, values, dt):
        t = time_value(values["t (s)"], self.t_end) + float(dt)
        return None if t > self.t_end + 1e-9 else {"t (s)": time_text(t)}

    def run_at(self, key, start, text, step, checkpoint: float, evals: int):
        """``(run, t, state, drift, events)`` at the time ``text`` of the run ``key`` (made by
        ``start()``), kept before it is integrated (a refused time's checkpoints stay) as the newer of
        two; ``step(budget)`` is its step (:func:`run_to`), one update spends at most ``evals``
        evaluations."""
        runs = self._cache("_runs")
        run = runs.get(key) or start()
        t = time_value(text, self.t_end)
        runs.pop(key, None)
        runs[key] = run
        while len(runs) > 2:
            runs.pop(next(iter(runs)))
        budget = Budget(evals)
        return (run, t, *run_to(run, t, checkpoint, step(budget), budget))

    def figure_message(self, exc):
        return refusal_on_picture(str(exc)) or super().figure_message(exc)
