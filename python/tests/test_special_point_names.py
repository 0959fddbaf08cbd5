"""The special points' types have one table on each side: python/hbtrack/special_points.py and
include/hbtrack/util/special_point_type.hpp. They hold the same names in the same order (a type
added on one side only fails here), and the Python parser refuses an unknown name as the C++ one
does."""
import pytest

from hbtrack._core import require_core
from hbtrack.special_points import CurveExtremumType, SpecialPointType, parse_special_point_type


def test_python_names_are_the_libraries():
    core = require_core()
    assert [t.value for t in SpecialPointType] == core.special_point_type_names()
    assert [t.value for t in CurveExtremumType] == core.curve_extremum_type_names()


def test_every_type_round_trips_through_its_name():
    for t in SpecialPointType:
        assert parse_special_point_type(str(t)) is t and f"{t}" == t.value


def test_an_unknown_name_is_refused_as_the_library_refuses_it():
    with pytest.raises(ValueError, match=r"^special point type: must be LP, BP, PD, NS, R1 or R2, got 'lp'$"):
        parse_special_point_type("lp")
    # The library's message for the same name, through a binding that parses a type.
    with pytest.raises(ValueError, match=r"^special point type: must be LP, BP, PD, NS, R1 or R2, got 'lp'$"):
        require_core().special_point_index([], "lp", 1, "lp", "the frc result")
