"""Mechanisms: joints, subspaces, the model/data split, kinematics and contacts (thesis ch. 3, 4.8, 6).

* :mod:`planargeo.mechanics.joints` -- joint motion spaces ``s`` and reaction spaces ``R``;
* :mod:`planargeo.mechanics.subspaces` -- the weighted pseudo-inverses ``T`` and ``U`` and the
  decompositions of wrenches, twists and inertias (6.1-6.8); the package's one singularity rule;
* :mod:`planargeo.mechanics.model` -- the frozen :class:`Model` and its per-state :class:`Data`;
* :mod:`planargeo.mechanics.kinematics` -- poses, twists and bias accelerations of every body;
* :mod:`planargeo.mechanics.contacts` -- loop-closing contacts (pins, sliders, welds).
"""
