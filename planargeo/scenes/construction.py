"""Chapter 4's constructions as step-by-step protocols (thesis 4.2–4.7, 4.10–4.57).

A *construction* takes a few numbers and returns the ordered steps by which the thesis builds
its figure: what each step adds, the equation it uses, the elements it draws (homogeneous
points, lines, segments, a conic) and the numbers a reader checks by hand.  Nothing here draws
(:class:`~planargeo.widgets.construction.ConstructionExplorer` does).  Special cases (a pole at
infinity, parallel lines, a couple) are ordinary values, named in the caption (10.2.4).  The
kinds, with their thesis sections, are :data:`CONSTRUCTIONS`.

Examples
--------
>>> c = construct("twist_sum", x1=0.0, y1=0.0, w1=1.0, x2=4.0, y2=0.0, w2=3.0)
>>> [s.id for s in c.steps]
['poles', 'lever', 'sum']
>>> c.values["pole of v₃"], c.values["β"]           # 3/4 of the way from Q₁ to Q₂ (4.12)
((3.0, 0.0), 0.75)
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from planargeo._validate import check_positive
from planargeo.errors import InputError
from planargeo.geometry.projective import direction, from_xy, is_ideal, join, to_xy
from planargeo.screws.inertia import centre_of_mass
from planargeo.screws.special import (horizon_point, pair_case, twist_case, twists_case, wrench_case,
                                      wrenches_case)
from planargeo.screws.twists import (add_twists, add_wrenches, bias_force, inertia_matrix, kappa,
                                     unit_rotation)

__all__ = ["Element", "ConstructionStep", "Construction", "CONSTRUCTIONS", "construct",
           "parameters"]


@dataclass(frozen=True)
class Element:
    """One drawn element of a step.

    Attributes
    ----------
    name : str
        Identifier, unique within a construction (e.g. ``"Q1"``).
    kind : {"point", "line", "segment", "conic"}
        A homogeneous point or line (3,), a Euclidean segment (2, 2) or a conic (3, 3).
    value : ndarray
    role : str
        Style role (:mod:`planargeo.draw.style`), e.g. ``"twist"``.
    label : str
        The thesis symbol (mathtext), "" for none.
    emphasis : bool
        A sum (drawn heavier).
    """

    name: str
    kind: str
    value: np.ndarray
    role: str
    label: str = ""
    emphasis: bool = False


@dataclass(frozen=True)
class ConstructionStep:
    """One step of a construction protocol.

    Attributes
    ----------
    id : str
        Short identifier (also the SVG layer id, prefixed ``step-``).
    title : str
        What the step constructs, with its numbers (one line).
    equation : str
        The thesis equation(s) used, e.g. ``"4.12–4.13"``.
    elements : tuple of Element
        What the step adds to the drawing (possibly nothing).
    """

    id: str
    title: str
    equation: str
    elements: tuple = ()

    @property
    def caption(self) -> str:
        """``title (equation)``: the caption shown with the step."""
        return f"{self.title} ({self.equation})"


@dataclass(frozen=True)
class Construction:
    """The steps of one construction and its numbers.

    Attributes
    ----------
    kind : str
        A key of :data:`CONSTRUCTIONS`.
    title : str
    steps : tuple of ConstructionStep
    values : dict
        Numbers for the readout (hand-checkable), keyed by thesis symbol.
    case : str
        The special case reached (:mod:`planargeo.screws.special`), readable.
    params : dict
        The parameters used.
    """

    kind: str
    title: str
    steps: tuple
    values: dict
    case: str
    params: dict = field(default_factory=dict)

    def elements(self, upto: int | None = None) -> list[Element]:
        """The elements of steps ``1 … upto`` (all steps when None).

        Parameters
        ----------
        upto : int, optional

        Returns
        -------
        list of Element
        """
        steps = self.steps if upto is None else self.steps[:upto]
        return [e for s in steps for e in s.elements]


def _pt(name, p, role, label="", emphasis=False) -> Element:
    return Element(name, "point", np.asarray(p, float), role, label, emphasis)


def _ln(name, l, role, label="", emphasis=False) -> Element:
    return Element(name, "line", np.asarray(l, float), role, label, emphasis)


def _seg(name, p, q, role="construct", label="") -> Element:
    return Element(name, "segment", np.array([p, q], float), role, label)


def _drawn(*elements: Element) -> tuple:
    """The elements with a non-zero value: a zero twist has no pole, a zero wrench no line."""
    return tuple(e for e in elements if np.any(e.value))


def _xy_or_inf(p) -> Any:
    """``(x, y)`` of a finite point; "at infinity (direction (dx, dy))" for an ideal one (:func:`is_ideal`)."""
    p = np.asarray(p, float)
    if bool(is_ideal(p)):
        d = direction(p)
        return f"at infinity (direction ({_num(d[0], 4)}, {_num(d[1], 4)}))"
    return tuple(float(v) + 0.0 for v in to_xy(p))


def _num(x, digits: int = 3) -> str:
    x = float(x) + 0.0
    if not math.isfinite(x):
        return "∞"
    return "0" if abs(x) < 1e-12 else f"{x:.{digits}g}"


def _nonzero(v: np.ndarray, name: str, what: str, *zeros: tuple[str, str]) -> np.ndarray:
    """``v``, or :class:`InputError` saying which values (symbol, unit) make twist or wrench ``name`` zero.

    >>> _nonzero(np.zeros(3), "v₁", "twist", ("ω₁", "rad/s"), ("u₁", "m/s"))
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: ω₁ = 0 rad/s and u₁ = 0 m/s make v₁ the zero twist: no motion, so no pole. Choose ω₁ ≠ 0 or u₁ ≠ 0.
    """
    if not np.any(v):
        said = " and ".join(f"{sym} = 0 {unit}" for sym, unit in zeros)
        nothing = "no motion, so no pole" if what == "twist" else "no load, so no line"
        choose = " or ".join(f"{sym} ≠ 0" for sym, _ in zeros)
        raise InputError(f"{said} make{'s' if len(zeros) == 1 else ''} {name} the zero {what}: "
                         f"{nothing}. Choose {choose}.")
    return v


def _direction(angle_deg: float) -> np.ndarray:
    a = math.radians(angle_deg)
    c, s = math.cos(a), math.sin(a)
    # exact axes: cos(90°) is 6e-17, which would tilt a vertical force by round-off
    return np.array([0.0 if abs(c) < 1e-15 else c, 0.0 if abs(s) < 1e-15 else s])


def _twist(x, y, w, u, angle, k) -> np.ndarray:
    """Twist ``v_k``: a rotation ``w`` about ``(x, y)`` plus a translation ``u`` at ``angle`` degrees."""
    v = w * unit_rotation([x, y]) + np.append(u * _direction(angle), 0.0)
    s = "₁₂"[k - 1]
    return _nonzero(v, f"v{s}", "twist", (f"ω{s}", "rad/s"), (f"u{s}", "m/s"))


def _wrench(x, y, F, angle, tau, k) -> np.ndarray:
    """Wrench ``f_k``: a force ``F`` at ``angle`` degrees through ``(x, y)`` plus a couple ``tau``."""
    d = F * _direction(angle)
    s = "₁₂"[k - 1]
    return _nonzero(np.array([d[0], d[1], x * d[1] - y * d[0] + tau]), f"f{s}", "wrench",
                    (f"F{s}", "N"), (f"τ{s}", "N·m"))


def _operands(id_, title, eq, element, name, a, b, role, sym) -> ConstructionStep:
    """The first step of a sum: its two operands ``a``, ``b`` drawn as ``element`` (:func:`_pt`, :func:`_ln`)."""
    return ConstructionStep(id_, title, eq, (element(f"{name}1", a, role, f"${sym}_1$"),
                                             element(f"{name}2", b, role, f"${sym}_2$")))


# ------------------------------------------------------------ twist sum (4.2): 4.11–4.16
def _twist_sum(x1=-1.5, y1=0.0, w1=1.0, u1=0.0, angle1=0.0,
               x2=1.5, y2=0.5, w2=2.0, u2=0.0, angle2=90.0) -> Construction:
    v1, v2 = _twist(x1, y1, w1, u1, angle1, 1), _twist(x2, y2, w2, u2, angle2, 2)
    c, case = add_twists(v1, v2), twists_case(v1, v2)
    steps = [_operands("poles", "Q₁, Q₂: the poles of v₁ and v₂", "4.10", _pt, "Q", v1, v2, "twist", "v")]
    if c.line is None:
        steps.append(ConstructionStep("lever", "Q₁ = Q₂: one pole, every line through it is a lever",
                                      "4.11"))
    else:
        steps.append(ConstructionStep("lever", "Q₁Q₂ = Q₁ × Q₂: the line through both poles", "5.32",
                                      (_ln("Q1Q2", c.line, "construct"),)))
    if c.case == "rotations":
        title = f"v₃ on Q₁Q₂ at β = ω₂/(ω₁+ω₂) = {_num(c.beta)}"
        eq = "4.11–4.13"
    elif c.case == "opposite_rotations":
        title = "ω₁ + ω₂ = 0: v₃ is a translation, its pole at infinity"
        eq = "4.13"
    elif c.case == "rotation_translation":
        title = f"v₃ = the rotation shifted by ρ = u/ω = {_num(c.rho)}"
        eq = "4.16"
    else:
        title, eq = "two translations: v₃ is a translation", "4.10"
    if case.name == "coincident_poles":
        title, eq = "same pole: v₃ turns about it at ω₁ + ω₂", "4.11"
    sum_el = (_pt("v3", c.sum.array, "twist", "$v_3 = v_1 + v_2$", True),) if c.P is not None else ()
    if c.P is None:
        title, eq = "v₁ + v₂ = 0: the zero twist has no pole", "4.6"
    steps.append(ConstructionStep("sum", title, eq, sum_el))
    values = {"ω₁": c.omega1, "ω₂": c.omega2, "ω₃ = ω₁ + ω₂": c.omega3,
              "β": "—" if c.beta is None else c.beta, "ρ": "—" if c.rho is None else c.rho,
              "pole of v₃": "none" if c.P is None else _xy_or_inf(c.P)}
    return Construction("twist_sum", "Twist addition", tuple(steps), values, case.text)


# ------------------------------------------------------------ wrench sum (4.4): 4.33–4.46
def _wrench_sum(x1=-1.5, y1=-0.5, F1=1.0, angle1=60.0, tau1=0.0,
                x2=1.5, y2=0.0, F2=1.5, angle2=120.0, tau2=0.0) -> Construction:
    f1, f2 = _wrench(x1, y1, F1, angle1, tau1, 1), _wrench(x2, y2, F2, angle2, tau2, 2)
    c, case = add_wrenches(f1, f2), wrenches_case(f1, f2)
    steps = [_operands("lines", "L₁, L₂: the lines of action of f₁ and f₂", "4.27", _ln, "f", f1, f2,
                       "wrench", "f")]
    if c.P is None:
        steps.append(ConstructionStep("meet", "two couples: no finite line to meet", "4.46"))
    elif case.name == "same_line":
        steps.append(ConstructionStep("meet", "L₁ = L₂: the forces share their line", "4.4.1"))
    elif bool(is_ideal(c.P)):
        steps.append(ConstructionStep("meet", "L₁ ∥ L₂: they meet at infinity", "5.34",
                                      (_pt("P", c.P, "accel", ""),)))
    elif c.case == "force_couple":
        steps.append(ConstructionStep("meet", "a couple is the line at infinity: L₁ × L∞ is "
                                      "the force's direction", "5.34"))
    else:
        steps.append(ConstructionStep("meet", "P = L₁ × L₂: where the lines meet", "5.34",
                                      (_pt("P", c.P, "accel", "$P$"),)))
    if c.case == "concurrent":
        P = to_xy(c.P)
        a, b, s = P + f1[:2], P + f2[:2], P + f1[:2] + f2[:2]
        par = (_seg("par1", P, a, "wrench"), _seg("par2", P, b, "wrench"),
               _seg("par3", a, s), _seg("par4", b, s), _seg("diag", P, s, "wrench"))
        steps.append(ConstructionStep("parallelogram", f"the force parallelogram at P: "
                                      f"|f₁ + f₂| = {_num(c.F3)}", "4.39", par))
    elif c.case == "parallel":
        steps.append(ConstructionStep("lever", f"lever rule: β = F₂/(F₁+F₂) = {_num(c.beta)}, "
                                      f"d₃ = d₁ + β(d₂ − d₁) = {_num(c.d3)}", "4.43–4.45"))
    elif c.case == "force_couple":
        force = f1 if np.any(f1[:2]) else f2
        anchor = np.array([x1, y1]) if force is f1 else np.array([x2, y2])
        e = force[:2] / np.hypot(*force[:2])
        n = np.array([e[1], -e[0]])
        steps.append(ConstructionStep("shift", f"the force shifted by ρ = τ/F = {_num(c.rho)}",
                                      "4.46", (_seg("rho", anchor, anchor + c.rho * n, "construct",
                                                    r"$\rho$"),)))
    elif c.case == "couple":
        steps.append(ConstructionStep("couple", "equal and opposite parallel forces: a couple "
                                      f"τ = {_num(c.sum.array[2])}", "4.4.2"))
    else:
        steps.append(ConstructionStep("check", case.text.rsplit(" (", 1)[0], case.equation))
    if c.L3 is None:
        steps.append(ConstructionStep("sum", "f₁ + f₂ = 0: no load", "4.21"))
    else:
        steps.append(ConstructionStep("sum", "f₃ = f₁ + f₂: its line passes through P", "4.33",
                                      (_ln("f3", c.sum.array, "wrench", "$f_3 = f_1 + f_2$", True),)))
    values = {"F₁": c.F1, "F₂": c.F2, "F₃": c.F3, "β": "—" if c.beta is None else c.beta,
              "ρ": "—" if c.rho is None else c.rho,
              "meet P": "none" if c.P is None else _xy_or_inf(c.P),
              "f₃": tuple(float(v) for v in c.sum.array)}
    return Construction("wrench_sum", "Wrench addition", tuple(steps), values, case.text)


# ------------------------------------------------------------ velocity (4.5): 4.47–4.49
def _velocity(xv=-1.5, yv=1.0, w=1.0, xj=1.0, yj=0.0, qd=1.5) -> Construction:
    v_prev = _nonzero(w * unit_rotation([xv, yv]), "vᵢ₋₁", "twist", ("ωᵢ₋₁", "rad/s"))
    s = unit_rotation([xj, yj])
    u = _nonzero(s * qd, "sᵢ q̇ᵢ", "twist", ("q̇ᵢ", "rad/s"))
    v = v_prev + u
    k = math.hypot(xj - xv, yj - yv)
    case = twists_case(v_prev, u)
    steps = [ConstructionStep("previous", "vᵢ₋₁: the pole of the previous body", "4.47",
                              (_pt("v_prev", v_prev, "twist", "$v_{i-1}$"),)),
             ConstructionStep("joint", "sᵢ q̇ᵢ: the joint's relative rotation, its pole at the "
                              "joint", "2.1", (_pt("joint", u, "twist", r"$s_i\dot q_i$"),))]
    if k == 0:
        steps.append(ConstructionStep("lever", "the joint is at the pole of vᵢ₋₁: kᵢ = 0", "4.48"))
    else:
        steps.append(ConstructionStep("lever", f"kᵢ = {_num(k)}: the line from vᵢ₋₁ to the "
                                      "joint", "4.48", (_ln("lever", join(v_prev, s), "construct"),)))
    beta = qd / (qd + w) if qd + w != 0 else float("inf")
    if np.any(v):
        title = (f"vᵢ on it at βᵢ kᵢ, βᵢ = q̇ᵢ/(q̇ᵢ + ωᵢ₋₁) = {_num(beta)}; "
                 f"ωᵢ = {_num(v[2])}")
        steps.append(ConstructionStep("sum", title, "4.48–4.49",
                                      (_pt("v", v, "twist", "$v_i$", True),)))
    else:
        steps.append(ConstructionStep("sum", "vᵢ = 0: the body is at rest", "4.47"))
    values = {"ωᵢ₋₁": w, "q̇ᵢ": qd, "ωᵢ": float(v[2]), "kᵢ": k, "βᵢ": beta,
              "pole of vᵢ": "none" if not np.any(v) else _xy_or_inf(v)}
    return Construction("velocity", "Velocity kinematics", tuple(steps), values, case.text)


# ------------------------------------------------------------ acceleration (4.6): 4.52–4.54
def _acceleration(xv=-1.5, yv=1.0, w=1.0, xa=-1.0, ya=-1.0, alpha=0.5, xj=1.0, yj=0.0, qd=1.5,
                  qdd=2.0) -> Construction:
    v_prev = w * unit_rotation([xv, yv])
    a_prev = alpha * unit_rotation([xa, ya])
    s = unit_rotation([xj, yj])
    v = v_prev + s * qd
    rel = s * qdd
    kap = kappa(v_prev, s, qd)                  # = vᵢ × sᵢ q̇ᵢ (4.52)
    combo = rel + kap
    a = a_prev + combo
    k = math.hypot(xj - xv, yj - yv)
    steps = [ConstructionStep("previous", "aᵢ₋₁: the acceleration pole of the previous body",
                              "4.52", _drawn(_pt("a_prev", a_prev, "accel", "$a_{i-1}$"))),
             ConstructionStep("velocity", "vᵢ = vᵢ₋₁ + sᵢ q̇ᵢ: the velocity pole", "4.47",
                              _drawn(_pt("v", v, "twist", "$v_i$"))),
             ConstructionStep("joint", "sᵢ q̈ᵢ: the relative acceleration about the joint", "4.52",
                              _drawn(_pt("rel", rel, "accel", r"$s_i\ddot q_i$")))]
    kn = float(np.hypot(kap[0], kap[1]))
    steps.append(ConstructionStep("bias", f"κᵢ = vᵢ × sᵢ q̇ᵢ: a translation along the line to "
                                  f"the joint, |κᵢ| = ωᵢ₋₁ q̇ᵢ kᵢ = {_num(kn)}", "4.53",
                                  _drawn(_pt("kappa", kap, "accel", r"$\kappa_i$"))))
    if qdd == 0 and np.any(combo):
        rho = float("inf")
        steps.append(ConstructionStep("combined", "q̈ᵢ = 0: sᵢ q̈ᵢ + κᵢ is κᵢ itself, a translation "
                                      "(ρᵢ = ∞)", "4.54"))
    elif np.any(combo):
        rho = kn / qdd
        els = [_pt("combo", combo, "accel", r"$s_i\ddot q_i + \kappa_i$")]
        if qdd != 0 and kn:
            els.append(_ln("joint_lever", np.cross(rel, kap), "construct"))
        steps.append(ConstructionStep("combined", f"sᵢ q̈ᵢ + κᵢ: a rotation ρᵢ = ωᵢ₋₁ q̇ᵢ kᵢ"
                                      f"/q̈ᵢ = {_num(rho)} from the joint", "4.54", tuple(els)))
    else:
        rho = float("nan")
        steps.append(ConstructionStep("combined", "sᵢ q̈ᵢ + κᵢ = 0: the joint adds nothing", "4.54"))
    els = []
    if np.any(a_prev) and np.any(combo) and np.linalg.norm(np.cross(a_prev, combo)) > 0:
        els.append(_ln("lever", np.cross(a_prev, combo), "construct"))
    if np.any(a):
        els.append(_pt("a", a, "accel", "$a_i$", True))
    steps.append(ConstructionStep("sum", "aᵢ = aᵢ₋₁ + (sᵢ q̈ᵢ + κᵢ): on the line joining "
                                  "their poles", "4.52", tuple(els)))
    values = {"ωᵢ₋₁": w, "q̇ᵢ": qd, "q̈ᵢ": qdd, "kᵢ": k, "|κᵢ|": kn, "ρᵢ": rho,
              "pole of aᵢ": "none" if not np.any(a) else _xy_or_inf(a),
              "aᵢ": tuple(float(x) for x in a)}
    case = twists_case(a_prev, combo) if np.any(a_prev) and np.any(combo) else twists_case(a, a)
    return Construction("acceleration", "Acceleration kinematics", tuple(steps), values, case.text)


# ------------------------------------------------------------ Newton–Euler (4.7): 4.55–4.57
def _newton_euler(m=1.0, xc=0.5, yc=0.0, r=0.4, xv=0.5, yv=2.0, w=1.5, xa=2.0, ya=-1.0, alpha=1.5,
                  xj=-0.5, yj=0.0) -> Construction:
    check_positive(m, "m")
    check_positive(r, "r")
    I = inertia_matrix(m, [xc, yc], m * r * r)
    v = w * unit_rotation([xv, yv])
    a = alpha * unit_rotation([xa, ya])
    Ia = I @ a
    p = bias_force(I, v)
    f = Ia + p
    J = np.array([xj, yj])
    tau = float(f[2] - (xj * f[1] - yj * f[0]))     # moment of f about the joint (4.24)
    F = float(np.hypot(f[0], f[1]))
    steps = [ConstructionStep("inertia", "I: the inertia, drawn as its circle of gyration, radius "
                              f"r = {_num(r)} about the centre of mass", "4.58, 10.2.3",
                              (Element("I", "conic", I, "inertia", "$I$"),)),
             ConstructionStep("motion", "v, a: the velocity and acceleration poles", "4.47, 4.52",
                              _drawn(_pt("v", v, "twist", "$v$"), _pt("a", a, "accel", "$a$")))]
    steps.append(ConstructionStep("Ia", "I a: the axis of percussion of a", "5.64",
                                  _drawn(_ln("Ia", Ia, "wrench", "$Ia$"))))
    c = centre_of_mass(I)
    l = math.hypot(xv - c[0], yv - c[1])
    steps.append(ConstructionStep("p", f"p = −(v×)ᵀIv: through the centre of mass toward v, "
                                  f"|p| = m l ω² = {_num(m * l * w * w)}", "4.56",
                                  _drawn(_ln("p", p, "momentum", "$p$"))))
    if not np.any(f):
        steps.append(ConstructionStep("fnet", "fⁿᵉᵗ = 0: the body needs no force", "4.55"))
        rho = float("nan")
    else:
        steps.append(ConstructionStep("fnet", "fⁿᵉᵗ = I a + p", "4.55",
                                      (_ln("fnet", f, "wrench", r"$f^{net}$", True),)))
        els = [_pt("J", from_xy(J), "reaction", "joint")]
        if F == 0:
            rho = float("inf")
            title = f"fⁿᵉᵗ is a couple: τ = {_num(tau)}, ρ = ∞"
        else:
            rho = tau / F
            foot = J + rho * np.array([f[1], -f[0]]) / F     # ρ along n = (fy, −fx)/F (4.32)
            if rho != 0:
                els.append(_seg("rho", J, foot, "construct", r"$\rho$"))
            title = (f"ρ = τ/|fⁿᵉᵗ| = {_num(rho)}: the joint torque τ = {_num(tau)} is the net force's "
                     "moment about the joint" if rho != 0 else
                     "ρ = 0: fⁿᵉᵗ passes through the joint (τ = 0, an unpowered joint)")
        steps.append(ConstructionStep("rho", title, "4.57", tuple(els)))
    values = {"m": m, "|Ia|": float(np.hypot(*Ia[:2])), "|p|": float(np.hypot(*p[:2])),
              "|fⁿᵉᵗ|": F, "τ": tau, "ρ = τ/|fⁿᵉᵗ|": rho, "fⁿᵉᵗ": tuple(float(x) for x in f),
              "power of fⁿᵉᵗ on v": float(v @ f)}
    case = wrench_case(f).text if np.any(f) else "zero net force"
    if np.any(v) and np.any(f):
        case += "; " + pair_case(v, f).text
    return Construction("newton_euler", "Newton–Euler balance of one body", tuple(steps), values, case)


# ------------------------------------------------------------ a pole through infinity (10.2.4)
#: radius of the horizon of :func:`_through_infinity` (the line at infinity in the disc model)
HORIZON = 2.0


def _through_infinity(x1=-1.5, y1=-1.0, w1=1.0, hx=1.0, hy=0.5, k=1.5) -> Construction:
    v1 = _nonzero(w1 * unit_rotation([x1, y1]), "v₁", "twist", ("ω₁", "rad/s"))
    v2 = k * horizon_point([hx, hy], (0.0, 0.0), HORIZON)
    v2 = _nonzero(v2, "v₂", "twist", ("k", "rad/s"))
    c = add_twists(v1, v2)
    horizon = np.diag([1.0, 1.0, -HORIZON ** 2])           # the circle |x| = R (5.35)
    w = 1.0 - np.hypot(hx, hy) / HORIZON
    case2 = twist_case(v2)
    steps = [ConstructionStep("horizon", f"the horizon |h| = {_num(HORIZON)}: a handle h on it means "
                              "a point at infinity (opposite rim points are one)", "10.2.4",
                              (Element("horizon", "conic", horizon, "conic", "horizon"),
                               _pt("v1", v1, "twist", "$v_1$"))),
             ConstructionStep("v2", f"v₂ = k [h_y, −h_x, 1 − |h|/R], weight {_num(w)}: "
                              f"{case2.text.rsplit(' (', 1)[0]}", "10.2.4, 4.10",
                              (_pt("h", from_xy([hx, hy]), "construct", "$h$"),
                               _pt("v2", v2, "twist", "$v_2$")))]
    els = []
    if c.line is not None:
        els.append(_ln("lever", c.line, "construct"))
    if c.P is not None:
        els.append(_pt("v3", c.sum.array, "twist", "$v_3 = v_1 + v_2$", True))
    case = twists_case(v1, v2)
    steps.append(ConstructionStep("sum", f"v₃ = v₁ + v₂ moves on smoothly: {case.text.rsplit(' (', 1)[0]}",
                                  case.equation, tuple(els)))
    values = {"weight of v₂": w, "v₂": case2.text.split(":")[0], "pole of v₂": _xy_or_inf(v2),
              "pole of v₃": "none" if c.P is None else _xy_or_inf(c.P),
              "v₃": tuple(float(x) for x in c.sum.array)}
    return Construction("through_infinity", "A pole through infinity", tuple(steps), values,
                        case.text)


#: kind -> (title, builder); the builder's keyword defaults are the parameters.
CONSTRUCTIONS: dict[str, tuple[str, Callable[..., Construction]]] = {
    "twist_sum": ("Twist addition (4.2)", _twist_sum),
    "wrench_sum": ("Wrench addition (4.4)", _wrench_sum),
    "velocity": ("Velocity kinematics (4.5)", _velocity),
    "acceleration": ("Acceleration kinematics (4.6)", _acceleration),
    "newton_euler": ("Equations of motion, Newton–Euler balance (4.7, Fig. 4.9)", _newton_euler),
    "through_infinity": ("A pole dragged through infinity (10.2.4)", _through_infinity),
}


def parameters(kind: str) -> dict[str, float]:
    """The parameters of construction ``kind`` and their defaults.

    Parameters
    ----------
    kind : str
        A key of :data:`CONSTRUCTIONS`, e.g. ``"twist_sum"``.

    Returns
    -------
    dict
        ``{parameter: default}``, in the builder's order.

    Raises
    ------
    InputError
        An unknown kind.

    Examples
    --------
    >>> list(parameters("velocity"))
    ['xv', 'yv', 'w', 'xj', 'yj', 'qd']
    """
    import inspect

    if kind not in CONSTRUCTIONS:
        raise InputError(f"kind must be one of {list(CONSTRUCTIONS)}, got {kind!r}")
    sig = inspect.signature(CONSTRUCTIONS[kind][1])
    return {n: p.default for n, p in sig.parameters.items()}


def construct(kind: str, **params) -> Construction:
    """Build construction ``kind`` with ``params`` (the rest at their defaults).

    Parameters
    ----------
    kind : str
        A key of :data:`CONSTRUCTIONS`.
    **params : float
        Parameters (:func:`parameters`); angles in degrees.

    Returns
    -------
    Construction

    Raises
    ------
    InputError
        An unknown kind or parameter, a non-finite value, or a zero twist or wrench (named).
    PlanargeoError
        Any other value the geometry refuses.

    Examples
    --------
    >>> c = construct("velocity", xv=0.0, yv=0.0, w=1.0, xj=3.0, yj=0.0, qd=2.0)
    >>> c.values["pole of vᵢ"]                     # β k = 2/3 · 3 along the lever (4.48)
    (2.0, 0.0)
    """
    defaults = parameters(kind)
    unknown = sorted(set(params) - set(defaults))
    if unknown:
        raise InputError(f"{kind} has no parameter {unknown[0]!r} (parameters: {', '.join(defaults)})")
    for k, v in params.items():
        if isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating)) \
                or not math.isfinite(float(v)):
            raise InputError(f"{k} must be a finite number, got {v!r}")
    clean = {k: float(v) for k, v in params.items()}
    c = CONSTRUCTIONS[kind][1](**clean)
    return Construction(c.kind, c.title, c.steps, c.values, c.case, {**defaults, **clean})

