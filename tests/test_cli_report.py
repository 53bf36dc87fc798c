"""``planargeo report`` end to end: every output named in issue 3, checked against references
computed here (closed forms, dense solves), and one-line errors.  The checks that need
Pinocchio (the n = 50 chain, the slider-crank's multiplier solve) are in
``test_cli_report_pinocchio.py``, so these run without it.

The references never call the scene or algorithm under test: inertias are written out by hand
(twist ``[vx, vy, w]`` at the origin, momentum ``m (v + w × c)``), Jacobians from the joint
points (a revolute joint at ``(x, y)`` has ``s = [y, -x, 1]``), and joint-space problems are
solved densely with numpy.
"""
from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from planargeo import report
from planargeo.errors import SingularConfigurationError

EXE = Path(sys.executable).with_name("planargeo")


def cli(*args) -> subprocess.CompletedProcess:
    """Run the installed console script (or ``-m planargeo.cli`` if it is not installed)."""
    cmd = [str(EXE)] if EXE.exists() else [sys.executable, "-m", "planargeo.cli"]
    env = dict(os.environ, PYTHONWARNINGS="ignore")
    return subprocess.run(cmd + ["report", *args], capture_output=True, text=True, timeout=300, env=env)


def report_json(*args) -> dict:
    r = cli(*args, "--json")
    assert r.returncode == 0, r.stderr
    assert r.stderr == ""
    obj = json.loads(r.stdout)
    assert set(obj) == {"scene", "params", "state", "quantities"}
    return obj


def inertia(m, c, J):
    """Planar inertia at the origin, by hand: momentum of twist [vx, vy, w] is m (v + w × c), J + m|c|²."""
    cx, cy = c
    return np.array([[m, 0.0, -m * cy], [0.0, m, m * cx], [-m * cy, m * cx, J + m * (cx * cx + cy * cy)]])


def rot_twist(x, y):
    """Unit rotation twist about (x, y) (conventions: the point [y, -x, 1])."""
    return np.array([y, -x, 1.0])


# ---------------------------------------------------------------------------
# chain: a method's error
# ---------------------------------------------------------------------------
def test_chain_method_error_makes_report_fail(monkeypatch, capsys):
    """A PlanargeoError raised by any method propagates: exit 1, its message on one line."""
    from planargeo.scenes import chain as chain_mod

    def broken(*a, **k):
        raise SingularConfigurationError("s^T A s of joint 2 vanishes", 1e17)

    monkeypatch.setitem(chain_mod.METHODS, "projective", broken)
    p = argparse.ArgumentParser()
    report.add_arguments(p)
    code = report.main(p.parse_args(["chain", "--json"]))
    out = capsys.readouterr()
    assert code == 1 and out.out == ""
    assert out.err.strip().splitlines() == [
        "planargeo report: error: s^T A s of joint 2 vanishes (condition number 1e+17)"]


# ---------------------------------------------------------------------------
# slider-crank (9.6); the multiplier-solve references are in test_cli_report_pinocchio.py
# ---------------------------------------------------------------------------
R_, L_, T_ = 2.29, 5.00, 0.5


def test_slider_crank_default_h_is_the_thesis_value():
    qs = report_json("slider-crank")["quantities"]
    # h = r sin psi + sqrt(l^2 - r^2 cos^2 psi) + t at psi = 0.4 (9.85)
    assert qs["h"] == pytest.approx(R_ * np.sin(0.4) + np.sqrt(L_ ** 2 - (R_ * np.cos(0.4)) ** 2) + T_, rel=1e-14)


