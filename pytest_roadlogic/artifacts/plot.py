"""A picture of one simulation: the road from above with every vehicle's path, and position over
time, with the instants at which the monitor's run met each guard marked on both."""

from __future__ import annotations

import warnings
from pathlib import Path

from ..monitor import Verdict
from ..outcomes import DUT_FAILED, FINE, simulated_outcome
from ..simulation import Simulation
from ..simulation.geometry import CAR_LENGTH, CAR_WIDTH
from .files import replaced

COLOURS = ("tab:purple", "tab:red", "tab:blue", "tab:green", "tab:orange", "tab:brown")


def _box(axes, x: float, y: float, heading: float, colour: str) -> None:
    """A vehicle's box at its centre (x, y), turned by ``heading`` (rad)."""
    from matplotlib.patches import Rectangle

    axes.add_patch(
        Rectangle(
            (x - CAR_LENGTH / 2, y - CAR_WIDTH / 2),
            CAR_LENGTH,
            CAR_WIDTH,
            angle=float(heading) * 57.2958,
            rotation_point="center",
            facecolor=colour,
            alpha=0.35,
            edgecolor=colour,
        )
    )


def _top_on_map(top, simulation: Simulation, x_min: float, x_max: float, run_indices, lane_number) -> None:
    """The view from above on a map, in its coordinates: the route's lane lines between ``x_min``
    and ``x_max`` (road coordinates), every vehicle's path and its box at the guards' instants."""
    import numpy as np

    trace, road = simulation.trace, simulation.road
    _junction_roads(top, road.route)
    xs = np.linspace(x_min, x_max, 400)
    edge, left = road.right_edge(xs), road.left_edge(xs)
    for side in (edge, left):  # the edges, moving where lanes begin or end
        wx, wy, _ = road.world(xs, side)
        top.plot(wx, wy, "-", color="grey", linewidth=0.8)
    for boundary in range(1, road.lanes):
        y = np.full_like(xs, boundary * road.lane_width)
        wx, wy, _ = road.world(xs, y)
        wx[(y < edge + 0.5) | (y > left - 0.5)] = np.nan  # only where the lanes either side are there
        top.plot(wx, wy, "--", color="grey", linewidth=0.8)
    for lane in range(road.lanes):
        number = lane_number(lane) if lane_number is not None else road.lanes - lane
        wx, wy, _ = road.world(x_min + 1, road.center_y(lane))
        top.text(float(wx), float(wy), f"lane {number}", va="center", fontsize=7, color="grey")
    # true to scale when the route turns enough to show it; stretched across a nearly straight one,
    # where the vehicles at the guards' instants are dots (a box would be drawn distorted)
    spans = [np.ptp(c["world_x"]) for c in trace.actors.values()], [np.ptp(c["world_y"]) for c in trace.actors.values()]
    to_scale = max(spans[1]) > 0.15 * max(max(spans[0]), 1.0)
    for index, (name, columns) in enumerate(trace.actors.items()):
        colour = COLOURS[index % len(COLOURS)]
        top.plot(columns["world_x"], columns["world_y"], color=colour, linewidth=1.2, label=name)
        top.text(columns["world_x"][-1], columns["world_y"][-1] + 0.5, name, color=colour, fontsize=9, weight="bold")
        for k, _ in run_indices:
            x, y, heading = columns["world_x"][k], columns["world_y"][k], columns["world_heading"][k]
            if not to_scale:
                top.plot([x], [y], "o", color=colour, alpha=0.6, markersize=6)
                continue
            _box(top, x, y, heading, colour)
    top.set_aspect("equal" if to_scale else "auto")
    if road.route.junction_span is not None:  # the junction's roads run on: the view is the vehicles'
        xs_all = np.concatenate([np.asarray(c["world_x"], dtype=float) for c in trace.actors.values()])
        ys_all = np.concatenate([np.asarray(c["world_y"], dtype=float) for c in trace.actors.values()])
        top.set_xlim(xs_all.min() - 25.0, xs_all.max() + 25.0)
        top.set_ylim(ys_all.min() - 25.0, ys_all.max() + 25.0)
    top.set_xlabel("map x [m]")
    top.set_ylabel(f"map y [m] ({road.route.turn or road.route.name})")


