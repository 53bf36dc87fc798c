"""Behaviour shared by every explorer: construction, fuzzed controls, errors, export, the page."""
import subprocess
import sys
import textwrap
from pathlib import Path

import ipywidgets as W
import pytest

import planargeo.widgets as widgets
from planargeo.draw.picture import Picture
from planargeo.errors import InputError, OutputError, SceneError
from planargeo.widgets.base import Explorer, Step, fmt

NAMES = sorted(widgets.EXPLORERS)


def _values_for(w):
    if isinstance(w, (W.FloatSlider, W.IntSlider)):
        lo, hi = w.min, w.max
        return [lo, hi, w.value]
    if isinstance(w, (W.Dropdown, W.ToggleButtons)):
        return [o if not isinstance(o, tuple) else o[1] for o in w.options] + [w.value]
    if isinstance(w, W.Checkbox):
        return [not w.value, w.value]
    if isinstance(w, W.Text):
        return ["1,2; nonsense", "", w.value]
    return [w.value]


def _draw(ex) -> None:
    """Build what is shown: the picture."""
    assert ex.picture()["elements"]


@pytest.mark.parametrize("name", NAMES)
def test_constructs_with_a_readout(name):
    ex = getattr(widgets, name)(display="agg")
    assert ex.message == "" and ex.readout_values and ex.n_updates == 1
    assert "<table" in ex.readout.value
    assert isinstance(ex.widget, W.VBox) and "planargeo-explorer" in ex.widget._dom_classes


@pytest.mark.parametrize("name", NAMES)
def test_every_control_every_extreme_never_raises(name):
    ex = getattr(widgets, name)(display="agg")
    for cname, w in ex.controls.items():
        if w.disabled:
            continue
        for v in _values_for(w):
            w.value = v                      # must not raise, whatever the value
            assert isinstance(ex.message, str)
            assert not ex.message.startswith("internal error"), (cname, v, ex.message)
        _draw(ex)
    ex.reset()
    assert ex.message == "", ex.message
    assert ex.values == ex.defaults


def test_unknown_control_and_display_are_input_errors():
    with pytest.raises(InputError, match="no control 'nope'"):
        widgets.ScrewSumExplorer(display="agg", nope=1)
    with pytest.raises(InputError, match="display must be one of"):
        widgets.ScrewSumExplorer(display="svg")


class Toy(Explorer):
    """A minimal explorer: a segment from the origin to (a, b); a > b is 'impossible'."""

    def make_controls(self):
        return {"a": Step(-2, 2, 0.1, 0.5, "a").make("a"), "b": Step(-2, 2, 0.1, 1.0, "b").make("b")}

    def scene_picture(self, st, view=None):
        pic = Picture(view or (-2, 2, -2, 2), size=self.figure_px)
        if self.values.get("show", True):
            pic.path("seg", [[0.0, 0.0], [st["a"], st["b"]]], symbol="s", desc="the segment (1.1)")
        return pic

    def compute(self, v, changed):
        if v["a"] > v["b"]:
            raise SceneError("a must not exceed b")
        if v["a"] == -2:
            return {"a": 1 / 0}
        if v["b"] == -2:
            return {"boom": True}
        return dict(v, changed=sorted(changed))

    def readout_of(self, st):
        if st.get("boom"):
            raise KeyError("render failed on purpose")
        return {"a": st["a"], "b": st["b"], "changed": ",".join(st["changed"])}


def _seg(t):
    """The segment's element in the toy's picture (None: not drawn)."""
    return next((e for e in t.picture()["elements"] if e["id"] == "seg"), None)


def _seg_x(t) -> float:
    """The x of the segment's drawn end."""
    xy = _seg(t)["parts"][0]["xy"]
    return xy[-1][0] if isinstance(xy[0], list) else xy[-2]


