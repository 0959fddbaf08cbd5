"""Elements along directions from Python: the planar Jenkins slider (elastic_dry_friction_2d)
and a scalar element along a direction over several dofs, written with the element helpers and
case_from_arrays, give the example case files' solutions; bad weights raise the reader's errors."""
import os

import numpy as np
import pytest

import hbtrack

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
PLANAR = os.path.join(ROOT, "examples", "planar_jenkins.toml")
DIRECTIONS = os.path.join(ROOT, "examples", "element_directions.toml")


def planar_case(elements):
    return hbtrack.case_from_arrays(
        M=np.eye(2), K=np.diag([1.0, 1.44]), dofs=["x", "y"], damping={"rayleigh": [0.0, 0.01]},
        forcing=[{"cos": [0.0866, 0.05]}], parameters={"slip_force": 0.06}, elements=elements,
        harmonic_balance={"harmonics": 7, "samples": 512}, continuation={"omega_start": 0.6, "omega_end": 1.8})


def same_solution(a, b, omega):
    sa, sb = hbtrack.solve(a, omega)["dof_states"], hbtrack.solve(b, omega)["dof_states"]
    assert sa.keys() == sb.keys()
    for name in sa:
        assert np.allclose(sa[name], sb[name], rtol=0, atol=1e-12), name


def test_the_planar_slider_from_python_is_the_example():
    slider = hbtrack.elements.elastic_dry_friction_2d(["x", "y"], stiffness=1.0, limit_force="slip_force")
    assert slider == {"type": "elastic_dry_friction_2d", "dofs": ["x", "y"], "stiffness": 1.0, "limit_force": "slip_force"}
    # The default weights on two dofs are the identity: given explicitly, the same element.
    explicit = dict(slider, weights=[[1.0, 0.0], [0.0, 1.0]])
    for omega in (0.97, 1.2):
        same_solution(planar_case([slider]), hbtrack.load_case(PLANAR), omega)
        same_solution(planar_case([explicit]), hbtrack.load_case(PLANAR), omega)


def test_a_direction_over_three_dofs_from_python_is_the_example():
    dofs = ["n1_x", "n1_y", "n2_x"]
    case = hbtrack.case_from_arrays(
        M=np.diag([1.0, 1.0, 2.0]), K=[[2.0, 0.0, -1.0], [0.0, 2.25, 0.0], [-1.0, 0.0, 1.5]], dofs=dofs,
        damping={"rayleigh": [0.0, 0.02]}, forcing=[{"dof": "n2_x", "cos": 0.2}],
        elements=[hbtrack.elements.elastic_dry_friction(dofs, weights=[0.6, 0.8, -1.0], stiffness=3.0, limit_force=0.05),
                  hbtrack.elements.cubic_spring(dofs[:2], weights=[-0.8, 0.6], cubic_stiffness=0.5)],
        harmonic_balance={"harmonics": 7, "samples": 256}, continuation={"omega_start": 0.3, "omega_end": 2.0})
    same_solution(case, hbtrack.load_case(DIRECTIONS), 1.1)


@pytest.mark.parametrize("element, message", [
    (dict(weights=[[1.0, 0.0], [2.0, 0.0]]), "elements[0].weights: the two rows must not be parallel"),
    (dict(weights=[[1.0, 0.0], [0.0, 0.0]]), "elements[0].weights[1]: must not all be zero"),
    (dict(weights=[[1.0, 0.0, 0.0], [0.0, 1.0]]), "elements[0].weights[0]: expected one weight per dof (2)"),
    (dict(stiffness=-1.0), "elements[0].stiffness: must be > 0"),
])
def test_bad_planar_weights_name_the_field(element, message):
    slider = dict(hbtrack.elements.elastic_dry_friction_2d(["x", "y"], stiffness=1.0, limit_force=0.06), **element)
    with pytest.raises(ValueError, match=message.replace("[", r"\[").replace("]", r"\]").replace("(", r"\(").replace(")", r"\)")):
        planar_case([slider])
