"""An animated GIF of one simulation: the road from above, every vehicle as a labelled box, the
time, and which phase of the scenario the monitor's run was in; the view follows the vehicles.

Frames are taken every ``frame_dt`` seconds (0.2 s by default, half the samples of the trace), which
keeps a 20 s run to about a hundred frames and the file small enough to attach to a CI report.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..monitor import Verdict
from ..simulation import Simulation
from ..simulation.geometry import CAR_LENGTH, CAR_WIDTH
from .files import replaced
from .plot import COLOURS


def animate_simulation(simulation: Simulation, verdict: Verdict | None, path: str | Path, title: str = "", frame_dt: float = 0.2) -> Path:
    """Write the GIF atomically (a temporary file renamed into place) and return its path."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.animation import FuncAnimation, PillowWriter
    from matplotlib.patches import Rectangle
    from matplotlib.transforms import Affine2D

    path = Path(path)
    trace, road = simulation.trace, simulation.road
    stride = max(1, int(round(frame_dt / simulation.dt)))
    frames = list(range(0, len(trace), stride))
    if frames[-1] != len(trace) - 1:
        frames.append(len(trace) - 1)
    names = list(trace.actors)
    xs = np.array([trace.actors[v]["x"] for v in names])
    width = max(60.0, float(np.ptp(xs, axis=0).max()) + 30.0)  # wide enough to show every vehicle at once

    figure, axes = plt.subplots(figsize=(10, 2.6))
    axes.set_ylim(-0.5, road.width + 0.5)
    axes.set_aspect("equal")
    axes.set_yticks([road.center_y(lane) for lane in range(road.lanes)], [f"lane {road.lanes - lane}" for lane in range(road.lanes)])
    axes.set_xlabel("x [m]")
    for boundary in range(road.lanes + 1):
        style = "-" if boundary in (0, road.lanes) else "--"
        axes.axhline(boundary * road.lane_width, linestyle=style, color="grey", linewidth=0.8)
    boxes, labels = [], []
    for index, name in enumerate(names):
        colour = COLOURS[index % len(COLOURS)]
        box = Rectangle((-CAR_LENGTH / 2, -CAR_WIDTH / 2), CAR_LENGTH, CAR_WIDTH, color=colour, alpha=0.85)
        axes.add_patch(box)
        boxes.append(box)
        labels.append(axes.text(0, 0, name, color=colour, fontsize=8, weight="bold", ha="center", va="bottom"))
    clock = axes.set_title("")
    phases = _phases(verdict, trace.times) if verdict is not None else None

    def draw(k: int):
        centre = float(xs[:, k].mean())
        axes.set_xlim(centre - width / 2, centre + width / 2)
        for index, name in enumerate(names):
            columns = trace.actors[name]
            x, y, heading = float(columns["x"][k]), float(columns["y"][k]), float(columns["heading"][k])
            boxes[index].set_transform(Affine2D().rotate(heading).translate(x, y) + axes.transData)
            labels[index].set_position((x, y + CAR_WIDTH / 2 + 0.2))
        phase = f"   {phases[k]}" if phases is not None else ""
        clock.set_text(f"{title}   t = {trace.times[k]:5.1f} s{phase}")
        return [*boxes, *labels, clock]

    animation = FuncAnimation(figure, draw, frames=frames, blit=False)
    try:
        with replaced(path) as temporary:
            animation.save(temporary, writer=PillowWriter(fps=max(1, int(round(1 / (stride * simulation.dt))))))
    finally:
        plt.close(figure)
    return path


def _phases(verdict: Verdict, times: np.ndarray) -> list[str]:
    """For every sample, the last transition of the monitor's run taken by then (its events)."""
    labels = ["before the scenario"] * len(times)
    for t, events in verdict.run:
        k = int(np.searchsorted(times, t - 1e-9))
        labels[k:] = [events] * (len(times) - k)
    return labels
