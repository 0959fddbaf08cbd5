#!/usr/bin/env python3
"""Reference periodic solutions and Floquet multipliers of small piecewise-linear systems

    M q'' + C q' + K q + k_c max(q_i - gap, 0) e_i = F cos(w t)

by exact shooting, independent of hbtrack (numpy + scipy only), to judge hbtrack's stability
flags and bifurcation types.

Method. The state is augmented to y = [q, v, cos wt, sin wt, 1]: the forcing and the contact
offset k_c*gap become linear, so in each region (open: q_i <= gap, contact: q_i > gap) the flow
is exactly y(t + tau) = expm(A_r tau) y(t). A period is scanned on a grid of spacing h (at least
32 steps per period of the fastest in-region eigenvalue or of the forcing); in each grid step the
contact coordinate q_i(t) - gap is split at its extremum (a zero of v_i, found by brentq) into
monotone pieces, so that two crossings inside one step (a grazing touch) cannot be missed; each
crossing is located by brentq on the exact in-region solution. The vector field is continuous
across q_i = gap, so the saltation matrix is the identity and the monodromy matrix is the plain
product of the region exponentials between switches (their upper-left 2n x 2n blocks).
Periodic solutions: Newton on x(T) - x(0) = 0 with Jacobian (monodromy - I), pseudo-arclength
continuation in w (secant predictor, bordered Newton). Special points are bracketed by sign
changes of det(Phi - I) (LP: fold; BP if w is not extremal there), det(Phi + I) (PD), the
bialternate product prod_{i<j}(mu_i mu_j - 1) (NS; a real pair mu, 1/mu is a neutral saddle, not
a bifurcation), max q_i - gap and the number of contact phases per period (GR: grazing, a contact
phase starts or stops), and located by brentq on the arclength of the secant between the two
points, each trial point corrected onto the branch.

    /usr/bin/python3 scripts/reference/piecewise_linear_shooting.py all
    /usr/bin/python3 scripts/reference/piecewise_linear_shooting.py nlvib_two_dof two_dof_contact
"""
import argparse
import json
import math
import os
import re
import sys
import time

import numpy as np
from scipy.linalg import expm
from scipy.optimize import brentq

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
NEWTON_TOL = 1e-11      # on |x(T) - x(0)|; rounding over ~1000 steps is ~1e-13
STEPS_PER_FAST_PERIOD = 32


class UnilateralSystem:
    """The model; dofs are 0-based, `force` is the cos amplitude vector F."""

    def __init__(self, M, C, K, force, contact_dof, stiffness, gap):
        self.M, self.C, self.K = (np.atleast_2d(np.asarray(a, float)) for a in (M, C, K))
        self.force = np.asarray(force, float)
        self.n = self.M.shape[0]
        self.i, self.kc, self.gap = contact_dof, float(stiffness), float(gap)
        self.Minv = np.linalg.inv(self.M)

    def augmented_matrix(self, w, contact):
        n, i, K, offset = self.n, self.i, self.K.copy(), np.zeros(self.n)
        if contact:  # k_c (q_i - gap): stiffness on the diagonal, k_c*gap as a constant force
            K[i, i] += self.kc
            offset[i] = self.kc * self.gap
        A = np.zeros((2 * n + 3, 2 * n + 3))
        A[:n, n:2 * n] = np.eye(n)
        A[n:2 * n, :n] = -self.Minv @ K
        A[n:2 * n, n:2 * n] = -self.Minv @ self.C
        A[n:2 * n, 2 * n] = self.Minv @ self.force
        A[n:2 * n, 2 * n + 2] = self.Minv @ offset
        A[2 * n, 2 * n + 1], A[2 * n + 1, 2 * n] = -w, w
        return A

    def linear_response(self, w):
        """State at t = 0 of the periodic solution without the unilateral spring."""
        Q = np.linalg.solve(self.K - w * w * self.M + 1j * w * self.C, self.force.astype(complex))
        return np.concatenate([Q.real, -w * Q.imag])


