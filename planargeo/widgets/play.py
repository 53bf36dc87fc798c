"""Play at true real time: each tick advances the simulation by the wall time since the last one
(× speed × ``time_scale``, at most :data:`MAX_CATCHUP` s), through ``play_step`` sub-steps of at
most ``1 / play_fps`` s: no physics step is skipped, only display frames are dropped.  Long runs
are bounded (:func:`check_count`, :func:`check_duration`) unless ``allow_long=True``.

Examples
--------
>>> substeps(0.25, 0.1)
[0.08333333333333333, 0.08333333333333333, 0.08333333333333333]
>>> run_substeps(lambda v, dt: {"t": v["t"] + dt}, {"t": 0.0}, 1.0, 0.05)[0]["t"]
1.0000000000000002
"""
from __future__ import annotations

import asyncio
import contextlib
import math
import numbers
import time
from typing import Any, Callable

import ipywidgets as W

from planargeo.errors import InputError, PlanargeoError
from planargeo.widgets.controls import same_value

__all__ = ["MAX_CATCHUP", "PLAY_SYNC_S", "DRAG_SYNC_S", "MAX_ADVANCE_FRAMES", "MAX_ADVANCE_SECONDS",
           "MAX_ANIMATION_FRAMES", "substeps", "run_substeps", "check_count", "check_duration", "PlayClock"]
# PlayMixin (below) is the explorer's Play; it is documented with the Explorer it is part of

#: wall seconds a single Play tick may catch up (a longer gap: the motion resumes, it does not jump)
MAX_CATCHUP = 0.5
#: while the page plays, controls and readout reach it at most this often (s); pictures at once,
#: and with each picture the controls Play moves (the time: the number compared with the picture)
PLAY_SYNC_S = 0.25
#: while the page drags a handle, controls, readout and message reach it at most this often (s),
#: and at once when the drag ends or a step is refused; the picture follows every step (the
#: explorer's ``drag_sync_s``, 0: with every picture)
DRAG_SYNC_S = 0.2
#: frames one call of ``advance`` may take without ``allow_long=True``
MAX_ADVANCE_FRAMES = 10_000
#: simulated seconds one call of ``advance`` may cover without ``allow_long=True``
MAX_ADVANCE_SECONDS = 3600.0
#: frames of an exported animation without ``allow_long=True`` (a minute at 20 frames per second)
MAX_ANIMATION_FRAMES = 1200
#: seconds after an explorer is shown in a kernel before Play's first frame is computed ahead
#: (not shown): the imports and compiled kernels it needs load then, not when Play is pressed
WARM_PLAY_S = 1.0


def check_count(name: str, value: Any, limit: int, allow_long: bool | None = False) -> int:
    """``value`` as a positive integer at most ``limit`` (unless ``allow_long``), or a named error.

    Parameters
    ----------
    name : str
        The argument's name (for the message).
    value : Any
        The count.
    limit : int
        The largest count without ``allow_long``.
    allow_long : bool or None
        Opt in to counts beyond ``limit`` (None: no opt-in, ``limit`` is final).

    Returns
    -------
    int

    Raises
    ------
    InputError
        Not a positive integer, or beyond ``limit`` without ``allow_long``.

    Examples
    --------
    >>> check_count("frames", 50, 10)
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: frames must be at most 10 (pass allow_long=True for a longer run), got 50
    """
    if not isinstance(value, numbers.Integral) or isinstance(value, bool) or value < 1:
        raise InputError(f"{name} must be a positive integer, got {value!r}")
    if value > limit and not allow_long:
        opt_in = "" if allow_long is None else " (pass allow_long=True for a longer run)"
        raise InputError(f"{name} must be at most {limit}{opt_in}, got {value!r}")
    return int(value)


def check_duration(name: str, value: Any, limit: float, allow_long: bool = False) -> float:
    """``value`` as a positive finite number of seconds at most ``limit`` (unless ``allow_long``).

    Parameters
    ----------
    name : str
        The argument's name.
    value : Any
        The duration (s).
    limit : float
        The longest duration without ``allow_long``.
    allow_long : bool
        Opt in to durations beyond ``limit``.

    Returns
    -------
    float

    Raises
    ------
    InputError
        Not a positive finite number, or beyond ``limit`` without ``allow_long``.

    Examples
    --------
    >>> check_duration("seconds", float("nan"), 10.0)
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: seconds must be a positive finite number of seconds, got nan
    """
    real = isinstance(value, numbers.Real) and not isinstance(value, bool)
    if not real or not math.isfinite(float(value)) or float(value) <= 0:
        raise InputError(f"{name} must be a positive finite number of seconds, got {value!r}")
    if float(value) > limit and not allow_long:
        raise InputError(f"{name} must be at most {limit:g} s (pass allow_long=True for a longer run), "
                         f"got {value!r}")
    return float(value)