def test_errors_become_messages_and_keep_the_last_drawing():
    t = Toy(display="agg")
    t.controls["a"].value = 0.8
    assert t.readout_values["a"] == 0.8 and _seg_x(t) == 0.8
    t.controls["a"].value = 1.5                              # a PlanargeoError
    assert t.message == "a must not exceed b (refused: a = 1.5)" and _seg_x(t) == 0.8
    assert t.readout_values["a"] == 0.8 and t.values["a"] == 0.8
    msg = next(e for e in t.picture()["elements"] if e["id"] == "figure message")    # said on the picture
    text = next(p["text"] for p in msg["parts"] if p["p"] == "text")
    assert t.figure_text and text.startswith("a must not exceed b") and msg["fill"] == "white"
    t.controls["a"].value = -2.0                             # ZeroDivisionError in compute
    assert t.message.startswith("cannot compute this configuration")
    t.controls["a"].value = 0.0
    t.controls["b"].value = -2.0 + 0.0                       # a <= b fails first: message
    t.set(a=-1.9, b=-2.0)                                    # still a > b
    assert "exceed" in t.message
    t.set(a=-2.0, b=-2.0)                                    # compute raises ZeroDivisionError
    assert "cannot compute" in t.message
    t.controls["a"].value = 0.3
    t.controls["b"].value = 1.0
    assert t.message == "" and not t.figure_text and t.readout_values["a"] == 0.3
    assert all(e["id"] != "figure message" for e in t.picture()["elements"])


def test_render_errors_are_reported_not_raised():
    t = Toy(display="agg")
    t.set(a=-2.0 + 0.1, b=-2.0 + 0.1)
    t.compute = lambda v, c: {"boom": True}
    t.controls["b"].value = 1.0
    assert t.message.startswith("internal error (KeyError)")
    del t.compute
    t.controls["b"].value = 1.5
    assert t.message == ""


def test_hold_batches_updates():
    t = Toy(display="agg")
    n = t.n_updates
    with t.hold():
        t.controls["a"].value = -1.0
        t.controls["b"].value = 0.0
    assert t.n_updates == n + 1 and t.readout_values["changed"] == "a,b"


def test_export_button(tmp_path):
    t = Toy(display="agg", export_dir=tmp_path)
    t.export_button.click()
    files = list(tmp_path.glob("*.svg"))
    assert len(files) == 1 and str(files[0]) in t.export_label.value
    assert "<svg" in files[0].read_text()


def test_reset_button():
    t = Toy(display="agg", a=-1.0)
    assert t.defaults["a"] == -1.0
    t.set(a=0.2, b=0.4)
    t.reset_button.click()
    assert t.values == {"a": -1.0, "b": 1.0, "key": False} and t.readout_values["a"] == -1.0


def test_image_display_renders_png():
    t = Toy(display="image")
    first = bytes(t.image.value)
    assert first.startswith(b"\x89PNG")
    t.controls["b"].value = -0.5
    assert bytes(t.image.value) != first


def test_fmt():
    assert fmt(float("inf")) == "∞" and fmt(0.0) == "0" and fmt(True) == "yes"
    assert fmt(1234567.0) == "1.235×10⁶" and fmt((1.0, 2.5)) == "(1, 2.5)" and fmt("<b>") == "&lt;b&gt;"


def test_every_explorer_is_drawn_by_the_page_without_a_figure():
    """Old notebooks asking for display='ipympl' get the page too; no matplotlib figure, ipympl not needed."""
    code = textwrap.dedent("""
        import sys
        import planargeo.widgets as widgets
        from planargeo.widgets.canvas import PictureCanvas
        assert widgets.use_widget_backend() == "page"
        def inside(w, c):
            return w is c or any(inside(k, c) for k in getattr(w, "children", ()))
        for name in widgets.EXPLORERS:
            for display in ("auto", "ipympl", "page"):
                ex = getattr(widgets, name)(display=display)
                assert ex.message == "" and ex.display_mode == "page", (name, ex.message)
                assert isinstance(ex.canvas, PictureCanvas) and inside(ex.widget, ex.canvas)
                assert not hasattr(ex, "fig") and ex.canvas.picture["elements"]
        assert "ipympl" not in sys.modules and "matplotlib.pyplot" not in sys.modules
        print("ok")
    """)
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0 and r.stdout.strip().endswith("ok"), r.stderr[-2000:]


