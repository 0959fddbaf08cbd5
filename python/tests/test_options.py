"""Options are Python classes named as the C++ fields, the case keys and the CLI flags; they
round-trip through attributes, keywords and repr, and a Case's options are live references."""
import re

import pytest

import hbtrack

from conftest import DUFFING


@pytest.mark.parametrize("cls", [hbtrack.ContinuationOptions, hbtrack.StabilityOptions, hbtrack.HarmonicBalanceOptions, hbtrack.AdaptiveHarmonics,
                                 hbtrack.FoldTrackingOptions, hbtrack.SteadyStateOptions])
def test_repr_rebuilds_an_equal_object(cls):
    original = cls()
    rebuilt = eval(repr(original), vars(hbtrack))  # noqa: S307 - nested options print as their class
    assert repr(rebuilt) == repr(original)
    assert type(rebuilt) is cls
    for field in cls.fields:
        assert getattr(rebuilt, field) == getattr(original, field)


def test_keywords_set_attributes_and_repr_shows_them():
    options = hbtrack.ContinuationOptions(step=0.05, predictor="secant", max_points=12, locate=False)
    assert (options.step, options.predictor, options.max_points, options.locate) == (0.05, "secant", 12, False)
    options.tolerance = 1e-11
    assert options.tolerance == 1e-11
    text = repr(options)
    for part in ("step=0.05", "predictor='secant'", "max_points=12", "locate=False", "tolerance=1e-11"):
        assert part in text


def test_names_are_the_case_file_keys(duffing_frc):
    # summary.json's options are written under the case file's keys: the [continuation] keys
    # other than the NFRC's range and length scale are ContinuationOptions' fields, in order.
    written = list(duffing_frc["summary"]["options"]["continuation"])
    nfrc_only = {"omega_start", "omega_end", "length_scale"}
    assert sorted(hbtrack.ContinuationOptions.fields) == sorted(k for k in written if k not in nfrc_only)
    assert sorted(hbtrack.StabilityOptions.fields) == sorted(duffing_frc["summary"]["options"]["stability"])


def reader_keys(section):
    """The case-file reader's keys of a section (the source of truth of the option names), from
    its message for a key nowhere near a valid one."""
    with pytest.raises(ValueError) as error:
        hbtrack.load_case(DUFFING, set={f"{section}.qqqqqqqqqqqqqqqqqqqqqqqq": 1})
    return set(re.search(r"expected one of: ([^)]*)\)", str(error.value)).group(1).split(", "))


@pytest.mark.parametrize("section, fields", [
    ("continuation", set(hbtrack.ContinuationOptions.fields) | set(hbtrack.NfrcOptions.fields) - {"continuation", "stability"}),
    ("continuation", set(hbtrack.ContinuationSection.fields)),  # case.continuation, python/src/bind_case_settings.cpp
    ("stability", set(hbtrack.StabilityOptions.fields)),
    ("harmonic_balance", set(hbtrack.HarmonicBalanceOptions.fields))])
def test_option_classes_bind_every_key_the_reader_accepts(section, fields):
    # A key added to the reader and not to the binders (or the reverse) fails here;
    # tests/test_option_lists.cpp checks summary.json's and with_overrides' lists the same way.
    assert fields == reader_keys(section)


def test_overrides_and_case_options_round_trip():
    case = hbtrack.load_case(DUFFING, set={"amplitude": 2.0, "harmonic_balance.harmonics": 9, "continuation.step": 0.01})
    assert case.parameters["amplitude"] == 2.0
    assert case.harmonic_balance.harmonics == 9
    assert case.continuation.step == 0.01
    case.continuation.step = 0.03  # a view into the case: its arc-length options change too
    assert case.continuation.options.step == 0.03
    stability = case.stability
    stability.method = "monodromy"  # a reference into the case
    assert case.stability.method == "monodromy"
    case.set_parameter("amplitude", 1.5)
    assert case.parameters["amplitude"] == 1.5
    assert case.outputs == ["x"] and case.dof_names == ["x"]
    assert repr(case).startswith("Case(path=")