def substeps(seconds: float, max_dt: float) -> list[float]:
    """Equal steps covering ``seconds``, each at most ``max_dt``.

    Parameters
    ----------
    seconds, max_dt : float
        Time to cover and the largest step (> 0).

    Returns
    -------
    list of float
    """
    n = max(1, math.ceil(seconds / max_dt - 1e-9))
    return [seconds / n] * n


def run_substeps(step: Callable[[dict, float], dict | None], values: dict, seconds: float,
                 max_dt: float) -> tuple[dict, bool, Exception | None]:
    """Chain ``step(values, dt)`` over ``seconds`` in sub-steps of at most ``max_dt``.

    Parameters
    ----------
    step : callable (values, dt) -> dict or None
        The explorer's ``play_step``: the control values ``dt`` later (None: the run is over).
    values : dict
        The control values to start from.
    seconds : float
        Simulated seconds to cover.
    max_dt : float
        Largest sub-step.

    Returns
    -------
    (dict, bool, Exception or None)
        The values reached, whether the run ended (``step`` returned None), and the exception
        (even ``KeyboardInterrupt``) that stopped it.
    """
    vals = dict(values)
    for dt in substeps(seconds, max_dt):
        try:
            new = step(dict(vals), dt)
        except (Exception, KeyboardInterrupt) as exc:  # noqa: BLE001 - the caller reports it (or
            return vals, True, exc                     # raises Ctrl-C again): the steps done are kept
        if new is None:
            return vals, True, None
        vals.update(new)
    return vals, False, None


class PlayClock:
    """Simulated seconds due at each Play tick, from the wall clock.

    Parameters
    ----------
    rate : float
        Simulated seconds per wall second (speed × time scale).
    clock : callable, optional
        The wall clock (default :func:`time.monotonic`).
    lead : float
        Wall seconds already due at the start (the first tick shows one frame's motion).

    Examples
    --------
    >>> t = iter([0.0, 0.05, 0.30, 5.0])
    >>> c = PlayClock(2.0, clock=lambda: next(t))
    >>> c.due(), c.due(), c.due()
    (0.1, 0.5, 1.0)
    """

    def __init__(self, rate: float, clock: Callable[[], float] | None = None, lead: float = 0.0):
        self.rate = float(rate)
        self.clock = clock or time.monotonic
        self.last = self.clock() - float(lead)

    def due(self) -> float:
        """Simulated seconds since the last call (the gap capped at :data:`MAX_CATCHUP` wall seconds).

        Returns
        -------
        float
        """
        now = self.clock()
        gap = min(max(now - self.last, 0.0), MAX_CATCHUP)
        self.last = now
        return gap * self.rate