class PeriodFlow:
    """The exact flow over one forcing period T = 2 pi / w, region by region."""

    def __init__(self, system, w):
        self.s, self.w, self.T = system, w, 2 * math.pi / w
        self.A = [system.augmented_matrix(w, c) for c in (False, True)]
        n2 = 2 * system.n
        fastest = max(w, *(np.abs(np.linalg.eigvals(A[:n2, :n2])).max() for A in self.A))
        # >= 32 steps per period of the fastest in-region motion: v_i then has at most one zero
        # per step except in degenerate near-inflection cases, so the extremum split below finds
        # every double crossing (grazing touch) inside a step.
        self.steps = max(64, math.ceil(self.T * fastest * STEPS_PER_FAST_PERIOD / (2 * math.pi)))
        self.h = self.T / self.steps
        self.E = [expm(A * self.h) for A in self.A]
        # Eigen-decompositions: cheap evaluation of the in-region solution inside root finding
        # and sampling (states are always re-propagated with expm, so they stay exact).
        self.eig = [(lam, V, np.linalg.inv(V)) if np.linalg.cond(V) < 1e8 else None
                    for lam, V in map(np.linalg.eig, self.A)]

    def state(self, r, y, tau):
        """y(tau) in region r from y(0) = y (tau scalar or array)."""
        if self.eig[r] is None:  # ill-conditioned eigenvectors: expm itself
            return np.squeeze(np.array([expm(self.A[r] * t) @ y for t in np.atleast_1d(tau)]).T)
        lam, V, Vinv = self.eig[r]
        return (V @ (np.exp(np.multiply.outer(lam, tau)).T * (Vinv @ y)).T).real

    def run(self, x0, keep_segments=False):
        """x(T), the monodromy matrix, the number of contact phases, and the segments
        (t_start, region, y_start) when asked."""
        n2 = 2 * self.s.n
        y = np.concatenate([x0, [1.0, 0.0, 1.0]])
        P = np.eye(n2 + 3)
        g = y[self.s.i] - self.s.gap
        r = 1 if g > 0 or (g == 0 and y[self.s.n + self.s.i] > 0) else 0
        segments, switches, r0, t = [(0.0, r, y.copy())], 0, r, 0.0
        for k in range(self.steps):
            b = self.T if k == self.steps - 1 else (k + 1) * self.h
            while True:
                span = b - t
                E = self.E[r] if t == k * self.h else expm(self.A[r] * span)
                yb = E @ y
                root = self.first_crossing(r, y, yb, span)
                if root is None:
                    y, P, t = yb, E @ P, b
                    break
                E = expm(self.A[r] * root)
                y, P, t = E @ y, E @ P, t + root
                r = 1 - r
                switches += 1
                if keep_segments:
                    segments.append((t, r, y.copy()))
        contacts = switches // 2 if switches else r0  # contact phases per period
        return y[:n2], P[:n2, :n2], contacts, segments

    def first_crossing(self, r, ya, yb, span):
        """Time (from ya) of the first crossing of q_i = gap within span, None if none."""
        i, vi, gap = self.s.i, self.s.n + self.s.i, self.s.gap
        side = 1.0 if r == 1 else -1.0
        g = lambda tau: self.state(r, ya, tau)[i] - gap
        pieces = [(0.0, ya[i] - gap, span, yb[i] - gap)]
        if ya[vi] * yb[vi] < 0:  # q_i has an extremum inside: split into monotone pieces
            te = brentq(lambda tau: self.state(r, ya, tau)[vi], 0.0, span, xtol=1e-15)
            ge = g(te)
            pieces = [(0.0, ya[i] - gap, te, ge), (te, ge, span, yb[i] - gap)]
        for p, gp, q, gq in pieces:
            if side * gq < 0:
                if side * gp <= 0:  # starts on the surface and leaves at once (tangency)
                    return p if p > 0 else 1e-300
                return brentq(g, p, q, xtol=1e-15)
        return None

    def extremes(self, segments, samples_per_step=2):
        """Max and min of each q over the period: fine sampling, then each candidate extremum
        refined by brentq on the velocity of the exact segment solution."""
        n = self.s.n
        starts = np.array([seg[0] for seg in segments])

        def at(t):
            t = t % self.T
            j = np.searchsorted(starts, t, side="right") - 1
            t0, r, y0 = segments[j]
            return self.state(r, y0, t - t0)

        times = np.linspace(0.0, self.T, self.steps * samples_per_step, endpoint=False)
        Y = np.column_stack([at(t) for t in times])
        out = []
        for d in range(n):
            q, best = Y[d], {}
            for sign in (1.0, -1.0):
                sq = sign * q
                span = sq.max() - sq.min()
                cand = [j for j in range(len(sq))
                        if sq[j] >= sq[j - 1] and sq[j] >= sq[(j + 1) % len(sq)]
                        and sq[j] >= sq.max() - 0.01 * span]
                value = sq.max()
                for j in cand:
                    a, b = times[j] - times[1], times[j] + times[1]
                    va, vb = sign * at(a)[n + d], sign * at(b)[n + d]
                    if va > 0 > vb:
                        tm = brentq(lambda t: at(t)[n + d], a, b, xtol=1e-14)
                        value = max(value, sign * at(tm)[d])
                best[sign] = sign * value
            out.append((best[1.0], best[-1.0]))
        return out