# ----------------------------------------------------------------- display-only controls
class ToyOverlay(Toy):
    """Toy with a display-only checkbox: it hides the segment, changes nothing computed."""

    display_controls = ("show",)

    def make_controls(self):
        c = super().make_controls()
        c["show"] = W.Checkbox(value=True, description="show")
        return c



def test_display_only_control_redraws_without_computing():
    t = ToyOverlay(display="agg")
    assert t.n_computes == 1
    state = t.state
    t.controls["show"].value = False
    assert t.n_computes == 1 and t.n_updates == 2 and t.state is state
    assert _seg(t) is None
    t.controls["show"].value = True
    assert _seg(t) is not None and t.n_computes == 1
    t.controls["a"].value = 0.7                                # physics: one compute
    assert t.n_computes == 2 and _seg_x(t) == 0.7
    with t.hold():                                              # mixed changes: one compute
        t.controls["show"].value = False
        t.controls["b"].value = 1.5
    assert t.n_computes == 3 and t.readout_values["changed"] == "b,show"


def test_display_toggle_after_a_refused_value_redraws_the_shown_state():
    t = ToyOverlay(display="agg")
    t.controls["a"].value = 1.5                                 # a > b: refused, a back to 0.5
    assert t.values == t.shown_values and t.values["a"] == 0.5
    n = t.n_computes
    t.controls["show"].value = False                            # the shown state is current
    assert t.n_computes == n and t.message == "" and _seg(t) is None
    t.controls["show"].value = True
    assert _seg_x(t) == 0.5
    t.controls["show"].value = False
    t.controls["a"].value = 0.2
    assert t.message == "" and _seg(t) is None


def test_display_controls_must_name_controls():
    class Bad(ToyOverlay):
        display_controls = ("shwo",)

    with pytest.raises(InputError, match="display_controls names no control 'shwo'"):
        Bad(display="agg")


def _change_and_restore(w, check) -> bool:
    """Give control ``w`` another value, call ``check()``, give it back its own; False if it has no other.

    A choice (Dropdown, ToggleButtons, RadioButtons: anything with ``options``)
    moves to another option by its ``index``; a Checkbox or ToggleButton flips;
    a slider goes to its max (its min when already there).
    """
    if hasattr(w, "options") and hasattr(w, "index"):
        if len(w.options) < 2:
            return False
        old = w.index
        w.index = (old + 1) % len(w.options)
        check()
        w.index = old
        return True
    old = w.value
    if isinstance(old, bool):
        w.value = not old
    else:
        w.value = w.max if old != w.max else w.min
    check()
    w.value = old
    return True


def test_change_and_restore_handles_every_kind_of_display_control():
    kinds = [W.Checkbox(value=False), W.ToggleButton(value=True), W.Dropdown(options=["all", "1", "2"]),
             W.ToggleButtons(options=[("a", 1), ("b", 2)]), W.RadioButtons(options=["x", "y"]),
             W.FloatSlider(value=0.5, min=0.0, max=1.0), W.IntSlider(value=3, min=0, max=3)]
    for w in kinds:
        before, seen = w.value, []
        assert _change_and_restore(w, lambda: seen.append(w.value))
        assert seen and seen[0] != before and w.value == before
    assert not _change_and_restore(W.Dropdown(options=["only"]), lambda: None)


@pytest.mark.parametrize("name", [n for n in NAMES if getattr(widgets, n).display_controls])
def test_every_display_control_skips_the_compute(name):
    ex = getattr(widgets, name)(display="agg")
    calls = []
    real = ex.compute
    ex.compute = lambda v, changed: calls.append(set(changed)) or real(v, changed)
    changed = 0
    for cname in ex.display_controls:
        w = ex.controls[cname]
        if not _change_and_restore(w, lambda: ex.message == "" or pytest.fail(f"{cname}: {ex.message}")):
            continue
        changed += 1
    assert changed >= 1
    assert calls == []
    assert ex.n_updates == 1 + 2 * changed
    _draw(ex)
    # every other control still recomputes
    physics = next(k for k, w in ex.controls.items()
                   if k not in ex.display_controls and isinstance(w, W.FloatSlider))
    w = ex.controls[physics]
    w.value = w.min + 0.5 * (w.max - w.min)
    assert calls == [{physics}]


