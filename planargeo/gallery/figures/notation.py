"""Figures 2.1 (chain notation) and 3.3 (apparent mass of an articulated body)."""
from __future__ import annotations

import numpy as np
from shapely.geometry import Point as SPoint, box as sbox

from planargeo.draw.picture import PX_PER_PT
from planargeo.draw.sketch import arrow, body, frame, label, model, panel, show
from planargeo.draw.style import COLORS
from planargeo.gallery.figures import chain, register
from planargeo.mechanics.kinematics import kinematics
from planargeo.screws.twists import inertia_matrix


@register(2.01, height=2.5)
def fig2_1(ax):
    """Fig. 2.1 — notation of a chain: body i is joined to its parent i − 1 by joint i, whose
    unit twist s_i (here a revolute: its pole is the joint) carries the relative motion s_i q̇_i
    (2.1); each body has its local frame (black arrows) at its joint, turned with the body."""
    m = chain(3)
    q = np.array([0.5, -0.6, 0.7])
    d = kinematics(m, q, np.zeros(3))
    pose = np.asarray(d.pose)
    tip = 2 * np.asarray(d.com)[2] - pose[2, :2]
    pic = panel(ax, [pose[0, :2] - [0.35, 0.45], tip + [0.25, 0.2], pose[1, :2] + [0.0, 0.5]],
                margin=0.06)
    names = ["i − 1", "i", "i + 1"]
    model(pic, m, d, alpha=0.25, names=[f"body {n}" for n in names], show_com=False)
    for i in range(3):             # body i's frame at joint i, turned with the body
        frame(pic, f"frame {i + 1}", pose[i, :2], angle=pose[i, 2], length=0.3, labels=("", ""),
              desc=f"the local frame of body {names[i]}, at joint {names[i]}, turned with the body")
    s = np.asarray(d.s(1))[:, 0]                  # joint i's unit twist: its pole is the joint
    assert np.allclose([-s[1] / s[2], s[0] / s[2]], pose[1, :2])
    pic.point("s_i", s, role="twist", label="joint i: sᵢq̇ᵢ", symbol="sᵢ",
              desc="unit twist of joint i (2.1): its pole is the joint, the relative motion sᵢq̇ᵢ")
    label(pic, "joint i+1", pose[2, :2], "joint i + 1", offset=(8, -16))
    label(pic, "joint i-1", pose[0, :2], "joint i − 1", offset=(10, -18))
    show(pic, ax)


def apparent_mass(m: float = 1.0):
    """Fig. 3.3's articulated inertia ``A = I_c + I_s − I_s s (sᵀ I_s s)⁻¹ sᵀ I_s`` (3.20–3.27), apparent masses.

    A disc (the sphere) slides along x on a slider (the cylinder), each of mass ``m``.

    Parameters
    ----------
    m : float

    Returns
    -------
    A : ndarray (3, 3)
        The articulated inertia at the slider.
    mass_along : callable
        ``mass_along(theta)``: the apparent mass ``1 / (eᵀ A⁻¹ e)`` for a force at angle ``theta``.

    Examples
    --------
    >>> A, along = apparent_mass(2.0)
    >>> float(along(0.0)), float(along(np.pi / 2))          # m along the slot, 2m across (3.14)
    (2.0, 4.0)
    """
    Ic = inertia_matrix(m, [0.0, 0.0], 0.05 * m)       # the cylinder
    Is = inertia_matrix(m, [0.0, 0.0], 0.4 * m)        # the sphere (disc)
    s = np.array([1.0, 0.0, 0.0])
    Iss = Is @ s
    A = Ic + Is - np.outer(Iss, Iss) / (s @ Iss)
    Ainv = np.linalg.inv(A)

    def along(theta):
        e = np.array([np.cos(theta), np.sin(theta), 0.0])
        return 1.0 / (e @ Ainv @ e)

    return A, along


@register(3.03, height=2.6)
def fig3_3(ax):
    """Fig. 3.3 — apparent mass of an articulated body: a disc of mass m slides in a slot along x
    on a slider of mass m; a force on the slider along the slot moves the slider alone (apparent
    mass m), across it both bodies (2m), as the articulated inertia A = diag(m, 2m, ·) of (3.14)
    says; the dashed curve is the apparent mass 1/(eᵀA⁻¹e) for every force direction e."""
    m = 1.0
    A, along = apparent_mass(m)
    assert np.isclose(along(0.0), m) and np.isclose(along(np.pi / 2), 2 * m)    # 3.14
    assert np.allclose(A[:2, :2], np.diag([m, 2 * m]))
    R = 1.0
    pic = panel(ax, [[-1.6, -1.7], [2.3, 1.7]], margin=0.02)
    body(pic, "sphere", SPoint(0.0, 0.0).buffer(R, quad_segs=24), alpha=0.3,
         desc="the sphere (a disc), mass m, free to slide along the slot")
    body(pic, "slot", sbox(-R, -0.16, R, 0.16), color="white", alpha=1.0, z=2,
         desc="the slot along x in which the sphere slides")
    body(pic, "cylinder", sbox(-0.3, -0.13, 0.3, 0.13), color=COLORS["momentum"], alpha=0.6, z=3,
         desc="the cylinder (the slider), mass m")
    label(pic, "sphere label", (0.62, 0.62), "sphere m", offset=(4, 4))
    label(pic, "cylinder label", (-0.3, -0.13), "cylinder m", offset=(-6, -14), ha="right")
    th = np.linspace(0, 2 * np.pi, 181)
    r = 0.75 * np.array([along(t) for t in th])
    pic.path("apparent mass", np.column_stack([r * np.cos(th), r * np.sin(th)]), role="wrench",
             width=1.0 * PX_PER_PT, dash=[4.0 * PX_PER_PT, 1.5 * PX_PER_PT], z=4,
             desc="apparent mass 1/(eᵀA⁻¹e) for a force along e (3.14), 0.75 units per kg: "
                  f"{along(0.0):.3g} kg along x, {along(np.pi / 2):.3g} kg along y")
    label(pic, "apparent mass label", (0.0, -1.5), "apparent mass", offset=(0, -2), ha="center",
          va="top", role="wrench")
    for d, name, txt, off in (((1.0, 0.0), "F_along", "F∥: mass m", (4, 4)),
                              ((0.0, 1.0), "F_across", "F⊥: mass 2m", (5, 0))):
        tip = 0.35 * np.array(d) + 0.9 * np.array(d) * (1.0 if d[0] else 1.2)
        arrow(pic, name, 0.3 * np.array(d), tip, role="wrench", label=txt, offset=off,
              symbol=txt.split(":")[0], desc=f"a force on the slider through its centre, "
              f"{'along' if d[0] else 'across'} the slot: apparent {txt.split(': ')[1]} (3.14)")
    show(pic, ax)
