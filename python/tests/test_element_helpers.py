"""hbtrack.element_types() and the helpers of hbtrack.elements built from the element catalogue."""
import inspect
import pydoc

import numpy as np
import pytest

import hbtrack


def duffing(elements):
    """examples/duffing.toml as arrays, with the given case-file elements."""
    return hbtrack.case_from_arrays(
        M=np.array([[1.0]]), K=np.array([[1.0]]), C=np.array([[0.05]]), dofs=["x"],
        forcing=[{"dof": "x", "harmonic": 1, "cos": 0.18}], parameters={"amplitude": 1.0, "k3": 0.1},
        elements=list(elements), harmonic_balance={"harmonics": 7, "samples": 64},
        continuation={"omega_start": 0.5, "omega_end": 1.6, "step": 0.02})


def test_every_catalogued_type_has_a_helper():
    types = hbtrack.element_types()
    assert "tip_contact" in types and "cubic_spring" in types
    for name in types:
        helper = getattr(hbtrack.elements, name)
        assert callable(helper) and helper.__name__ == name


def test_help_lists_every_key_and_property_of_every_type():
    for name, info in hbtrack.element_types().items():
        helper = getattr(hbtrack.elements, name)
        text = pydoc.render_doc(helper, renderer=pydoc.plaintext)
        signature = inspect.signature(helper)
        expected = set(info["keys"])
        for variant in info["variants"]:
            expected |= set(variant["properties"])
        assert expected, name
        for key in expected:
            assert key in signature.parameters, f"{name}: {key} not in the signature"
            assert f"\n    {key} : " in text, f"{name}: help() does not document {key}"
        # The signature is in help()'s first line, the summary and units in the text.
        assert f"{name}(dofs, *" in text and info["summary"] in text, text


def test_docstrings_state_units_ranges_and_defaults():
    text = inspect.getdoc(hbtrack.elements.power_damper)
    assert "exponent : float, str or dict, optional" in text
    assert "Velocity exponent [1]." in text and "Must be >= 1." in text and "Default 2." in text
    tip = inspect.getdoc(hbtrack.elements.tip_contact)
    assert 'Only with friction="stick_slip"' in tip  # tangential_stiffness
    assert 'Must be != 0 with friction="sliding"' in tip  # engine_order


def test_a_helper_writes_the_dict_form():
    table = hbtrack.elements.tip_contact(["r", "t", "z"], stiffness="kc", clearance=1e-3, width=0.1, mu=0.2, radius=0.3,
                                         friction="stick_slip", tangential_stiffness=5.0)
    assert table == {"type": "tip_contact", "dofs": ["r", "t", "z"], "friction": "stick_slip", "stiffness": "kc",
                     "clearance": 1e-3, "width": 0.1, "mu": 0.2, "radius": 0.3, "tangential_stiffness": 5.0}
    with pytest.raises(TypeError, match="cubic_stiffness"):
        hbtrack.elements.cubic_spring(["x"])
    with pytest.raises(TypeError, match="stifness"):
        hbtrack.elements.cubic_spring(["x"], cubic_stiffness=1.0, stifness=2.0)


def test_a_helper_built_element_gives_the_same_nfrc_as_the_dict_form():
    as_dict = hbtrack.frc(duffing([{"type": "cubic_spring", "dofs": ["x"], "cubic_stiffness": "k3", "lanczos": 0.5}]))
    helper = hbtrack.frc(duffing([hbtrack.elements.cubic_spring("x", cubic_stiffness="k3", lanczos=0.5)]))
    assert as_dict["summary"]["stop_reason"] == "reached_end"
    # The same case text, so the same arithmetic: equal to the last bit.
    assert np.array_equal(helper["states"], as_dict["states"])
    assert set(helper["branch"]) == set(as_dict["branch"])
    for column in as_dict["branch"]:
        assert np.array_equal(helper["branch"][column], as_dict["branch"][column], equal_nan=True), column


def test_the_reader_checks_what_a_helper_writes():
    with pytest.raises(ValueError, match=r"elements\[0\]\.exponent: must be >= 1"):
        duffing([hbtrack.elements.power_damper(["x"], coefficient=0.1, exponent=0.5)])
