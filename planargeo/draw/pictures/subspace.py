"""The subspace explorer's picture: a body, its joint, ``s, R, T, U``, the splits of ``f`` (thesis 6.1–6.4).

The motion space ``s`` (poles), with the forces the reaction space ``R`` and ``T`` (6.36),
with the accelerations ``U`` (6.37), and the force ``f`` split as ``TQ + Rμ`` (6.38) or the
free acceleration as ``sψ + Uγ`` (6.44).  Points drawn at one place are one element.

Examples
--------
>>> import numpy as np
>>> from planargeo.scenes.subspace import subspace_state
>>> from planargeo.screws.twists import inertia_matrix
>>> I = inertia_matrix(2.0, (1.0, 0.0), 0.5)
>>> st = subspace_state("revolute", (0.0, 0.0), np.array([1.0, 0.0]), I, np.array([0.0, 1.0, 1.6]))
>>> st.update(point=np.zeros(2), direction=np.array([1.0, 0.0]), **{"force point": np.array([1.6, 0.0])})
>>> d = subspace_picture(st, show="wrench", m=2.0, rho=0.5, view=(-1.5, 3.5, -2, 2)).to_dict()
>>> [e["symbol"] for e in d["elements"] if e["id"] == "s1"]
['s']
"""
from __future__ import annotations

import math

import numpy as np

from planargeo.draw.pictures.common import builder, labelled_line
from planargeo.draw.picture import Picture
from planargeo.draw.pictures._words import force, num, pair, where
from planargeo.draw.style import COLORS
from planargeo.geometry.projective import is_ideal

__all__ = ["subspace_picture", "BAR", "COM", "DIR_HANDLE"]

#: the body: a bar along x with its centre of mass at (1, 0)
COM = (1.0, 0.0)
BAR = np.array([(-0.3, -0.12), (2.3, -0.12), (2.3, 0.12), (-0.3, 0.12)])
#: distance of the joint's direction mark from the joint (m)
DIR_HANDLE = 0.7
_SUB = "₁₂"
_JOINT = {"revolute": "a revolute pivot", "prismatic": "a prismatic slide",
          "revolute_prismatic": "a pin in a slot (revolute + prismatic)",
          "twin_prismatic": "the plane joint (4.79): two translations"}


def _along(line, ref, t: float):
    """The point ``t`` along ``line`` from the foot of ``ref`` on it; ``ref`` for a couple."""
    fx, fy, tz = (float(x) for x in line)
    F = math.hypot(fx, fy)
    ref = np.asarray(ref, dtype=float)
    if F == 0:
        return ref
    d = np.array([fx, fy]) / F
    p0 = np.array([fy * tz, -fx * tz]) / (F * F)
    return p0 + d * ((ref - p0) @ d + t)


def _same_point(p, q) -> bool:
    p, q = np.asarray(p, float), np.asarray(q, float)
    return bool(np.linalg.norm(np.cross(p, q)) <= 1e-9 * float(np.linalg.norm(p)) * float(np.linalg.norm(q)))


