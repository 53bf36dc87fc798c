"""Forward and inverse dynamics algorithms on a :class:`planargeo.mechanics.model.Model`.

Every forward dynamics function has the signature
``(model, q, qd, tau, f_ext=None) -> qdd``; ``f_ext`` is ``(N, 3)`` world
wrenches at the origin applied to each body (besides gravity).

* :mod:`planargeo.algorithms.aba` -- recursive articulated-body algorithm (thesis 3.6): ``forward_dynamics``
  and the full workspace ``articulated_body`` (the general array recursion, every joint kind)
* :mod:`planargeo.algorithms.rnea` -- recursive Newton-Euler inverse dynamics (3.9)
* :mod:`planargeo.algorithms.kernels` -- ABA (3.31-3.42) and RNEA as plain loops over bodies, compiled
  by numba (revolute, prismatic and fixed joints; the same source runs under ``NUMBA_DISABLE_JIT=1``)
* :mod:`planargeo.algorithms.compiled` -- which calls the kernels serve (and how batches are split)
* :mod:`planargeo.algorithms.crba` -- dense reference: mass matrix and bias, solved densely
* :mod:`planargeo.algorithms.articulated_inertia` -- articulated inertias ``A_i``, bias forces ``d_i`` (7.1.1),
  the one copy of that recursion, and the model glue of the chapter 6-9 algorithms
* :mod:`planargeo.algorithms.articulated_mobility` -- articulated mobilities ``Λ_i⁻¹``, bias accelerations ``b_i``
  (7.4.1; trees 9.45), the one copy of 7.38
* :mod:`planargeo.algorithms.projective` -- projective formulation (6.108-6.113)
* :mod:`planargeo.algorithms.chain_splitting` -- mobility split (7.4.1, 7.54/7.56)
* :mod:`planargeo.algorithms.stacked` -- stacked formulation (9.1, 9.39/9.48)
* :mod:`planargeo.algorithms.loops` -- closed loops and contacts (9.3-9.5: ``G``, ``Υ``, ``F = Γ(Gu - ν)``),
  with a Lagrange-multiplier reference

Import the functions from their submodules (this package imports nothing).  Within the chapter 6-9
modules imports point one way: ``articulated_inertia`` ← ``articulated_mobility``, ``projective`` ←
``chain_splitting``, ``stacked`` ← ``loops``.
"""