# ----------------------------------------------------------------- export, every explorer
@pytest.mark.parametrize("name", NAMES)
def test_export_svg_every_explorer_writes_the_current_view(name, tmp_path):
    import xml.etree.ElementTree as ET

    ex = getattr(widgets, name)(display="agg", export_dir=tmp_path)
    ex.export_button.click()
    first = ex.last_export
    assert first is not None and first.parent == tmp_path.resolve()
    assert "saved" in ex.export_label.value and str(first) in ex.export_label.value
    root = ET.parse(first).getroot()
    assert root.tag.endswith("svg")
    w_in, h_in = (v / ex.dpi for v in ex.figure_px)
    assert float(root.get("width").rstrip("pt")) == pytest.approx(72 * w_in)
    assert float(root.get("height").rstrip("pt")) == pytest.approx(72 * h_in)
    ex.export_button.click()                          # the same view: the same file
    assert ex.last_export != first and ex.last_export.read_text() == first.read_text()
    # move the float sliders in turn (one that moves the drawing, not only values): the next
    # export shows the new view
    n = 2
    for slider in (w for w in ex.controls.values() if isinstance(w, W.FloatSlider) and not w.disabled):
        slider.value = slider.min + 0.37 * (slider.max - slider.min)
        ex.export_button.click()
        n += 1
        if ex.last_export.read_text() != first.read_text():
            break
    second = ex.last_export
    assert second != first and second.read_text() != first.read_text()
    assert len(list(tmp_path.glob(f"planargeo-{ex.slug}-*.svg"))) == n


def test_display_only_toggle_repaints_the_image():
    t = ToyOverlay(display="image")
    png = t.image.value
    t.controls["show"].value = False
    assert t.n_computes == 1 and t.image.value[:8] == b"\x89PNG\r\n\x1a\n" and t.image.value != png


# ----------------------------------------------------------------- atomic export (issue 16, items 2 and 8)
def test_export_to_a_full_device_is_an_output_error(tmp_path):
    """``export_svg('/dev/full')`` raised a raw OSError; the Export button reports the same as text."""
    t = Toy(display="agg")
    with pytest.raises(OutputError, match="cannot write /dev/full"):
        t.export_svg("/dev/full")
    assert Path("/dev/full").is_char_device()                 # a device is never replaced by a file
    t = Toy(display="agg", export_dir="/dev/full")
    t.export_button.click()                                   # must not raise
    assert "export failed: cannot write /dev/full" in t.export_label.value and t.last_export is None


def test_export_failure_midway_leaves_the_old_file(tmp_path):
    """A write cut short (a file-size limit, as a full disk would) keeps the old file whole."""
    target = tmp_path / "view.svg"
    old = b"<svg>" + b"x" * 66_000 + b"</svg>"
    target.write_bytes(old)
    code = textwrap.dedent(f"""
        import resource, signal
        from planargeo.errors import OutputError
        from planargeo.widgets import ChainExplorer
        ex = ChainExplorer(display="agg", links=10)
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)      # a write past the limit fails (EFBIG)
        resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))
        try:
            ex.export_svg({str(target)!r})
        except OutputError as exc:
            print("OutputError:", exc)
    """)
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0 and r.stdout.startswith(f"OutputError: cannot write {target}"), r.stderr[-2000:]
    assert target.read_bytes() == old
    assert [p.name for p in tmp_path.iterdir()] == ["view.svg"]     # no temporary file left behind
    # without the limit the same export replaces the file in one step
    Toy(display="agg").export_svg(target)
    assert target.read_bytes().lstrip().startswith(b"<?xml") and len(list(tmp_path.iterdir())) == 1


def test_export_path_that_names_no_file_is_an_input_error():
    with pytest.raises(InputError, match="path must be a str or os.PathLike naming a file, got 3"):
        Toy(display="agg").export_svg(3)


def test_a_refused_set_inside_hold_refuses_the_batch_and_keeps_its_message():
    t = Toy(display="agg")
    with t.hold():
        t.controls["a"].value = 0.2
        t.set(b=float("nan"))
    assert t.message == "b must be a number between -2 and 2, got nan"
    assert t.values == t.shown_values and t.values["a"] == 0.5 and t.readout_values["a"] == 0.5


