"""Every explorer is legible as shown (issue 13): text ≥ 11 px, labels apart and inside the axes.

The check is :func:`planargeo.draw.layout.legibility_problems` on the figure as
the notebook shows it (native size).  It runs on every registered explorer
(``planargeo.widgets.EXPLORERS``, including ones added later) in its default
state, and on the states the tests of the projective and percussion
explorers visit.  Also here: the check itself, sizes, units and round-off.
"""
from __future__ import annotations

import ipywidgets as W
import matplotlib
import pytest
from matplotlib.figure import Figure

import planargeo.widgets as widgets
from planargeo.draw.layout import legibility_problems
from planargeo.draw.style import EXPLORER_MIN_WIDTH_PX
from planargeo.errors import InputError
from planargeo.widgets.base import Step, fmt

#: explorers known to fail, with the reason (none: every explorer's default state is legible)
KNOWN: dict[str, str] = {}


def _params():
    out = []
    for name in sorted(widgets.EXPLORERS):
        marks = [pytest.mark.xfail(reason=KNOWN[name], strict=False)] if name in KNOWN else []
        out.append(pytest.param(name, id=name, marks=marks))
    return out


def _shown(ex):
    """The explorer's picture as matplotlib draws it (exports, the stored image)."""
    from planargeo.draw.render import figure

    return figure(ex.picture())


@pytest.mark.parametrize("name", _params())
def test_default_state_is_legible(name):
    ex = getattr(widgets, name)(display="agg")
    assert ex.message == ""
    assert legibility_problems(_shown(ex)) == []


@pytest.mark.parametrize("name", sorted(widgets.EXPLORERS))
def test_figure_fills_the_notebook_column(name):
    ex = getattr(widgets, name)(display="agg")
    w, h = ex.figure_px
    assert w >= EXPLORER_MIN_WIDTH_PX


@pytest.mark.parametrize("name", sorted(widgets.EXPLORERS))
def test_image_is_shown_at_its_native_width_and_scales_down(name):
    ex = getattr(widgets, name)(display="image")
    assert ex.image.layout.width == f"{ex.figure_px[0]}px" and ex.image.layout.max_width == "100%"


#: explorers of other helpers whose defaults are off their slider grid (the integrator removes these)
OFF_GRID: dict[str, str] = {}


@pytest.mark.parametrize("name", [
    pytest.param(n, id=n, marks=[pytest.mark.xfail(reason=OFF_GRID[n], strict=False)] if n in OFF_GRID
                 else []) for n in sorted(widgets.EXPLORERS)])
def test_slider_defaults_are_on_their_grid(name):
    """A default the browser's slider cannot show (9.81 on a 0.05 grid reads 9.80) is not allowed."""
    ex = getattr(widgets, name)(display="agg")
    for k, w in ex.controls.items():
        if isinstance(w, W.FloatSlider) and w.step:
            steps = (ex.defaults[k] - w.min) / w.step
            assert abs(steps - round(steps)) < 1e-6, (k, w.value, w.min, w.step)


def test_a_default_off_the_grid_gets_a_finer_step():
    w = Step(0.0, 20.0, 0.1, 9.81, "g").make("g")
    assert w.step == pytest.approx(0.01) and w.readout_format == ".2f"


def test_layout_is_stable():
    ex = widgets.ProjectiveExplorer(display="image")
    assert ex.readout.layout.width == f"{ex.figure_px[0]}px"
    assert ex.message_box.layout.min_height == "2.8em"       # two lines reserved (grows for more)
    ex.set(**{"P at infinity": True, "P x": 0.0, "P y": 0.0})                  # refused
    assert ex.message and ex.message_box.layout.min_height == "2.8em"


# -------------------------------------------------------------- states the explorer tests visit
PROJECTIVE_STATES = [
    {},
    {"P x": 0.1, "P y": 0.1},
    {"P x": -3.5, "P y": 3.2},
    {"P at infinity": True},
    {"M at infinity": True},
    {"conic": "circle"},
    {"conic": "hyperbola"},
    {"conic": "parabola"},
    {"conic": "inertia (imaginary circle)"},
    {"key": True},
    {"line offset": 3.9, "line angle (deg)": 0.0},
]


