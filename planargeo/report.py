"""``planargeo report``: print a scene's parameters, state and solved quantities.

Usage::

    planargeo report SCENE [--set NAME=VALUE ...] [--json] [--allow-big]
    planargeo report --list [--json]

``--list`` prints every scene with its parameters and, for each quantity it reports, a
description, the thesis symbol and equation, and the unit (:data:`QUANTITY_INFO`; a scene
module may add its own as a module attribute ``QUANTITY_INFO = {scene: {key: (description,
symbol, equation, unit)}}``).  The table prints each quantity's unit after its value, and
values whose magnitude is below :data:`ZERO_TOL` times the scene's scale for that unit (the
largest magnitude among the scene's quantities in the same unit) as ``0.0``: round-off such
as ``4.7e-11`` where the exact value is 0.  ``--json`` keeps every value at full precision.

Values given with ``--set`` are read as ``int``, ``float`` (``1e-3``, ``nan``,
``inf``), ``bool`` (``true``/``false``), ``none``, a JSON list (``[1, 2]``) or
else kept as a string; an integer given for a parameter whose default is a
float becomes a float.  Errors (unknown scene or parameter, a value that makes
the scene impossible or beyond double precision, a size past the scene's limit
without ``--allow-big``) exit with status 1 and one line on stderr; malformed
arguments exit with status 2.

Examples
--------
>>> import argparse
>>> p = argparse.ArgumentParser(); add_arguments(p)
>>> main(p.parse_args(["two-body", "--set", "phi=0", "--json"]))  # doctest: +ELLIPSIS
{"scene": "two-body", "params": {"m": 1.0, "rho": 0.5, "L": 1.0, "phi": 0.0}, ...
0
>>> parse_value("3"), parse_value("2.5"), parse_value("True"), parse_value("none"), parse_value("abc")
(3, 2.5, True, None, 'abc')
"""
from __future__ import annotations

import argparse
import json
import math
import sys
from typing import Any

import numpy as np

__all__ = ["add_arguments", "main", "parse_value", "parse_sets", "to_plain", "format_table", "quantity_info",
           "round_off", "format_listing", "QUANTITY_INFO", "ZERO_TOL"]

#: Values below ``ZERO_TOL`` times the scene's scale for their unit print as 0 in the table.
ZERO_TOL = 1e-9

#: Units of screw arrays (components ``[x, y, z]`` at the global origin).
TWIST = "m/s, m/s, rad/s"
ACCEL = "m/s², m/s², rad/s²"
WRENCH = "N, N, N·m"
INERTIA = "kg, kg·m, kg·m²"
MOBILITY = "1/kg, 1/(kg·m), 1/(kg·m²)"
BASIS = "—"

