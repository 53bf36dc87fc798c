"""The reported quantities' descriptions are data (issue 24): one file, ``planargeo/data/quantities.toml``,
read by ``planargeo report`` and open to the docs and explorers through ``planargeo.report.quantity``."""
import tomllib
from pathlib import Path

import pytest

from planargeo import report, scenes
from planargeo.errors import InputError, SceneError

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "planargeo" / "data" / "quantities.toml"
FIELDS = ["description", "symbol", "equation", "unit"]


def raw() -> dict:
    return tomllib.loads(DATA.read_text(encoding="utf-8"))["scene"]


def test_one_file_holds_the_report_and_the_explorers_words():
    """The report's quantities and the explorers' readout rows and symbols are one data file,
    read by one reader; no other data file of words ships with the package."""
    from planargeo.draw.pictures._words import words_data
    from planargeo.files import package_words

    data = tomllib.loads(DATA.read_text(encoding="utf-8"))
    assert set(data) == {"scene", "explorer"}
    assert sorted(p.name for p in DATA.parent.glob("*.toml")) == ["quantities.toml"]
    assert package_words("explorer") == data["explorer"] and len(data["explorer"]) >= 10
    assert words_data("impulse") == data["explorer"]["impulse"]
    assert words_data("no such explorer") == {}
    with pytest.raises(InputError, match="part must be one of"):
        package_words("widgets")


def test_the_file_describes_every_quantity_with_four_strings():
    data = raw()
    assert set(data) <= set(scenes.names()), set(data) - set(scenes.names())
    assert len(data) >= 12 and sum(len(t) for t in data.values()) > 150
    for scene, table in data.items():
        for key, entry in table.items():
            assert list(entry) == FIELDS, (scene, key)
            assert all(isinstance(v, str) and v.strip() for v in entry.values()), (scene, key)


def test_report_reads_the_file_and_writes_no_descriptions_itself():
    data = raw()
    assert {s: {k: list(v) for k, v in t.items()} for s, t in report.QUANTITY_INFO.items()} == \
        {s: {k: list(e.values()) for k, e in t.items()} for s, t in data.items()}
    source = (ROOT / "planargeo" / "report.py").read_text(encoding="utf-8")
    for table in data.values():                    # not one description is written twice
        for entry in table.values():
            assert entry["description"] not in source, entry["description"]


def test_quantity_returns_the_files_entry():
    entry = raw()["slider-crank"]["F3"]
    q = report.quantity("slider-crank", "F3")
    assert q == report.Quantity(**entry) and q.unit == "N, N, N·m" and q.equation == "9.91, 9.92"
    assert q._asdict() == report.quantity_info("slider-crank")["F3"]


def test_quantity_names_what_is_wrong():
    with pytest.raises(InputError, match=r"key must be a quantity of scene 'car' \(omega_dot, mu, .*got 'nope'"):
        report.quantity("car", "nope")
    with pytest.raises(SceneError, match="scene must be one of"):
        report.quantity("no-such-scene", "q")


def test_the_file_ships_with_the_package():
    """pyproject.toml's package data names the file, so a wheel (not only an editable install) has it."""
    pyproject = tomllib.loads((ROOT / "pyproject.toml").read_text())
    globs = pyproject["tool"]["setuptools"]["package-data"]["planargeo"]
    assert any(Path(report.QUANTITIES_FILE).match(g) for g in globs), globs
