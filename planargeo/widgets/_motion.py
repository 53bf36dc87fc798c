"""A motion integrated once in fixed chunks (DOP853, dense output) and read at any time: the state
at ``t`` depends on ``t`` and the initial state alone, whatever frames were shown before.  One
call spends a bounded :class:`Budget` of evaluations; a time beyond is refused
(:class:`~planargeo.errors.SizeLimitError`), the chunks done kept.
"""
from __future__ import annotations

import math
import re
import time

import numpy as np

from planargeo.errors import InputError, SingularConfigurationError, SizeLimitError

__all__ = ["Motion", "Budget", "MAX_EVALS", "refusal_on_picture"]

#: Evaluations of the dynamics one call may spend (about 5 s for a 20-link chain).
MAX_EVALS = 250_000


class _OverBudget(Exception):
    """The evaluations of one call ran out (caught in :meth:`Motion.extend`)."""


class Budget:
    """The ``max_evals`` (at least 1) evaluations of the dynamics one update may spend, and the
    refusal when they run out.

    Examples
    --------
    >>> b = Budget(100)
    >>> b.charge(120); b.spent, b.left
    (True, -20)
    >>> print(b.refusal(30.0, 1.5))
    t = 30 s is more motion than one step computes (100 evaluations of the dynamics); it is computed up to t = 1.5 s now: ask again to go on from there, or press Play
    """

    def __init__(self, max_evals: int = MAX_EVALS):
        if isinstance(max_evals, bool) or not int(max_evals) == max_evals or int(max_evals) < 1:
            raise InputError(f"max_evals must be a whole number of at least 1, got {max_evals!r}")
        self.max_evals = int(max_evals)
        self.left = self.max_evals

    @property
    def spent(self) -> bool:
        """True once the evaluations are used up (the next step must not start)."""
        return self.left <= 0

    def charge(self, n: int = 1) -> None:
        """Count ``n`` evaluations done (a step already taken is kept: this never raises)."""
        self.left -= int(n)

    def counting(self, rhs):
        """``rhs`` charging one evaluation per call, stopping the integration when none is left."""
        def counted(t, y):
            if self.left <= 0:
                raise _OverBudget
            self.left -= 1
            return rhs(t, y)
        return counted

    def refusal(self, t: float, reached: float) -> SizeLimitError:
        """The error of an update stopped at ``reached`` on its way to ``t`` (the limit and what to do)."""
        return SizeLimitError(
            f"t = {t:.4g} s is more motion than one step computes ({self.max_evals:,} evaluations "
            f"of the dynamics); it is computed up to t = {reached:.4g} s now: ask again to "
            f"go on from there, or press Play")


def refusal_on_picture(text: str) -> str | None:
    """The short form of a :meth:`Budget.refusal` for the picture, or None for another message.

    Examples
    --------
    >>> refusal_on_picture(str(Budget(10).refusal(30.0, 1.5)))
    'too far for one step: computed up to 1.5 s; ask again to go on'
    """
    if "more motion than one step computes" not in text:
        return None
    far = re.search(r"computed up to t = (\S+) s", text)
    return f"too far for one step: computed up to {far.group(1) if far else '?'} s; ask again to go on"


