"""The cornering car's picture (thesis 6.9, Fig 6.6): body, tyres, ICR, forces to scale, inertia.

The car turns about its instant centre of rotation (ICR), the joint ``s`` of the model
(6.114); it is drawn turned by the heading about the ICR (:func:`moves`).

Examples
--------
>>> from planargeo.scenes.car import car
>>> res = car(omega=0.5, F_A=0.0, outlines=False)
>>> d = car_picture(res, heading=0.0, view=view_box(8.0, 2.6, 0.0)).to_dict()
>>> sorted(e["symbol"] for e in d["elements"] if e["role"] == "reaction")
['R₁μ₁', 'R₂μ₂']
"""
from __future__ import annotations

import math

import numpy as np

from planargeo.draw.pictures.common import builder
from planargeo.draw.picture import PX_PER_PT, Picture
from planargeo.draw.pictures.kit import aim_label, force, label_at, num, scale_bar, where
from planargeo.draw.style import COLORS

__all__ = ["car_picture", "moves", "view_box", "steer_lever", "FORCE_SCALE", "HALF_TRACK", "OVERHANG", "TYRE",
           "VIEW_MARGIN", "NEAR", "SLIDES", "STEER_ARM"]

#: metres of arrow per newton for the tyre, drive and bias forces
FORCE_SCALE = 1e-3
#: half track and overhangs of the drawn body, half length of a drawn tyre (m)
HALF_TRACK, OVERHANG, TYRE = 0.8, 0.7, 0.35
#: margin (m) of the view around the car (and the ICR when it is in view)
VIEW_MARGIN = 1.0
#: the ICR is kept in view for turn radii up to this many metres; beyond, the view holds the car
#: alone (so that it fills a third of the view) and the ICR is an arrow at the edge pointing to it
NEAR = 10.0
#: the picture's banner once the tyres reach their limit
SLIDES = "the car slides out: its tyres reach μ·g"
#: length (m) of the steering lever: from the front tyre along its axle line, towards the ICR (at most
#: half way there); 100 px or more in the explorer's view, clear of the drive arrow along the wheel
STEER_ARM = 2.0


def steer_lever(extra) -> np.ndarray:
    """The end of the steering lever, in the car's frame (m): the front axle line turns with the wheel.

    It lies :data:`STEER_ARM` from the front tyre towards the ICR (at most half way there), on the
    front axle line, which meets the rear axle line at the ICR (6.114).

    Parameters
    ----------
    extra : dict
        The scene ``"car"``'s ``extra`` (``front_contact``, ``icr``).

    Returns
    -------
    numpy.ndarray
        ``(x, y)`` (m).

    Examples
    --------
    >>> from planargeo.scenes.car import car
    >>> end = steer_lever(car(d=8.0, outlines=False).extra)     # front tyre at (8, 2.6), ICR at (0, 0)
    >>> [round(float(v), 4) for v in end]
    [6.0979, 1.9818]
    """
    front = np.asarray(extra["front_contact"], float)
    to_icr = np.asarray(extra["icr"], float) - front
    dist = math.hypot(*to_icr)
    return front + min(STEER_ARM, 0.5 * dist) * to_icr / dist


def moves(theta: float, d: float, shift=(0.0, 0.0)):
    """The drawing's placement of the scene: turned by ``theta`` about the ICR, rear tyre at the origin.

    A scene point ``p`` is drawn at ``R p + t`` (``t = (-d, 0) + shift``); twists and points map by
    ``V = [[R, -J t], [0, 1]]``, wrenches and lines by ``W = V⁻ᵀ``, inertias by ``W I Wᵀ``.

    Parameters
    ----------
    theta : float
        Heading (rad).
    d : float
        Turn radius (m).
    shift : (float, float)
        The whole drawing moved by this (m): the explorer holds the car still while a handle is dragged.

    Returns
    -------
    tuple
        ``(R, t, V, W)``.

    Examples
    --------
    >>> R, t, V, W = moves(0.0, 8.0)
    >>> (V @ [0.0, 0.0, 1.0]).tolist()          # the ICR (scene origin) drawn at (-8, 0): [y, -x, 1]
    [0.0, 8.0, 1.0]
    """
    c, s = math.cos(theta), math.sin(theta)
    R = np.array([[c, -s], [s, c]])
    t = np.array([-float(d) + float(shift[0]), float(shift[1])])
    V = np.eye(3)
    V[:2, :2] = R
    V[:2, 2] = -np.array([-t[1], t[0]])
    return R, t, V, np.linalg.inv(V).T


