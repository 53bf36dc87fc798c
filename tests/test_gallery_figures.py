"""The gallery's figure scaffolding: register (caption = docstring), new_figure, the shared models."""
from __future__ import annotations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from planargeo.errors import PlanargeoError  # noqa: E402
from planargeo.gallery import figures  # noqa: E402
from planargeo.mechanics.model import chain_model  # noqa: E402


@pytest.fixture
def registry(monkeypatch):
    """An empty registry, so that test figures never reach the gallery."""
    monkeypatch.setattr(figures, "REGISTRY", {})
    return figures


def test_register_names_the_figure_after_the_function_and_captions_it_with_the_docstring(registry):
    @registry.register(7.5, height=2.0, nrows=2)
    def fig7_99(axs):
        """Fig. 7.99 — two panels:
        a line
        and a point (7.1)."""
        axs[0].plot([0, 1], [0, 1])
        axs[1].plot([0.5], [0.5], "o")

    spec = registry.REGISTRY["fig7_99"]
    assert spec.caption == "Fig. 7.99 — two panels: a line and a point (7.1)."
    assert spec.order == 7.5
    fig = spec.build()
    try:
        assert tuple(fig.get_size_inches()) == (3.4, 2.0)
        assert len(fig.axes) == 2 and [len(ax.lines) for ax in fig.axes] == [1, 1]
        assert all(ax.get_aspect() == 1.0 and not ax.get_xticks().size for ax in fig.axes)
    finally:
        plt.close(fig)


def test_register_without_docstring_is_an_error(registry):
    with pytest.raises(PlanargeoError, match="fig0_1 has no caption"):
        @registry.register(0.1)
        def fig0_1(ax):
            pass
    assert registry.REGISTRY == {}


def test_new_figure_chart_and_polar_layouts():
    fig, ax = figures.new_figure(2.3, margins=(0.17, 0.97, 0.19, 0.95))
    try:
        box = ax.get_position()
        np.testing.assert_allclose([box.x0, box.x1, box.y0, box.y1], [0.17, 0.97, 0.19, 0.95])
        assert ax.get_aspect() == "auto"
    finally:
        plt.close(fig)
    fig, ax = figures.new_figure(3.0, polar=[0.1, 0.1, 0.66, 0.8])
    try:
        assert ax.name == "polar" and tuple(fig.get_size_inches()) == (3.4, 3.0)
    finally:
        plt.close(fig)


@pytest.mark.parametrize("n", [1, 3, 4])
def test_chain_is_the_unit_chain_of_mechanics(n):
    """figures.chain(n) is mechanics' chain_model(n) (the independent builder) with bodies named 1…n."""
    m, ref = figures.chain(n), chain_model(n, gravity=(0.0, 0.0))
    assert [b.name for b in m.bodies] == [str(i + 1) for i in range(n)]
    for b, r in zip(m.bodies, ref.bodies):
        np.testing.assert_array_equal(b.spatial_inertia(), r.spatial_inertia())
    assert [(j.kind, j.placement) for j in m.joints] == [(j.kind, j.placement) for j in ref.joints]
    assert list(m.parents) == list(ref.parents)


def test_chain_options():
    m = figures.chain(3, base="plane", gravity=(0.0, -9.81), tip_com=0.4)
    assert m.joints[0].kind == "plane" and [j.kind for j in m.joints[1:]] == ["revolute"] * 2
    assert [tuple(b.com) for b in m.bodies] == [(0.5, 0.0), (0.5, 0.0), (0.4, 0.0)]
    np.testing.assert_array_equal(m.gravity, [0.0, -9.81])