# ---------------------------------------------------------------------------
# car (6.9): 6.131 and the tyre forces from Newton's law, written out here
# ---------------------------------------------------------------------------
def test_car_json_against_closed_forms():
    m, rho, L, d, eps, om, F = 900.0, 1.1, 2.4, 6.0, 0.4, 0.7, 1500.0
    obj = report_json("car", *sum((["--set", f"{k}={v}"] for k, v in
                                   dict(m=m, rho=rho, L=L, d=d, eps=eps, omega=om, F_A=F).items()), []))
    qs = obj["quantities"]
    for key in ("omega_dot", "mu", "T", "U"):
        assert key in qs, key
    hyp = np.hypot(d, L)
    # 6.131: moment of the drive force about the ICR (= F_A hyp) over the inertia about the ICR
    wdot = F / m * hyp / (rho ** 2 + d ** 2 + (1 - eps) ** 2 * L ** 2)
    assert qs["omega_dot"] == pytest.approx(wdot, rel=1e-12)
    # tyre forces: m a_cg = mu1 [1, 0] + mu2 (d, L)/hyp + F_A (-L, d)/hyp
    c = np.array([d, (1 - eps) * L])
    a_cg = wdot * np.array([-c[1], c[0]]) - om ** 2 * c
    A = np.array([[1.0, d / hyp], [0.0, L / hyp]])
    mu = np.linalg.solve(A, m * a_cg - F * np.array([-L, d]) / hyp)
    np.testing.assert_allclose(qs["mu"], mu, rtol=1e-10)
    # T (6.125) and U (6.127): s^T T = 1, R^T U = 1, T^T U = 0, s^T I U = 0 (6.124, 6.126)
    T, U = np.array(qs["T"]), np.array(qs["U"])
    assert T.shape == (3,) and U.shape == (3, 2)
    s = rot_twist(0.0, 0.0)
    # tyre reactions as wrenches [fx, fy, tz] at the origin, tz = x fy - y fx of the contact point:
    # rear (1, 0) through (d, 0) and front (d, L)/hyp through (d, L) both pass through the ICR (6.114)
    Rm = np.array([[1.0, d / hyp], [0.0, L / hyp], [0.0, 0.0]])
    I = inertia(m, c, m * rho ** 2)
    assert s @ T == pytest.approx(1.0, abs=1e-12)
    np.testing.assert_allclose(Rm.T @ U, np.eye(2), atol=1e-12)
    np.testing.assert_allclose(T @ U, [0.0, 0.0], atol=1e-12 * np.abs(U).max())
    np.testing.assert_allclose(s @ I @ U, [0.0, 0.0], atol=1e-12 * np.abs(I).max() * np.abs(U).max())


# ---------------------------------------------------------------------------
# chapter 7 scenes: 7.19-7.24, 7.26/7.27 and 7.48 against dense references
# ---------------------------------------------------------------------------
def articulated_first_body(masses, rhos, xs_joint, L):
    """A_1 of bodies in line along +x (body 1 free, joints 2.. free) as a dense Schur complement."""
    n = len(masses)
    blocks = []
    for i in range(n):
        J = np.zeros((3, 3 + n - 1))
        J[:, :3] = np.eye(3)
        for k in range(1, i + 1):
            J[:, 2 + k] = rot_twist(xs_joint[k], 0.0)
        blocks.append(J)
    Mm = sum(J.T @ inertia(masses[i], (xs_joint[i] + L / 2, 0.0), masses[i] * rhos[i] ** 2) @ J
             for i, J in enumerate(blocks))
    return Mm[:3, :3] - Mm[:3, 3:] @ np.linalg.solve(Mm[3:, 3:], Mm[3:, :3])


@pytest.mark.parametrize("phi", [0.0, 0.7, np.pi / 2, 2.5])
def test_two_body_json_against_7_20_and_3_29(phi):
    m, rho, L = 2.0, 0.6, 1.5
    qs = report_json("two-body", "--set", f"m={m}", "--set", f"rho={rho}", "--set", f"L={L}",
                     "--set", f"phi={phi}")["quantities"]
    for key in ("A1", "m_x"):
        assert key in qs, key
    # 7.20 (verified closed form)
    assert qs["m_x"] == pytest.approx(m * (L ** 2 + 8 * rho ** 2 + L ** 2 * np.cos(phi) ** 2) / (L ** 2 + 4 * rho ** 2),
                                      rel=1e-12)
    # A_1 = I_1 + I_2 - I_2 s (s^T I_2 s)^-1 s^T I_2 (3.29 with A_2 = I_2), inertias by hand
    I1 = inertia(m, (L / 2, 0.0), m * rho ** 2)
    I2 = inertia(m, (L + L / 2 * np.cos(phi), L / 2 * np.sin(phi)), m * rho ** 2)
    s = rot_twist(L, 0.0)
    A1 = I1 + I2 - np.outer(I2 @ s, s @ I2) / (s @ I2 @ s)
    np.testing.assert_allclose(qs["A1"], A1, rtol=1e-12, atol=1e-12 * np.abs(A1).max())