# --------------------------------------------------------------------------- the shared API (issue 22)
class Shape(Explorer):
    """n dots on a circle; a "slide" control that only acts in prismatic mode; focus on a dot."""

    limits = (-2, 2, -2, 2)
    units = {"radius": "m", "centre": "m", "twist": ("m/s", "m/s", "rad/s"), "state": "m",
             "pole": "m"}

    def make_controls(self):
        return {"n": Step(1, 6, 1, 4, "n", integer=True).make("n"),
                "mode": W.Dropdown(options=["revolute", "prismatic"], value="revolute"),
                "slide": Step(-1, 1, 0.1, 0.0, "slide").make("slide"),
                "size": Step(0.1, 1e300, 0.1, 1.0, "size").make("size"),
                "list": W.Text(value="", description="list")}

    def focus_options(self):
        return [f"dot {i + 1}" for i in range(int(self.values["n"]))]

    def disabled(self, values):
        return {} if values["mode"] == "prismatic" else {"slide": "only prismatic joints slide"}

    def explain(self):
        return {"radius": "the circle's radius (thesis 1.1)", "$\\omega_1$": "the first dot's rate"}

    def scene_picture(self, st, view=None):
        import numpy as np

        pic = Picture(view or self.limits, size=self.figure_px)
        t = np.linspace(0.0, 2 * np.pi, st["n"], endpoint=False)
        pic.marks("dots", st["r"] * np.column_stack([np.cos(t), np.sin(t)]), symbol="ω₁",
                  desc="the dots on the circle (1.1)")
        return pic

    def compute(self, v, changed):
        import numpy as np

        r = 1.0 + v["slide"] if v["mode"] == "prismatic" else 1.0
        s = np.float64(v["size"]) * np.float64(1e10)          # overflows for a size beyond 1e298
        return {"r": r, "n": v["n"], "s": float(s)}

    def readout_of(self, st):
        return {"radius": st["r"], "centre": (0.0, 0.0), "twist": (1.0, 2.0, 0.5),
                "state": "at rest", "pole": point_text([1.0, 0.0, 0.0]), "size": st["s"]}


from planargeo.widgets.base import point_text  # noqa: E402


def test_disabled_controls_carry_their_reason_as_tooltip():
    ex = Shape(display="agg")
    assert ex.controls["slide"].disabled and ex.controls["slide"].tooltip == "only prismatic joints slide"
    ex.set(mode="prismatic")
    assert not ex.controls["slide"].disabled and not ex.controls["slide"].tooltip
    ex.set(slide=0.5)
    assert ex.readout_values["radius"] == 1.5


def test_the_key_lists_the_symbols_of_the_picture():
    ex = Shape(display="agg")
    assert not ex.controls["key"].disabled
    assert not any(e["id"].startswith("key ") for e in ex.picture()["elements"])
    ex.set(key=True)
    key = [e for e in ex.picture()["elements"] if e["id"].startswith("key ")]
    assert [p["text"] for e in key for p in e["parts"] if p["p"] == "text"] == ["ω₁: the dots on the circle"]
    assert any(e["id"] == "key panel" and e["fill"] == "white" for e in key)      # on a white panel


def test_explain_panel_lists_every_symbol_readably():
    ex = Shape(display="agg")
    assert "<details" in ex.explain_box.value and "ω₁" in ex.explain_box.value
    assert "the circle&#x27;s radius (thesis 1.1)" in ex.explain_box.value
    assert ex.explain_box in ex.widget.children[1].children[1].children


def test_units_follow_numbers_only_one_per_component():
    ex = Shape(display="agg")
    s = ex.readout_strings
    assert s["radius"] == "1 m" and s["centre"] == "(0, 0) m"
    assert s["twist"] == "(1 m/s, 2 m/s, 0.5 rad/s)"
    assert s["state"] == "at rest"                      # a word takes no unit
    assert s["pole"] == "at infinity (direction (0, 1))"


