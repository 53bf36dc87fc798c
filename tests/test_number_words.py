"""Numbers in the refusals as a student reads them: "between -1 000 000 and 1 000 000", not
"between -1e+06 and 1e+06" (a student's review), and the same way in every explorer.

The reference for each number is the number itself: the text, its digit groups removed, parses back
to it; below a million the text is what every other message writes (``:g``).
"""
from __future__ import annotations

import math
import re

import ipywidgets as W
import pytest

import planargeo.widgets as widgets
from planargeo.errors import InputError
from planargeo.widgets.controls import (DIGIT_GROUP, TEXT_LIMIT, Step, check_control, number_text,
                                        short_text)

EXPONENT = re.compile(r"\d[eE][-+]?\d")
SUPER = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻", "0123456789-")


def parsed(text: str) -> float:
    """The number a student reads in ``text`` (digit groups, or a power of ten with superscripts)."""
    if "×10" in text:
        mant, exp = text.split("×10")
        return float(mant) * 10.0 ** int(exp.translate(SUPER))
    return float(text.replace(DIGIT_GROUP, ""))


@pytest.mark.parametrize("x", [1e6, -1e6, 2_500_000.0, 123_456_789.0, 999_999_999_999_999.0,
                               1e15, -3.5e20, 1e299, 2e-5, -7.25e-9])
def test_big_and_small_numbers_read_back_without_an_exponent(x):
    text = number_text(x)
    assert not EXPONENT.search(text), text
    assert math.isclose(parsed(text), x, rel_tol=1e-6), (text, x)


def test_a_million_in_groups_of_three():
    assert number_text(-1e6) == "-1 000 000".replace(" ", DIGIT_GROUP)


@pytest.mark.parametrize("x", [-180, 0.05, 6000, 10000, 0.1 + 0.2, 123456.7, 999999, 1e-4, -0.5, 42])
def test_below_a_million_as_every_other_message_writes_numbers(x):
    assert number_text(x) == f"{x:g}"


def test_the_text_field_limit_is_said_in_digits():
    with pytest.raises(InputError) as err:
        check_control("joint speeds", W.Text(), "1, 1e150")
    said = str(err.value)
    assert not EXPONENT.search(said.split(", got")[0]), said
    lo, hi = re.search(r"between ([^ ,]+) and ([^ ,]+),", said).groups()
    assert (parsed(lo), parsed(hi)) == (-TEXT_LIMIT, TEXT_LIMIT)


def test_a_slider_range_is_said_in_digits():
    w = Step(-2e6, 3e6, 1000, 0, "force (N)").make("F")
    big = number_text(-2e6), number_text(3e6)
    assert big == ("-2 000 000".replace(" ", DIGIT_GROUP), "3 000 000".replace(" ", DIGIT_GROUP))
    with pytest.raises(InputError, match=f"between {big[0]} and {big[1]}, got nan"):
        check_control("F", w, float("nan"))


def test_the_digit_groups_stay_on_one_line_in_the_picture():
    text = short_text("numbers typed here must lie between\n  -1 000 000 and 1 000 000".replace(
        "1 000 000", number_text(1e6)))
    assert number_text(1e6) in text and "\n" not in text


@pytest.mark.parametrize("name", [n for n in widgets.__all__ if n.endswith("Explorer") and n != "Explorer"])
def test_no_explorer_says_a_slider_range_with_an_exponent(name):
    ex = getattr(widgets, name)(display="agg")
    for key, w in ex.controls.items():
        if isinstance(w, (W.FloatSlider, W.IntSlider)) and not w.disabled:
            with pytest.raises(InputError) as err:
                check_control(key, w, float("nan"))
            said = str(err.value).split(", got")[0]
            assert not EXPONENT.search(said), said
            lo, hi = re.search(r"between (.+) and (.+)$", said).groups()
            assert (parsed(lo), parsed(hi)) == (pytest.approx(w.min), pytest.approx(w.max)), said
