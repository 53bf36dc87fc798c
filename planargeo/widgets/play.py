"""Play's clock: simulated time at true real time × speed × time scale, in bounded sub-steps.

Play shows a frame whenever the page ticks, but a frame may take longer to
draw than the tick interval.  So the time is measured on the wall clock: each
tick advances the simulation by the wall time since the last one (× speed ×
the explorer's ``time_scale``), through ``play_step`` calls of at most
``1 / play_fps`` simulated seconds each.  No physics step is skipped; only
display frames are dropped.  A tick never catches up more than
:data:`MAX_CATCHUP` wall seconds (after a pause of the kernel the motion
resumes, it does not jump).

Long runs are bounded (issue 23): :func:`check_count` and
:func:`check_duration` refuse, with a named :class:`~planargeo.errors.InputError`,
a non-positive or non-finite count or duration, and one beyond the stated
limit unless the caller opts in with ``allow_long=True``.

Examples
--------
>>> substeps(0.25, 0.1)
[0.08333333333333333, 0.08333333333333333, 0.08333333333333333]
>>> run_substeps(lambda v, dt: {"t": v["t"] + dt}, {"t": 0.0}, 1.0, 0.05)[0]["t"]
1.0000000000000002
>>> check_count("n_frames", 0, 10)
Traceback (most recent call last):
...
planargeo.errors.InputError: n_frames must be a positive integer, got 0
"""
from __future__ import annotations

import math
import numbers
import time
from typing import Any, Callable

from planargeo.errors import InputError

__all__ = ["MAX_CATCHUP", "MAX_ADVANCE_FRAMES", "MAX_ADVANCE_SECONDS", "MAX_ANIMATION_FRAMES",
           "substeps", "run_substeps", "check_count", "check_duration", "PlayClock"]

#: wall seconds a single Play tick may catch up (a longer gap: the motion resumes, it does not jump)
MAX_CATCHUP = 0.5
#: frames one call of ``advance`` may take without ``allow_long=True``
MAX_ADVANCE_FRAMES = 10_000
#: simulated seconds one call of ``advance`` may cover without ``allow_long=True``
MAX_ADVANCE_SECONDS = 3600.0
#: frames of an exported animation without ``allow_long=True`` (a minute at 20 frames per second)
MAX_ANIMATION_FRAMES = 1200


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
    >>> check_count("frames", 5, 10)
    5
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
    seconds : float
        Time to cover (> 0).
    max_dt : float
        Largest step (> 0).

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
        The control values reached (what was computed is kept), whether the run
        ended (``step`` returned None), and the exception that stopped it, if any
        (a ``KeyboardInterrupt`` too: the caller shows what was computed, then raises it).
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
            Wall seconds since the last call (at most :data:`MAX_CATCHUP`) times the rate.
        """
        now = self.clock()
        gap = min(max(now - self.last, 0.0), MAX_CATCHUP)
        self.last = now
        return gap * self.rate