def _junction_roads(top, route) -> None:
    """The outer edges of the roads of the junction a route turns at and of those meeting it
    (``Route.junction_roads``), light: the junction as a reader sees it."""
    import numpy as np

    for road in route.junction_roads:
        s = np.linspace(0.0, road.length, max(2, int(road.length) + 1))
        for sign, side in ((1.0, lambda section: section.left), (-1.0, lambda section: section.right)):
            width = np.zeros_like(s)
            for section in road.sections:
                inside = (s >= section.s - 1e-9) & (s <= section.end + 1e-9)
                for lane in side(section):
                    width = np.where(inside, width + lane.width(s - section.s), width)
            x, y, _ = road.reference_line.pose(s, road.offset(s) + sign * width)
            top.plot(x, y, "-", color="lightgrey", linewidth=0.7, zorder=0)


def status_line(verdict: Verdict, dut=None) -> str:
    """How the picture's title states the case's outcome (``outcomes.simulated_outcome``): a failing
    one in capitals, with the oracle that failed for a vehicle under test."""
    word = simulated_outcome(verdict.accepted, dut)
    robustness = f"robustness {verdict.robustness:+.2f}"
    if word == DUT_FAILED:
        return f"vehicle under test FAILED: {dut.failures[0]} ({robustness})"
    if word in FINE:
        return f"{word} ({robustness})"
    return f"{word.upper()} ({robustness})"


def plot_simulation(
    simulation: Simulation, verdict: Verdict, path: str | Path, title: str = "", lane_number=None, dut=None
) -> Path:
    """The picture, lanes labelled by ``lane_number(index)`` (the scenario's dialect's numbering;
    default the standard's, 1 the rightmost); its title says the case's outcome, with ``dut`` (the
    oracles' ``DutReport``) for a vehicle under test."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    trace, road = simulation.trace, simulation.road
    on_map = road.route is not None and trace.on_map
    figure, (top, bottom) = plt.subplots(
        2, 1, figsize=(12, 10 if on_map else 7), gridspec_kw={"height_ratios": [2.2 if on_map else 1, 1.4]}
    )
    x_min = min(float(c["x"].min()) for c in trace.actors.values()) - 10
    x_max = max(float(c["x"].max()) for c in trace.actors.values()) + 10
    run_indices = [(int(round(t / simulation.dt)), events) for t, events in verdict.run]
    if on_map:
        _top_on_map(top, simulation, x_min, x_max, run_indices, lane_number)
    for boundary in range(road.lanes + 1 if not on_map else 0):
        style = "-" if boundary in (0, road.lanes) else "--"
        top.plot([x_min, x_max], [boundary * road.lane_width] * 2, style, color="grey", linewidth=0.8)
    for lane in range(road.lanes if not on_map else 0):
        number = lane_number(lane) if lane_number is not None else road.lanes - lane
        top.text(x_min + 1, road.center_y(lane), f"lane {number}", va="center", fontsize=7, color="grey")
    for index, (name, columns) in enumerate(trace.actors.items()):
        colour = COLOURS[index % len(COLOURS)]
        bottom.plot(trace.times, columns["x"], color=colour, label=name)
        if on_map:
            continue
        top.plot(columns["x"], columns["y"], color=colour, linewidth=1.2, label=name)
        top.text(columns["x"][-1], columns["y"][-1] + 0.6, name, color=colour, fontsize=9, weight="bold")
        for k, _ in run_indices:
            _box(top, columns["x"][k], columns["y"][k], columns["heading"][k], colour)
    for number, (k, events) in enumerate(run_indices, start=1):
        time = trace.times[k]
        bottom.axvline(time, color="black", linewidth=0.6, linestyle=":")
        bottom.text(time, bottom.get_ylim()[1], f" {number}: {events}", rotation=90, va="top", fontsize=7)
        if not on_map:
            x_lead = max(float(c["x"][k]) for c in trace.actors.values())
            top.text(x_lead + 3, road.width + 0.4, str(number), fontsize=8, ha="center")
    for incident in verdict.incidents:
        bottom.axvline(incident.time, color="red", linewidth=1.0)
    if not on_map:
        top.set_xlim(x_min, x_max)
        top.set_ylim(-0.5, road.width + 1.5)
        top.set_aspect("auto")
        top.set_ylabel("y [m]")
    top.legend(loc="lower right", fontsize=8)
    bottom.set_xlabel("time [s]")
    bottom.set_ylabel("x [m]")
    figure.suptitle(f"{title}  {status_line(verdict, dut)}; numbered marks: guards met", fontsize=10)
    with warnings.catch_warnings():
        # five_vehicle_minute's 13 guard labels leave tight_layout no room, and matplotlib said so
        # on stderr of every run ("Tight layout not applied"); the figure is drawn as laid out
        warnings.simplefilter("ignore", UserWarning)
        figure.tight_layout()
    path = Path(path)
    with replaced(path) as temporary:
        figure.savefig(temporary, dpi=110)
    plt.close(figure)
    return path
