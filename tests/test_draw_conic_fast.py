"""conic_geometry (plain-float 2×2 eigen-decomposition) against numpy.linalg on random conics."""
from __future__ import annotations

import numpy as np
import pytest

from planargeo.draw.geometry import conic_geometry

_M = np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])   # package p = M [x, y, 1]


def _random_central(rng):
    """A random ellipse, imaginary ellipse or hyperbola (Euclidean matrix, package matrix)."""
    th = rng.uniform(0, 2 * np.pi)
    c, s = np.cos(th), np.sin(th)
    T = np.eye(3)
    T[:2, :2] = np.array([[c, -s], [s, c]]) @ np.diag(10.0 ** rng.uniform(-1.5, 1.5, 2))
    T[:2, 2] = rng.normal(size=2) * 3
    can = np.diag([1.0, rng.choice([1.0, -1.0]), rng.choice([1.0, -1.0])])
    Ti = np.linalg.inv(T)
    E = Ti.T @ can @ Ti * 10.0 ** rng.uniform(-4, 4) * rng.choice([1.0, -1.0])
    return E, _M @ E @ _M.T


@pytest.mark.parametrize("seed", range(4))
def test_central_conics_agree_with_numpy_eigh(seed):
    rng = np.random.default_rng(seed)
    for _ in range(250):
        E, C = _random_central(rng)
        E = E / np.abs(E).max()
        A, b, c = E[:2, :2], E[:2, 2], E[2, 2]
        # the reference: numpy.linalg (eigh, solve), larger |eigenvalue| first, a proper rotation
        lam, R = np.linalg.eigh(A)
        order = np.argsort(-np.abs(lam))
        lam, R = lam[order], R[:, order]
        if np.linalg.det(R) < 0:
            R[:, 1] = -R[:, 1]
        x0 = -np.linalg.solve(A, b)
        k = c + b @ x0
        g = conic_geometry(C)
        aff = g["affine"]
        tol = 1e-9 * max(1.0, np.abs(aff).max())
        np.testing.assert_allclose(g["center"], x0, rtol=1e-9, atol=1e-9 * max(1.0, np.abs(x0).max()))
        np.testing.assert_allclose(aff[:2, 2], x0, rtol=1e-9, atol=tol)
        if lam[0] * lam[1] > 0:
            assert g["kind"] == "ellipse"
            assert g["imaginary"] == bool(lam[0] * k > 0)
            ax = np.sqrt(np.abs(k / lam))
        else:
            assert g["kind"] == "hyperbola" and not g["imaginary"]
            ax = np.sqrt(np.abs(k / lam))
            if lam[0] * k >= 0:     # the real axis is the other eigenvector
                ax, R = ax[::-1], np.column_stack([R[:, 1], -R[:, 0]])
        np.testing.assert_allclose(aff[:2, :2], R @ np.diag(ax), rtol=1e-9, atol=tol)
        # and the map carries the unit curve onto the (real stand-in of the) conic
        t = np.linspace(0.0, 2 * np.pi, 7)
        u = np.stack([np.cos(t), np.sin(t), np.ones_like(t)]) if g["kind"] == "ellipse" else \
            np.stack([np.cosh(t - 3), np.sinh(t - 3), np.ones_like(t)])
        p = aff @ u
        Er = E.copy()
        if g["imaginary"]:
            Er[2, 2] -= 2 * k    # the sign-flipped conic: k -> -k
        q = np.einsum("in,ij,jn->n", p, Er, p)
        assert np.all(np.abs(q) <= 1e-7 * np.einsum("in,in->n", p, p))


@pytest.mark.parametrize("a, b, c", [(1.0, 0.0, 1.0), (2.0, 0.0, 1.0), (1.0, 0.0, 2.0), (1.0, 1e-20, 1.0),
                                     (1.0, 0.9, 1.0), (-1.0, 0.5, -1.0), (3.0, -2.0, 0.0), (0.0, 1.0, 0.0)])
def test_special_quadratic_parts_agree_with_numpy_eigh(a, b, c):
    """Equal, diagonal, nearly diagonal and zero-trace quadratic parts: numpy's eigenvectors, signs too."""
    E = np.array([[a, b, 0.3], [b, c, -0.2], [0.3, -0.2, -5.0]])
    g = conic_geometry(_M @ E @ _M.T)
    En = E / np.abs(E).max()
    lam, R = np.linalg.eigh(En[:2, :2])
    order = np.argsort(-np.abs(lam))
    lam, R = lam[order], R[:, order]
    if np.linalg.det(R) < 0:
        R[:, 1] = -R[:, 1]
    x0 = -np.linalg.solve(En[:2, :2], En[:2, 2])
    k = En[2, 2] + En[:2, 2] @ x0
    ax = np.sqrt(np.abs(k / lam))
    if lam[0] * lam[1] < 0 and lam[0] * k >= 0:
        ax, R = ax[::-1], np.column_stack([R[:, 1], -R[:, 0]])
    assert g["kind"] == ("ellipse" if lam[0] * lam[1] > 0 else "hyperbola")
    np.testing.assert_allclose(g["affine"][:2, :2], R @ np.diag(ax), rtol=1e-12, atol=1e-12)
