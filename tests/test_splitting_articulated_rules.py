"""Splitting and articulated explorers against the rules of issues 22 and 23: controls that follow n
(or say why they do nothing), round-off that reads 0, views that hold the folded chain, no value
silently replaced, one state per set of controls, readable and explained symbols."""
import math

import numpy as np
import pytest

from _picture_checks import elements
from planargeo.errors import InputError
from planargeo.widgets.articulated import ArticulatedExplorer
from planargeo.widgets.splitting import SplittingExplorer


# ------------------------------------------------------------------------------------ splitting
def test_split_is_disabled_for_two_bodies_and_its_range_follows_n():
    ex = SplittingExplorer(display="agg")
    assert ex.values["bodies n"] == 2
    assert "only joint" in ex.disabled(ex.values)["split at joint"]
    with pytest.raises(InputError, match="cannot be dragged"):
        ex.drag("split", tuple(ex.state["joints"][1]), (2.0, 0.0))
    ex.set(**{"bodies n": 5})
    assert ex.disabled(ex.values) == {} and ex.controls["split at joint"].max == 5
    ex.set(**{"split at joint": 5})                     # the slider's end is the last joint
    assert ex.message == "" and ex.readout_values["split at joint"] == 5
    x, y = ex.state["joints"][2]
    ex.drag("split", tuple(ex.state["joints"][4]), (x, y), steps=2)   # the handle moves the split
    assert ex.values["split at joint"] == 3 and ex.readout_values["split at joint"] == 3
    ex.set(**{"bodies n": 2})
    assert ex.values["split at joint"] == 2 and ex.controls["split at joint"].max == 2


@pytest.mark.parametrize("end", [(9.0, 0.0), (40.0, 0.0), (-9.0, 0.0)])
def test_a_far_drag_along_the_chain_reads_zero_not_round_off(end):
    ex = SplittingExplorer(display="agg")
    h = ex._handle("tip")
    ex.drag("tip", h.where(), end, steps=4)
    assert ex.message == ""
    assert ex.values["bend φ (deg)"] == (0.0 if end[0] > 0 else -180.0)   # straight or folded, exactly
    for k, text in ex.readout_strings.items():
        assert "e-0" not in text and "e-1" not in text, (k, text)
    assert ex.readout_strings["fᵢ₊₁ (7.56)"].startswith("(0 N,")


@pytest.mark.parametrize("n", [2, 3, 5, 8])
@pytest.mark.parametrize("phi", [180.0, -180.0, 179.5])
def test_the_folded_chain_stays_in_a_view_as_big_as_it(n, phi):
    ex = SplittingExplorer(display="agg", **{"bodies n": n, "bend φ (deg)": phi})
    assert ex.message == ""
    pts = ex.state["joints"]
    x0, x1, y0, y1 = ex.picture()["box"]
    assert np.all((x0 <= pts[:, 0]) & (pts[:, 0] <= x1) & (y0 <= pts[:, 1]) & (pts[:, 1] <= y1))
    size = max(float(np.max(np.ptp(pts, axis=0))), 1.0)              # at least a body's length
    assert min(x1 - x0, y1 - y0) >= size


def test_splitting_readout_names_units_and_points():
    ex = SplittingExplorer(display="agg", **{"bodies n": 3})
    r, units = ex.readout_values, ex.units
    for name in ("aᵢ (7.54)", "aᵢ₊₁", "fᵢ₊₁ (7.56)", "bᵢ", "aₙ (tip)", "row 1 of Λᵢ⁻¹"):
        assert len(r[name]) == 3 and len(units[name]) == 3, name
    assert units["aᵢ (7.54)"] == ("m/s²", "m/s²", "rad/s²") and units["fᵢ₊₁ (7.56)"] == ("N", "N", "N·m")
    assert not any("_" in k or "[" in k for k in r)
    # a pole is its acceleration's point (thesis 5.49): x = −a_y/α, y = a_x/α
    a = r["aᵢ₊₁"]
    x, y = -a[1] / a[2], a[0] / a[2]
    assert abs(y) < 1e-12 and r["pole of aᵢ₊₁"] == f"({x:.4g}, 0) m"      # on the x axis; round-off reads 0
    words = ex.explain()
    assert all(k in words for k in r)
    ex.set(**{"bend φ (deg)": 180.0, "bodies n": 5})                  # bodies that do not accelerate
    assert ex.message == "" and ex.readout_values["pole of aᵢ"] == "none: no acceleration"