@pytest.mark.parametrize("n, lam", [(2, 3.0), (3, 1.5), (4, 2.0)])
def test_horizontal_chain_json_against_dense_schur(n, lam):
    qs = report_json("horizontal-chain", "--set", f"n={n}", "--set", f"lam={lam}")["quantities"]
    L, m = 1.0, 1.0
    rho = L / lam
    A = articulated_first_body([m] * n, [rho] * n, [k * L for k in range(n)], L)
    d = A[1, 2] / A[1, 1]                                      # diagonalising point (d, 0) (7.26)
    assert qs["d_over_L"] == pytest.approx(d / L, rel=1e-12)
    assert qs["mx_over_m"] == pytest.approx(A[0, 0] / m, rel=1e-12) and qs["mx_over_m"] == pytest.approx(n)
    assert qs["my_over_m"] == pytest.approx(A[1, 1] / m, rel=1e-12)
    assert qs["Az_over_m_rho2"] == pytest.approx((A[2, 2] - A[1, 2] ** 2 / A[1, 1]) / (m * rho ** 2), rel=1e-12)
    if n == 2:   # 7.27, derived by hand
        assert qs["d_over_L"] == pytest.approx((lam ** 2 + 12) / (2 * (lam ** 2 + 8)), rel=1e-13)
    if lam == 2.0:   # the 7.3 claim: with lambda = 2 every further body leaves d, m_y, A_z unchanged
        assert (qs["d_over_L"], qs["my_over_m"], qs["Az_over_m_rho2"]) == pytest.approx((2 / 3, 1.5, 4 / 3), rel=1e-12)


@pytest.mark.parametrize("phi, tau", [(0.0, 1.0), (0.9, -2.5)])
def test_mobility_example_json_against_dense_joint_space(phi, tau):
    m, rho, L = 1.3, 0.4, 0.9
    qs = report_json("mobility-example", *sum((["--set", f"{k}={v}"] for k, v in
                                               dict(m=m, rho=rho, L=L, phi=phi, tau=tau).items()), []))["quantities"]
    for key in ("Lambda2_inv", "a2", "x_over_L"):
        assert key in qs, key
    I1 = inertia(m, (L / 2, 0.0), m * rho ** 2)
    I2 = inertia(m, (L + L / 2 * np.cos(phi), L / 2 * np.sin(phi)), m * rho ** 2)
    J1 = np.stack([rot_twist(0.0, 0.0), np.zeros(3)], axis=1)
    J2 = np.stack([rot_twist(0.0, 0.0), rot_twist(L, 0.0)], axis=1)
    H = J1.T @ I1 @ J1 + J2.T @ I2 @ J2
    Lam2 = J2 @ np.linalg.solve(H, J2.T)                       # mobility of body 2 (7.43)
    np.testing.assert_allclose(qs["Lambda2_inv"], Lam2, rtol=1e-12, atol=1e-12 * np.abs(Lam2).max())
    a2 = -Lam2 @ np.array([0.0, 0.0, tau])                     # at rest, no gravity (7.45/7.46)
    np.testing.assert_allclose(qs["a2"], a2, rtol=1e-12, atol=1e-12 * np.abs(a2).max())
    eta = L / rho
    assert qs["x_over_L"] == pytest.approx(1 + 2 * eta ** 2 * np.cos(phi) / (4 + 5 * eta ** 2), rel=1e-12)


