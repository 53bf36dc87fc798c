"""Label places of the pictures' kit measured all at once (clearest_sides, pin_heads) against one at a time."""
from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from planargeo.draw.pictures.kit import clearest_sides, pin_heads


def seg_dist(p, a, b):
    """Point to segment distance, by hand (projection clamped to the segment)."""
    (px, py), (ax, ay), (bx, by) = p, a, b
    dx, dy = bx - ax, by - ay
    L2 = dx * dx + dy * dy
    t = 0.0 if L2 == 0 else min(1.0, max(0.0, ((px - ax) * dx + (py - ay) * dy) / L2))
    return math.hypot(ax + t * dx - px, ay + t * dy - py)


def farthest(points, segs):
    gaps = [min((seg_dist(p, a, b) for a, b in segs), default=math.inf) for p in points]
    best = max(gaps)
    # a near-tie decides nothing: report it so that the test skips it
    return points[gaps.index(best)], sorted(gaps)[-2] > best - 1e-9 if len(gaps) > 1 else False


@pytest.mark.parametrize("seed", range(5))
def test_clearest_sides_pick_each_segments_side_clearer_of_the_others(seed):
    rng = np.random.default_rng(seed)
    segs = rng.uniform(-2, 2, (7, 2, 2))
    sides = clearest_sides(segs)
    for i, (a, b) in enumerate(segs):
        m, d = 0.5 * (a + b), b - a
        n = np.array([-d[1], d[0]]) / math.hypot(*d)
        span = 0.25 * math.hypot(*d)
        want, tie = farthest([m + span * n, m - span * n], [s for j, s in enumerate(segs) if j != i])
        if not tie:
            assert np.allclose(sides[i], want, rtol=0, atol=1e-12)


def test_clearest_sides_of_one_segment_and_of_two_rails():
    assert np.allclose(clearest_sides([[[0.0, 0.0], [1.0, 0.0]]]), [[0.5, 0.25]])     # nothing near: the first
    assert clearest_sides([[[0.0, 0.0], [2.0, 0.0]], [[0.0, 1.0], [2.0, 1.0]]]).tolist() == [[1.0, -0.5],
                                                                                            [1.0, 1.5]]


@pytest.mark.parametrize("seed", range(5))
def test_pin_heads_pick_the_spot_along_each_force_clearest_of_the_obstacles(seed):
    rng = np.random.default_rng(10 + seed)
    obstacles = rng.uniform(-2, 2, (6, 2, 2))
    forces = [SimpleNamespace(point=tuple(rng.uniform(-1, 1, 2)), wrench=tuple(rng.normal(size=3)))
              for _ in range(9)] + [SimpleNamespace(point=(0.3, 0.2), wrench=(0.0, 0.0, 1.0))]   # a couple
    spots = (0.4, -0.4, 0.25, -0.25)
    heads = pin_heads(forces, spots, obstacles)
    assert heads.shape == (10, 2)
    for x, head in zip(forces, heads):
        fx, fy = x.wrench[0], x.wrench[1]
        F = math.hypot(fx, fy)
        e = (fx / F, fy / F) if F else (0.0, 0.0)
        want, tie = farthest([(x.point[0] + k * e[0], x.point[1] + k * e[1]) for k in spots], obstacles)
        if not tie:
            assert np.allclose(head, want, rtol=0, atol=1e-12)