class Motion:
    """``y(t)`` of ``ẏ = rhs(t, y)`` from ``y(0) = y0``, integrated in chunks of ``chunk`` seconds.

    ``rhs`` of a time-invariant system (``t`` is the time within a chunk); ``rtol``, ``atol``: DOP853's
    tolerances; ``max_evals``: evaluations of ``rhs`` one call of :meth:`extend` (or :meth:`at`) may spend.

    Examples
    --------
    >>> m = Motion(lambda t, y: -y, [1.0], chunk=0.5)
    >>> round(float(m.at(1.25)[0]), 8) == round(math.exp(-1.25), 8)
    True
    """

    def __init__(self, rhs, y0, chunk: float = 1.0, rtol: float = 1e-9, atol: float = 1e-11,
                 max_evals: int = MAX_EVALS):
        self.rhs, self.chunk, self.rtol, self.atol = rhs, float(chunk), float(rtol), float(atol)
        self.max_evals = int(max_evals)
        self.starts = [np.array(y0, dtype=float)]       # the state at k * chunk
        self.sols = []                                   # chunk k's interpolant (k < len(sols))
        self._open = None              # the chunk being computed: (solver, times, interpolants)
        self._rhs_now = rhs

    @property
    def reached(self) -> float:
        """The time up to which the motion is computed (s)."""
        return len(self.sols) * self.chunk

    def extend(self, t: float) -> None:
        """Compute the chunks up to time ``t`` (each kept as soon as it is done: Ctrl-C keeps them).

        A SingularConfigurationError if the integrator stops, a SizeLimitError if reaching ``t``
        needs more than :attr:`max_evals` evaluations in this call.
        """
        self._complete(int(math.floor(t / self.chunk)) + 1, t)

    def _complete(self, need: int, t: float) -> Budget:
        """Compute the first ``need`` chunks (:meth:`extend`, on its way to ``t``); what is left of
        this call's budget."""
        budget = Budget(self.max_evals)
        while len(self.sols) < need:
            try:
                self._steps(budget, None)
            except _OverBudget:
                raise budget.refusal(t, self.reached) from None
        return budget

    def work_ahead(self, t: float, seconds: float) -> bool:
        """Spend about ``seconds`` of wall time (one integrator step more at worst) computing the
        chunks up to time ``t``; True while work is left.

        The same steps as :meth:`extend` (the same states, bit for bit); a failure is left for
        :meth:`extend` to report.
        """
        need = int(math.floor(t / self.chunk)) + 1
        end = time.perf_counter() + float(seconds)
        try:
            while len(self.sols) < need:
                if self._steps(Budget(self.max_evals), end):
                    continue
                return True
        except Exception:  # noqa: BLE001 - extend() reports it when the time is asked for
            self._open = None
            return False
        return False

    def _steps(self, budget: Budget, until: float | None, cover: float | None = None) -> bool:
        """Steps of the chunk being computed, until it is done (True), past the wall time ``until``
        or, with ``cover``, once its steps reach the time ``cover`` within it (False)."""
        from scipy.integrate import DOP853, OdeSolution

        if self._open is None:
            k = len(self.sols)
            self._rhs_now = self.rhs
            solver = DOP853(lambda t, y: self._rhs_now(t, y), 0.0, self.starts[k], self.chunk,
                            rtol=self.rtol, atol=self.atol)
            self._open = (solver, [0.0], [])
        solver, ts, interpolants = self._open
        self._rhs_now = budget.counting(self.rhs)
        try:
            # solve_ivp's loop (t_eval None, dense output), one step at a time
            while True:
                message = solver.step()
                if solver.status == "failed":
                    self._open = None
                    raise self._failed(message)
                interpolants.append(solver.dense_output())
                if len(ts) > 1 and ts[-1] == solver.t:
                    interpolants.pop()
                else:
                    ts.append(solver.t)
                if solver.status == "finished":
                    break
                if (until is not None and time.perf_counter() > until) or \
                        (cover is not None and ts[-1] >= cover):
                    return False
        except _OverBudget:
            self._open = None       # the chunk starts again at the next call (as before)
            raise
        finally:
            self._rhs_now = self.rhs
        self._open = None
        y = solver.y
        if not np.all(np.isfinite(y)):
            raise self._failed("the state is not finite")
        self.sols.append(OdeSolution(np.array(ts), interpolants, alt_segment=False))
        self.starts.append(np.array(y, dtype=float))
        return True

    def _failed(self, why: str) -> SingularConfigurationError:
        return SingularConfigurationError(
            f"the motion could not be integrated past t = {self.reached:.4g} s: {why}")

    def at(self, t: float) -> np.ndarray:
        """The state at time ``t >= 0`` (chunk start: exactly the stored state).

        Its chunk is computed only as far as ``t`` (the rest later, by the same steps): the first
        frame of Play does not wait for a whole chunk.  The value is the one the whole chunk's
        interpolant gives, bit for bit (the same step's dense output).
        """
        t = float(t)
        k = int(math.floor(t / self.chunk))
        s = t - k * self.chunk
        budget = self._complete(k, t)          # the chunks before k
        if s <= 0.0:
            return self.starts[k].copy()
        while len(self.sols) <= k and (self._open is None or self._open[1][-1] < s):
            try:
                self._steps(budget, None, cover=s)
            except _OverBudget:
                raise budget.refusal(t, self.reached) from None
        if len(self.sols) > k:
            return np.asarray(self.sols[k](s), dtype=float)
        from scipy.integrate import OdeSolution

        _solver, ts, interpolants = self._open      # chunk k's steps so far reach s
        return np.asarray(OdeSolution(np.array(ts), interpolants, alt_segment=False)(s), dtype=float)