class PlayMixin:
    """Play for :class:`~planargeo.widgets.base.Explorer`: the controls, the clock, the page's ticks."""

    def _make_play_controls(self) -> None:
        """Play, speed, loop and the time scale (an explorer with :meth:`play_step`)."""
        self.play_control = self.play_speed = self.play_loop = self.play_scale = None
        self._clock: PlayClock | None = None
        self._play_origin: dict[str, Any] | None = None
        self._last_tick = (0.0, 0.0)
        self._play_hold: contextlib.ExitStack | None = None
        self._play_synced = 0.0
        self._play_moved: tuple[str, ...] = ()     # the controls the last Play frame moved
        self._play_sent: dict[str, Any] = {}       # their values sent with a frame, since the last sync
        if not self.has_play:
            return
        self.play_control = W.Play(value=0, min=0, max=10 ** 9, step=1,
                                   interval=int(round(1000 / self.play_fps)), description="play",
                                   show_repeat=False)
        self.play_speed = W.Dropdown(options=[("¼×", 0.25), ("½×", 0.5), ("1×", 1.0),
                                              ("2×", 2.0), ("4×", 4.0)], value=1.0,
                                     description="play at", layout=W.Layout(width="150px"))
        self.play_loop = W.Checkbox(value=True, description="loop", indent=False,
                                    layout=W.Layout(width="80px"))
        scale = float(self.time_scale)
        self.play_scale = W.HTML(
            f"<span style='white-space:nowrap' title='1× plays {scale:g} simulated seconds per second'>"
            + ("1× = real time" if scale == 1.0 else f"1× plays {scale:g} s of motion a second") + "</span>")
        self.play_speed.observe(self.guarded(lambda _c: self._restart_clock()), names="value")
        self.play_control.observe(self.guarded(self._play_tick), names="value")
        self.play_control.observe(self.guarded(self._play_toggled), names="playing")

    def _reset_play(self) -> None:
        """Play's speed and loop at their defaults (for :meth:`Explorer.reset`)."""
        if self.play_speed is not None:
            self.play_speed.value = 1.0
            self.play_loop.value = True

    def advance(self, n_frames: int = 1, *, seconds: float | None = None,
                allow_long: bool = False) -> "Explorer":
        """Step Play ``n_frames`` frames without a front end (one update per frame).

        Each frame covers :attr:`play_dt` (or ``seconds / n_frames``) in :meth:`play_step`
        sub-steps; a None from ``play_step`` or a refused step ends the run.

        Parameters
        ----------
        n_frames : int
            Number of frames, at most :data:`MAX_ADVANCE_FRAMES`.
        seconds : float, optional
            Simulated seconds the frames cover together, at most :data:`MAX_ADVANCE_SECONDS`.
        allow_long : bool
            Opt in to more frames or seconds than the limits.

        Returns
        -------
        Explorer

        Raises
        ------
        InputError
            No Play, or a count or duration that is not positive or beyond its limit.
        """
        if not self.has_play:
            raise InputError(f"{type(self).__name__} has no Play (it does not define play_step)")
        n = check_count("n_frames", n_frames, MAX_ADVANCE_FRAMES, allow_long)
        if seconds is None:
            per_frame = self.play_dt
            check_duration("n_frames × play_dt", n * per_frame, MAX_ADVANCE_SECONDS, allow_long)
        else:
            per_frame = check_duration("seconds", seconds, MAX_ADVANCE_SECONDS, allow_long) / n
        for _ in range(n):
            if not self._frame(per_frame):
                break
        return self

    @property
    def play_dt(self) -> float:
        """Simulated seconds per Play frame: ``speed × time_scale / play_fps``."""
        speed = self.play_speed.value if self.play_speed is not None else 1.0
        return float(speed) * float(self.time_scale) / float(self.play_fps)

    @property
    def play_max_dt(self) -> float:
        """The longest :meth:`play_step` sub-step: ``1 / play_fps`` simulated seconds."""
        return 1.0 / float(self.play_fps)

    def _frame(self, seconds: float | None = None) -> bool:
        """One shown Play frame ``seconds`` on (default :attr:`play_dt`), in sub-steps."""
        seconds = self.play_dt if seconds is None else float(seconds)
        start = dict(self.shown_values or self.values)
        vals, ended, exc = run_substeps(self.play_step, start, seconds, self.play_max_dt)
        new = {k: v for k, v in vals.items() if k in self.controls and not same_value(v, start.get(k))}
        self._play_moved = tuple(new)
        before = self.n_updates
        if new:
            self.set(**new)
        shown = self.n_updates > before
        if isinstance(exc, KeyboardInterrupt):      # Ctrl-C: what was computed is shown, then it stops
            raise exc
        if exc is not None:
            message = f"play stopped: {self._reason(exc)}"
            if self.message:
                message += f"; {self.message}"
            self._refuse(message, self.figure_message(exc))
            return False
        if new and not shown:        # the new values were refused (the message says why)
            return False
        return not ended

    def _restart_clock(self) -> None:
        """Play's wall clock: started with Play (one frame due at once), its rate following the speed."""
        rate = float(self.play_speed.value) * float(self.time_scale)
        if self.play_control is None or not self.play_control.playing:
            self._clock = None
        elif self._clock is None:
            self._clock = PlayClock(rate, self.wall_clock, lead=1.0 / self.play_fps)
        else:
            self._clock.rate = rate

    def _play_toggled(self, change) -> None:
        if change["new"]:
            self._play_origin = dict(self.shown_values)
        else:
            self._release_play_hold()
        self._clock = None
        self._restart_clock()

    @property
    def _page_plays(self) -> bool:
        """True when the page's canvas paces Play (its ``playing`` trait and tick messages)."""
        canvas = getattr(self, "canvas", None)
        return canvas is not None and canvas.has_trait("playing")

    def _connect_page_play(self) -> None:
        """Play in the page: the button's ``playing`` is the canvas's; its ticks advance Play.

        The Play widget's own timer is slowed to nothing: it only shows the button.
        """
        if not (self.has_play and self._page_plays):
            return
        self.canvas.on_tick = self._page_tick
        if type(self).play_ahead is not PlayMixin.play_ahead:
            self.canvas.on_idle = self._page_idle
        self.play_control.interval = 10 ** 7
        self._play_link = W.link((self.play_control, "playing"), (self.canvas, "playing"))
        with contextlib.suppress(RuntimeError):       # in a kernel (an event loop runs)
            asyncio.get_running_loop().call_later(WARM_PLAY_S, self._warm_play)

    def _warm_play(self) -> None:
        """Play's first frame computed and dropped: loads what it needs (about 0.6 s the first time
        in a kernel: the integrator's module and compiled dynamics) before Play is pressed."""
        if self.play_control.playing:
            return
        start = dict(self.shown_values or self.values)
        values, _ended, exc = run_substeps(self.play_step, start, self.play_dt, self.play_max_dt)
        if exc is None:
            changed = {k for k, v in values.items() if k in self.controls and not same_value(v, start.get(k))}
            with contextlib.suppress(Exception):     # a failure is Play's to report, when pressed
                self.compute(values, changed)

    def play_ahead(self, values, seconds: float) -> bool:
        """Play's work between the page's frames (an explorer's own; none here): the motion the next
        frames show, computed ahead by the same steps, so the states stay bit-identical.

        Parameters
        ----------
        values : dict
            The controls' values shown.
        seconds : float
            About how much wall time to spend now.

        Returns
        -------
        bool
            True while work is left.
        """
        return False

    def _page_idle(self, seconds: float) -> bool:
        """Between the page's frames: the explorer's ``play_ahead`` for at most about ``seconds``."""
        if not (self.play_control.playing and self._clock is not None):
            return False
        return bool(self.play_ahead(self.shown_values, seconds))

    def _page_tick(self) -> None:
        """A tick from the page while it plays: one frame of the wall-clock time since the last."""
        if not self.play_control.playing:
            return
        if self._clock is None:
            self._restart_clock()
        seconds = self._clock.due()
        if seconds <= 0 or self._frame(seconds):
            return
        self._release_play_hold()
        if not self._play_again() and self._message:
            raise PlanargeoError(self._message)      # the page shows why Play stopped

    def _play_again(self) -> bool:
        """At the end of a run: start again (loop, no refusal: True) or stop Play."""
        if self.play_loop is not None and self.play_loop.value and self._play_origin and \
                not self._message:
            self.set(**self._play_origin)
            return True
        self.play_control.playing = False
        return False

    def _keep_hold(self, stack: contextlib.ExitStack, dragging: bool = False) -> bool:
        """While the page plays or drags, keep the syncs ``stack`` holds (True), sent every
        PLAY_SYNC_S (Play) or ``drag_sync_s`` (a drag step: ``dragging``).

        Called as each update's syncs would go (after its picture).  While Play holds them, the
        controls the last Play frame moved (the time) go at once (:meth:`_send_play_moved`); a
        drag's held values go at the next update that is not a drag step (its release, a refusal),
        or ``drag_sync_s`` after they were first held (a timer, in a kernel) if that comes first.
        """
        if not hasattr(self, "_play_hold"):      # before Play's controls exist
            return False
        playing = (self.has_play and self._page_plays and self.play_control is not None
                   and self.play_control.playing)
        drag_s = float(getattr(self, "drag_sync_s", 0.0) or 0.0)
        every = PLAY_SYNC_S if playing else (drag_s if dragging and drag_s > 0 else 0.0)
        now = time.monotonic()
        if every and self._play_hold is None:
            self._play_hold, self._play_synced = stack, now
            if playing:
                self._send_play_moved()
            else:
                self._sync_later(every)
            return True
        if self._play_hold is not None:
            if not every or now - self._play_synced >= every:
                self._release_play_hold()
            elif playing:
                self._send_play_moved()
        return False

    def _sync_later(self, seconds: float) -> None:
        """A drag's held values sent ``seconds`` from now if still held (in a kernel; without an
        event loop the drag's release sends them)."""
        try:
            loop = asyncio.get_running_loop()
        except RuntimeError:
            return
        hold = self._play_hold

        def due():
            playing = self.play_control is not None and self.play_control.playing
            if self._play_hold is hold and not playing and not getattr(self, "_after_depth", 0):
                self._release_play_hold()

        loop.call_later(seconds, due)

    def _send_play_moved(self) -> None:
        """The values of the controls the last Play frame moved, sent now (the rest wait for the
        next sync): the time field follows every picture; one small message per control moved."""
        for k in self._play_moved:
            w = self.controls.get(k)
            if w is None or k in self._play_sent and same_value(self._play_sent[k], w.value):
                continue
            w.send_state("value")
            self._play_sent[k] = w.value

    def _release_play_hold(self) -> None:
        """Send the controls' and readout's held values to the page (Play's or a drag's sync)."""
        hold, self._play_hold = self._play_hold, None
        self._play_sent.clear()
        if hold is not None:
            hold.close()

    def _play_tick(self, change) -> None:
        if not self.play_control.playing or self._page_plays:
            return
        # ticks that arrive while a slow frame was drawn are dropped; the next covers their time
        interval = self.play_control.interval / 1000.0
        now = self.wall_clock()
        last_end, last_cost = self._last_tick
        if last_cost > interval and now - last_end < max(0.5 * interval, 0.01):
            return
        if self._clock is None:
            self._restart_clock()
        seconds = self._clock.due()
        if seconds <= 0:
            return
        t0 = self.wall_clock()
        ok = self._frame(seconds)
        t1 = self.wall_clock()
        self._last_tick = (t1, t1 - t0)
        if not ok:
            self._play_again()