# ---------------------------------------------------------------------------
# --list and errors
# ---------------------------------------------------------------------------
def test_list_over_subprocess():
    r = cli("--list")
    assert r.returncode == 0 and r.stderr == ""
    lines = r.stdout.splitlines()
    for name in ("chain", "car", "two-body", "horizontal-chain", "mobility-example", "slider-crank", "tree",
                 "constrained-tree"):
        assert any(line.startswith(name + ":") for line in lines), name
    assert "chain: n=3, mass=1.0, length=1.0, joint=revolute, seed=None, gravity=-9.81" in lines
    r = cli("--list", "--json")
    listing = json.loads(r.stdout)["scenes"]
    assert listing["slider-crank"]["psi"] == 0.4 and listing["slider-crank"]["psidot"] == 20.0
    assert listing["car"] == {"m": 1200.0, "rho": 1.2, "L": 2.6, "d": 8.0, "eps": 0.45, "omega": 0.5, "F_A": 2000.0, "outlines": True}


@pytest.mark.parametrize("psi", ["0", "3.141592653589793"])
def test_folded_slider_crank_reports_the_singular_contact_matrix_with_its_condition(psi):
    """l = r at a dead centre (ψ = 0 or π): the piston pin lies on the crank pivot.

    Exit 1 with one line naming the singular configuration and carrying the condition number of
    the contact matrix (past the loop solver's limit), not the velocity closure's message.
    """
    r = cli("slider-crank", "--set", "l=2.29", "--set", f"psi={psi}")
    assert r.returncode == 1 and r.stdout == ""
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in r.stderr
    line = lines[0]
    assert line.startswith("planargeo report: error: singular configuration: slider-crank at a dead centre "
                           "with the piston pin on the crank pivot")
    assert "the contact matrix Bᵀ G Λ⁻¹ Gᵀ B of the piston slider is singular" in line
    cond = float(line.rsplit("(condition number ", 1)[1].rstrip(")"))
    assert cond > 1e10


def test_folded_slider_crank_in_process_error_and_independent_condition():
    """The named error carries the contact matrix's condition; ``J_c H⁻¹ J_cᵀ`` (dense, by hand) is singular too."""
    from planargeo import scenes
    from planargeo.algorithms.crba import mass_matrix
    from planargeo.algorithms.loops import SINGULAR_COND
    from planargeo.scenes.slider_crank import slider_crank_model
    from planargeo.simulate.loops import closure_jacobian

    with pytest.raises(SingularConfigurationError, match="piston pin on the crank pivot") as e:
        scenes.build("slider-crank", l=R_, psi=0.0)
    assert e.value.cond > SINGULAR_COND
    # the folded pose: crank along +x, rod back along -x to the pivot, piston upright
    model, q = slider_crank_model(l=R_), np.array([0.0, np.pi, -np.pi / 2])
    Jc = closure_jacobian(model, q)
    H = mass_matrix(model, q)
    assert np.linalg.cond(Jc @ np.linalg.solve(H, Jc.T)) > 1e10
    # a rod too short for the pivot but horizontal at psi = arccos(l / r) is only a kinematic limit:
    # the contact matrix is regular there and the velocity closure's error stands
    with pytest.raises(SingularConfigurationError,
                       match=r"loop closure is singular \(rod along the horizontal\): the rod's turning rate θ̇ is undetermined") as e:
        scenes.build("slider-crank", l=2.0, psi=float(np.arccos(2.0 / R_)))
    assert "piston pin" not in str(e.value)
    assert e.value.cond > 1e12


