"""ScrewSumExplorer: the drawn sum follows hand-derived constructions (thesis 4.2, 4.4)."""
import numpy as np
import pytest

from planargeo.widgets.screw_sum import ScrewSumExplorer


def xy(p):
    p = np.asarray(p, float)
    return np.array([-p[1] / p[2], p[0] / p[2]])


@pytest.fixture
def ex():
    return ScrewSumExplorer(display="agg")


def test_two_rotations_lever_rule(ex):
    ex.set(x1=-1.0, y1=0.5, size1=1.0, x2=2.0, y2=-1.0, size2=3.0)
    # pole of the sum = weighted mean of the poles (velocity zero there)
    P = (1.0 * np.array([-1.0, 0.5]) + 3.0 * np.array([2.0, -1.0])) / 4.0
    assert ex.readout_values["case"] == "rotations"
    assert ex.readout_values["β"] == pytest.approx(0.75)
    assert ex.readout_values["pole of sum"] == pytest.approx(tuple(P))
    assert xy(ex.p3.get_point()) == pytest.approx(P)
    # the pole lies on the drawn join of the two poles (incidence, 5.24)
    assert np.dot(ex.p3.get_point(), ex.join.get_line()) == pytest.approx(0.0, abs=1e-12)


def test_opposite_rotations_give_a_translation(ex):
    ex.set(x1=0.0, y1=0.0, size1=1.0, x2=2.0, y2=0.0, size2=-1.0)
    assert ex.readout_values["case"] == "opposite_rotations"
    assert ex.readout_values["pole of sum"] == "at infinity"
    # velocity of the sum at the origin: rotation about (2, 0) with ω=-1 gives (0, 2)
    assert ex.readout_values["sum"] == pytest.approx((0.0, 2.0, 0.0))
    assert ex.p3.get_point()[2] == 0.0 and ex.p3.get_visible()
    ex.fig.canvas.draw()


def test_rotation_plus_translation(ex):
    ex.set(kind2="translation", x1=0.5, y1=0.0, size1=2.0, size2=3.0, angle2=0.0)
    # P = Q + (u/ω) (e turned +90°) = (0.5, 0) + 1.5 (0, 1)
    assert ex.readout_values["ρ"] == pytest.approx(1.5)
    assert ex.readout_values["pole of sum"] == pytest.approx((0.5, 1.5))


def test_wrenches_concurrent_parallel_couple(ex):
    ex.set(add="wrenches")
    assert ex.values["kind1"] == "force" and ex.values["kind2"] == "force"
    ex.set(x1=-1.0, y1=0.0, size1=1.0, angle1=0.0, x2=2.0, y2=1.0, size2=2.0, angle2=90.0)
    assert ex.readout_values["case"] == "concurrent"
    assert ex.readout_values["meet of lines"] == pytest.approx((2.0, 0.0))
    L3 = ex.l3.get_line()
    assert L3[:2] == pytest.approx([1.0, 2.0])
    assert np.dot([0.0, -2.0, 1.0], L3) == pytest.approx(0.0, abs=1e-12)  # passes through (2, 0)
    # parallel forces, lever rule: 1 N at x=-1 and 3 N at x=3, both along +y -> line x = 2
    ex.set(angle1=90.0, size2=3.0, x2=3.0)
    assert ex.readout_values["case"] == "parallel"
    L3 = ex.l3.get_line()
    assert L3[:2] == pytest.approx([0.0, 4.0])
    assert L3[2] / L3[1] == pytest.approx(2.0)        # tz + y fx - x fy = 0  ->  x = tz / fy
    # equal and opposite: moments x fy about the origin, -1 * 1 + 3 * (-1) = -4
    ex.set(size2=-1.0)
    assert ex.readout_values["case"] == "couple"
    assert ex.readout_values["sum"] == pytest.approx((0.0, 0.0, -4.0))
    ex.fig.canvas.draw()


def test_force_plus_couple(ex):
    ex.set(add="wrenches", kind2="couple", x1=0.0, y1=0.0, angle1=0.0, size1=2.0, size2=1.0)
    assert ex.readout_values["case"] == "force_couple"
    assert ex.readout_values["ρ"] == pytest.approx(0.5)


def test_zero_screw_is_a_message_not_an_exception(ex):
    good = dict(ex.readout_values)
    ex.controls["size2"].value = 0.0
    assert "v2" in ex.message and "non-zero" in ex.message
    assert ex.readout_values == good
    assert ex._msg_text.get_visible()
    ex.controls["size2"].value = 1.0
    assert ex.message == "" and not ex._msg_text.get_visible()


def test_meet_of_forces_on_one_line_is_not_at_infinity(ex):
    # two forces along the x-axis: their lines coincide, so they meet at every point of it
    ex.set(add="wrenches", kind1="force", kind2="force", x1=0.0, y1=0.0, angle1=0.0, size1=1.0,
           x2=1.5, y2=0.0, angle2=0.0, size2=-1.0)
    assert ex.readout_values["case"] == "zero"
    assert ex.readout_values["meet of lines"] == "every point of their common line"
    ex.set(size2=-2.0)                                 # unequal: a force on the same line
    assert ex.readout_values["case"] == "parallel"
    assert ex.readout_values["meet of lines"] == "every point of their common line"
    assert ex.readout_values["sum"] == pytest.approx((-1.0, 0.0, 0.0), abs=1e-12)
    # distinct parallel lines (y = 0 and y = 1) do meet at infinity
    ex.set(y2=1.0)
    assert ex.readout_values["meet of lines"] == "at infinity"
    # crossing lines meet at a finite point: the x-axis and the vertical through x = 1.5
    ex.set(y2=0.0, angle2=90.0, size2=1.0)
    assert ex.readout_values["meet of lines"] == pytest.approx((1.5, 0.0))