def view_box(d: float, L: float, theta: float, F_A: float = 0.0):
    """The view ``(x0, x1, y0, y1)`` (m) holding the car, the drive arrow and an ICR up to :data:`NEAR`.

    A square about them whose half side is their box's half diagonal plus :data:`VIEW_MARGIN`
    (rounded up to 0.5 m): it holds them at every heading.

    Parameters
    ----------
    d, L : float
        Turn radius and wheelbase (m).
    theta : float
        Heading (rad).
    F_A : float
        Drive force (N), drawn ``FORCE_SCALE`` m per N from the front tyre.

    Returns
    -------
    tuple of float

    Examples
    --------
    >>> [round(v, 2) for v in view_box(8.0, 2.6, 0.0)]
    [-9.6, 2.4, -4.7, 7.3]
    >>> [round(v, 2) for v in view_box(40.0, 2.6, 0.0)]     # the ICR far left, out of view
    [-3.5, 3.5, -2.2, 4.8]
    """
    hyp = math.hypot(d, L)
    tip = np.array([d, L]) + FORCE_SCALE * F_A * np.array([-L, d]) / hyp
    xs = [d - HALF_TRACK, d + HALF_TRACK, float(tip[0])]
    ys = [-OVERHANG, L + OVERHANG, float(tip[1])]
    if d <= NEAR:
        xs.append(0.0)
        ys.append(0.0)
    hx, hy = (max(xs) - min(xs)) / 2, (max(ys) - min(ys)) / 2
    R, t, _V, _W = moves(theta, d)
    c = R @ np.array([min(xs) + hx, min(ys) + hy]) + t
    half = math.ceil(2 * (math.hypot(hx, hy) + VIEW_MARGIN)) / 2
    return (float(c[0] - half), float(c[0] + half), float(c[1] - half), float(c[1] + half))


