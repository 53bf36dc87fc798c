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

__all__ = ["impulse_picture", "moved_outline"]


def moved_outline(outline, dv, t: float) -> np.ndarray:
    """The outline ``t`` seconds after the blow: turned by ``ω t`` about the pole of ``dv`` (or shifted).

    Parameters
    ----------
    outline : array_like (n, 2)
    dv : array_like (3,)
        The twist just after the blow ``[vx, vy, ω]``.
    t : float

    Returns
    -------
    numpy.ndarray (n, 2)

    Examples
    --------
    >>> moved_outline([[1.0, 0.0]], [0.0, 0.0, math.pi / 2], 1.0).round(12).tolist()  # a quarter turn about 0
    [[0.0, 1.0]]
    """
    return moved_points(dv, outline, t)   # written without the pole: finite for a subnormal ω


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
    pic.path("body", moved_outline(outline, dv, t), role="body", closed=True, fill=COLORS["body"], alpha=0.6,
             color="#000000", symbol="body",
             desc=f"the {prm['body']} t = {num(t)} s after the blow, turned about its velocity pole: "
                  f"mass m = {num(prm['m'])} kg", z=2)
    com = np.asarray(q["com"], float)
    pic.conic("I", ex["I"], role="inertia", symbol="I (ρ)", label="I (ρ)",
              desc=f"the body's inertia, its circle of gyration about c (5.4): ρ = {num(q['rho'])} m")
    pic.point("c", [com[1], -com[0], 1.0], role="twist", color="#000000", glyph=False, size=5.0, symbol="c",
              desc=f"the centre of mass: at {pair(com)} m")
    cop = np.asarray(q["centre_of_percussion"], float)
    d = float(np.hypot(*com))
    labelled_line(pic, "axis", percussion_axis(ex["I"], [0.0, 0.0, 1.0]), "axis of percussion of P",
                  role="construct", arrow=False,
             symbol="axis of percussion of P", anchor=(cop[0], cop[1] - 0.4),
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
        pic.point("pole", dv, role="twist", glyph_scale=3.0, symbol="v", label="v (pole)",
                  desc=f"the velocity pole just after the blow (4.10): ω = {num(dv[2])} rad/s, {where(dv)}")
    near = math.hypot(free[0], free[1]) < 0.04 * abs(free[2])      # at the grip (drawn)
    ptext = f"P ({grip})" + (" ≈ pole if free" if held and near else "")
    pic.point("P", [0.0, 0.0, 1.0], role="twist", color=COLORS["ground"], glyph=False, shape="s", size=8.0,
              symbol="P", label=ptext,
              desc=f"the {grip}, where the {prm['body']} is " + ("held (a revolute joint): at (0, 0) m" if held
                                                                else "held when held; now free: at (0, 0) m"))
    if held and not near:
        pic.point("free pole", free, role="twist", color=COLORS["construct"], glyph=False, symbol="pole if free",
                  desc=f"where the body would turn if nothing held it: the pole of I⁻¹ĵ (5.64–5.68), {where(free)}")
    return pic
