"""Cost of an element written in Python against the built-in one: the Duffing NFRC
(examples/duffing.toml, H = 7, N = 64) with the built-in cubic spring, then with the same law as a
Python callable returning its derivative, then with central differences for it.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_element_speed.py [repeats]
"""
import sys
import time

import numpy as np

import hbtrack


def duffing(elements=()):
    return hbtrack.case_from_arrays(
        M=np.array([[1.0]]), K=np.array([[1.0]]), C=np.array([[0.05]]), dofs=["x"],
        forcing=[{"dof": "x", "harmonic": 1, "cos": 0.18}], parameters={"amplitude": 1.0},
        elements=list(elements), harmonic_balance={"harmonics": 7, "samples": 64},
        continuation={"omega_start": 0.5, "omega_end": 1.6, "step": 0.02})


def best_time(make_case, repeats):
    times = []
    for _ in range(repeats):
        case = make_case()
        t0 = time.perf_counter()
        result = hbtrack.frc(case)
        times.append(time.perf_counter() - t0)
    return min(times), len(result["branch"]["omega"])


def main():
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    builtin = best_time(lambda: duffing([{"type": "cubic_spring", "dofs": ["x"], "cubic_stiffness": 0.1}]), repeats)
    exact = best_time(lambda: hbtrack.add_python_element(duffing(), ["x"], lambda x, v: (0.1 * x**3, (0.3 * x**2)[:, :, None])), repeats)
    fd = best_time(lambda: hbtrack.add_python_element(duffing(), ["x"], lambda x, v: 0.1 * x**3), repeats)
    print(f"built-in cubic_spring        {builtin[0] * 1e3:8.2f} ms  ({builtin[1]} points)")
    print(f"python, with derivative      {exact[0] * 1e3:8.2f} ms  ({exact[1]} points)  ratio {exact[0] / builtin[0]:.2f}")
    print(f"python, central differences  {fd[0] * 1e3:8.2f} ms  ({fd[1]} points)  ratio {fd[0] / builtin[0]:.2f}")


if __name__ == "__main__":
    main()
