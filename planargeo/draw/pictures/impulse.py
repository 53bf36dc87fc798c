"""The impulse explorer's picture: a bat or door struck at rest, its poles and the sting (thesis 5.4).

The body ``t`` s after the blow (and at rest, dashed), the grip or hinge ``P`` with its axis
and centre of percussion (5.67), the blow ``ĵ`` and the grip's reaction ``ĵᵣ``, the velocity
pole ``v`` (4.10) and the pole the body would have if free.

Examples
--------
>>> from planargeo import scenes
>>> r = scenes.build("impulse", body="door", x=0.3)
>>> d = impulse_picture(r, t=0.0, view=(-0.45, 1.2, -0.6, 0.6)).to_dict()
>>> sorted(e["id"] for e in d["elements"])
['I', 'P', 'axis', 'blow', 'body', 'c', 'centre of percussion', 'free pole', 'pole', 'reaction']
"""
from __future__ import annotations

import math

import numpy as np

from planargeo.draw.pictures.common import builder, labelled_line
from planargeo.draw.picture import Picture
from planargeo.draw.pictures._words import force, num, pair, where
from planargeo.draw.style import COLORS
from planargeo.mechanics.impulse import moved_points
from planargeo.screws.inertia import percussion_axis
from planargeo.screws.twists import inertia_matrix

__all__ = ["impulse_picture", "moved_outline", "twist_at"]


def moved_outline(outline, dv, t: float, com=None) -> np.ndarray:
    """Body points ``t`` seconds after the blow, nothing acting on the body after it.

    Held at the grip (``com`` None), the body turns at ``ω`` about the grip, the fixed pole of ``dv``.
    Free (``com``, its centre of mass at ``t = 0``, given), its momentum is kept: the centre of mass moves
    straight on at its velocity ``v_c`` while the body turns by ``ω t`` about it (a fixed pole would need a
    force).  At ``t = 0`` both have the velocity ``dv``.

    Parameters
    ----------
    outline : array_like (n, 2) or (2,)
    dv : array_like (3,)
        The twist just after the blow ``[vx, vy, ω]`` (the velocity of the origin and ``ω``).
    t : float
    com : array_like (2,), optional
        The centre of mass of a free body at ``t = 0``.

    Returns
    -------
    numpy.ndarray, the shape of ``outline``

    Examples
    --------
    >>> moved_outline([[1.0, 0.0]], [0.0, 0.0, math.pi / 2], 1.0).round(12).tolist()  # a quarter turn about 0
    [[0.0, 1.0]]

    Free, struck at its centre of mass ``(1, 0)`` across: it slides on at 1 m/s without turning; turning
    too, its centre of mass still moves straight on (here ``v_c = (0, 1)``).

    >>> moved_outline([[1.0, 0.0]], [0.0, 1.0, 0.0], 2.0, com=[1.0, 0.0]).tolist()
    [[1.0, 2.0]]
    >>> moved_outline([1.0, 0.0], [0.0, 0.0, 1.0], 3.0, com=[1.0, 0.0]).round(12).tolist()
    [1.0, 3.0]
    """
    if com is None:
        return moved_points(dv, outline, t)   # written without the pole: finite for a subnormal ω
    dv = np.asarray(dv, dtype=float)
    c = np.asarray(com, dtype=float)
    v_c = dv[:2] + dv[2] * np.array([-c[1], c[0]])          # the velocity of the centre of mass
    turned = moved_points([0.0, 0.0, dv[2]], np.asarray(outline, dtype=float) - c, t)   # about c
    return moved_points([v_c[0], v_c[1], 0.0], turned + c, t)                           # c moves straight


def twist_at(dv, t: float, com=None) -> np.ndarray:
    """The twist ``[vx, vy, ω]`` (velocity of the origin, ``ω``) of the body ``t`` seconds after the blow.

    Held (``com`` None) it is ``dv`` at all times; free, ``v_c`` and ``ω`` stay, ``c`` moves (see
    :func:`moved_outline`), so the velocity pole moves with the centre of mass.

    Parameters
    ----------
    dv : array_like (3,)
        The twist the blow gave, at ``t = 0``.
    t : float
        Seconds after the blow.
    com : array_like (2,), optional
        The free body's centre of mass at ``t = 0``; None: the body is held.

    Returns
    -------
    numpy.ndarray (3,)

    Examples
    --------
    >>> twist_at([0.0, 1.0, 1.0], 2.0, com=[1.0, 0.0]).round(12).tolist()   # c at (1, 4) moving at (0, 2)
    [4.0, 1.0, 1.0]
    """
    dv = np.asarray(dv, dtype=float)
    if com is None:
        return dv
    c = np.asarray(com, dtype=float)
    v_c = dv[:2] + dv[2] * np.array([-c[1], c[0]])
    ct = moved_outline(c, dv, t, com=c)
    return np.array([v_c[0] + dv[2] * ct[1], v_c[1] - dv[2] * ct[0], dv[2]])