@pytest.mark.parametrize("args, msg", [
    (("no-such-scene",), "scene must be one of"),
    (("chain", "--set", "links=3"), "scene 'chain' has no parameter 'links'"),
    (("chain", "--set", "n"), "--set expects NAME=VALUE, got 'n'"),
    (("chain", "--set", "=3"), "--set expects NAME=VALUE"),
    (("slider-crank", "--set", "l=2", "--set", "psi=0"), "rod too short: l = 2 cannot reach the piston line"),
    (("chain", "--set", "seed=-1"), "seed must be a non-negative integer, got -1"),
    (("chain", "--set", "seed=1.5"), "seed must be a non-negative integer, got 1.5"),
    (("chain", "--set", "n=true"), "n must be a positive integer, got True"),
    (("chain", "--set", "mass=nan"), "mass must be finite, got nan"),
    (("slider-crank", "--set", "psidot=nan"), "psidot must be finite, got nan"),
    (("slider-crank", "--set", "psi=inf"), "psi must be finite, got inf"),
    (("tree", "--set", "speed=nan"), "speed must be finite, got nan"),
    (("constrained-tree", "--set", "g=abc"), "g must be numeric, got 'abc'"),
    (("car", "--set", "omega=false"), "omega must be numeric, got False"),
    (("horizontal-chain", "--set", "n=2.5"), "n must be a positive integer, got 2.5"),
])
def test_errors_exit_nonzero_with_one_line_and_no_traceback(args, msg):
    r = cli(*args)
    assert r.returncode != 0
    assert r.stdout == ""
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1, r.stderr
    assert msg in lines[0]
    assert "Traceback" not in r.stderr


# ---------------------------------------------------------------------------
# non-finite results: exit 1, one line naming the parameter, no NaN tokens, no warnings
# ---------------------------------------------------------------------------
NONFINITE_MSG = (r"planargeo report: error: scene 'slider-crank' overflows \(kinematics overflow: kappa is not finite "
                 r"for these finite inputs \(qd reaches 1.\d*e\+200\)\) with psidot=1e\+200 \(beyond what double "
                 r"precision can evaluate\)")


@pytest.mark.parametrize("fmt", [["--json"], []])
@pytest.mark.parametrize("extra", [[], ["--set", "psi=0.3"]])
def test_non_finite_quantities_exit_1_naming_the_parameter(fmt, extra):
    cmd = [str(EXE)] if EXE.exists() else [sys.executable, "-m", "planargeo.cli"]
    env = {k: v for k, v in os.environ.items() if k != "PYTHONWARNINGS"}      # warnings would show
    r = subprocess.run(cmd + ["report", "slider-crank", "--set", "psidot=1e200", *extra, *fmt],
                       capture_output=True, text=True, timeout=300, env=env)
    assert r.returncode == 1
    assert r.stdout == ""                                   # no JSON with NaN tokens, no table of nans
    assert len(r.stderr.splitlines()) == 1
    assert re.fullmatch(NONFINITE_MSG, r.stderr.strip())    # psi=0.3 is fine on its own: not named


def test_large_but_finite_speed_still_reports():
    obj = report_json("slider-crank", "--set", "psidot=1e100")
    assert np.isfinite(np.array(obj["quantities"]["qdd"])).all()


def test_non_finite_in_process(capsys):
    """The tree spun at 1e300 (issue 16.4: inf/NaN quantities): one line naming the quantities and the
    parameter that did it (mass=2.0, given too, is fine on its own and not named)."""
    p = argparse.ArgumentParser()
    report.add_arguments(p)
    for fmt in (["--json"], []):
        code = report.main(p.parse_args(["tree", "--set", "speed=1e300", "--set", "mass=2.0", *fmt]))
        out = capsys.readouterr()
        assert code == 1 and out.out == ""
        assert out.err.splitlines() == ["planargeo report: error: scene 'tree' overflows (kinematics overflow: "
                                        "kappa is not finite for these finite inputs (qd reaches 1e+300)) with "
                                        "speed=1e+300 (beyond what double precision can evaluate)"]
    assert report.main(p.parse_args(["tree", "--set", "speed=2.0", "--json"])) == 0

def test_a_size_past_the_limit_fails_fast_and_allow_big_lifts_it():
    """`planargeo report chain --set n=1000000` was still running after 30 s (issue 16.7)."""
    r = cli("chain", "--set", "n=1000000")
    assert r.returncode == 1 and r.stdout == ""
    assert r.stderr.splitlines() == [
        "planargeo report: error: n = 1000000 is past the limit of 200 for scene 'chain' (n = 200 takes about "
        "0.5 s; the cost grows as n³); pass allow_big=True (planargeo report --allow-big) to build it anyway"]
    obj = report_json("horizontal-chain", "--set", "n=2001", "--allow-big")
    assert obj["params"]["n"] == 2001 and len(obj["state"]["q"]) == 2001