@builder
def car_picture(res, *, heading: float, view, slides: bool = False, limit: float = 0.0,
                size=(600, 560), shift=(0.0, 0.0)) -> Picture:
    """The picture of the car of the scene ``res`` turned by ``heading`` (module docstring).

    Parameters
    ----------
    res : SceneResult
        The scene ``"car"`` (at heading 0).
    heading : float
        How far the car has turned about the ICR (rad).
    slides : bool
        The tyres have reached their limit: the banner says so.
    limit : float
        What the tyres hold, μ·g (m/s²).
    shift : (float, float)
        The whole drawing moved by this (m) (:func:`moves`).
    """
    q, x, p = res.quantities, res.extra, res.params
    L, d = p["L"], p["d"]
    R, tr, V, W = moves(heading, d, shift)
    pic = Picture(view, size=size, ticks=False, margin=(6, 6, 6, 6))
    rear, front, cg = (R @ x[k] + tr for k in ("rear_contact", "front_contact", "cg"))
    icr = tr.copy()
    roll = R @ x["front_rolling"]
    ahead = R @ [0.0, 1.0]
    r_cg = float(np.hypot(*x["cg"]))
    omega, wdot, F_A = float(p["omega"]), float(q["omega_dot"]), float(p["F_A"])
    body = np.array([[d - HALF_TRACK, -OVERHANG], [d + HALF_TRACK, -OVERHANG],
                     [d + HALF_TRACK, L + OVERHANG], [d - HALF_TRACK, L + OVERHANG]])
    pic.path("body", body @ R.T + tr, role="body", symbol="car", closed=True, fill=COLORS["body"], alpha=0.5,
             color="#000000", width=1.0 * PX_PER_PT, z=2,
             desc=f"the car's body: wheelbase L = {L:.3g} m, track {2 * HALF_TRACK:.3g} m")
    pic.path("rear tyre", [rear - TYRE * ahead, rear + TYRE * ahead], role="body", symbol="tyre 1",
             color="#000000", width=4.0 * PX_PER_PT, z=3,
             desc=f"tyre (6.114): the rear one, rolling along the car; its axle passes through the ICR, "
                  f"d = {d:.3g} m away")
    pic.path("front tyre", [front - TYRE * roll, front + TYRE * roll], role="body", symbol="tyre 2",
             color="#000000", width=4.0 * PX_PER_PT, z=3,
             desc=f"tyre (6.114): the front one, steered by {math.degrees(x['steer']):.3g}°; its axle passes "
                  f"through the ICR")
    pic.path("axles", np.array([icr, rear, [np.nan, np.nan], icr, front]), role="construct", symbol="axles",
             color=COLORS["construct"], width=0.8 * PX_PER_PT, dash=[4.0, 3.0], z=1,
             desc=f"the axle lines: they meet at the ICR, d = {d:.3g} m from the rear tyre (6.114)")
    pic.path("steering lever", np.array([front, R @ steer_lever(x) + tr]), role="body", symbol="steering",
             color="#000000", width=2.4 * PX_PER_PT, z=5,            # over R₂μ₂'s line, which runs along it
             desc=f"steering lever along the front axle line (6.114): drag its end to turn the front wheel, "
                  f"now by {math.degrees(x['steer']):.3g}°; the axle line meets the rear axle line at the ICR")
    t = np.linspace(0.0, 2 * np.pi, 181)
    pic.path("path of G", icr + r_cg * np.column_stack([np.cos(t), np.sin(t)]), role="construct", symbol="circle of G",
             color=COLORS["construct"], width=0.8 * PX_PER_PT, dash=[1.0, 2.5], z=1,
             desc=f"the circle G runs on about the ICR: radius {r_cg:.3g} m")
    drive = F_A != 0.0                    # ω̇ = f_A's moment about the ICR / I_ICR (6.131): zero coasting
    v_desc = (f"velocity pole: the ICR, the joint s the car turns about, v = s ω (6.114, 6.115): "
              f"ω = {num(omega)} rad/s, {where(V @ q['v'])}")
    v_desc += ("; it is also the acceleration pole a" if drive else
               "; coasting, ω̇ = 0 and a = s ω̇ = 0 (6.131): no acceleration pole")
    pic.point("ICR", V @ np.asarray(q["v"], float), role="twist", symbol="v = sω", label="v = sω (ICR)",
              desc=v_desc, glyph_scale=8.0)
    aim_label(pic.elements[-1], R @ [0.0, -1.0], 12.0)      # below: the axle lines leave it to the right
    if drive:
        pic.point("a", V @ np.asarray(q["a"], float), role="accel", symbol="a", glyph_scale=3.0,
                  desc=f"acceleration pole (6.131): a = s ω̇ is a turn about the ICR, so its pole is the "
                       f"ICR too: ω̇ = {num(wdot)} rad/s², {where(V @ q['a'])}")
        aim_label(pic.elements[-1], R @ [-0.6, 0.8], 12.0)  # up and back: no line leaves the ICR there
    pic.marks("G", [cg], role="body", color="#000000", size=8.0, symbol="G", z=6,
              desc=f"centre of gravity G: ε = {p['eps']:.3g} of the wheelbase behind the front axle, "
                   f"{r_cg:.3g} m from the ICR")
    label_at(pic, cg, "G")
    pic.conic("I", W @ np.asarray(q["I"], float) @ W.T, role="inertia", symbol="I",
              desc=f"inertia (6.117): the car's, as its conic, mass {p['m']:.4g} kg, radius of gyration "
                   f"{p['rho']:.3g} m about G")
    tw = np.asarray(x["tyre_wrenches"], float)
    mu = q["mu"]
    for k, (sym, which, at) in enumerate((("R₁μ₁", "rear", rear), ("R₂μ₂", "front", front))):
        force(pic, sym, W @ tw[:, k], scale=FORCE_SCALE, anchor=at, role="reaction", symbol=sym,
              desc=f"tyre force (6.114, 6.133): the {which} one, reaction R{'₁₂'[k]} times its size μ{'₁₂'[k]}, "
                   f"μ{'₁₂'[k]} = {num(mu[k], 4)} N", z=4,
              label_xy=R @ [d + HALF_TRACK + 0.9, (0.0, L)[k]] + tr)   # beside the car, off the body
    fA = np.asarray(q["f_A"], float)
    if np.any(fA[:2]):
        force(pic, "f_A", W @ fA, scale=FORCE_SCALE, anchor=front, role="wrench", symbol="f (drive)", start=True,
              desc=f"drive force (6.120): at the front tyre, along its rolling direction, {num(F_A, 4)} N", z=4)
    pb = np.asarray(q["p"], float)
    if np.any(pb[:2]):
        force(pic, "p", W @ pb, scale=FORCE_SCALE, anchor=cg, role="momentum", symbol="p", start=True,
              width=1.0 * PX_PER_PT, z=4,                          # labelled at the tip, or in view
              label_xy=cg + min(FORCE_SCALE, 0.25 * (view[1] - view[0]) / math.hypot(*pb[:2])) * (R @ pb[:2]),
              desc=f"bias force (6.119): the force that keeps G on its circle, from G towards the ICR, "
                   f"{num(math.hypot(pb[0], pb[1]), 4)} N (m ω² times G's distance from the ICR)")
    T = W @ np.asarray(q["T"], float)
    icr_h = V @ [0.0, 0.0, 1.0]                               # the ICR, homogeneous
    off = abs(float(T @ icr_h)) / math.hypot(T[0], T[1]) if math.hypot(T[0], T[1]) > 0 else math.inf
    pic.line("T", T, role="construct", symbol="T", arrow=False,
             anchor=R @ [d, -OVERHANG - 1.2] + tr,                       # behind the car
             desc=f"active force line (6.125): the percussion axis of the joint at the ICR, {num(off)} m "
                  f"from the ICR; a force along it turns the car without loading the tyres")
    scale_bar(pic)
    if slides:
        x0, x1, y0, y1 = pic.box
        pic.text("banner", (x0, y1), SLIDES, color="#7a3d00", ha="left", va="top", dx=8.0, dy=-8.0, symbol="μ·g",
                 desc=f"the acceleration G needs reaches what the tyres hold: μ·g = {limit:.3g} m/s²")
    return pic
