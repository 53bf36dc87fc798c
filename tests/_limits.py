"""Limits shared by the tests and the fuzz harness: a hang guard, and the words of an explorer's update budget.

* :func:`time_limit` makes a block that runs past its wall time fail (not hang).  It is a hang guard,
  generous because the machine may be loaded, never a speed figure.
* :data:`REFUSAL` is the refusal of a time too far for one update
  (:class:`planargeo.widgets._motion.Budget`), :func:`ask` sets a time under the guard and reads that
  refusal, :func:`by_steps` and :func:`play_after_refusal` walk an explorer's time through it,
  :func:`picture_texts` gathers the words drawn in a picture.

Examples
--------
>>> import time
>>> try:
...     with time_limit(0.05):
...         time.sleep(1)
... except Hang as e:
...     print(e)
no answer within 0.05 s
>>> m = REFUSAL.search("t = 30 s is more motion than one step computes (100 evaluations of the dynamics); "
...                    "it is computed up to t = 1.5 s now: ask again to go on from there, or press Play")
>>> m["t"], m["n"], m["reached"]
('30', '100', '1.5')
>>> picture_texts({"elements": [{"parts": [{"text": "too  far"}, {"lines": ["ask", "again"]}]}]})
'too far ask again'
"""
from __future__ import annotations

import contextlib
import re
import signal


class Hang(BaseException):
    """Raised by the alarm inside a call past its time limit (a BaseException: no ``except Exception`` stops it)."""


@contextlib.contextmanager
def time_limit(seconds: float):
    """Raise :class:`Hang` in the main thread after ``seconds`` (SIGALRM; POSIX).

    An alarm raised where Python swallows exceptions (a garbage-collector callback) is raised
    again every 0.5 s, and a block that ends after its alarm fired raises :class:`Hang` at its
    end: a call past its limit is always a hang.

    >>> with time_limit(5):
    ...     print("done in time")
    done in time
    """
    fired = []

    def alarm(signum, frame):
        fired.append(True)
        signal.setitimer(signal.ITIMER_REAL, 0.5)
        raise Hang(f"no answer within {seconds:g} s")

    old = signal.signal(signal.SIGALRM, alarm)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
    if fired:
        raise Hang(f"no answer within {seconds:g} s")


#: An explorer's refusal of a time too far for one update: the time asked, the evaluations one update
#: spends, the time computed so far.
REFUSAL = re.compile(r"t = (?P<t>\S+) s is more motion than one step computes \((?P<n>[\d,]+) evaluations of "
                     r"the dynamics\); it is computed up to t = (?P<reached>\S+) s now: ask again to go on "
                     r"from there, or press Play")


def ask(ex, control: str, value, seconds: float = 300) -> re.Match | None:
    """Set the explorer's time ``control`` to ``value`` (under :func:`time_limit`); the refusal, or None."""
    with time_limit(seconds):
        ex.set(**{control: value})
    return REFUSAL.search(ex.message)


def by_steps(ex, control: str, steps, check):
    """Ask the times ``steps`` in turn: each is computed in one update (no refusal, no message), and
    ``check(ex)`` holds after each; the explorer."""
    for t in steps:
        assert ask(ex, control, t) is None and ex.message == "", (t, ex.message)
        check(ex)
    return ex


def play_after_refusal(ex, control: str, far, frames: int = 2, seconds: float = 120):
    """Ask the time ``far`` (refused: too far for one update), then Play ``frames`` frames, which goes on
    without a message; the explorer."""
    assert ask(ex, control, far), ex.message
    with time_limit(seconds):
        ex.advance(frames)
    assert ex.message == "", ex.message
    return ex


def picture_texts(pic) -> str:
    """Every text, label and line of text in a picture, joined, white space folded."""
    out = []

    def walk(x):
        if isinstance(x, dict):
            for k, v in x.items():
                if k in ("text", "label", "lines") and isinstance(v, (str, list)):
                    out.append(v if isinstance(v, str) else " ".join(map(str, v)))
                else:
                    walk(v)
        elif isinstance(x, list):
            for v in x:
                walk(v)
    walk(pic)
    return " ".join(" ".join(out).split())
