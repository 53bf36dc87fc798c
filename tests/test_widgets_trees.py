"""TreeExplorer: the closed loops hold (pin points share accelerations), forces pass the pins."""
import numpy as np
import pytest

from planargeo.widgets.trees import TreeExplorer


def point_accel(a, p):
    """Acceleration of the body point at p from a spatial acceleration twist at rest (like 4.5)."""
    ax, ay, al = a
    return np.array([ax - al * p[1], ay + al * p[0]])


def pin_points(ex):
    d = ex.state["res"].extra["solution"].data
    pose = d.pose
    return pose[:, :2] + np.column_stack([np.cos(pose[:, 2]), np.sin(pose[:, 2])])


@pytest.fixture
def ex():
    return TreeExplorer(display="agg", speed=0.0)


def test_loops_close_at_rest(ex):
    a = np.asarray(ex.state["res"].quantities["a"]).reshape(9, 3)
    tips = pin_points(ex)
    for i, j in ((3, 6), (7, 8)):
        assert tips[i] == pytest.approx(tips[j], abs=1e-12)
        assert point_accel(a[i], tips[i]) == pytest.approx(point_accel(a[j], tips[j]), abs=1e-9)
    assert ex.readout_values["degrees of freedom"] == 5


def test_contact_forces_pass_through_the_pins(ex):
    tips = pin_points(ex)
    for k, i in enumerate((3, 7)):
        F = ex.F_art[k].get_line()
        x, y = tips[i]
        assert ex.F_art[k].get_visible()
        assert np.dot([y, -x, 1.0], F) == pytest.approx(0.0, abs=1e-9 * (1 + np.abs(F).max()))
        assert ex.readout_values[list(ex.readout_values)[3 + k]] == pytest.approx(np.hypot(F[0], F[1]))
    ex.fig.canvas.draw()


def test_opening_the_loops_changes_the_motion(ex):
    closed = dict(ex.readout_values)
    ex.controls["loops"].value = "open (Fig 9.1)"
    assert ex.readout_values["degrees of freedom"] == 9
    assert not any(a.get_visible() for a in ex.F_art)
    a = np.asarray(ex.state["res"].quantities["a"]).reshape(9, 3)
    tips = pin_points(ex)
    assert not np.allclose(point_accel(a[3], tips[3]), point_accel(a[6], tips[6]))   # tips drift apart
    assert ex.readout_values["qdd[1] (root)"] != closed["qdd[1] (root)"]


def test_overlays_and_speed(ex):
    ex.set(speed=1.5, **{"velocity poles": True, "acceleration poles": True})
    assert all(a.get_visible() for a in ex.v_art + ex.a_art)
    assert ex.message == ""
    ex.fig.canvas.draw()