@builder
def subspace_picture(st: dict, *, show: str, m: float, rho: float, view, size=(640, 500)) -> Picture:
    """The picture of one state of the subspace explorer (module docstring).

    Parameters
    ----------
    st : dict
        :func:`planargeo.scenes.subspace.subspace_state` with ``point``, ``direction``, ``force point``.
    show : {"wrench", "twist", "spaces"}
        The split of the force, the split of the free acceleration, or the four spaces.
    m, rho : float
        The body's mass (kg) and radius of gyration (m), for the descriptions.
    """
    s, R, T, U = st["s"], st["R"], st["T"], st["U"]
    k = int(s.shape[1])
    p, e, fp = (np.asarray(st[key], float) for key in ("point", "direction", "force point"))
    kind = st["joint"]
    pic = Picture(view, size=size)
    pic.path("body", BAR, role="body", closed=True, fill=COLORS["body"], alpha=0.45, color="#000000",
             symbol="body", desc=f"the body, a bar at rest: mass m = {num(m)} kg, radius of gyration "
                                 f"ρ = {num(rho)} m (5.4)", z=1)
    jdesc = f"the joint: {_JOINT[kind]} at {pair(p)} m"
    if kind != "revolute":
        nrm = np.array([-e[1], e[0]])
        track = (np.array([p - 0.9 * e, p + 0.9 * e]) if kind != "twin_prismatic" else
                 np.array([p - 0.5 * e, p + 0.5 * e, [np.nan, np.nan], p - 0.5 * nrm, p + 0.5 * nrm]))
        deg = math.degrees(math.atan2(e[1], e[0]))
        pic.path("joint", track, role="ground", color=COLORS["ground"], width=7.0,
                 symbol="joint", desc=f"{jdesc}, direction {num(deg)}° from x", z=2, opacity=0.45)
        pic.marks("joint direction", [p + DIR_HANDLE * e], role="body", color=COLORS["ground"], shape="D",
                  size=7.0, symbol="joint", desc=f"the joint's direction: {num(deg)}° from x", z=6)
    if kind in ("revolute", "revolute_prismatic"):
        pic.marks("pin", [p], role="body", color=COLORS["ground"], size=10.0, symbol="joint",
                  desc=f"{jdesc}: the pin", z=6)
    pic.point("c", [COM[1], -COM[0], 1.0], role="twist", color="#000000", glyph=False, size=5.0,
              symbol="c", desc=f"the centre of mass of the body: at {pair(COM)} m")
    pic.conic("I", st["I"], role="inertia", symbol="I",
              desc=f"the body's inertia, drawn as its circle of gyration about c (5.4): ρ = {num(rho)} m, "
                   f"m = {num(m)} kg")
    # the subspaces: s always; R, T with the forces; U with the accelerations
    forces, twist = show in ("wrench", "spaces"), show in ("twist", "spaces")
    points = []   # (id, p, role, colour, symbol, desc, glyph, label): merged where they coincide
    for i in range(k):
        sub = _SUB[i] if k > 1 else ""
        what = "a rotation" if not bool(is_ideal(s[:, i])) else "a translation"
        points.append((f"s{i + 1}", s[:, i], "twist", COLORS["twist"], f"s{sub}",
                       f"motion space (6.1, 6.8): an allowed motion, {what}, its pole {where(s[:, i])}", False,
                       f"s{sub}"))
    for j in range(3 - k):
        if not twist:
            break
        sub = _SUB[j] if 3 - k > 1 else ""
        meet = ", where T₁ and T₂ meet" if k == 2 else ""
        points.append((f"U{j + 1}", U[:, j], "accel", COLORS["accel"], f"U{sub}",
                       f"reactive acceleration U = I⁻¹R(RᵀI⁻¹R)⁻¹ (6.37), a point on T{meet}: {where(U[:, j])}",
                       False, f"U{sub}" + (" (T₁ ∩ T₂)" if k == 2 else "")))
    if forces:
        for j in range(3 - k):
            sub = _SUB[j] if 3 - k > 1 else ""
            name = f"R{sub}"
            label = name + (" = poles of s" if k == 2 and kind != "twin_prismatic" else "")
            extra = ("; with two allowed motions it is the line of their poles" if label != name else
                     "; the allowed motions are all translations" if k == 2 else "")
            labelled_line(pic, f"R{j + 1}", R[:, j], label, role="reaction", width=1.4, symbol=name,
                     anchor=_along(R[:, j], p, 1.2 if j == 0 else -1.2),
                     desc=f"reaction space (6.1): a force the joint can take, sᵀR = 0: {force(R[:, j])}{extra}")
        for i in range(k):
            sub = _SUB[i] if k > 1 else ""
            ref = (-U[1, 0] / U[2, 0], U[0, 0] / U[2, 0]) if k == 2 and not bool(is_ideal(U[:, 0])) else COM
            labelled_line(pic, f"T{i + 1}", T[:, i], f"T{sub}", role="wrench", width=1.4, dash=[8.0, 4.0],
                          symbol=f"T{sub}", side=-1.0 if i else 1.0,
                     anchor=_along(T[:, i], ref, 1.3 if i == 0 else -1.3),
                     desc=f"T = I s (sᵀIs)⁻¹ (6.36): the axis of percussion of s{sub}, an active force: "
                          f"{force(T[:, i])}")
    labelled_line(pic, "f", st["f"], "f", role="wrench", symbol="f", anchor=fp, ahead=0.35,
             desc=f"the applied force on the body (5.56): {force(st['f'])}")
    if show == "wrench":
        if np.any(st["TQ"] != 0):
            labelled_line(pic, "TQ", st["TQ"], "TQ", role="wrench", width=3.6, symbol="TQ", side=-1.0,
                          anchor=fp + np.array([0.3, -0.4]),
                     desc=f"the part of f that accelerates the body along the joint (6.38): {force(st['TQ'])}")
        if np.any(st["Rmu"] != 0):
            labelled_line(pic, "Rmu", st["Rmu"], "Rμ", role="reaction", width=3.6, symbol="Rμ",
                     anchor=p + np.array([-0.4, 0.5]),
                     desc=f"the part of f that goes into the joint (6.38): {force(st['Rmu'])}")
    if show == "twist":
        for key, sym, color, meaning in (
                ("a_free", "I⁻¹f", COLORS["accel"], "the acceleration the body would have if free (6.68)"),
                ("s_psi", "sψ", COLORS["accel"], "the acceleration of the body held by the joint (6.44)"),
                ("U_gamma", "Uγ", COLORS["momentum"],
                 "the acceleration the joint's base would need to let the body move freely (6.44)")):
            a = st[key]
            if np.any(a != 0):
                points.append((key, a, "accel", color, sym,
                               f"{meaning}: rate {num(a[2])} rad/s², pole {where(a)}", True, sym))
    # one element per place: coinciding points share it, their labels and descriptions joined
    merged: list[list] = []
    for item in points:
        for group in merged:
            if _same_point(group[0][1], item[1]):
                group.append(item)
                break
        else:
            merged.append([item])
    for group in merged:
        eid, q, role, color = group[0][:4]
        pic.point(eid, q, role=role, color=color, symbol=", ".join(g[4] for g in group),
                  desc="; ".join(g[5] for g in group), glyph=any(g[6] for g in group), glyph_scale=3.0,
                  label=", ".join(g[7] for g in group), size=8.0 if eid.startswith("s") else 7.0)
    return pic