# ------------------------------------------------------------------------------------ articulated
def test_outboard_bodies_follow_n():
    ex = ArticulatedExplorer(display="agg")
    w = ex.controls["outboard bodies"]
    assert (ex.values["outboard bodies"], w.max) == (3, 3)
    assert ex.readout_values["outboard included"] == "3 of 3"
    ex.set(**{"bodies n": 8})                                         # "all" stays all
    assert (ex.values["outboard bodies"], w.max) == (7, 7)
    assert ex.readout_values["outboard included"] == "7 of 7"
    ex.set(**{"outboard bodies": 2})
    ex.set(**{"bodies n": 3})
    assert (ex.values["outboard bodies"], w.max) == (2, 2)
    assert ex.readout_values["outboard included"] == "2 of 2"
    ex.set(**{"bodies n": 6, "outboard bodies": 5})               # both at once: the new n's range
    assert ex.message == "" and (ex.values["outboard bodies"], w.max) == (5, 5)
    ex.set(**{"bodies n": 2, "outboard bodies": 5})               # beyond the new n: follows it
    assert ex.message == "" and (ex.values["outboard bodies"], w.max) == (1, 1)
    ex.set(**{"bodies n": 1})
    assert "no body outboard" in ex.disabled(ex.values)["outboard bodies"]


def test_focus_options_follow_n_and_a_focus_shows_its_own_body():
    ex = ArticulatedExplorer(display="agg", **{"bodies n": 8, "focus": "body 6"})
    assert ex.message == "" and ex.values["focus"] == "body 6"
    assert "A₆" in ex.explain()["Aₖ"] and [q["text"] for q in elements(ex.picture())["A6"]["parts"] if q["p"] == "text"] == ["A₆"]
    ex.set(**{"bodies n": 4})
    assert list(ex.controls["focus"].options) == ["all", "body 1", "body 2", "body 3", "body 4"]
    assert ex.values["focus"] == "all"                                # body 6 is gone: not body 4


def test_a_time_given_to_the_constructor_is_computed_not_replaced():
    ex = ArticulatedExplorer(display="agg", **{"time (s)": 13.5})
    assert ex.message == "" and ex.values["time (s)"] == 13.5 and ex.readout_values["t"] == 13.5
    r = ex.readout_values
    assert r["T + V + W"] == pytest.approx(r["initial energy E₀"], abs=1e-6 * abs(r["initial energy E₀"]))
    assert r["dissipated W"] > 1.0                                     # the damping worked for 13.5 s
    # Play to the same time in uneven steps shows the same state
    played = ArticulatedExplorer(display="agg")
    vals, rng = dict(played.values), np.random.default_rng(5)
    while vals["time (s)"] < 13.5:
        vals.update(played.play_step(vals, min(float(rng.uniform(0.001, 1 / played.play_fps)),
                                               13.5 - vals["time (s)"])))
    played.set(**{"time (s)": vals["time (s)"]})
    assert played.readout_values["t"] == pytest.approx(13.5, abs=1e-9)
    np.testing.assert_allclose(played.state["q"], ex.state["q"], rtol=0, atol=1e-9)


def test_a_change_of_the_chain_starts_the_swing_again_unless_the_time_comes_with_it():
    ex = ArticulatedExplorer(display="agg")
    ex.set(**{"time (s)": 2.0})
    ex.set(**{"damping c": 0.1})
    assert ex.values["time (s)"] == 0.0
    ex.set(**{"damping c": 0.2, "time (s)": 3.0})
    assert ex.values["time (s)"] == 3.0 and ex.readout_values["t"] == 3.0


def test_articulated_names_are_readable_and_k_is_defined():
    ex = ArticulatedExplorer(display="agg")
    words = ex.explain()
    assert "k" in words and "focused body" in words["k"]
    for name, value in ex.readout_values.items():
        assert "_" not in name and name in words, name
        if isinstance(value, float):
            assert ex.units.get(name), name
    assert ex.readout_values["pole a"] == "(0, -0.8) m"
    assert ex.readout_values["effective centre of Aₖ"].endswith(" m")
    ex.set(**{"damping c": 1.5})                                      # the damping shows at rest too
    assert ex.readout_values["damping power at 1 rad/s in every joint"] == pytest.approx(4 * 1.5)


def test_sixty_seconds_of_swing_keep_the_energy_balance():
    ex = ArticulatedExplorer(display="agg")
    vals = dict(ex.values)
    while vals["time (s)"] < 60.0:
        vals.update(ex.play_step(vals, 1.0 / ex.play_fps))
    ex.set(**{"time (s)": vals["time (s)"]})
    r = ex.readout_values
    assert ex.message == "" and r["t"] >= 60.0
    assert abs(r["T + V + W"] - r["initial energy E₀"]) < 1e-6 * abs(r["initial energy E₀"])
    fresh = ArticulatedExplorer(display="agg", **ex.values)
    for k, v in r.items():
        if isinstance(v, float):
            assert fresh.readout_values[k] == pytest.approx(v, rel=1e-12, abs=1e-12), k
        else:
            assert fresh.readout_values[k] == v, k
    assert math.isclose(fresh.picture()["box"][0], ex.picture()["box"][0])
