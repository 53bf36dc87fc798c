"""Students see symbols, not code identifiers: no ASCII ``x_y`` subscripts in what the car, articulated,
construction and splitting explorers put on screen (control labels and hover texts, readout rows, the
"what is shown" panel, the picture's symbols, labels and hover texts), in their default states and after a
change or two."""
import re

import pytest

from planargeo.scenes.construction import CONSTRUCTIONS
from planargeo.widgets.articulated import ArticulatedExplorer
from planargeo.widgets.car import CarExplorer
from planargeo.widgets.construction import ConstructionExplorer
from planargeo.widgets.splitting import SplittingExplorer

#: a letter or digit, an underscore, a letter, digit or brace: ``I_i``, ``r_G``, ``f_A``, ``J_c``, ``I_{ICR}``
CODE = re.compile(r"[A-Za-z0-9]_[A-Za-z0-9{]")


def on_screen(ex) -> list[str]:
    texts = []
    for w in ex.controls.values():
        texts += [str(getattr(w, "description", "")), str(getattr(w, "tooltip", None) or "")]
    texts += list(ex.readout_values)
    for k, v in ex.explain().items():
        texts += [k, v]
    for el in ex.picture()["elements"]:
        texts += [el.get("symbol", ""), el.get("desc", "")]
        texts += [p["text"] for p in el.get("parts", ()) if p.get("p") == "text"]
    return texts


def explorers():
    yield "car", CarExplorer(display="agg", **{"drive force (N)": 2000.0})
    yield "articulated", ArticulatedExplorer(display="agg")
    yield "splitting", SplittingExplorer(display="agg")
    for kind in CONSTRUCTIONS:
        yield kind, ConstructionExplorer(kind, display="agg", key=True)


@pytest.mark.parametrize("name, ex", list(explorers()), ids=lambda v: v if isinstance(v, str) else "")
def test_no_code_subscripts_on_screen(name, ex):
    assert [t for t in on_screen(ex) if CODE.search(t)] == []


def test_the_drive_force_and_the_rigid_inertias_read_as_symbols():
    car = CarExplorer(display="agg", **{"drive force (N)": 2000.0})
    assert "drive force f at the front tyre" in car.explain()["f (drive)"]
    assert ArticulatedExplorer(display="agg").controls["rigid inertias"].description == "rigid inertias Iᵢ"


def test_the_trees_degrees_of_freedom_row_reads_in_words():
    from planargeo.widgets.trees import TreeExplorer

    meaning = TreeExplorer(display="agg").explain()["degrees of freedom"]
    assert not CODE.search(meaning) and "closure Jacobian" in meaning
