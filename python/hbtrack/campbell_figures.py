"""The Campbell diagram of `hbtrack modes CASE --speeds LO:HI:N` (or hbtrack.campbell): each
mode's frequency against the rotation speed, the engine-order lines k W, and their crossings.
"""
import os

import numpy as np

from .figure_style import plt, save_figure


def campbell_figure(result, engine_orders=8, title=None, speed_unit="rad/s", path=None):
    """The Campbell diagram of a result.

    Parameters
    ----------
    result : dict
        ``hbtrack.campbell(...)`` or ``read_result(DIR)`` of a ``modes --speeds`` folder: its
        ``campbell`` table (``speed``, then a column per mode) and ``summary``.
    engine_orders : int, optional
        Draw the lines w = k W for k = 1 .. engine_orders (default 8) and mark the summary's
        crossings up to that order.
    title : str, optional
        A title (default none).
    speed_unit : str, optional
        "rad/s" (default) or "rpm" for the speed axis; frequencies stay in rad/s.
    path : str, optional
        Also save it as PATH.png and PATH.pdf (a .png or .pdf extension given is dropped).

    Returns
    -------
    matplotlib.figure.Figure
        The figure.

    Examples
    --------
    >>> figure = campbell_figure(read_result("out/r67-campbell"), engine_orders=4, path="campbell.png")
    """
    table = result["campbell"]
    speed = np.asarray(table["speed"], dtype=float)
    scale = 30.0 / np.pi if speed_unit == "rpm" else 1.0
    names = [n for n in table if n != "speed"]
    fig, ax = plt.subplots(figsize=(7.0, 5.0))
    top = max(float(np.max(table[n])) for n in names) * 1.05
    for k in range(1, engine_orders + 1):
        ax.plot(speed * scale, k * speed, color="0.75", linewidth=0.8, zorder=1)
        if k * speed[-1] < top:
            ax.annotate(f"{k}EO", (speed[-1] * scale, k * speed[-1]), xytext=(3, 0), textcoords="offset points", fontsize=8,
                        color="0.45", va="center")
        else:
            end = top / k
            ax.annotate(f"{k}EO", (end * scale, top), xytext=(0, 2), textcoords="offset points", fontsize=8, color="0.45",
                        ha="center", va="bottom")
    for name in names:
        ax.plot(speed * scale, table[name], linewidth=1.8, label=name, zorder=3)
    for crossing in result["summary"].get("engine_order_crossings", []):
        if crossing["engine_order"] <= engine_orders:
            ax.plot(crossing["speed"] * scale, crossing["frequency"], "o", markersize=4, markerfacecolor="white",
                    markeredgecolor="black", zorder=4)
    ax.set_xlim(speed[0] * scale, speed[-1] * scale * 1.08)
    ax.set_ylim(0, top)
    ax.set_xlabel(f"rotation speed $\\Omega$ [{speed_unit}]")
    ax.set_ylabel(r"natural frequency $\omega$ [rad/s]")
    ax.grid(True, linewidth=0.3)
    ax.legend(loc="upper left", fontsize=9, framealpha=0.9)
    if title:
        ax.set_title(title)
    fig.tight_layout()
    if path:
        stem, extension = os.path.splitext(path)
        save_figure(fig, stem if extension in (".png", ".pdf") else path)
    return fig