@pytest.mark.parametrize("values", PROJECTIVE_STATES, ids=str)
def test_projective_states_are_legible(values):
    ex = widgets.ProjectiveExplorer(display="agg")
    ex.set(**values)
    assert ex.message == ""
    assert legibility_problems(_shown(ex)) == []


def test_projective_after_drags_is_legible():
    ex = widgets.ProjectiveExplorer(display="agg")
    h = {x.name: x for x in ex.handles()}
    ex.drag("P", h["P"].where(), (0.5, -0.3), steps=3)
    assert legibility_problems(_shown(ex)) == []
    h = {x.name: x for x in ex.handles()}
    ex.drag("pole of M", h["pole of M"].where(), (0.5, 0.7), steps=3)
    assert legibility_problems(_shown(ex)) == []


PERCUSSION_STATES = [
    {},
    {"shape": "uniform rod"},
    {"shape": "disc"},
    {"shape": "L-shape"},
    {"pole x": -0.4, "pole y": 0.3},
    {"pole x": 1.2, "pole y": -0.5},
    {"pole x": 0.5, "pole y": 0.9},
    {"drive": "impact"},
    {"drive": "impact", "impact at": 1.2},
    {"key": True},
]


@pytest.mark.parametrize("values", PERCUSSION_STATES, ids=str)
def test_percussion_states_are_legible(values):
    ex = widgets.PercussionExplorer(display="agg")
    ex.set(**values)
    assert ex.message == ""
    assert legibility_problems(_shown(ex)) == []


# -------------------------------------------------------------- the check itself
def _fig():
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    fig = Figure(figsize=(4, 3), dpi=100)
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    ax.tick_params(labelsize=9)
    return fig, ax


def test_check_passes_a_clean_figure():
    fig, ax = _fig()
    ax.text(0.2, 0.5, "P", fontsize=9)
    ax.text(0.7, 0.5, "Q", fontsize=9)
    assert legibility_problems(fig) == []


def test_check_finds_small_text_overlap_and_labels_outside():
    fig, ax = _fig()
    ax.text(0.2, 0.5, "tiny", fontsize=6)
    ax.text(0.6, 0.5, "polar of P", fontsize=9)
    ax.text(0.62, 0.5, "pole of M", fontsize=9)
    ax.text(1.3, 0.5, "away", fontsize=9)
    found = legibility_problems(fig)
    assert any("'tiny'" in p and "px high" in p for p in found)
    assert any("'polar of P'" in p and "'pole of M'" in p and "overlap" in p for p in found)
    assert any("'away'" in p and "leaves the axes" in p for p in found)
    # shown at twice the size, 6 pt at 100 dpi is 16.7 px: legible
    assert not any("'tiny'" in p for p in legibility_problems(fig, scale=2.0))


def test_check_arguments():
    fig, _ = _fig()
    with pytest.raises(InputError, match="scale"):
        legibility_problems(fig, scale=0)


# -------------------------------------------------------------- units and round-off
def test_round_off_prints_as_zero_relative_to_the_scene_scale():
    assert fmt(-1.2e-16, zero=1e-9) == "0"
    assert fmt(-1.2e-16) == "-1.2×10⁻¹⁶"
    assert fmt((2.0, 3e-13), zero=1e-9) == "(2, 0)"


def test_readout_shows_units_and_zero():
    ex = widgets.PercussionExplorer(display="agg", shape="uniform rod")
    s = ex.readout_strings
    assert s["mass m"] == "1 kg" and s["radius of gyration ρ"].endswith(" m")
    assert s["centre of mass"] == "(0.5, 0) m"        # y of the centre: round-off shown as 0
    assert s["force for α: m d α (5.66)"] == "5 N"
    assert "<td" in ex.readout.value and ">kg<" in ex.readout.value


def test_use_widget_backend_changes_nothing():
    """Notebooks still call it first: explorers are drawn by the page, matplotlib's backend is left alone."""
    backend = matplotlib.get_backend()
    assert widgets.use_widget_backend() == "page"
    assert matplotlib.get_backend() == backend
