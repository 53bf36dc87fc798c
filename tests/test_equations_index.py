"""``docs/equations.md`` maps every cited thesis equation to the code, and is current."""
import importlib.util
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
_spec = importlib.util.spec_from_file_location("equations_index", ROOT / "docs" / "equations_index.py")
eqi = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(eqi)

LABELS = eqi.thesis_labels()


def test_committed_index_is_current():
    assert (ROOT / "docs" / "equations.md").read_text(encoding="utf-8") == eqi.render(), \
        "docs/equations.md is stale: run `python docs/equations_index.py`"


def test_citations_are_read_as_the_book_writes_them():
    doc = ("Joint accelerations (thesis 3.40-3.42), with the force 3.13 and (6.113b);\n"
           "the recursion of (thesis 7.1.1: 7.7a, 7.8) and section 4.8.1 of the book;\n"
           "the point (2.5, 1.25) is data.\n\nExamples\n--------\n>>> f(3.31)\n")
    got = eqi.cited(doc, LABELS)
    assert got[:3] == ["3.40", "3.41", "3.42"]
    assert "6.113b" in got and "6.113a" not in got and "2.5" not in got and "3.31" not in got
    assert "7.7a" in got and "7.8" in got and "7.1" not in got and "4.8" not in got


def test_the_recursions_are_found_from_their_numbers():
    index = eqi.implementations(LABELS)
    for label, function in [("3.41", "planargeo.algorithms.kernels.articulated_body_state"),
                             ("3.41", "planargeo.algorithms.aba.forward_dynamics"),
                             ("6.113a", "planargeo.algorithms.projective.acceleration_propagator"),
                             ("7.7a", "planargeo.algorithms.articulated_inertia.articulated_recursion"),
                             ("7.38a", "planargeo.algorithms.articulated_mobility.mobility_recursion")]:
        assert function in index[label], (label, index[label])
