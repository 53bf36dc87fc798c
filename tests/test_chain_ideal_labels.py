"""Poles at infinity in one direction are drawn as one edge arrow: one label names them all
(review H4: with prismatic joints "v₂ at ∞" was written over "v₃ at ∞", and v₄'s label hid)."""
from __future__ import annotations

import pytest

from planargeo.geometry.projective import is_ideal
from planargeo.widgets import ChainExplorer


@pytest.mark.parametrize("links", [2, 4])
def test_edge_arrows_at_one_place_share_one_label_naming_them_all(links):
    ex = ChainExplorer(display="agg", joints="prismatic", links=links)
    poles = ex.state["w"].v                                  # every link translates: ideal poles
    assert all(is_ideal(p) for p in poles)
    pic = ex.picture()
    kx = (pic["size"][0] - pic["margin"][0] - pic["margin"][1]) / (pic["box"][1] - pic["box"][0])
    places: dict[tuple, list[str]] = {}
    labels: dict[tuple, list[str]] = {}
    for el in pic["elements"]:
        if el["id"] not in {f"v{i + 1}" for i in range(links)}:
            continue
        (arrow,) = [q for q in el["parts"] if q["p"] == "arrow"]
        # the arrow's middle, in pixels, and its direction: where it is drawn
        at = (round((arrow["x"] * kx + arrow["dx"] / 2)), round(arrow["y"] * kx), arrow["dx"] > 0, arrow["dy"] > 0)
        places.setdefault(at, []).append(el["symbol"])
        labels.setdefault(at, []).extend(q["text"] for q in el["parts"] if q["p"] == "text" and not q.get("hidden"))
    assert sum(map(len, places.values())) == links
    for at, syms in places.items():
        (text,) = labels[at]                                  # one label at each place
        assert text == f"{', '.join(syms)} at ∞", text        # naming every pole drawn there
