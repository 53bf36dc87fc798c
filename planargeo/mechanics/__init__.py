"""Mechanisms (thesis ch. 3-6): joints (``s``, ``R``), subspaces (``T``, ``U``, the one singularity
rule), the frozen model and its per-state data, kinematics, loop-closing contacts, and blows."""