def newton_fixed_w(system, x, w, maxit=30):
    """Periodic solution at fixed w (plain Newton)."""
    flow = PeriodFlow(system, w)
    for _ in range(maxit):
        xT, Phi, _, _ = flow.run(x)
        R = xT - x
        if np.linalg.norm(R) < NEWTON_TOL:
            return x, Phi
        x = x - np.linalg.solve(Phi - np.eye(len(x)), R)
    raise RuntimeError(f"Newton at fixed w = {w} did not converge (|R| = {np.linalg.norm(R):.2e})")


def correct(system, u_pred, tangent, u_base, s, maxit=12):
    """Bordered Newton: R(x, w) = 0 and tangent . (u - u_base) = s. Returns (u, Phi) or None."""
    u, m = u_pred.copy(), len(u_pred) - 1
    for _ in range(maxit):
        x, w = u[:m], u[m]
        if not 0 < w < 1e6:
            return None
        xT, Phi, _, _ = PeriodFlow(system, w).run(x)
        R = xT - x
        g = tangent @ (u - u_base) - s
        if np.linalg.norm(R) < NEWTON_TOL and abs(g) < NEWTON_TOL:
            return u, Phi
        dw = 1e-7 * max(1.0, w)  # forward difference: only the convergence rate depends on it
        Rw = (PeriodFlow(system, w + dw).run(x)[0] - x - R) / dw
        J = np.zeros((m + 1, m + 1))
        J[:m, :m], J[:m, m], J[m] = Phi - np.eye(m), Rw, tangent
        u = u - np.linalg.solve(J, np.concatenate([R, [g]]))
    return None


def test_functions(system, u, Phi, extremes):
    I = np.eye(len(Phi))
    mu = np.linalg.eigvals(Phi)
    bialt = np.prod([mu[a] * mu[b] - 1 for a in range(len(mu)) for b in range(a + 1, len(mu))])
    return {"LP": np.linalg.det(Phi - I), "PD": np.linalg.det(Phi + I), "NS": bialt.real,
            "GR": extremes[system.i][0] - system.gap}


