"""Time integration with diagnostics: :mod:`~planargeo.simulate.integrate` for open chains and trees,
:mod:`~planargeo.simulate.loops` for closed loops (thesis 9.3-9.5)."""
