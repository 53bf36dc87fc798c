"""The chain, slider-crank and trees explorers' words are data (issue 24): each meaning, unit and
template is written once, in ``planargeo/data/quantities.toml``, read here with :mod:`tomllib` as the
reference, and never in the explorer's source."""
import tomllib
from pathlib import Path

import pytest

from planargeo.widgets.chain import ChainExplorer
from planargeo.widgets.slider_crank import SliderCrankExplorer
from planargeo.widgets.trees import TreeExplorer

ROOT = Path(__file__).resolve().parents[1]
DATA = tomllib.loads((ROOT / "planargeo" / "data" / "quantities.toml").read_text(encoding="utf-8"))["explorer"]
SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def strings(table):
    """Every meaning and template of an explorer's tables (units left out: "m", "N" are too short to look for)."""
    for value in table.values():
        if isinstance(value, dict):
            yield from strings(value)
        elif isinstance(value, list):
            yield value[-1]
        else:
            yield value


@pytest.mark.parametrize("name, module", [("chain", "chain"), ("slider-crank", "slider_crank"), ("trees", "trees")])
def test_no_meaning_is_written_in_the_source(name, module):
    source = (ROOT / "planargeo" / "widgets" / f"{module}.py").read_text(encoding="utf-8")
    words = list(strings(DATA[name]))
    assert len(words) >= 20
    for text in words:
        assert text not in source, text


def test_slider_crank_panel_and_units_are_its_table_in_order():
    table = DATA["slider-crank"]["explain"]
    ex = SliderCrankExplorer(display="agg")
    assert list(ex.explain().items()) == [(k, v[1] if isinstance(v, list) else v) for k, v in table.items()]
    assert ex.units == {k: v[0] for k, v in table.items() if isinstance(v, list)}
    assert set(ex.readout_values) == set(ex.units)         # every readout row has its unit and meaning


@pytest.mark.parametrize("links, joints, last", [(3, "revolute", "revolute"), (4, "alternating", "prismatic")])
def test_chain_panel_names_each_link_in_the_figure(links, joints, last):
    ex = ChainExplorer(display="agg", links=links, joints=joints)
    words = ex.explain()
    symbols, rows = DATA["chain"]["symbols"], DATA["chain"]["rows"]
    assert words["vᵢ"] == symbols["vᵢ"] + "; in the figure: " + ", ".join(f"v{i}".translate(SUB)
                                                                           for i in range(1, links + 1))
    assert words["link i, joint i"].endswith(f"link {links}, joint {links}")
    assert {k: words[k] for k in rows} == {k: v[1] for k, v in rows.items()}
    assert {k: ex.units[k] for k in rows} == {k: v[0] for k, v in rows.items()}
    unit = {"revolute": "rad/s²", "prismatic": "m/s²"}[last]
    key = f"q̈{links}".translate(SUB)
    assert words[key] == f"acceleration of joint {links} ({last}, {unit}; eq. 3.41)" and ex.units[key] == unit
    assert list(words)[-1] == key and set(ex.readout_values) <= set(words)


def test_trees_panel_has_each_body_pin_and_contact_once():
    words = TreeExplorer(display="agg").explain()
    assert words["v₉"] == "velocity pole of body 9: the point it turns about now (section 4.5)"
    assert words["|F₂| (pin 8-9)"] == "size of the contact force F₂ (9.71)"
    assert words["moment of f₃ about its pin"] == "moment of f₃ about its own pin: 0 for a free pin (9.61)"
    per = DATA["trees"]
    n = len(per["rows"]) + len(per["symbols"]) + 9 * (len(per["bodies"]) + len(per["pins"]) + len(per["pin_forces"])) \
        + 2 * (len(per["contacts"]) + len(per["contact_forces"]))
    assert len(words) == n == 68