def point_record(system, u, Phi):
    flow = PeriodFlow(system, u[-1])
    _, _, contacts, segments = flow.run(u[:-1], keep_segments=True)
    extremes = flow.extremes(segments)
    mu = np.linalg.eigvals(Phi)
    mu = mu[np.lexsort((-mu.imag, -np.abs(mu)))]
    return {"u": u, "Phi": Phi, "mu": mu, "extremes": extremes, "contacts": contacts,
            "stable": bool(np.abs(mu).max() < 1), "tests": test_functions(system, u, Phi, extremes)}


def locate(system, p0, p1, kind):
    """Special point of test function `kind` between records p0 and p1, by brentq on the
    arclength along their secant (each trial point corrected onto the branch). Kind "GC": where
    the number of contact phases changes without max q_i crossing the gap (a secondary local
    maximum touches the gap, or two contact phases merge): brentq on a +-1 step is a bisection."""
    d = p1["u"] - p0["u"]
    L = np.linalg.norm(d)
    d = d / L
    cache = {}
    value = (lambda rec: 1.0 if rec["contacts"] == p0["contacts"] else -1.0) if kind == "GC" \
        else (lambda rec: rec["tests"][kind])

    def phi(s):
        if s <= 0 or s >= L:
            return value(p0 if s <= 0 else p1)
        done = correct(system, p0["u"] + s * d, d, p0["u"], s)
        if done is None:
            raise RuntimeError(f"corrector failed while locating {kind}")
        cache[s] = point_record(system, *done)
        return value(cache[s])

    s = brentq(phi, 0.0, L, xtol=1e-10 * max(1.0, L), rtol=1e-12)
    rec = cache.get(s) or point_record(system, *correct(system, p0["u"] + s * d, d, p0["u"], s))
    w, mu = rec["u"][-1], rec["mu"]
    label, crossing = ("GR" if kind == "GC" else kind), None
    if kind == "LP":
        crossing = mu[np.argmin(np.abs(mu - 1))]
        if (w - p0["u"][-1]) * (w - p1["u"][-1]) <= 0:
            label = "BP"  # det(Phi - I) = 0 where w is not extremal: a branch point
    elif kind == "PD":
        crossing = mu[np.argmin(np.abs(mu + 1))]
    elif kind == "NS":
        pairs = [(abs(mu[a] * mu[b] - 1), a, b) for a in range(len(mu)) for b in range(a + 1, len(mu))]
        _, a, b = min(pairs)
        crossing = mu[a] if mu[a].imag >= 0 else mu[b]
        if abs(mu[a].imag) < 1e-8:
            label = "neutral_saddle"  # real mu, 1/mu: not a bifurcation
    return {"type": label, "w": w, "x0": list(rec["u"][:-1]),
            "multiplier": None if crossing is None else [crossing.real, crossing.imag],
            "abs_multiplier": None if crossing is None else abs(crossing),
            "stable_before": p0["stable"], "stable_after": p1["stable"],
            "max_q": [e[0] for e in rec["extremes"]], "contacts_before": p0["contacts"],
            "contacts_after": p1["contacts"], "record": rec, "s": s}


