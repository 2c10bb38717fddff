"""Lookups by id (single ids and ranges), by name, and of PDI errors."""

from __future__ import annotations

import doctest

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from veronte4x import variables
from veronte4x.variables import VARIABLES, Kind, by_id, by_name, pdi_error


@pytest.mark.parametrize(
    ("kind", "number", "name"),
    [
        (Kind.BIT, 7, "System Error"),
        (Kind.BIT, 38, "4XV Arbitrating"),
        (Kind.BIT, 230, "4XV Custom msg 0-63 Rx Error"),
        (Kind.BIT, 293, "4XV Custom msg 0-63 Rx Error"),
        (Kind.BIT, 800, "PWM 0-5 GPIO Off"),
        (Kind.BIT, 803, "PWM 0-5 GPIO Off"),
        (Kind.BIT, 805, "PWM 0-5 GPIO Off"),
        (Kind.BIT, 1200, "User BIT 00-09 Error"),
        (Kind.BIT, 1205, "User BIT 00-09 Error"),
        (Kind.BIT, 1209, "User BIT 00-09 Error"),
        (Kind.RVAR, 1353, "4XV ADC0-6 Converted Value"),
        (Kind.RVAR, 1358, "4XV Internal ADC7-8 Converted Value"),
        (Kind.RVAR, 1369, "4XV Autopilot External Score"),
        (Kind.UVAR, 3, "ADC 0-4"),
        (Kind.UVAR, 17, "Internal ADC 1-10"),
        (Kind.UVAR, 64, "4XV Internal ADC 0-9"),
        (Kind.UVAR, 455, "CAN to Serial 0-1 frames dropped"),
    ],
)
def test_by_id(kind: Kind, number: int, name: str) -> None:
    var = by_id(kind, number)
    assert var is not None
    assert var.name == name
    assert number in var.ids


@pytest.mark.parametrize(
    ("kind", "number"),
    [
        (Kind.BIT, 0),
        (Kind.BIT, 13),
        (Kind.BIT, 229),
        (Kind.BIT, 294),
        (Kind.BIT, 401),
        (Kind.BIT, 799),
        (Kind.BIT, 806),
        (Kind.BIT, 1210),
        (Kind.RVAR, 1349),
        (Kind.RVAR, 1370),
        (Kind.UVAR, 71),
        (Kind.UVAR, 497),
        (Kind.UVAR, -1),
    ],
)
def test_by_id_unknown(kind: Kind, number: int) -> None:
    assert by_id(kind, number) is None


def test_same_id_differs_per_kind() -> None:
    assert by_id(Kind.BIT, 53) is None
    rvar = by_id(Kind.RVAR, 53)
    uvar = by_id(Kind.UVAR, 53)
    assert rvar is not None and rvar.name == "CAN-B Tx Skip Rate"
    assert uvar is not None and uvar.name == "4XV Veronte ID"


def test_kind_value_works_as_key() -> None:
    assert by_id(Kind("bit"), 20) is by_id(Kind.BIT, 20)


@given(st.sampled_from(list(Kind)), st.integers(min_value=-10, max_value=1500))
@settings(max_examples=300)
def test_by_id_agrees_with_rows(kind: Kind, number: int) -> None:
    covering = [v for v in VARIABLES[kind] if v.first <= number <= v.last]
    assert by_id(kind, number) == (covering[0] if covering else None)


@pytest.mark.parametrize(
    ("kind", "name", "first"),
    [
        (Kind.BIT, "System Error", 7),
        (Kind.BIT, "system error", 7),
        (Kind.BIT, "  4XV   ALIVE 3 external ", 33),
        (Kind.BIT, "pwm 0-5 gpio off", 800),
        (Kind.RVAR, "4xv vcc-2", 1365),
        (Kind.UVAR, "VERSION MAJOR", 90),
    ],
)
def test_by_name(kind: Kind, name: str, first: int) -> None:
    var = by_name(kind, name)
    assert var is not None
    assert var.first == first


def test_by_name_unknown_or_other_kind() -> None:
    assert by_name(Kind.BIT, "no such variable") is None
    assert by_name(Kind.BIT, "Version Major") is None
    assert by_name(Kind.UVAR, "System Error") is None


def test_every_entry_found_by_its_id_and_name() -> None:
    for kind, rows in VARIABLES.items():
        for var in rows:
            assert by_name(kind, var.name) is var
            assert all(by_id(kind, number) is var for number in var.ids)


def test_pdi_error_lookup() -> None:
    by_number = pdi_error(10005)
    assert by_number is not None
    assert by_number.code == "pdi_arb_cfg2"
    assert not by_number.inferred
    assert pdi_error("PDI_ARB_CFG2") is by_number
    assert pdi_error(" pdi_arb_varcfg ") is pdi_error(10008)
    assert pdi_error(9999) is None
    assert pdi_error(10009) is None
    assert pdi_error("pdi_unknown") is None


def test_package_docstring_example() -> None:
    result = doctest.testmod(variables, raise_on_error=False)
    assert result.attempted == 4  # the import and three lookups
    assert result.failed == 0
