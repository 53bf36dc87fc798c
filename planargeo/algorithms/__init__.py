"""Forward and inverse dynamics on a :class:`planargeo.mechanics.model.Model` (thesis chapters 3, 6-9).

Every forward dynamics function is ``(model, q, qd, tau, f_ext=None) -> qdd``, ``f_ext`` (N, 3)
world wrenches at the origin.  ``aba`` (3.6) and ``rnea`` (3.9) are the recursions, compiled in
``kernels`` (reached through ``compiled``); ``crba`` is the dense reference; ``articulated_inertia``
(7.1.1), ``articulated_mobility`` (7.4.1), ``projective`` (6.108-6.113), ``chain_splitting`` (7.6),
``stacked`` (9.1) and ``loops`` (9.3-9.5, with a Lagrange reference) the chapter 6-9 algorithms.
Import from the submodules (this package imports nothing).
"""