def trace_branch(system, w_start, w_end, ds_max, ds_min=1e-6, max_points=5000, log=print):
    """Pseudo-arclength continuation of the periodic solution from w_start to w_end."""
    direction = 1.0 if w_end > w_start else -1.0
    x0 = system.linear_response(w_start)
    try:
        x0, Phi = newton_fixed_w(system, x0, w_start)
    except (RuntimeError, np.linalg.LinAlgError):
        flow = PeriodFlow(system, w_start)  # let the transient die out, then Newton
        for _ in range(2000):
            x0 = flow.run(x0)[0]
        x0, Phi = newton_fixed_w(system, x0, w_start)
    points = [point_record(system, np.append(x0, w_start), Phi)]
    w1 = w_start + direction * 0.1 * ds_max
    x1, Phi = newton_fixed_w(system, x0, w1)
    points.append(point_record(system, np.append(x1, w1), Phi))
    specials, ds = [], ds_max
    while len(points) < max_points:
        u_prev, u_last = points[-2]["u"], points[-1]["u"]
        t = (u_last - u_prev) / np.linalg.norm(u_last - u_prev)
        done = correct(system, u_last + ds * t, t, u_last, ds)
        if done is not None:
            step = done[0] - u_last
            turn = step @ t / np.linalg.norm(step)
        if done is None or (turn < 0.995 and ds > ds_min):  # failed, or bent too far: shorter
            ds = max(ds / 2, ds_min)
            if done is None and ds == ds_min:
                raise RuntimeError(f"continuation stuck at w = {u_last[-1]}")
            continue
        u, Phi = done
        if (u[-1] - w_end) * direction > 0:  # past the end: finish exactly at w_end
            x, Phi = newton_fixed_w(system, u_last[:-1] + (u[:-1] - u_last[:-1])
                                    * (w_end - u_last[-1]) / (u[-1] - u_last[-1]), w_end)
            u = np.append(x, w_end)
        rec = point_record(system, u, Phi)
        changed = [k for k in ("LP", "PD", "NS", "GR") if points[-1]["tests"][k] * rec["tests"][k] < 0]
        if points[-1]["contacts"] != rec["contacts"] and "GR" not in changed:
            changed.append("GC")
        for kind in changed:
            sp = locate(system, points[-1], rec, kind)
            sp["after"] = len(points) - 1  # where its record goes among the points
            specials.append(sp)
            log(f"  {sp['type']:>3} at w = {sp['w']:.9f}  multiplier {sp['multiplier']}")
        points.append(rec)
        if u[-1] == w_end:
            break
        ds = min(ds * 1.5, ds_max) if turn > 0.999 else ds
    return points, specials


# ---------------------------------------------------------------- cases
def nlvib_two_dof():
    K = np.array([[1.0, -1.0], [-1.0, 2.0]])
    return UnilateralSystem(np.eye(2), 0.03 * K, K, [0.0, 0.1], 0, 100.0, 1.0), 0.8, 0.5, 0.01


def two_dof_contact():
    K = np.array([[2.0, -1.0], [-1.0, 1.0]])
    return UnilateralSystem(np.eye(2), 0.02 * K, K, [0.1, 0.0], 1, 5.0, 0.5), 0.3, 2.0, 0.02


def chain(n, zeta=0.05, force=0.01, stiffness=2.0, gap=0.05):
    """examples/chain_contact.toml with n masses (its parameters, so that hbtrack's chain tests
    can run the example itself): a fixed-free chain of unit masses and springs (ground - k - m0 -
    k - ... - m_{n-1}), modal damping zeta on every mode, force on mass 0, the unilateral spring
    at the free end; the linear tip peak is 2.3 (n = 2) and 2.5 (n = 8) gaps. Range 0.6 .. 1.6
    times the first natural frequency, as bench/bench_chain.cpp."""
    K = 2 * np.eye(n) - np.eye(n, k=1) - np.eye(n, k=-1)
    K[-1, -1] = 1.0
    lam, Phi = np.linalg.eigh(K)  # unit masses: mass-normalised modes, C = Phi diag(2 zeta w) Phi^T
    C = Phi @ np.diag(2 * zeta * np.sqrt(lam)) @ Phi.T
    F = np.zeros(n)
    F[0] = force
    w1 = 2 * math.sin(math.pi / (2 * (2 * n + 1)))
    return UnilateralSystem(np.eye(n), C, K, F, n - 1, stiffness, gap), 0.6 * w1, 1.6 * w1, 0.004


# w windows of the figures' right-hand zoom panels, around the special points
ZOOM = {"nlvib_two_dof": (0.733, 0.7575), "two_dof_contact": (0.655, 0.775), "chain_2": (0.675, 0.722),
        "chain_8": (0.205, 0.212)}
