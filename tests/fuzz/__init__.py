"""The fuzz suite: random and hostile arguments against planargeo's public entry points (issue 16).

Every call is classified (:mod:`fuzz.harness`) as

* ``ok`` — returned finite results (or a non-finite value the entry point documents, e.g.
  ``to_xy`` of a point at infinity);
* ``package error`` — raised a :class:`planargeo.errors.PlanargeoError` (the CLI: a one-line
  message and a non-zero status);
* ``foreign`` — raised anything else, or let a warning out (numpy's ``ComplexWarning``, an overflow);
* ``non-finite`` — returned NaN or infinity from finite arguments;
* ``hang`` — did not return within the entry point's time limit;
* ``inconsistent`` — an explorer whose controls, readout and message disagree (:mod:`fuzz.targets`).

The arguments come from :mod:`fuzz.strategies` (hypothesis), including NaN, ±inf, 1e±300, zero
vectors, wrong lengths and shapes, strings, None, complex numbers and dicts; the entry points
are listed in :mod:`fuzz.targets`.  ``make fuzz`` runs ``python tests/fuzz/run.py`` (at least 10⁴
calls, a table of outcomes per entry point); ``tests/test_fuzz.py`` runs a fast profile inside
``make test``.
"""