#: ``scene -> quantity -> (description, thesis symbol, thesis equation, unit)`` of every quantity
#: ``planargeo report`` prints (``—``: dimensionless; screw arrays at the global origin).
QUANTITY_INFO: dict[str, dict[str, tuple[str, str, str, str]]] = {
    "chain": {
        "q": ("joint coordinates", "q", "2.1", "rad or m"),
        "qd": ("joint rates", "q̇", "2.3", "rad/s or m/s"),
        "tau": ("joint torques or forces", "Q", "3.13", "N·m or N"),
        "qdd": ("joint accelerations by each of five methods (ABA, projective, mobility + splitting, "
                "stacked, CRBA)", "q̈", "3.6, 6.108-6.113, 7.56, 9.43, 3.21", "rad/s² or m/s²"),
        "max_disagreement": ("largest difference between the methods' q̈", "max |Δq̈|", "—",
                             "rad/s² or m/s²"),
    },
    "car": {
        "omega_dot": ("angular acceleration of the car about the instant centre", "ω̇ = ψ", "6.131", "rad/s²"),
        "mu": ("lateral tyre forces [rear, front] along R₁, R₂ (negative: towards the ICR)", "μ", "6.133", "N"),
        "T": ("percussion space of the ICR joint", "T", "6.125", BASIS),
        "U": ("quake space of the ICR joint", "U", "6.127", BASIS),
        "s": ("motion space: unit rotation about the ICR", "s", "6.114", BASIS),
        "R": ("reaction space: unit forces along the rear and front axles", "R", "6.114", BASIS),
        "I": ("inertia of the car at the ICR", "I", "6.117", INERTIA),
        "v": ("velocity twist", "v", "6.115", TWIST),
        "kappa": ("bias acceleration", "κ", "6.116", ACCEL),
        "p": ("bias force", "p", "6.119", WRENCH),
        "f_A": ("drive force at the front tyre", "f_A", "6.120", WRENCH),
        "gamma": ("reactive acceleration components", "γ = Rᵀκ", "6.129", "m/s²"),
        "a": ("acceleration twist", "a", "6.44", ACCEL),
        "f": ("total tyre wrench (the joint force)", "f", "6.122", WRENCH),
        "V": ("speed of the rear contact", "V = ω d", "6.115", "m/s"),
    },
    "two-body": {
        "A1": ("articulated inertia of body 1 at joint CJ₁", "A₁", "7.19", INERTIA),
        "m_x": ("effective mass along x", "m_x", "7.12", "kg"),
        "mx_over_m": ("effective mass along x per body mass", "m_x / m", "7.22", "—"),
        "lam": ("length over radius of gyration", "λ = L/ρ", "7.21", "—"),
        "A2": ("articulated inertia of body 2 (= its rigid inertia)", "A₂ = I₂", "7.14, 7.17", INERTIA),
        "U2": ("quake space of joint 2", "U₂", "7.18", BASIS),
        "T2": ("percussion space of joint 2", "T₂", "6.30", BASIS),
        "s": ("joint motion spaces s₁, s₂", "s", "7.15", BASIS),
        "R": ("joint reaction spaces R₁, R₂", "R", "7.16", BASIS),
    },
    "horizontal-chain": {
        "d_over_L": ("effective centre of gravity of body 1 per link length", "d / L", "7.26, 7.27", "—"),
        "mx_over_m": ("effective mass along x per body mass", "m_x / m", "7.26", "—"),
        "my_over_m": ("effective mass along y per body mass", "m_y / m", "7.26", "—"),
        "Az_over_m_rho2": ("effective rotational inertia per m ρ²", "A_z / (m ρ²)", "7.26", "—"),
        "A1": ("articulated inertia of body 1 at the origin", "A₁", "7.1.1", INERTIA),
    },
    "mobility-example": {
        "Lambda1_inv": ("articulated mobility of body 1", "Λ₁⁻¹", "7.42", MOBILITY),
        "Lambda2_inv": ("articulated mobility of body 2", "Λ₂⁻¹", "7.43", MOBILITY),
        "f3": ("pure couple on body 2 from the fictitious joint 3", "f₃", "7.44", WRENCH),
        "a2": ("acceleration of body 2", "a₂ = -Λ₂⁻¹ f₃", "7.45, 7.46", ACCEL),
        "x_over_L": ("acceleration pole of body 2 per link length", "x / L", "7.47, 7.48", "—"),
        "eta": ("length over radius of gyration", "η = L/ρ", "7.49", "—"),
        "T1": ("percussion space of joint 1", "T₁", "7.40", BASIS),
        "U1": ("quake space of joint 1", "U₁", "7.40", BASIS),
        "T2": ("percussion space of joint 2", "T₂", "7.41", BASIS),
        "U2": ("quake space of joint 2", "U₂", "7.41", BASIS),
    },
    "slider-crank": {
        "q": ("joint angles crank, rod, piston", "q = (ψ, θ, φ)", "9.78", "rad"),
        "qd": ("joint rates", "q̇", "9.79", "rad/s"),
        "v": ("velocity twists of the three bodies", "v₁, v₂, v₃", "9.80", TWIST),
        "u": ("open-loop accelerations (loop cut at the slider)", "u", "9.63, 9.82", ACCEL),
        "Lambda3_inv": ("articulated mobility of the piston in the tree", "Λ₃⁻¹", "9.81", MOBILITY),
        "h": ("height of the piston's centre of mass", "h", "9.85, 9.86", "m"),
        "z3": ("contact motion space of the slider", "z₃", "9.83", BASIS),
        "B3": ("contact reaction space of the slider", "B₃", "9.87", BASIS),
        "xi": ("contact force components in B₃ (force, couple)", "ξ₃", "9.89, 9.90", "N, N·m"),
        "F3": ("contact force of the slider (-F₃ acts on the piston)", "F₃ = B₃ ξ₃", "9.91, 9.92", WRENCH),
        "a3": ("closed-loop acceleration of the piston", "a₃", "9.93, 9.94", ACCEL),
        "a": ("closed-loop accelerations of the three bodies", "a", "9.73", ACCEL),
        "qdd": ("joint accelerations", "q̈", "9.75", "rad/s²"),
        "tau_drive": ("joint torques the drive needs (constant-speed crank)", "Q", "9.75", "N·m"),
        "cond": ("condition number of the contact matrix", "κ(BᵀGΛ⁻¹GᵀB)", "9.70-9.72", "—"),
        "f": ("joint wrenches f₁ crank pivot, f₂ crank pin, f₃ wrist pin (on each body from its parent)",
              "f", "9.61", WRENCH),
        "mu": ("reaction magnitudes of each joint in its basis R_i (f = T Q + R μ; a free pin: its force along "
               "x and y)", "μ = Uᵀ f", "6.38, 6.61b", "N"),
        "pin_forces": ("every pin and bearing force: f₁-f₃ and the slider bearing's -F₃ on the piston",
                       "f_i, -F₃", "9.61, 9.71", WRENCH),
        "reaction_moments": ("moment of each reaction about its own pin or contact point (drive torque, "
                             "0 at a free pin, the bearing's couple)", "τ_o + y f_x − x f_y", "4.27", "N·m"),
    },
    "tree": {
        "C": ("adjacency matrix of Fig 9.1", "C", "9.1", "—"),
        "Dinv": ("trunk matrix", "Δ⁻¹", "9.12, 9.13", "—"),
        "L": ("articulation matrix (1 - Cᵀ R Uᵀ)⁻¹", "L", "9.31", "—"),
        "Lambda_inv": ("articulated mobilities of the nine bodies", "Λ_i⁻¹", "7.37, 9.45", MOBILITY),
        "b": ("bias accelerations of the direct solution", "b_i", "9.45", ACCEL),
        "qdd": ("joint accelerations", "q̈", "9.39, 9.43", "rad/s²"),
        "qdd_direct": ("joint accelerations by the direct solution", "q̈", "9.48", "rad/s²"),
        "a": ("body accelerations", "a", "9.39", ACCEL),
        "f": ("joint wrenches (on each body from its parent)", "f", "9.41", WRENCH),
    },
    "constrained-tree": {
        "G": ("contact matrix", "G", "9.49", "—"),
        "Upsilon": ("branch matrix", "Υ = GΔ⁻¹", "9.50, 9.51", "—"),
        "qdd": ("closed-loop joint accelerations", "q̈", "9.75", "rad/s²"),
        "a": ("closed-loop body accelerations", "a", "9.73", ACCEL),
        "u": ("open-loop accelerations", "u", "9.63", ACCEL),
        "F": ("contact forces of the pins 4-7 and 8-9 (-F acts on body a)", "F", "9.71", WRENCH),
        "xi": ("contact force components in B", "ξ", "9.70", "N"),
        "cond": ("condition number of the contact matrix", "κ(BᵀGΛ⁻¹GᵀB)", "9.70-9.72", "—"),
        "f": ("joint wrenches of the closed tree (on each body from its parent)", "f", "9.61", WRENCH),
        "mu": ("pin forces of each joint in its basis R_i (no joint torques here: the force along x and y)",
               "μ = Uᵀ f", "6.38, 6.61b", "N"),
    },
    "subspace": {
        "s": ("motion space of the joint (columns: allowed twists)", "s", "6.1", BASIS),
        "R": ("reaction space of the joint (columns: wrenches it can exert)", "R", "6.1", BASIS),
        "T": ("active force subspace T = I s (sᵀIs)⁻¹", "T", "6.36", BASIS),
        "U": ("constraint twist subspace U = I⁻¹R (RᵀI⁻¹R)⁻¹", "U", "6.37, 6.33 (corrected)", BASIS),
        "I": ("rigid-body inertia of the body", "I", "5.64", INERTIA),
        "f": ("applied wrench", "f", "6.38", WRENCH),
        "Q": ("active part of the wrench, Q = sᵀf", "Q", "6.38", "N·m or N"),
        "mu": ("reaction magnitudes, μ = Uᵀf", "μ", "6.61", "N or N·m"),
        "TQ": ("active force T Q (the part the joint passes on)", "TQ", "6.38", WRENCH),
        "Rmu": ("constraint force R μ (the part the joint takes)", "Rμ", "6.38", WRENCH),
        "psi": ("joint-space acceleration, ψ = Tᵀ I⁻¹ f", "ψ", "6.44, 6.80", "rad/s² or m/s²"),
        "gamma": ("reaction-space acceleration, γ = Rᵀ I⁻¹ f", "γ", "6.62, 6.81", "rad/s² or m/s²"),
        "a_free": ("acceleration of the free body, I⁻¹ f", "I⁻¹f", "6.80", ACCEL),
        "s_psi": ("acceleration of the body held by the joint, s ψ", "sψ", "6.93", ACCEL),
        "U_gamma": ("acceleration the joint's base would need, U γ", "Uγ", "6.81", ACCEL),
        "reaction": ("wrench of the joint on the body, I a − f = −R μ", "−Rμ", "6.93", WRENCH),
        "sIs": ("joint-space inertia", "sᵀIs", "6.67", "kg·m² or kg"),
        "RIR": ("reaction-space inverse inertia", "RᵀI⁻¹R", "6.71", "1/kg or 1/(kg·m²)"),
        "s_line": ("for a 2-dof joint, the line of poles its motion space spans (else none)", "s", "6.1", "—"),
        "T_pencil": ("for a 2-dof joint, the point U through which every active force passes (else none)",
                     "T", "6.36", "—"),
        "residuals": ("identities that must vanish: sᵀT − 1, RᵀU − 1, TᵀU, T sᵀ + R Uᵀ − 1, sᵀR and the powers "
                      "(sψ)ᵀ(Rμ), (Uγ)ᵀ(TQ)", "—", "6.1, 6.38, 6.41", "—"),
    },
    "impulse": {
        "I": ("rigid-body inertia of the struck body", "I", "5.64", INERTIA),
        "com": ("centre of mass", "c", "5.64", "m"),
        "rho": ("radius of gyration about the centre of mass", "ρ", "5.64", "m"),
        "impulse": ("the blow, an impulsive wrench on its line", "ĵ", "§5.4", "N·s, N·s, N·m·s"),
        "dv": ("twist just after the blow", "Δv", "6.63 (impulsive)", TWIST),
        "omega": ("angular velocity just after the blow", "ω", "6.63 (impulsive)", "rad/s"),
        "pole": ("velocity pole just after the blow (none for a translation)", "P", "§5.4", "m"),
        "v_com": ("velocity of the centre of mass just after the blow", "v_c", "6.63 (impulsive)", "m/s"),
        "reaction": ("reaction impulse of the grip or hinge on the body", "ĵ_R", "6.38", "N·s, N·s, N·m·s"),
        "reaction_force": ("force part of the reaction impulse", "ĵ_R", "6.38", "N·s"),
        "reaction_across": ("reaction impulse across the line grip – centre of mass (zero through the centre of "
                            "percussion)", "ĵ_R⊥", "5.67", "N·s"),
        "reaction_along": ("reaction impulse along the line grip – centre of mass", "ĵ_R∥", "5.67", "N·s"),
        "pole_if_free": ("velocity pole the body would have if free, I⁻¹ĵ", "I⁻¹ĵ", "6.80", "m"),
        "centre_of_percussion": ("centre of percussion for the grip, l = d + ρ²/d from it", "l", "5.67", "m"),
        "apparent_mass_held": ("apparent mass along the line of the blow, body held", "m_app", "figure 3.3",
                               "kg"),
        "apparent_mass_free": ("apparent mass along the line of the blow, body free", "m_app", "figure 3.3", "kg"),
        "kinetic_energy": ("kinetic energy just after the blow", "K = ½ vᵀI v", "—", "J"),
        "v_grip": ("velocity of the grip or hinge just after the blow (zero when held)", "v_P", "6.63 (impulsive)", "m/s"),
        "apparent_mass": ("apparent mass along the line of the blow for the chosen support", "m_app",
                          "figure 3.3", "kg"),
    },
    "articulated": {
        "joints": ("joint positions", "CJ_i", "—", "m"),
        "I": ("rigid-body inertias of the bodies", "I_i", "5.64", INERTIA),
        "A": ("articulated inertias with the chosen number of outboard bodies", "A_i", "7.7a, 10.2.2", INERTIA),
        "A_full": ("articulated inertias of the full recursion", "A_i", "7.7a", INERTIA),
        "centre_rigid": ("centres of the rigid-inertia conics (the centres of mass)", "c_i", "5.64", "m"),
        "centre": ("effective centres A_i⁻¹[0, 0, 1] (where a couple turns body i)", "c_A", "7.26", "m"),
        "pole": ("the chosen acceleration pole", "a", "§5.4", ACCEL),
        "axis_rigid": ("axes of percussion I_i a of the pole", "I_i a", "6.63, 5.67", WRENCH),
        "axis": ("axes of percussion A_i a of the pole", "A_i a", "6.63, 7.7a", WRENCH),
        "truncation_error": ("relative error of A_i truncated against the full recursion", "—", "10.2.2", "—"),
        "components": ("components of A_i at its joint after k = 0, 1, ... recursion steps", "A_i", "7.7a",
                       INERTIA),
        "error": ("error of those components against the full recursion", "—", "10.2.2", INERTIA),
        "effective_7_26": ("effective centre and masses of body 1: d/L, m_x/m, m_y/m, A_z", "d, m_x, m_y, A_z",
                           "7.26, 7.27", "—"),
    },
    "splitting": {
        "joints": ("joint positions", "CJ_i", "—", "m"),
        "Lambda_inv": ("articulated mobilities of the constrained chain", "Λ_i⁻¹", "7.38a (corrected)",
                       MOBILITY),
        "b": ("bias accelerations of the constrained chain", "b_i", "7.38b", ACCEL),
        "A": ("articulated inertias of the free-floating part", "A_i", "7.7a", INERTIA),
        "d": ("bias forces of the free-floating part", "d_i", "7.7b", WRENCH),
        "a_split": ("acceleration of the body at the split", "a_i", "7.54", ACCEL),
        "f_split": ("force of the joint at the split", "f_{i+1}", "7.56", WRENCH),
        "a": ("accelerations of all bodies by chain splitting at every joint", "a_i", "7.54", ACCEL),
        "f": ("joint forces by chain splitting", "f_i", "7.56", WRENCH),
        "qdd": ("joint accelerations", "q̈", "6.110", "rad/s²"),
        "a_tip_7_37": ("tip acceleration from its articulated mobility, −Λ_n⁻¹ f_{n+1} + b_n", "a_n", "7.37",
                       ACCEL),
        "f_tip": ("the couple from the fictitious joint n+1 on the tip", "f_{n+1}", "7.44", WRENCH),
        "Lambda1_inv": ("articulated mobility of body 1 (example 7.5)", "Λ_1⁻¹", "7.42", MOBILITY),
        "Lambda2_inv": ("articulated mobility of body 2 (example 7.5)", "Λ_2⁻¹", "7.43", MOBILITY),
        "a_tip": ("acceleration of the tip body", "a_n", "7.45", ACCEL),
        "x_over_L": ("where the tip turns: its pole's x over L (example 7.5)", "x/L", "7.47", "—"),
        "eta": ("L / ρ", "η", "7.47", "—"),
    },
}