def test_point_text_tells_ideal_points_by_is_ideal():
    assert point_text([0.0, -2.0, 1.0]) == "(2, 0) m"
    assert point_text([1e-300, 0.0, 1e-300]) == "(0, 1) m"    # a tiny weight is still finite
    assert point_text([3.0, 4.0, 0.0]).startswith("at infinity (direction (-0.8, 0.6")


def test_focus_options_follow_the_values_and_fall_back_to_all():
    ex = Shape(display="agg")
    assert list(ex.controls["focus"].options) == ["all", "dot 1", "dot 2", "dot 3", "dot 4"]
    ex.set(focus="dot 4")
    ex.set(n=2)
    assert ex.message == "" and ex.values["focus"] == "all"
    assert list(ex.controls["focus"].options) == ["all", "dot 1", "dot 2"]
    ex.set(focus="dot 2")
    ex.set(n=5)
    assert ex.values["focus"] == "dot 2" and len(ex.controls["focus"].options) == 6


def test_over_range_numbers_are_refused_in_the_package_words():
    ex = Shape(display="agg")
    ex.set(list="1, 1e150")
    # the numbers as a student reads them (controls.number_text), not 1e+06
    assert ex.message.startswith("list: numbers typed here must lie between -1\u202f000\u202f000 and "
                                 "1\u202f000\u202f000")
    ex.set(size=1e299)                                  # in the slider's range, overflows inside
    assert "size = 1×10²⁹⁹ cannot be computed" in ex.message and "overflow" in ex.message
    assert ex.values["size"] == 1.0 and ex.readout_values["size"] == 1e10


class Moving(Shape):
    def play_step(self, values, dt):
        return {"slide": min(1.0, values["slide"] + dt)}


def test_export_animation_is_bounded_and_mp4_has_its_button(tmp_path):
    import shutil

    ex = Moving(display="agg", mode="prismatic")
    for bad in (0, -1, 2.5, float("nan"), float("inf")):
        with pytest.raises(InputError, match="frames must be a positive integer"):
            ex.export_animation(tmp_path / "a.gif", frames=bad)
    with pytest.raises(InputError, match=r"frames must be at most 1200 \(pass allow_long=True"):
        ex.export_animation(tmp_path / "a.gif", frames=10 ** 6)
    assert not (tmp_path / "a.gif").exists()
    buttons = ex.widget.children[1].children[0].children[-2].children
    assert (ex.export_mp4_button in buttons) == (shutil.which("ffmpeg") is not None)


def test_a_focus_of_the_given_values_is_taken_at_construction():
    ex = Shape(display="agg", n=6, focus="dot 6")
    assert ex.values["focus"] == "dot 6" and ex.message == ""


def test_a_slider_value_set_by_the_page_is_not_echoed_back():
    """The page shows the value it set; the kernel's answer is the new picture, not an echo."""
    from planargeo.widgets.chain import ChainExplorer

    ex = ChainExplorer(display="page")
    slider = ex.controls["angle"]
    sent = []
    slider._send = lambda msg, buffers=None: sent.append(msg)
    before = ex.n_updates
    slider.set_state({"value": 12.0})                    # as the page sends it
    assert slider.value == 12.0 and ex.n_updates == before + 1
    assert not [m for m in sent if m.get("method") == "echo_update"]


class ToyInterrupted(Toy):
    """The toy whose compute is stopped by Ctrl-C when b reaches 1.9 (a long compute interrupted)."""

    def compute(self, v, changed):
        if v["b"] == 1.9:
            raise KeyboardInterrupt
        return super().compute(v, changed)


def test_ctrl_c_in_compute_returns_to_the_shown_state_and_stops():
    """Ctrl-C stops the cell, and the explorer shows what it computed last: control, readout and
    picture agree, with a message saying so; the next value is computed as usual."""
    t = ToyInterrupted(display="agg")
    t.set(b=1.2)
    with pytest.raises(KeyboardInterrupt):
        t.set(b=1.9)
    assert t.controls["b"].value == 1.2 and t.readout_values["b"] == 1.2
    assert _seg(t)["parts"][0]["xy"][-1] == [0.5, 1.2]
    assert "Ctrl-C" in t.message
    t.set(b=1.5)
    assert t.readout_values["b"] == 1.5 and t.message == ""
