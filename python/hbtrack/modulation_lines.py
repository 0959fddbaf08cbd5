"""The spectral lines of a quasi-periodic time integration around its forcing frequency.

A torus with base frequencies (omega, omega2) has lines at k1 omega + k2 omega2 only; a line at
omega +- omega2 / 2 says the motion's modulation has doubled its period (a torus doubling), a
line at neither says a third frequency. :func:`modulation_lines` lists the strongest lines of one
output of a ``simulate`` record, :func:`modulation_frequency` the offset of the strongest
sideband: the simulation's omega2, to compare with a torus row's (docs/analyses.md, "Rotor 67's
band")."""
import numpy as np

# Hann's first sidelobe is 31.5 dB below its main lobe, 2.4 resolutions off the line, and the
# sidelobes fall as the cube of the distance (18 dB per octave): a peak weaker than 1.5 times that
# envelope of a stronger line may be its leakage, and is not reported.
_FIRST_SIDELOBE, _FIRST_SIDELOBE_AT = 10.0 ** (-31.5 / 20.0), 2.4


def _leakage_level(distance):
    """The level, relative to a line, below which a peak `distance` resolutions away may be its leakage."""
    return 1.5 * _FIRST_SIDELOBE * min(1.0, (_FIRST_SIDELOBE_AT / max(distance, 1e-12)) ** 3)


def _record(simulation, name):
    signals = simulation["signals"]
    if name not in signals:
        outputs = [c for c in signals if c != "time"]
        raise ValueError(f"name: {name!r} is not an output of this simulation (outputs: {', '.join(outputs)})")
    time, x = np.asarray(signals["time"], float), np.asarray(signals[name], float)
    if len(time) < 16:
        raise ValueError(f"signals: {len(time)} samples, too few for a spectrum (record more periods)")
    step = np.diff(time)
    if np.ptp(step) > 1e-6 * np.mean(step):
        raise ValueError("signals: the samples are not evenly spaced in time (a record resampled to its periods is)")
    return float(np.mean(step)), x - np.mean(x)


def modulation_lines(simulation, name, *, around=None, width=None, count=8):
    """The strongest lines of output `name` of a time integration, near `around`.

    Hann window, the record zero-padded to 16 times its length or more, each peak refined by a
    parabola through the log magnitudes of its three samples: a line's frequency comes out to a
    few hundredths of the resolution 2 pi / (record length), its amplitude relative to the
    strongest line's to a few per cent. A peak weaker than 1.5 times the Hann sidelobes' envelope
    of a stronger line (-31.5 dB 2.4 resolutions away, falling as the cube of the distance) is
    dropped: it may be that line's leakage (so is a real line that weak and that close).

    Parameters
    ----------
    simulation : dict
        A simulate result (``hbtrack simulate`` folder read by :func:`hbtrack.read_result`, or
        :func:`hbtrack.simulate`) whose record spans many modulation periods, after the transient.
    name : str
        An output's name.
    around : float, optional
        The centre of the band searched, in rad/s: default the simulation's omega.
    width : float, optional
        The band's half width: default half of `around` (the sidebands k2 omega2 of a torus born at
        an NS point lie within omega / 2 of omega).
    count : int
        How many lines, strongest first.

    Returns
    -------
    list of (float, float)
        (frequency in rad/s, amplitude relative to the strongest line in the band), strongest first.

    Examples
    --------
    >>> lines = modulation_lines(read_result("out/r67_sim_2100"), "te")
    >>> [round(f - 2099.674, 2) for f, _ in lines[:3]]     # the carrier and the two sidebands
    """
    return _lines(simulation, name, around, width)[0][:count]


def _lines(simulation, name, around=None, width=None):
    """Every line kept (strongest first, relative amplitudes) and the record's resolution."""
    dt, x = _record(simulation, name)
    omega = float(simulation["summary"]["omega"]) if around is None else float(around)
    half = 0.5 * omega if width is None else float(width)
    padded = 1 << int(np.ceil(np.log2(16 * len(x))))
    magnitude = np.abs(np.fft.rfft(x * np.hanning(len(x)), padded))
    frequency = np.fft.rfftfreq(padded, d=dt) * 2.0 * np.pi
    bin_width, resolution = frequency[1], 2.0 * np.pi / (dt * len(x))
    inside = np.nonzero((frequency > omega - half) & (frequency < omega + half))[0]
    inside = inside[(inside > 0) & (inside < len(magnitude) - 1)]
    peaks = [j for j in inside if magnitude[j] > magnitude[j - 1] and magnitude[j] >= magnitude[j + 1]]
    lines = []
    for j in peaks:
        a, b, c = np.log(magnitude[j - 1 : j + 2] + 1e-300)
        curvature = a - 2.0 * b + c
        shift = 0.5 * (a - c) / curvature if curvature < 0 else 0.0
        lines.append((frequency[j] + shift * bin_width, float(np.exp(b - 0.25 * (a - c) * shift))))
    lines.sort(key=lambda line: -line[1])
    kept = []
    for f, size in lines:
        leaked = any(size < _leakage_level(abs(f - g) / resolution) * other for g, other in kept)
        if not leaked:
            kept.append((f, size))
    strongest = kept[0][1] if kept else 1.0
    return [(float(f), size / strongest) for f, size in kept], resolution


def _second_frequency(lines, omega, resolution, name="x"):
    """omega2 from lines (as :func:`modulation_lines` returns them, strongest first): the offset of
    the strongest one more than 2.5 resolutions from omega. ValueError when there is none."""
    for f, _ in lines:
        if abs(f - omega) > 2.5 * resolution:
            return abs(f - omega)
    raise ValueError(f"signals: no line of {name!r} beside omega = {omega}: the record looks periodic")


def modulation_frequency(simulation, name):
    """The simulation's second frequency omega2: the offset from omega of its strongest sideband.

    The strongest line of output `name` within omega / 2 of omega other than omega itself (a
    torus' first sidebands omega +- omega2 are its strongest off the carrier when its modulation is
    weak); :func:`modulation_lines` says how it is found and to what accuracy.

    Parameters
    ----------
    simulation : dict
        A simulate result (its record after the transient, many modulation periods long).
    name : str
        An output's name.

    Returns
    -------
    float
        omega2 in rad/s, at most omega / 2.

    Examples
    --------
    >>> modulation_frequency(read_result("out/r67_sim_2100"), "te")
    """
    omega = float(simulation["summary"]["omega"])
    lines, resolution = _lines(simulation, name)
    return _second_frequency(lines, omega, resolution, name)