CASES = {"nlvib_two_dof": nlvib_two_dof, "two_dof_contact": two_dof_contact,
         "chain_2": lambda: chain(2), "chain_8": lambda: chain(8)}


# ---------------------------------------------------------------- outputs
def thin(points, system, rows=300):
    """The points kept in the CSV: about `rows` of them, evenly spread along the curve of
    (w, max q of every dof) scaled to unit ranges, plus every point next to a stability change
    (the continuation itself takes far more, short steps where multipliers turn fast)."""
    X = np.array([[p["u"][-1]] + [e[0] for e in p["extremes"]] for p in points])
    X = (X - X.min(0)) / np.maximum(np.ptp(X, 0), 1e-300)
    stable = [p["stable"] for p in points]
    spacing = np.linalg.norm(np.diff(X, axis=0), axis=1).sum() / rows
    keep, last = [0], X[0]
    for k in range(1, len(points)):
        edge = k == len(points) - 1 or stable[k] != stable[k - 1] or stable[k] != stable[k + 1] \
            or "special" in points[k]
        if edge or np.linalg.norm(X[k] - last) >= spacing:
            keep.append(k)
            last = X[k]
    return [points[k] for k in keep]


def with_special_points(points, specials):
    """The branch with the located special points inserted where they lie (rows marked by
    their type), so that the CSV and the curves pass through them."""
    merged = []
    for k, p in enumerate(points):
        merged.append(p)
        for sp in sorted((sp for sp in specials if sp["after"] == k), key=lambda sp: sp["s"]):
            merged.append(dict(sp["record"], special=sp["type"]))
    return merged


def mark_grazing(specials):
    """Flags special points within 1e-5 in w (and 1e-3 in max q) of a grazing point: there the
    multipliers vary like the square root of the penetration, so a multiplier can cross the unit
    circle within a tiny interval of w (a nonsmooth bifurcation, not a smooth one)."""
    grazes = [sp for sp in specials if sp["type"] == "GR"]
    for sp in specials:
        if sp["type"] != "GR":
            sp["at_grazing"] = any(abs(sp["w"] - g["w"]) < 1e-5 and
                                   max(abs(a - b) for a, b in zip(sp["max_q"], g["max_q"])) < 1e-3
                                   for g in grazes)

def write_outputs(name, system, points, specials, folder, figure):
    os.makedirs(folder, exist_ok=True)
    n = system.n
    head = ["w"] + [f"q{d}_{m}" for d in range(n) for m in ("max", "min")] + \
           ["stable", "max_abs_mu", "contacts"] + [f"x0_{k}" for k in range(2 * n)] + \
           [f"mu{k}_{p}" for k in range(2 * n) for p in ("re", "im")] + ["special"]
    mark_grazing(specials)
    computed = len(points)
    points = with_special_points(points, specials)
    rows = thin(points, system)
    with open(os.path.join(folder, "branch.csv"), "w") as f:
        f.write(",".join(head) + "\n")
        for p in rows:
            row = [p["u"][-1]] + [v for e in p["extremes"] for v in e] + \
                  [int(p["stable"]), np.abs(p["mu"]).max(), p["contacts"]] + list(p["u"][:-1]) + \
                  [v for m in p["mu"] for v in (m.real, m.imag)] + [p.get("special", "")]
            f.write(",".join(f"{v:.11g}" if isinstance(v, float) else str(v) for v in row) + "\n")
    model = {"M": system.M.tolist(), "C": system.C.tolist(), "K": system.K.tolist(),
             "force_cos": system.force.tolist(), "contact_dof": system.i,
             "contact_stiffness": system.kc, "gap": system.gap}
    summary = {"case": name, "model": model,
               "equation": "M q'' + C q' + K q + k_c max(q_i - gap, 0) e_i = F cos(w t), dofs 0-based",
               "w_range": [points[0]["u"][-1], points[-1]["u"][-1]],
               "points_computed": computed, "points_in_csv": len(rows),
               "newton_tolerance": NEWTON_TOL,
               "special_points": [{k: v for k, v in sp.items() if k not in ("record", "s", "after")}
                                  for sp in specials]}
    text = json.dumps(summary, indent=1)
    # one line per innermost list (multipliers, states, matrix rows)
    text = re.sub(r"\[\s+([^\[\]{}]*?)\s+\]", lambda m: "[" + re.sub(r"\s+", " ", m.group(1)) + "]", text)
    with open(os.path.join(folder, "special_points.json"), "w") as f:
        f.write(text + "\n")
    plot(name, folder, figure)


