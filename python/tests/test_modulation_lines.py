"""modulation_lines / modulation_frequency on records whose lines are known: a torus' sidebands,
a doubled modulation's half-frequency lines, a periodic record, bad input."""
import numpy as np
import pytest

from hbtrack.modulation_lines import modulation_frequency, modulation_lines

OMEGA, OMEGA2 = 10.0, 0.7312  # omega / omega2 irrational enough: no line falls on another


def record(terms, periods=300, per_period=64):
    """A simulate-like result: sum of a cos((OMEGA + k OMEGA2) t + phase) over (a, k, phase)."""
    t = np.arange(periods * per_period) * (2.0 * np.pi / OMEGA) / per_period
    x = sum(a * np.cos((OMEGA + k * OMEGA2) * t + phase) for a, k, phase in terms)
    return {"summary": {"omega": OMEGA}, "signals": {"time": t, "x": x}}, 2.0 * np.pi / (t[1] * len(t))


TORUS = [(1.0, 0, 0.0), (0.2, -1, 0.3), (0.1, 1, 1.1), (0.03, -2, 2.0)]


def test_a_torus_record_gives_its_sidebands_and_its_second_frequency():
    simulation, resolution = record(TORUS)
    lines = modulation_lines(simulation, "x", count=4)
    # The parabola through three log magnitudes of the Hann window places an isolated line to about
    # 1e-3 of a resolution (2 pi / record length); a neighbour's leakage adds a little: 0.01 allowed.
    for (f, size), (a, k, _) in zip(lines, TORUS):
        assert f == pytest.approx(OMEGA + k * OMEGA2, abs=0.01 * resolution)
        assert size == pytest.approx(a, rel=0.02)  # relative to the carrier's, within the scalloping
    assert modulation_frequency(simulation, "x") == pytest.approx(OMEGA2, abs=0.01 * resolution)
    # No line at omega +- omega2 / 2: a torus has only k1 omega + k2 omega2.
    assert all(abs(abs(f - OMEGA) - 0.5 * OMEGA2) > 3 * resolution for f, _ in modulation_lines(simulation, "x", count=20))


def test_a_doubled_modulation_shows_lines_at_half_the_second_frequency():
    simulation, resolution = record(TORUS + [(0.02, 0.5, 0.7), (0.015, -1.5, 0.1)])
    lines = modulation_lines(simulation, "x", count=6)
    halves = [(f, size) for f, size in lines if abs(abs(f - OMEGA) / OMEGA2 - round(abs(f - OMEGA) / OMEGA2)) > 0.25]
    assert [round((f - OMEGA) / OMEGA2, 2) for f, _ in halves] == [0.5, -1.5]
    assert [size for _, size in halves] == pytest.approx([0.02, 0.015], rel=0.05)


def test_leakage_of_a_strong_line_is_not_reported_as_a_line():
    simulation, resolution = record([(1.0, 0, 0.0)])
    lines = modulation_lines(simulation, "x", count=10)
    assert lines[0][0] == pytest.approx(OMEGA, abs=0.01 * resolution)
    # Hann's sidelobes (-31.5, -41, -48 dB within 6 resolutions) are dropped; what is left is far
    # from the line and weaker than its fourth sidelobe (-53 dB).
    assert all(abs(f - OMEGA) > 6 * resolution and size < 10 ** (-53 / 20) for f, size in lines[1:])


def test_a_periodic_record_has_no_second_frequency():
    simulation, _ = record([(1.0, 0, 0.0)])
    with pytest.raises(ValueError, match="no line of 'x' beside omega = 10.0: the record looks periodic"):
        modulation_frequency(simulation, "x")


def test_bad_input_names_the_field():
    simulation, _ = record(TORUS)
    with pytest.raises(ValueError, match=r"name: 'y' is not an output of this simulation \(outputs: x\)"):
        modulation_lines(simulation, "y")
    short = {"summary": {"omega": OMEGA}, "signals": {"time": np.arange(8.0), "x": np.ones(8)}}
    with pytest.raises(ValueError, match="signals: 8 samples, too few for a spectrum"):
        modulation_lines(short, "x")
    uneven = {"summary": {"omega": OMEGA}, "signals": {"time": np.arange(64.0) ** 1.5, "x": np.ones(64)}}
    with pytest.raises(ValueError, match="signals: the samples are not evenly spaced"):
        modulation_lines(uneven, "x")