def quantity_info(scene: str) -> dict[str, dict[str, str]]:
    """Description, thesis symbol, equation and unit of each quantity ``planargeo report`` prints for ``scene``.

    From :data:`QUANTITY_INFO`, completed by the scene module's own ``QUANTITY_INFO``
    attribute if it has one (``{scene: {key: (description, symbol, equation, unit)}}``).

    Parameters
    ----------
    scene : str
        A registered scene name (:func:`planargeo.scenes.names`).

    Returns
    -------
    dict
        ``{key: {"description", "symbol", "equation", "unit"}}`` (empty for a scene nobody described).

    Raises
    ------
    SceneError
        If no scene has that name.

    Examples
    --------
    >>> quantity_info("slider-crank")["f"]["unit"], quantity_info("slider-crank")["f"]["equation"]
    ('N, N, N·m', '9.61')
    """
    import sys

    from planargeo import scenes

    fn = scenes.get(scene)
    table = dict(QUANTITY_INFO.get(scene, {}))
    own = getattr(sys.modules.get(getattr(fn, "__module__", ""), None), "QUANTITY_INFO", None)
    if isinstance(own, dict) and own is not QUANTITY_INFO and isinstance(own.get(scene), dict):
        table.update(own[scene])
    keys = ("description", "symbol", "equation", "unit")
    return {k: dict(zip(keys, v)) for k, v in table.items()}