# What each case's figure says it shows (its title), and a name per dof: masses numbered from 1
# in the figures (the CSV's q0, q1, ... are 0-based).
TITLES = {"nlvib_two_dof": "NLvib's two-DOF oscillator, unilateral spring on mass 1",
          "two_dof_contact": "examples/two_dof_contact: two masses, unilateral spring on mass 2",
          "chain_2": "Chain of 2 masses, unilateral spring on the tip (mass 2)",
          "chain_8": "Chain of 8 masses, unilateral spring on the tip (mass 8)"}


def dof_description(model, d):
    """"mass 1 (forced)", "mass 2 (unilateral spring, gap 0.5)": what a panel shows."""
    roles = (["forced"] if model["force_cos"][d] else []) + \
            ([f"unilateral spring, gap {model['gap']:g}"] if d == model["contact_dof"] else [])
    return f"mass {d + 1}" + (f" ({', '.join(roles)})" if roles else "")


def plot(name, folder, figure):
    """The figure of one case, from its stored branch.csv and special_points.json (so that it can
    be redrawn without the continuation: --redraw): per drawn dof (the forced one and the
    contact one) the max over a period against w, stable solid, unstable dashed (hbtrack's
    figure_style), every located special point marked once per panel by type, the legend naming
    each type and its count; a right-hand column zooms on ZOOM[name] (shaded on the left)."""
    sys.path.insert(0, os.path.join(ROOT, "python"))  # hbtrack's plotting needs no build
    from hbtrack.figure_style import (OMEGA_LABEL, SPECIAL_MARKERS, _plot_split, _stable_masks, length_label,
                                      marker_legend, plt, stability_legend)
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch
    with open(os.path.join(folder, "special_points.json")) as f:
        stored = json.load(f)
    model, specials = stored["model"], stored["special_points"]
    with open(os.path.join(folder, "branch.csv")) as f:
        head = f.readline().strip().split(",")
        rows = [line.rstrip("\n").split(",") for line in f]
    column = {h: k for k, h in enumerate(head)}
    n = len(model["M"])
    branch = {"omega": np.array([float(r[column["w"]]) for r in rows]),
              "stable": np.array([int(r[column["stable"]]) for r in rows])}
    stable, unstable = _stable_masks(branch)
    forced = [d for d in range(n) if model["force_cos"][d]]
    dofs = sorted(set(forced[:1]) | {model["contact_dof"]})
    zoom = ZOOM.get(name)
    if zoom and not any(zoom[0] <= sp["w"] <= zoom[1] for sp in specials):
        zoom = None
    cols = 1 if zoom is None else 2
    fig, axes = plt.subplots(len(dofs), cols, figsize=(6.2 * cols, 2.9 * len(dofs) + 0.8), squeeze=False)
    w = branch["omega"]
    counts = {t: sum(sp["type"] == t for sp in specials) for t in SPECIAL_MARKERS}
    for row, d in zip(axes, dofs):
        amp = np.array([float(r[column[f"q{d}_max"]]) for r in rows])
        for col, ax in enumerate(row):
            _plot_split(ax, w, amp, stable, unstable, "C0", None)
            for sp in specials:
                # LP larger, under the others: a PD or GR on a fold (nlvib, chain_8) shows inside its ring
                ax.plot(sp["w"], sp["max_q"][d], SPECIAL_MARKERS[sp["type"]][0], color="k", mfc="w", mew=1.0,
                        ms=(9 if sp["type"] == "LP" else 6) - col, ls="none", zorder=4 if sp["type"] == "LP" else 5)
            if d == model["contact_dof"]:
                ax.axhline(model["gap"], color="0.6", lw=0.8, ls=":")
            if col == 0 and zoom:
                ax.axvspan(*zoom, color="0.9", zorder=0)
            if col == 1:  # the zoom: y fitted to the stretch of branch from its first to its last special point there
                marked = [k for k, r in enumerate(rows) if r[column["special"]] and zoom[0] <= w[k] <= zoom[1]]
                pad = max(3, round(20 * len(rows) / stored["points_computed"]))  # rows, about 20 continuation points
                part = slice(max(marked[0] - pad, 0), marked[-1] + pad + 1)
                inside = amp[part][(w[part] >= zoom[0]) & (w[part] <= zoom[1])]
                pad = 0.05 * np.ptp(inside)
                ax.set(xlim=zoom, ylim=(inside.min() - pad, inside.max() + pad))
            ax.set_title(dof_description(model, d) + (", zoom" if col == 1 else ""), fontsize=9)
            ax.set_ylabel(length_label("max over a period"), fontsize=9)
            ax.set_xlabel(OMEGA_LABEL)
            ax.grid(alpha=0.3)
    handles = stability_legend([branch])
    for h in marker_legend({t for t, c in counts.items() if c}):
        kind = next(t for t, (_, text) in SPECIAL_MARKERS.items() if text == h.get_label())
        h.set_label(f"{h.get_label()}: {counts[kind]}")
        handles.append(h)
    handles.append(Line2D([], [], color="0.6", lw=0.8, ls=":", label="gap"))
    if zoom:
        handles.append(Patch(color="0.9", label="window zoomed on the right"))
    height, legend_rows = fig.get_figheight(), -(-len(handles) // 4)  # inches; the legend, 4 columns
    fig.suptitle(f"{TITLES.get(name, name)}: exact shooting", fontsize=10, y=1 - 0.08 / height, va="top")
    fig.legend(handles=handles, fontsize=8, ncol=min(len(handles), 4), loc="upper center",
               bbox_to_anchor=(0.5, 1 - 0.3 / height), frameon=False)
    fig.tight_layout(rect=(0, 0, 1, 1 - (0.35 + 0.2 * legend_rows) / height))
    os.makedirs(os.path.dirname(figure), exist_ok=True)
    fig.savefig(figure, dpi=110)  # PNG only: the pages show PNGs
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("cases", nargs="+", help=f"{', '.join(CASES)} or all")
    parser.add_argument("--out", default=os.path.join(ROOT, "tests", "data", "shooting"))
    parser.add_argument("--figures", default=os.path.join(ROOT, "docs", "figures"))
    parser.add_argument("--redraw", action="store_true",
                        help="only redraw the figures from the stored branch.csv and special_points.json (seconds)")
    args = parser.parse_args(argv)
    names = list(CASES) if args.cases == ["all"] else args.cases
    for name in names:
        if args.redraw:
            plot(name, os.path.join(args.out, name), os.path.join(args.figures, f"shooting_{name}.png"))
            continue
        system, w_start, w_end, ds_max = CASES[name]()
        print(f"{name}: w {w_start:g} -> {w_end:g}", flush=True)
        t0 = time.time()
        points, specials = trace_branch(system, w_start, w_end, ds_max)
        seconds = time.time() - t0
        print(f"  {len(points)} points in {seconds:.1f} s", flush=True)
        write_outputs(name, system, points, specials, os.path.join(args.out, name),
                      os.path.join(args.figures, f"shooting_{name}.png"))


if __name__ == "__main__":
    sys.exit(main())
