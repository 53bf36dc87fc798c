"""From a slider to the pixels: widget → scene → algorithm → draw artist, down the layers, kinematics once.

Issue 12: the path from a widget slider to the pixels passes through at most
five modules and never climbs back; widgets build their state through
``planargeo.scenes``, not algorithms or private helpers, and compute the
kinematics once per frame.

The path is observed, not assumed: :func:`calls_during` runs one control
change under :func:`sys.setprofile` and records every call into a planargeo
function with the chain of planargeo modules on the stack (calls inside one
module collapsed).  The layers are those of ``tests/test_layers.py``.
"""
from __future__ import annotations

import ast
import collections
import sys
from pathlib import Path

import pytest

import planargeo.widgets as widgets
from test_layers import level

WIDGETS = Path(widgets.__file__).parent
#: the modules the explorer base is made of (one job each): on a stack they count as the base
BASE_PARTS = {"planargeo.widgets.controls", "planargeo.widgets.front", "planargeo.widgets.handles",
              "planargeo.widgets.export", "planargeo.widgets.play"}

#: explorer, a physics control and a new value (the update computes a state)
CHANGES = [("ChainExplorer", "angle", 10.0), ("ChainExplorer", "joints", "alternating"),
           ("SliderCrankExplorer", "crank angle (deg)", 30.0), ("TreeExplorer", "speed", 0.5),
           ("TreeExplorer", "loops", "open (Fig 9.1)"), ("CarExplorer", "speed (m/s)", 6.0),
           ("ProjectiveExplorer", "P x", 1.0), ("PercussionExplorer", "pole x", 0.5),
           ("ScrewSumExplorer", "x1", 0.5)]
#: explorers whose state is a mechanism: one kinematics pass per computed state
MECHANISMS = ("ChainExplorer", "SliderCrankExplorer", "TreeExplorer")


def calls_during(action) -> tuple[collections.Counter, set[tuple[str, ...]]]:
    """Run ``action()``; return the entries ``{(caller, module, function): n}`` into planargeo and the stacks.

    An entry is a call from outside the called function's module (calls
    within a module are its own business); ``caller`` is the calling frame's
    module.  A module stack lists the planargeo modules from the outermost
    frame to the called function (other packages' frames left out, repeats
    collapsed).
    """
    calls, stacks = collections.Counter(), set()

    def profile(frame, event, arg):
        module = frame.f_globals.get("__name__", "")
        if event != "call" or not module.startswith("planargeo"):
            return
        caller = frame.f_back.f_globals.get("__name__", "") if frame.f_back is not None else ""
        if caller != module:
            calls[(caller, module, frame.f_code.co_name)] += 1
        chain, f = [], frame
        while f is not None:
            m = f.f_globals.get("__name__", "")
            m = "planargeo.widgets.base" if m in BASE_PARTS else m
            # a decorator's wrapper (planargeo._validate's errstate/overflow guards) is not a layer step
            if m.startswith("planargeo") and m != "planargeo._validate" and (not chain or chain[-1] != m):
                chain.append(m)
            f = f.f_back
        stacks.add(tuple(reversed(chain)))

    sys.setprofile(profile)
    try:
        action()
    finally:
        sys.setprofile(None)
    return calls, stacks


def kinematics_passes(calls) -> int:
    """Kinematics passes among the entries: calls into the kinematics functions of ``mechanics.kinematics``."""
    return sum(n for (_, module, fn), n in calls.items()
               if module == "planargeo.mechanics.kinematics" and "kinematics" in fn)


def _change(ex, control, value):
    """The change, as an action; run once there and back first, so that caches are warm (a steady frame)."""
    def run():
        ex.controls[control].value = value

    old = ex.controls[control].value
    run()
    ex.controls[control].value = old
    return run


def test_widgets_import_no_algorithm_and_no_private_name():
    """State comes through ``planargeo.scenes``; no widget reaches past it into algorithms or ``_helpers``."""
    bad = []
    for path in sorted(WIDGETS.glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom):
                modules, names = [node.module or ""], [a.name for a in node.names]
            elif isinstance(node, ast.Import):
                modules, names = [a.name for a in node.names], []
            else:
                continue
            ours = [m for m in modules if m.startswith("planargeo")]
            if any(m.startswith("planargeo.algorithms") for m in ours) or (
                    ours and any(n.startswith("_") for n in names)):
                bad.append(f"{path.name}: {modules} {names}")
    assert not bad, bad


@pytest.mark.parametrize("name, control, value", CHANGES, ids=lambda x: str(x))
def test_slider_to_pixels_goes_down_through_at_most_five_modules(name, control, value):
    # a native explorer draws nothing without a front end: its path is followed in the page
    native = getattr(widgets, name)(display="agg").native
    ex = getattr(widgets, name)(display="page" if native else "agg")
    calls, stacks = calls_during(_change(ex, control, value))
    assert ex.message == "" and ex.values[control] == value
    own = f"planargeo.widgets.{type(ex).__module__.rsplit('.', 1)[1]}"
    for stack in stacks:
        levels = [level(m)[0] for m in stack]
        assert levels == sorted(levels, reverse=True), f"climbs back up: {' > '.join(stack)}"
    # slider -> scene -> algorithm: the widget reaches an algorithm only through a scene module
    to_algorithm = {s[:next(i for i, m in enumerate(s) if m.startswith("planargeo.algorithms")) + 1]
                    for s in stacks if any(m.startswith("planargeo.algorithms") for m in s)}
    for path in to_algorithm:
        assert path[:2] == ("planargeo.widgets.base", own) and path[2].startswith("planargeo.scenes"), path
        assert len(path) <= 4, path
    # -> draw: the widget module sets the artists itself, and base redraws them; a native
    # explorer's scene_picture calls its picture builder (draw/chain.py, draw/pictures/...)
    drawn = {s[:3] for s in stacks if len(s) >= 3 and s[2].startswith("planargeo.draw")}
    if native:
        assert any(d[:2] == ("planargeo.widgets.base", own) and d[2] not in (
            "planargeo.draw.artists", "planargeo.draw.from_axes") for d in drawn), drawn
    else:
        assert ("planargeo.widgets.base", own, "planargeo.draw.artists") in drawn, drawn
    longest = max((len(p) for p in to_algorithm), default=2)
    assert longest + 1 <= 5


@pytest.mark.parametrize("name, control, value", [c for c in CHANGES if c[0] in MECHANISMS],
                         ids=lambda x: str(x))
def test_kinematics_run_once_per_computed_state(name, control, value):
    ex = getattr(widgets, name)(display="agg")
    change = _change(ex, control, value)
    n = ex.n_computes
    calls, _ = calls_during(change)
    assert ex.n_computes == n + 1 and kinematics_passes(calls) == 1, kinematics_passes(calls)
    # a display-only change draws the same state: no kinematics at all
    if ex.display_controls:
        toggle = ex.controls[ex.display_controls[0]]
        calls, _ = calls_during(_change(ex, ex.display_controls[0], not toggle.value))
        assert kinematics_passes(calls) == 0 and ex.n_computes == n + 1


def test_chain_play_frames_run_kinematics_once_each():
    """Every animation frame is one state: one kinematics pass, energies from the same workspace."""
    ex = widgets.ChainExplorer(display="agg", links=3, fps=10)
    ex.simulate(0.3)
    for k in (1, 2, 3):      # the player is the time slider: each frame one state at t = 0.1 k
        calls, _ = calls_during(lambda: setattr(ex.player, "value", 0.1 * k))
        assert ex.values["time (s)"] == pytest.approx(0.1 * k) and kinematics_passes(calls) == 1, \
            kinematics_passes(calls)