def _magnitude(v: Any) -> float:
    """Largest finite magnitude in a plain value (numbers, nested lists and dicts), 0 if none."""
    if isinstance(v, bool) or v is None or isinstance(v, str):
        return 0.0
    if isinstance(v, (int, float)):
        return abs(float(v)) if math.isfinite(v) else 0.0
    if isinstance(v, dict):
        return max((_magnitude(x) for x in v.values()), default=0.0)
    if isinstance(v, list):
        return max((_magnitude(x) for x in v), default=0.0)
    return 0.0


def _zeroed(v: Any, limit: float) -> Any:
    if isinstance(v, bool) or v is None or isinstance(v, str):
        return v
    if isinstance(v, float):
        return 0.0 if abs(v) < limit or v == 0 else v
    if isinstance(v, dict):
        return {k: _zeroed(x, limit) for k, x in v.items()}
    if isinstance(v, list):
        return [_zeroed(x, limit) for x in v]
    return v


def round_off(quantities: dict, info: dict | None = None, tol: float = ZERO_TOL) -> dict:
    """Plain quantities with round-off shown as 0: magnitudes below ``tol`` × the scene's scale for their unit.

    The scale of a unit is the largest magnitude among the quantities of that
    unit (from ``info``, :func:`quantity_info`); a quantity without a unit is
    its own group.  Integers, booleans and text are kept.

    Parameters
    ----------
    quantities : dict
        Plain values (:func:`to_plain`).
    info : dict, optional
        ``{key: {"unit": ...}}`` as :func:`quantity_info` returns.
    tol : float
        Relative threshold (default :data:`ZERO_TOL`).

    Returns
    -------
    dict
        A copy with the small floats (and ``-0.0``) replaced by ``0.0``.

    Raises
    ------
    InputError
        If ``tol`` is negative or not finite.

    Examples
    --------
    >>> round_off({"a": [3.98e-12, -5.7, 1e-12], "b": 2.5e-11}, {"a": {"unit": "m/s²"}, "b": {"unit": "m/s²"}})
    {'a': [0.0, -5.7, 0.0], 'b': 0.0}
    """
    from planargeo.errors import InputError

    if not (isinstance(tol, (int, float)) and math.isfinite(tol) and tol >= 0):
        raise InputError(f"tol must be a finite non-negative number, got {tol!r}")
    info = info or {}
    unit_of = {k: (info.get(k) or {}).get("unit") or f"\0{k}" for k in quantities}
    scale: dict[str, float] = {}
    for k, v in quantities.items():
        scale[unit_of[k]] = max(scale.get(unit_of[k], 0.0), _magnitude(v))
    return {k: _zeroed(v, tol * scale[unit_of[k]]) for k, v in quantities.items()}


