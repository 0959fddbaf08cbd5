"""The view of a 3D figure: the azimuth from which its curves hide each other least.

No one view suits every tracking figure. On the blade study (examples/blade/nominal.toml) the
amplitude curve's two branches from the cusp lie on top of each other seen from azimuth -120
and apart from -30 to -60, while the mu curve, whose folds and extrema crowd where it runs
towards the viewer, reads only from -120 to -135. So the figure counts, for each azimuth, the
pairs of points of its curves that are far apart in the box yet drawn on top of each other, and
takes the azimuth with fewest (matplotlib's default, -60, when several tie).
"""
import numpy as np

# Degrees above the (omega, parameter) plane: enough to separate the curves' levels, low enough
# that the response axis stays tall.
ELEVATION = 25.0
# Never within 30 degrees of looking along omega: the validation NFRCs, drawn in their planes of
# constant parameter, would be seen edge-on, as lines.
AZIMUTHS = tuple(range(-150, -29, 15))
DEFAULT_AZIMUTH = -60.0
# Of the box's width: points drawn closer than NEAR hide each other, unless they are within FAR
# in the box (neighbours along one curve).
NEAR = 0.02
FAR = 0.1
# matplotlib's 3D box is 4 x 4 x 3.
BOX = np.array([1.0, 1.0, 0.75])


def least_hidden_view(curves, limits, elevation=ELEVATION, azimuths=AZIMUTHS, samples=400):
    """The (elevation, azimuth) from which the curves hide each other least.

    Parameters
    ----------
    curves : sequence of (x, y, z) arrays
        The curves as drawn (omega, parameter, response).
    limits : sequence of 3 (low, high)
        The axes' limits, which scale each coordinate to the box.
    elevation : float, optional
        Degrees, kept as it is.
    azimuths : sequence of float, optional
        Degrees, the candidates.
    samples : int, optional
        Points compared at the most (evenly spread over all the curves).

    Returns
    -------
    (float, float)
        For Axes3D.view_init(elev, azim).

    Examples
    --------
    >>> elev, azim = least_hidden_view([(omega, amplitude, response)], [ax.get_xlim(), ax.get_ylim(), ax.get_zlim()])
    >>> ax.view_init(elev, azim)
    """
    parts = [np.column_stack([np.asarray(c, float) for c in curve]) for curve in curves]
    points = np.vstack(parts) if parts else np.empty((0, 3))
    points = points[np.all(np.isfinite(points), axis=1)]
    if len(points) < 2:
        return elevation, DEFAULT_AZIMUTH
    low = np.array([lo for lo, _ in limits], float)
    span = np.array([hi - lo for lo, hi in limits], float)
    span[span == 0] = 1.0
    points = (points - low) / span * BOX
    if len(points) > samples:
        points = points[np.linspace(0, len(points) - 1, samples).astype(int)]
    far = np.linalg.norm(points[:, None] - points[None], axis=2) > FAR
    best = None
    for azimuth in sorted(azimuths, key=lambda a: abs(a - DEFAULT_AZIMUTH)):
        e, a = np.radians(elevation), np.radians(azimuth)
        towards_viewer = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
        drawn = points - np.outer(points @ towards_viewer, towards_viewer)
        hidden = np.count_nonzero((np.linalg.norm(drawn[:, None] - drawn[None], axis=2) < NEAR) & far)
        if best is None or hidden < best[0]:
            best = (hidden, float(azimuth))
    return float(elevation), best[1]
