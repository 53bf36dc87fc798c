"""The fuzz suite: planargeo's public entry points called with generated arguments (issues 16, 23).

Every call ends one of three ways (:mod:`fuzz.harness`):

* *computed* (``ok``) — it returned finite results (or a non-finite value the entry point
  documents, e.g. ``to_xy`` of a point at infinity), or the explorer showed a new state;
* *refused* (``package error``) — a :class:`planargeo.errors.PlanargeoError` (the command line: a
  one-line message and a non-zero status), or the explorer's own message keeping its last state;
* *failed* — ``foreign``: any other exception, a warning let out, numpy's or Python's words
  ("overflow encountered", a traceback) shown to a user; ``non-finite``: NaN or infinity from
  finite arguments; ``hang``: no answer within the time limit; ``inconsistent``: an explorer that
  disagrees with a fresh one built from its control values.

The arguments come from each parameter's documented domain, extremes included, with one hostile
argument in about a fifth of the calls (:mod:`fuzz.strategies`, hypothesis); the entry points
are listed in :mod:`fuzz.targets`.  The explorers are driven by seeded action sequences through
the paths of the mouse and the page — slider jumps, drags of every handle, Play steps, Reset,
exports — each sequence followed by the one-state invariant (:mod:`fuzz.explorers`).

``make fuzz`` runs ``python tests/fuzz/run.py`` (8000 calls, more than 200 per explorer, a table
per entry point, exit status 1 on any failure, with the shortest failing action sequence of each
explorer failure); ``tests/test_fuzz.py`` runs a small version inside ``make test`` and checks
that the harness catches planted defects.
"""