def _width(text: str) -> int:
    """Columns ``text`` takes in a terminal: combining marks (the dot of ``q̇``) take none."""
    import unicodedata

    return sum(0 if unicodedata.combining(ch) else 1 for ch in text)


def format_listing(listing: dict, infos: dict) -> str:
    """Text of ``planargeo report --list``: each scene's parameters, then its quantities with symbol, equation, unit.

    Parameters
    ----------
    listing : dict
        ``{scene: {parameter: default}}``.
    infos : dict
        ``{scene: quantity_info(scene)}``.

    Returns
    -------
    str

    Examples
    --------
    >>> print(format_listing({"x": {"a": 1.5}}, {"x": {"h": {"description": "height", "symbol": "h",
    ...                                                      "equation": "9.85", "unit": "m"}}}))
    x: a=1.5
      h  h  (9.85)  m  height
    """
    out = []
    for name, params in listing.items():
        ps = ", ".join(f"{k}={_fmt_number(v) if not isinstance(v, str) else v}" for k, v in params.items())
        out.append(f"{name}: {ps}" if ps else name)
        rows = [(k, d.get("symbol", ""), f"({d.get('equation', '')})", d.get("unit", ""), d.get("description", ""))
                for k, d in infos.get(name, {}).items()]
        if rows:
            widths = [max(_width(r[c]) for r in rows) for c in range(4)]
            out += ["  " + "  ".join(r[c] + " " * (widths[c] - _width(r[c])) for c in range(4)) + "  " + r[4]
                    for r in rows]
    return "\n".join(out)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Register the ``report`` command's arguments on ``parser``.

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The parser of ``planargeo report``.
    """
    parser.add_argument("scene", nargs="?", help="scene name (see --list)")
    parser.add_argument("--set", dest="sets", action="append", default=[], metavar="NAME=VALUE",
                        help="set a scene parameter (repeatable)")
    parser.add_argument("--json", action="store_true", help="print one JSON object instead of a table")
    parser.add_argument("--list", action="store_true", help="list the scenes and their parameters")
    parser.add_argument("--allow-big", action="store_true",
                        help="lift the scene's size limits (e.g. chain n <= 200) for a deliberate big job")


def parse_value(text: str) -> Any:
    """Read a command-line value as int, float, bool, None, JSON list or string.

    Parameters
    ----------
    text : str
        The value as typed.

    Returns
    -------
    int, float, bool, None, list or str

    Examples
    --------
    >>> parse_value("-4"), parse_value("1e-3"), parse_value("[1, 2.5]"), parse_value("FALSE")
    (-4, 0.001, [1, 2.5], False)
    """
    t = text.strip()
    low = t.lower()
    if low in ("true", "false"):
        return low == "true"
    if low in ("none", "null"):
        return None
    try:
        return int(t)
    except ValueError:
        pass
    try:
        return float(t)
    except ValueError:
        pass
    if t.startswith("["):
        try:
            return json.loads(t)
        except json.JSONDecodeError:
            pass
    return text


def parse_sets(sets: list[str], defaults: dict[str, Any] | None = None) -> dict[str, Any]:
    """``["a=1", "b=x"]`` -> ``{"a": 1, "b": "x"}``; ints become floats where the default is a float.

    Parameters
    ----------
    sets : list of str
        The ``--set`` items.
    defaults : dict, optional
        The scene's parameters with their defaults.

    Returns
    -------
    dict

    Raises
    ------
    InputError
        For an item without ``=`` or with an empty name (``planargeo report`` exits
        with status 2 on it).

    Examples
    --------
    >>> parse_sets(["n=2", "lam=3"], {"n": 4, "lam": 2.0})
    {'n': 2, 'lam': 3.0}
    >>> parse_sets(["n"])
    Traceback (most recent call last):
        ...
    planargeo.errors.InputError: --set expects NAME=VALUE, got 'n'
    """
    from planargeo.errors import InputError

    out: dict[str, Any] = {}
    for item in sets:
        name, sep, value = item.partition("=")
        name = name.strip()
        if not sep or not name:
            raise InputError(f"--set expects NAME=VALUE, got {item!r}")
        v = parse_value(value)
        if defaults is not None and isinstance(defaults.get(name), float) and type(v) is int:
            v = float(v)
        out[name] = v
    return out


def to_plain(x: Any) -> Any:
    """Plain JSON-able Python values: numbers, strings, bools, None, lists and dicts.

    Parameters
    ----------
    x : any
        Nested dicts, lists, tuples, numpy arrays and scalars.

    Returns
    -------
    any
        The same structure with numpy values turned into Python ones (anything else as ``str``).
    """
    if isinstance(x, dict):
        return {str(k): to_plain(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [to_plain(v) for v in x]
    if isinstance(x, np.ndarray):
        return to_plain(x.tolist())
    if isinstance(x, (bool, np.bool_)):
        return bool(x)
    if isinstance(x, (int, np.integer)):
        return int(x)
    if isinstance(x, (float, np.floating)):
        return float(x)
    if x is None or isinstance(x, str):
        return x
    return str(x)


def _fmt_number(v: Any) -> str:
    if isinstance(v, bool) or v is None:
        return str(v)
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if v == 0:
            return "0.0"                       # also -0.0
        if math.isfinite(v) and v == int(v) and abs(v) < 1e12:
            return f"{v:.1f}"
        return f"{v:.6g}"
    return str(v)


#: Matrices with more columns than this are summarised in the table (``--json`` has the values).
MAX_TABLE_COLUMNS = 12


def _is_matrix(v: Any) -> bool:
    return (isinstance(v, list) and len(v) > 0 and all(isinstance(r, list) for r in v)
            and all(not isinstance(x, (list, dict)) for r in v for x in r))


def _shape(v: Any) -> tuple[int, ...] | None:
    """Shape of a rectangular nested list of numbers (``()`` for a number), else None."""
    if isinstance(v, list):
        if not v:
            return (0,)
        subs = [_shape(x) for x in v]
        if subs[0] is None or any(s != subs[0] for s in subs):
            return None
        return (len(v),) + subs[0]
    if isinstance(v, (int, float)) and not isinstance(v, bool):
        return ()
    return None


def _fmt_value(v: Any, indent: int) -> list[str]:
    """Lines for one value: scalars and vectors on one line, matrices as aligned rows.

    A matrix wider than :data:`MAX_TABLE_COLUMNS` is summarised by its shape
    (``--json`` gives its values); an array of three or more dimensions gets
    a shape line, then its matrices one after the other, each labelled with
    its leading indices.  Ragged nested lists are printed as JSON.

    Examples
    --------
    >>> for line in _fmt_value([[[1.0, 0.0], [0.0, 1.0]], [[2.0, 0.5], [0.5, 3.0]]], 0):
    ...     print(line)
    shape (2, 2, 2)
    [0]  [1.0  0.0]
         [0.0  1.0]
    [1]  [2.0  0.5]
         [0.5  3.0]
    >>> _fmt_value([[0.0] * 27] * 27, 0)
    ['27×27 matrix, too wide for the table (--json gives its values)']
    """
    shape = _shape(v)
    if shape is not None and len(shape) == 2 and shape[1] > MAX_TABLE_COLUMNS:
        return [f"{shape[0]}×{shape[1]} matrix, too wide for the table (--json gives its values)"]
    if shape is not None and len(shape) >= 3:
        if shape[-1] > MAX_TABLE_COLUMNS:
            dims = " × ".join(map(str, shape))
            return [f"{dims} array, too wide for the table (--json gives its values)"]
        lines = [f"shape {shape}"]
        width = len(str(shape[0] - 1)) + 2
        for i, sub in enumerate(v):
            body = _fmt_value(sub, indent + width + 2)
            if body and body[0].startswith("shape "):
                body = body[1:]
            label = f"[{i}]".ljust(width)
            lines.append(f"{label}  {body[0]}")
            lines.extend(" " * (width + 2) + s for s in body[1:])
        return lines
    if _is_matrix(v):
        cells = [[_fmt_number(x) for x in r] for r in v]
        width = max((len(c) for r in cells for c in r), default=1)
        return ["[" + "  ".join(c.rjust(width) for c in r) + "]" for r in cells]
    if isinstance(v, list) and all(not isinstance(x, (list, dict)) for x in v):
        return ["[" + ", ".join(_fmt_number(x) for x in v) + "]"]
    if isinstance(v, dict):
        lines = []
        for k, w in v.items():
            sub = _fmt_value(w, indent + 2)
            lines.append(f"{k}: {sub[0]}")
            lines.extend(" " * (len(str(k)) + 2) + s for s in sub[1:])
        return lines or ["{}"]
    if isinstance(v, list):
        return [json.dumps(v)]
    return [_fmt_number(v)]


def format_table(result: dict, info: dict | None = None) -> str:
    """Readable text of a plain report ``{"scene", "params", "state", "quantities"}``.

    Parameters
    ----------
    result : dict
        The plain report (values as :func:`to_plain` gives them).
    info : dict, optional
        :func:`quantity_info` of the scene: each quantity's unit is printed after its
        first line (none for dimensionless ``—`` quantities).

    Returns
    -------
    str

    Examples
    --------
    >>> print(format_table({"scene": "x", "params": {"a": 1.5}, "state": {}, "quantities": {"M": [[1.0, 0.0], [0.0, 2.0]]}}))
    scene: x
    <BLANKLINE>
    parameters
      a  1.5
    <BLANKLINE>
    state
      (none)
    <BLANKLINE>
    quantities
      M  [1.0  0.0]
         [0.0  2.0]
    """
    out = [f"scene: {result['scene']}"]
    for title, key in (("parameters", "params"), ("state", "state"), ("quantities", "quantities")):
        out += ["", title]
        items = result.get(key) or {}
        if not items:
            out.append("  (none)")
            continue
        width = max(len(str(k)) for k in items)
        for k, v in items.items():
            lines = _fmt_value(v, 0)
            unit = ((info or {}).get(k) or {}).get("unit", "") if key == "quantities" else ""
            if unit and unit != "—":
                lines[0] = f"{lines[0]}  {unit}"
            out.append(f"  {str(k).ljust(width)}  {lines[0]}")
            out.extend(" " * (width + 4) + line for line in lines[1:])
    return "\n".join(out)


def _error(msg: str, code: int) -> int:
    print(f"planargeo report: error: {msg}", file=sys.stderr)
    return code


def main(args: argparse.Namespace) -> int:
    """Run ``planargeo report``; returns the exit status.

    Parameters
    ----------
    args : argparse.Namespace
        Parsed arguments (:func:`add_arguments`).

    Returns
    -------
    int
        0 on success, 1 for a scene error, 2 for a usage error (one line on stderr).
    """
    from planargeo import scenes
    from planargeo.errors import InputError, PlanargeoError

    if args.list:
        listing, infos = {}, {}
        for name in scenes.names():
            try:
                listing[name] = to_plain(scenes.parameters(name))
                infos[name] = quantity_info(name)
            except PlanargeoError as exc:  # pragma: no cover - a broken scene module
                return _error(str(exc).splitlines()[0], 1)
        if args.json:
            print(json.dumps({"scenes": listing, "quantities": infos}))
        else:
            print(format_listing(listing, infos))
        return 0
    if not args.scene:
        return _error("a scene name is required (planargeo report --list shows them)", 2)
    try:
        defaults = scenes.parameters(args.scene)
    except PlanargeoError as exc:
        return _error(str(exc).splitlines()[0], 1)
    try:
        params = parse_sets(args.sets, defaults)
    except InputError as exc:                  # a malformed --set: a usage error
        return _error(str(exc).splitlines()[0], 2)
    try:       # results beyond double precision are a SceneRangeError naming the parameters
        res = scenes.build(args.scene, allow_big=args.allow_big, **params)
    except PlanargeoError as exc:
        return _error(str(exc).splitlines()[0] if str(exc) else type(exc).__name__, 1)
    report = {"scene": res.name, "params": to_plain(res.params), "state": to_plain(res.state),
              "quantities": to_plain(res.quantities)}
    if args.json:                              # full precision
        print(json.dumps(report, allow_nan=False))
        return 0
    info = quantity_info(res.name)
    report["quantities"] = round_off(report["quantities"], info)
    print(format_table(report, info))
    return 0
