"""Readout numbers in a power of ten read as a student writes them (review: the chain's energy drift read
"-5.293e-08 J"; now "-5.293×10⁻⁸ J", the way the controls' messages write powers of ten)."""
import re

import pytest

from planargeo.widgets.readout import fmt, value_text


@pytest.mark.parametrize("x, text", [(-5.293e-08, "-5.293×10⁻⁸"), (1.168e-09, "1.168×10⁻⁹"), (2.478e-07, "2.478×10⁻⁷"),
                                     (123456.0, "1.235×10⁵"), (1e-12, "1×10⁻¹²"), (-4.5e20, "-4.5×10²⁰")])
def test_a_power_of_ten_is_written_with_superscripts(x, text):
    assert fmt(x) == text
    # read back as the number it stands for, to the 4 significant digits shown
    mant, exp = re.fullmatch(r"(-?[\d.]+)×10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)", text).groups()
    exp = int(exp.translate(str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")))
    assert float(mant) * 10.0 ** exp == pytest.approx(x, rel=5e-4)


def test_the_energy_drift_reads_with_its_unit_and_no_e_notation():
    assert value_text(-5.293e-08, "J") == "-5.293×10⁻⁸ J"
    assert value_text((1.5e-6, -2.0), "m") == "(1.5×10⁻⁶, -2) m"


@pytest.mark.parametrize("x", [-0.0, (-0.0, 0.0), (-0.0, 2.0, -1e-18)])
def test_a_negative_zero_reads_0(x):
    assert "-" not in fmt(x) and fmt(x) in ("0", "(0, 0)", "(0, 2, 0)")
