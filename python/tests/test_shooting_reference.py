"""Checks of scripts/reference/piecewise_linear_shooting.py, the exact-shooting reference for
periodic solutions and Floquet multipliers of piecewise-linear systems with a unilateral spring,
and of the data it wrote into tests/data/shooting/ (see its README.md).

The reference needs scipy (expm, brentq), which is not in the project's install list
(scripts/install-deps.sh): these tests skip when scipy is missing. About 2 s.
"""
import csv
import importlib.util
import json
import math
import os

import numpy as np
import pytest

pytest.importorskip("scipy")

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
DATA = os.path.join(ROOT, "tests", "data", "shooting")
_spec = importlib.util.spec_from_file_location(
    "piecewise_linear_shooting", os.path.join(ROOT, "scripts", "reference", "piecewise_linear_shooting.py"))
ref = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(ref)


def read_case(name):
    with open(os.path.join(DATA, name, "branch.csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(DATA, name, "special_points.json")) as f:
        return rows, json.load(f)


def row_state(row, n):
    return np.array([float(row[f"x0_{k}"]) for k in range(2 * n)])


def row_multipliers(row, n):
    return np.array([complex(float(row[f"mu{k}_re"]), float(row[f"mu{k}_im"])) for k in range(2 * n)])


@pytest.mark.parametrize("case", ["nlvib_two_dof", "two_dof_contact", "chain_8"])
def test_linear_limit_is_the_frequency_response(case):
    # A gap no motion reaches: the periodic solution is the linear one, Q = (K - w^2 M + iwC)^-1 F,
    # and the multipliers are exp(lambda T) for the eigenvalues lambda of the first-order system.
    system = ref.CASES[case]()[0]
    system.gap = 1e9
    n = system.n
    A = system.augmented_matrix(1.0, False)[:2 * n, :2 * n]
    for w in (0.3, 0.7, 1.3):
        x, Phi = ref.newton_fixed_w(system, np.zeros(2 * n), w)
        assert np.abs(x - system.linear_response(w)).max() < 1e-10
        expected = np.exp(np.linalg.eigvals(A) * 2 * math.pi / w)
        mu = np.linalg.eigvals(Phi)
        assert max(np.abs(expected - m).min() for m in mu) < 1e-10
        assert max(np.abs(mu - e).min() for e in expected) < 1e-10


@pytest.mark.parametrize("case,w,scale", [("nlvib_two_dof", 0.7, 4.0), ("two_dof_contact", 0.76, 8.0)])
def test_monodromy_is_the_jacobian_of_the_flow_map(case, w, scale):
    # Any state whose period crosses the gap (not necessarily periodic): the product of region
    # exponentials must equal a central finite difference of x0 -> x(T), which sees the switch
    # times move (the identity saltation matrix is what this checks).
    system = ref.CASES[case]()[0]
    flow = ref.PeriodFlow(system, w)
    x0 = scale * system.linear_response(w)
    _, Phi, contacts, _ = flow.run(x0)
    assert contacts >= 1
    h = 1e-5  # the error is rounding-dominated: 3e-10 at h = 1e-5, 3e-9 at 1e-6
    fd = np.column_stack([(flow.run(x0 + h * e)[0] - flow.run(x0 - h * e)[0]) / (2 * h)
                          for e in np.eye(len(x0))])
    assert np.abs(fd - Phi).max() < 1e-7 * max(1.0, np.abs(Phi).max())


def monodromy_by_runge_kutta(system, x0, w):
    """x(T) and the monodromy matrix by solve_ivp (DOP853, rtol 1e-12) on the state and the
    variational equation, the switches found by its event location: independent of the exact
    flows (no expm, no eigen-decomposition, no bracket scan)."""
    from scipy.integrate import solve_ivp
    n, T = system.n, 2 * math.pi / w

    def rhs(t, z, contact):
        A = system.augmented_matrix(w, contact)[:2 * n]
        y = np.concatenate([z[:2 * n], [math.cos(w * t), math.sin(w * t), 1.0]])
        return np.concatenate([A @ y, (A[:, :2 * n] @ z[2 * n:].reshape(2 * n, 2 * n)).ravel()])

    events = []
    for direction in (1, -1):  # leaving the open region upwards, the contact region downwards
        event = lambda t, z, contact: z[system.i] - system.gap
        event.terminal, event.direction = True, direction
        events.append(event)
    z, t = np.concatenate([x0, np.eye(2 * n).ravel()]), 0.0
    contact = bool(x0[system.i] > system.gap)
    while t < T:
        sol = solve_ivp(rhs, (t, T), z, method="DOP853", rtol=1e-12, atol=1e-13,
                        events=events[1 if contact else 0], args=(contact,))
        if sol.status == 1:
            t, z, contact = sol.t_events[0][-1], sol.y_events[0][-1], not contact
        else:
            t, z = T, sol.y[:, -1]
    return z[:2 * n], z[2 * n:].reshape(2 * n, 2 * n)


@pytest.mark.parametrize("w_near", [0.745, 0.725, 0.59])
def test_stored_orbits_agree_with_runge_kutta(w_near):
    # nlvib_two_dof inside the reference's PD band, inside NLvib's claimed PD band but not the
    # reference's, and inside the reference's NS band but not NLvib's: the rows there (every
    # branch) are periodic and have the same monodromy matrix by Runge-Kutta.
    rows, _ = read_case("nlvib_two_dof")
    system = ref.nlvib_two_dof()[0]
    near = [r for r in rows if abs(float(r["w"]) - w_near) < 2e-3]
    assert near
    for row in near:
        w, x0 = float(row["w"]), row_state(row, 2)
        xT, Phi = monodromy_by_runge_kutta(system, x0, w)
        assert np.abs(xT - x0).max() < 1e-9
        assert np.abs(Phi - ref.PeriodFlow(system, w).run(x0)[1]).max() < 1e-8
        assert np.abs(np.linalg.eigvals(Phi)).max() == pytest.approx(float(row["max_abs_mu"]), rel=1e-8)


@pytest.mark.parametrize("case", ["nlvib_two_dof", "two_dof_contact", "chain_2", "chain_8"])
def test_stored_rows_are_periodic_with_their_multipliers(case):
    rows, summary = read_case(case)
    system = ref.CASES[case]()[0]
    n = system.n
    # rows away from the located points: at a grazing one the multipliers vary like the square
    # root of the penetration, so the CSV's 11 digits of x0 do not fix them to 1e-8
    plain = [r for r in rows if not r["special"]]
    for row in (plain[0], plain[len(plain) // 3], plain[2 * len(plain) // 3], plain[-1]):
        w, x0 = float(row["w"]), row_state(row, n)
        xT, Phi, contacts, _ = ref.PeriodFlow(system, w).run(x0)
        assert np.abs(xT - x0).max() < 1e-9
        assert contacts == int(row["contacts"])
        mu = np.linalg.eigvals(Phi)
        assert np.abs(mu).max() == pytest.approx(float(row["max_abs_mu"]), rel=1e-8)
        assert max(np.abs(row_multipliers(row, n) - m).min() for m in mu) < 1e-8
        assert (np.abs(mu).max() < 1) == (row["stable"] == "1")
    # every special point is on the branch, with its multiplier where its type says
    for sp in summary["special_points"]:
        x0 = np.array(sp["x0"])
        xT, Phi, _, _ = ref.PeriodFlow(system, sp["w"]).run(x0)
        assert np.abs(xT - x0).max() < 1e-9
        mu = np.linalg.eigvals(Phi)
        target = {"LP": 1.0, "BP": 1.0, "PD": -1.0}.get(sp["type"])
        if target is not None:  # a loose bound at grazing: there mu varies like sqrt(w - w_graze)
            assert np.abs(mu - target).min() < (1e-3 if sp["at_grazing"] else 1e-6)
        elif sp["type"] == "NS":
            assert np.abs(np.abs(mu[np.abs(mu.imag) > 1e-6]) - 1).min() < (1e-3 if sp["at_grazing"] else 1e-6)


def test_period_doubling_grows_into_a_period_two_orbit():
    # Just inside the PD band of two_dof_contact (0.7637 .. 0.7691): the deviation from the
    # unstable period-1 orbit along the eigenvector of mu < -1 flips sign every period and grows
    # by |mu| per period, then settles on a period-2 orbit (x(k+2) = x(k) != x(k+1)).
    rows, summary = read_case("two_dof_contact")
    system = ref.two_dof_contact()[0]
    pd = sorted(sp["w"] for sp in summary["special_points"] if sp["type"] == "PD" and 0.7 < sp["w"] < 0.8)
    assert pd == pytest.approx([0.7637, 0.7691], abs=1e-4)
    inside = [r for r in rows if pd[0] < float(r["w"]) < pd[1] and row_multipliers(r, 2).real.min() < -1.02]
    row = min(inside, key=lambda r: float(r["w"]))
    w = float(row["w"])
    x, Phi = ref.newton_fixed_w(system, row_state(row, 2), w)
    mu, V = np.linalg.eig(Phi)
    k = np.argmin(mu.real)
    e = V[:, k].real / np.linalg.norm(V[:, k].real)
    flow = ref.PeriodFlow(system, w)
    y, states = x + 1e-6 * e, []
    for _ in range(400):
        y = flow.run(y)[0]
        states.append(y)
    d = np.array([(s - x) @ e for s in states[:20]])
    assert np.all(d[1:] / d[:-1] == pytest.approx(mu[k].real, rel=1e-4))
    a, b, c = states[-3:]
    assert np.linalg.norm(b - a) > 0.05 and np.linalg.norm(c - a) < 1e-8
