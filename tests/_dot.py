"""A toy explorer for the explorer machinery's tests: a dot at (x, y) that cannot be shown past x = 1.5."""
from __future__ import annotations

from planargeo.draw.picture import Picture
from planargeo.errors import SceneError
from planargeo.widgets.base import Explorer, Handle, Step


class Dot(Explorer):
    """A dot at (x, y); x > 1.5 cannot be shown; its handle moves it."""

    limits = (-2, 2, -2, 2)
    units = {"x": "m", "y": "m"}

    def make_controls(self):
        return {"x": Step(-2, 2, 0.1, 0.0, "x").make("x"), "y": Step(-2, 2, 0.1, 0.0, "y").make("y")}

    def scene_picture(self, st, view=None):
        pic = Picture(view or self.limits, size=self.figure_px)
        pic.marks("dot", [[st["x"], st["y"]]], symbol="d", desc="the dot (1.1)")
        return pic

    def compute(self, v, changed):
        if v["x"] > 1.5:
            raise SceneError("x must not exceed 1.5")
        return dict(v)

    def readout_of(self, st):
        return {"x": st["x"], "y": st["y"]}

    def handles(self):
        return [Handle("dot", lambda: (float(self.values["x"]), float(self.values["y"])),
                       lambda x, y: {"x": x, "y": y})]


class PlayingDot(Dot):
    """The dot with Play: it moves right by ``v dt`` and stops past x = 1."""

    def make_controls(self):
        return {**super().make_controls(), "v": Step(-2, 2, 0.1, 1.0, "v").make("v")}

    def play_step(self, values, dt):
        x = values["x"] + values["v"] * dt
        return None if x > 1.0 else {"x": x}
