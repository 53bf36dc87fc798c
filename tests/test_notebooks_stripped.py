"""Notebooks are committed with outputs stripped (they are run, with their assertions, by nbmake)."""
import json
from pathlib import Path

import pytest

NOTEBOOKS = sorted((Path(__file__).parents[1] / "notebooks").glob("*.ipynb"))


def test_there_is_a_tour_and_teaching_notebooks():
    names = [p.name for p in NOTEBOOKS]
    assert "00-tour.ipynb" in names and len(names) >= 8


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_outputs_stripped_and_assertions_present(path):
    nb = json.loads(path.read_text())
    code = [c for c in nb["cells"] if c["cell_type"] == "code"]
    assert all(not c.get("outputs") and c.get("execution_count") is None for c in code), path.name
    assert any("assert" in "".join(c["source"]) for c in code), f"{path.name} asserts nothing"