@builder
def impulse_picture(r, *, t: float, view, size=(640, 460)) -> Picture:
    """The picture of one result of the impulse scene (module docstring).

    Parameters
    ----------
    r : SceneResult
        :func:`planargeo.scenes.impulse.impulse`.
    t : float
        Seconds after the blow.
    """
    q, ex, prm = r.quantities, r.extra, r.params
    held = prm["support"] == "held"
    bat = prm["body"] == "bat"
    grip = "grip" if bat else "hinge"
    outline, dv, free = ex["outline"], np.asarray(ex["dv"], float), np.asarray(ex["dv_free"], float)
    pic = Picture(view, size=size)
    if t > 0:
        ring = np.vstack([outline, outline[:1]])              # an open ring: dashed by every renderer
        pic.path("at rest", ring, role="construct", color=COLORS["construct"], dash=[5.0, 4.0],
                 symbol="body at rest", desc=f"the {prm['body']} where it was struck: at rest at t = 0 s", z=1)
    # everything on the body moves with it: its outline, c, its circle of gyration, the grip (when free),
    # the centre and axis of percussion of the grip; the blow, the reaction and the pole if free are of t = 0
    com0 = np.asarray(q["com"], float)
    c0 = None if held else com0
    pic.path("body", moved_outline(outline, dv, t, c0), role="body", closed=True, fill=COLORS["body"], alpha=0.6,
             color="#000000", symbol="body",
             desc=f"the {prm['body']} t = {num(t)} s after the blow, " +
                  ("turned about the grip" if held and bat else "turned about the hinge" if held else
                   "its centre of mass moving straight on" + (" as it turns" if dv[2] else "")) + f": mass m = {num(prm['m'])} kg", z=2)
    com = moved_outline(com0, dv, t, c0) if t > 0 else com0
    grip_at = moved_outline(np.zeros(2), dv, t, c0) if t > 0 and not held else np.zeros(2)
    # moved: its matrix built as is (a free body far from the origin is ill-conditioned there, yet definite)
    I = inertia_matrix(prm["m"], com, prm["m"] * q["rho"] ** 2) if t > 0 else ex["I"]
    pic.conic("I", I, role="inertia", symbol="I (ρ)", label="I (ρ)",
              desc=f"the body's inertia, its circle of gyration about c (5.4): ρ = {num(q['rho'])} m")
    pic.point("c", [com[1], -com[0], 1.0], role="twist", color="#000000", glyph=False, size=5.0, symbol="c",
              desc=f"the centre of mass: at {pair(com)} m")
    cop0 = np.asarray(q["centre_of_percussion"], float)
    cop = moved_outline(cop0, dv, t, c0) if t > 0 else cop0
    d = float(np.hypot(*com0))
    below = moved_outline(cop0 + [0.0, -0.4], dv, t, c0) if t > 0 else (cop0[0], cop0[1] - 0.4)
    labelled_line(pic, "axis", percussion_axis(I, [grip_at[1], -grip_at[0], 1.0]), "axis of percussion of P",
                  role="construct", arrow=False,
                  symbol="axis of percussion of P", anchor=below,
                  desc="the line of blows that leave P without reaction (5.67): at l = d + ρ²/d = "
                       f"{num(d + q['rho'] ** 2 / d)} m from P")
    pic.marks("centre of percussion", [cop], role="wrench", color=COLORS["wrench"], shape="D", size=10.0,
              symbol="centre of percussion",
              desc=f"the centre of percussion (5.67): where the axis of percussion of P crosses the body, "
                   f"at {pair(cop)} m", z=6)
    labelled_line(pic, "blow", ex["impulse"], "ĵ (blow)", role="wrench", symbol="ĵ", anchor=(prm["x"], prm["y"]),
                  ahead=0.15, desc=f"the blow, an impulse along its line (5.64): {force(ex['impulse'], 'N·s')}")
    jr = np.asarray(ex["reaction"], float)
    if held and bool(np.hypot(jr[0], jr[1]) > 1e-12 * abs(prm["J"])):
        u = jr[:2] / float(np.hypot(jr[0], jr[1]))
        labelled_line(pic, "reaction", jr, f"ĵᵣ ({grip})", role="reaction", width=1.7, symbol="ĵᵣ", anchor=-0.15 * u,
                      ahead=-0.2,
                 desc=f"the reaction impulse of the {grip} on the body, the sting (5.67): {force(jr, 'N·s')}")
    if np.any(dv != 0):
        now = twist_at(dv, t, c0) if t > 0 else dv
        pic.point("pole", now, role="twist", glyph_scale=3.0, symbol="v", label="v (pole)",
                  desc=(f"the velocity pole just after the blow (4.10): ω = {num(dv[2])} rad/s, {where(now)}"
                        if t == 0 or held else
                        f"the velocity pole t = {num(t)} s after the blow (4.10): ω = {num(dv[2])} rad/s, "
                        f"{where(now)}"))
    near = math.hypot(free[0], free[1]) < 0.04 * abs(free[2])      # at the grip (drawn)
    ptext = f"P ({grip})" + (" ≈ pole if free" if held and near else "")
    pic.point("P", [grip_at[1], -grip_at[0], 1.0], role="twist", color=COLORS["ground"], glyph=False, shape="s",
              size=8.0, symbol="P", label=ptext,
              desc=f"the {grip}, where the {prm['body']} is " + ("held (a revolute joint): at (0, 0) m" if held
                                                                else f"held when held; now free: at {pair(grip_at)} m"))
    if held and not near:
        pic.point("free pole", free, role="twist", color=COLORS["construct"], glyph=False, symbol="pole if free",
                  desc=f"where the body would turn if nothing held it: the pole of I⁻¹ĵ (5.64–5.68), {where(free)}")
    return pic
