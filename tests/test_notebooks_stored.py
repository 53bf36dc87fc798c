"""The notebooks are committed WITH their outputs, made by ``make notebooks`` (notebooks/run_all.py).

Here: the form of what is stored (the lessons in course order, every code cell run except the ones
waiting for an explorer of another branch, no timings, widget state or dates, no ``assert`` in a
notebook: checks live in tests/test_lessons.py).  That the stored outputs are what a fresh run
produces is tests/test_notebook_outputs.py.
"""
import importlib.util
import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))
LESSONS = [p for p in NOTEBOOKS if re.match(r"\d\d-", p.name) and p.name != "00-tour.ipynb"]

_spec = importlib.util.spec_from_file_location("run_all", ROOT / "notebooks" / "run_all.py")
run_all = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(run_all)

#: the course order of issue 15: one notebook per idea
COURSE = ["screws", "kinematics", "projective", "inertia", "subspace", "planar-example",
          "articulated", "mobility", "car", "trees", "loops", "speed"]


def test_a_tour_and_twelve_lessons_in_course_order():
    assert (ROOT / "notebooks" / "00-tour.ipynb") in NOTEBOOKS
    assert [p.name[:2] for p in LESSONS] == [f"{k:02d}" for k in range(1, len(LESSONS) + 1)]
    for path, key in zip(LESSONS, COURSE):
        assert key in path.name, (path.name, key)


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_stored_with_outputs_no_asserts_no_timings(path):
    nb = json.loads(path.read_text(encoding="utf-8"))
    assert "widgets" not in nb["metadata"], "widget state is not stored"
    code = [c for c in nb["cells"] if c["cell_type"] == "code"]
    assert code
    first = "".join(code[0]["source"])
    assert "use_widget_backend()" in first, "the first code cell turns on the widget backend"
    for c in code:
        src = "".join(c["source"])
        assert not re.search(r"^\s*assert\b", src, re.M), f"{path.name}: assert belongs in tests/"
        assert "execution" not in c.get("metadata", {}), "no timings stored"
        tags = c.get("metadata", {}).get("tags", [])
        if run_all.NEEDS_TAG in tags:
            assert c["metadata"].get("planargeo", {}).get("needs"), "a needs-merge cell names what it needs"
            continue                                   # run once the explorer exists
        assert c["execution_count"] is not None, f"{path.name}: a code cell was not run (make notebooks)"
        for o in c["outputs"]:
            assert o["output_type"] != "error"
    counts = [c["execution_count"] for c in code if c["execution_count"] is not None]
    assert counts == list(range(1, len(counts) + 1)), "run top to bottom in one kernel"
    text = path.read_text(encoding="utf-8")
    assert not re.search(r"20\d\d-\d\d-\d\dT\d\d:\d\d", text), "no dates stored"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_explorers_show_a_picture(path):
    """Every notebook stores at least one figure (PNG), so it shows pictures unexecuted."""
    nb = json.loads(path.read_text(encoding="utf-8"))
    pngs = sum("image/png" in o.get("data", {}) for c in nb["cells"] if c["cell_type"] == "code"
               for o in c["outputs"])
    assert pngs >= 1, path.name
