"""Time integration with diagnostics.

* :mod:`planargeo.simulate.integrate` -- :func:`simulate` for open chains and trees;
* :mod:`planargeo.simulate.loops` -- :func:`simulate_loops` for closed loops (thesis 9.3-9.5).
"""
