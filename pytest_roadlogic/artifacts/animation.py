"""An animated GIF of one simulation: the road from above, every vehicle as a labelled box, the
time, and which phase of the scenario the monitor's run was in; the view follows the vehicles (on
a map, turned with the route at the view's centre, the lanes bending as the map's).

Frames are drawn straight into palette images with Pillow, not through matplotlib, whose
animation redraws and quantises a figure per frame, an order of magnitude slower
(docs/decisions.md). Frames are taken every ``frame_dt``
seconds (0.2 s by default, half the samples of the trace), which keeps a 20 s run to about a
hundred frames and the file small enough to attach to a CI report.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..monitor import Verdict
from ..simulation import Simulation
from ..simulation.geometry import CAR_LENGTH, CAR_WIDTH
from .files import replaced

# palette indices: what a frame is drawn with (a GIF frame is a 256-colour palette image anyway)
BACKGROUND, ROAD, LINE, TEXT = 0, 1, 2, 3
# matplotlib's tab10 colours in the order plot.COLOURS names them: a vehicle has one colour in the
# plot and in the animation
VEHICLE_RGB = ((148, 103, 189), (214, 39, 40), (31, 119, 180), (44, 160, 44), (255, 127, 14), (140, 86, 75))
PALETTE = [(255, 255, 255), (236, 236, 236), (128, 128, 128), (20, 20, 20), *VEHICLE_RGB]
FIRST_VEHICLE = 4

PIXELS_WIDE = 1000
MARGIN = 40  # px above the road for the title line and below it for the scale


def animate_simulation(
    simulation: Simulation,
    verdict: Verdict | None,
    path: str | Path,
    title: str = "",
    frame_dt: float = 0.2,
    lane_number=None,
) -> Path:
    """Write the GIF atomically (a temporary file renamed into place) and return its path; lanes
    are labelled by ``lane_number(index)`` (default the standard's numbering, 1 the rightmost)."""
    from PIL import Image, ImageDraw, ImageFont

    path = Path(path)
    trace, road = simulation.trace, simulation.road
    stride = max(1, int(round(frame_dt / simulation.dt)))
    frames = list(range(0, len(trace), stride))
    if frames[-1] != len(trace) - 1:
        frames.append(len(trace) - 1)
    if road.route is not None and trace.on_map:
        images = _frames_on_map(simulation, verdict, frames, title, lane_number)
        return _save(images, path, stride, simulation.dt)
    names = list(trace.actors)
    xs = np.array([trace.actors[v]["x"] for v in names])
    view = max(60.0, float(np.ptp(xs, axis=0).max()) + 30.0)  # metres wide enough to show every vehicle at once
    scale = PIXELS_WIDE / view  # px per metre, the same along and across the road: boxes keep their shape
    height = int(math.ceil(road.width * scale)) + 2 * MARGIN
    font = ImageFont.load_default(size=13)
    small = ImageFont.load_default(size=11)
    phases = _phases(verdict, trace.times) if verdict is not None else None
    palette = [channel for colour in PALETTE for channel in colour]

    def to_pixels(x: np.ndarray | float, y: np.ndarray | float, left: float):
        return (np.asarray(x) - left) * scale, MARGIN + (road.width - np.asarray(y)) * scale

    corners = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]]) * [CAR_LENGTH / 2, CAR_WIDTH / 2]
    images = []
    for k in frames:
        # centred between the rearmost and the foremost vehicle: around their mean, a car far ahead
        # of two others fell outside the view (found by tests/artifacts/test_animation.py)
        left = float(xs[:, k].min() + xs[:, k].max()) / 2 - view / 2
        image = Image.new("P", (PIXELS_WIDE, height), BACKGROUND)
        image.putpalette(palette)
        draw = ImageDraw.Draw(image)
        draw.rectangle((0, MARGIN, PIXELS_WIDE, MARGIN + road.width * scale), fill=ROAD)
        for boundary in range(road.lanes + 1):
            y = MARGIN + boundary * road.lane_width * scale
            if boundary in (0, road.lanes):
                draw.line((0, y, PIXELS_WIDE, y), fill=LINE, width=2)
            else:  # dashed: 3 m marks every 9 m, fixed to the road so that the motion shows
                first = math.floor(left / 9.0) * 9.0
                for mark in np.arange(first, left + view + 9.0, 9.0):
                    x0, _ = to_pixels(mark, 0.0, left)
                    draw.line((float(x0), y, float(x0) + 3.0 * scale, y), fill=LINE, width=1)
        for lane in range(road.lanes):
            _, y = to_pixels(0.0, road.center_y(lane), left)
            number = lane_number(lane) if lane_number is not None else road.lanes - lane
            draw.text((4, float(y)), f"lane {number}", fill=LINE, font=small, anchor="lm")
        for index, name in enumerate(names):
            columns = trace.actors[name]
            x, y, heading = float(columns["x"][k]), float(columns["y"][k]), float(columns["heading"][k])
            rotation = np.array([[math.cos(heading), -math.sin(heading)], [math.sin(heading), math.cos(heading)]])
            box = corners @ rotation.T + [x, y]
            px, py = to_pixels(box[:, 0], box[:, 1], left)
            colour = FIRST_VEHICLE + index % len(VEHICLE_RGB)
            draw.polygon(list(zip(px.tolist(), py.tolist())), fill=colour)
            lx, ly = to_pixels(x, y + CAR_WIDTH / 2, left)
            draw.text((float(lx), float(ly) - 2), name, fill=colour, font=font, anchor="mb")
        phase = f"   {phases[k]}" if phases is not None else ""
        draw.text((8, MARGIN / 2), f"{title}   t = {trace.times[k]:5.1f} s{phase}", fill=TEXT, font=font, anchor="lm")
        bar = 10.0 if view < 150 else 50.0  # a scale bar: the picture has no axes
        draw.line((8, height - MARGIN / 2, 8 + bar * scale, height - MARGIN / 2), fill=TEXT, width=2)
        draw.text((12 + bar * scale, height - MARGIN / 2), f"{bar:g} m", fill=TEXT, font=small, anchor="lm")
        images.append(image)
    return _save(images, path, stride, simulation.dt)


def _save(images: list, path: Path, stride: int, dt: float) -> Path:
    milliseconds = int(round(1000 * stride * dt))
    with replaced(path) as temporary:
        images[0].save(temporary, format="GIF", save_all=True, append_images=images[1:], duration=milliseconds, loop=0)
    return path


def _frames_on_map(simulation: Simulation, verdict: Verdict | None, frames: list[int], title: str, lane_number):
    """The frames of a run on a map, in the map's geometry: each frame is centred on the vehicles
    and turned so that the route runs left to right at its centre; the lanes bend as the map's do."""
    from PIL import Image, ImageDraw, ImageFont

    trace, road = simulation.trace, simulation.road
    names = list(trace.actors)
    xs = np.array([trace.actors[v]["x"] for v in names])
    view = max(60.0, float(np.ptp(xs, axis=0).max()) + 30.0)
    scale = PIXELS_WIDE / view
    # room across for the route's bend within a view: its sagitta at the sharpest curve
    bend = view * view * road.route.greatest_curvature() / 8.0
    height = int(math.ceil((road.width + 2 * bend) * scale)) + 2 * MARGIN
    font = ImageFont.load_default(size=13)
    small = ImageFont.load_default(size=11)
    phases = _phases(verdict, trace.times) if verdict is not None else None
    palette = [channel for colour in PALETTE for channel in colour]
    corners = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]]) * [CAR_LENGTH / 2, CAR_WIDTH / 2]
    images = []
    for k in frames:
        middle = float(xs[:, k].min() + xs[:, k].max()) / 2
        cx, cy, ch = (float(v) for v in road.world(middle, road.width / 2))
        cos_c, sin_c = math.cos(-ch), math.sin(-ch)

        def to_pixels(wx, wy, cx=cx, cy=cy, cos_c=cos_c, sin_c=sin_c):
            dx, dy = np.asarray(wx) - cx, np.asarray(wy) - cy
            u, w = dx * cos_c - dy * sin_c, dx * sin_c + dy * cos_c
            return PIXELS_WIDE / 2 + u * scale, height / 2 - w * scale

        image = Image.new("P", (PIXELS_WIDE, height), BACKGROUND)
        image.putpalette(palette)
        draw = ImageDraw.Draw(image)
        along = np.linspace(middle - view * 0.6, middle + view * 0.6, 120)
        edge, left = road.right_edge(along), road.left_edge(along)
        left_x, left_y = to_pixels(*road.world(along, left)[:2])
        right_x, right_y = to_pixels(*road.world(along, edge)[:2])
        outline = list(zip(left_x.tolist(), left_y.tolist())) + list(
            zip(right_x.tolist()[::-1], right_y.tolist()[::-1])
        )
        draw.polygon(outline, fill=ROAD)
        draw.line(list(zip(left_x.tolist(), left_y.tolist())), fill=LINE, width=2)
        draw.line(list(zip(right_x.tolist(), right_y.tolist())), fill=LINE, width=2)
        for boundary in range(1, road.lanes):
            y = np.full_like(along, boundary * road.lane_width)
            px, py = to_pixels(*road.world(along, y)[:2])
            # dashed: 3 m marks every 9 m along the road, only where the lane below the line is there
            for i in range(len(along) - 1):
                if edge[i] + 0.5 <= y[i] <= left[i] - 0.5 and (along[i] % 9.0) < 3.0:
                    draw.line((float(px[i]), float(py[i]), float(px[i + 1]), float(py[i + 1])), fill=LINE, width=1)
        for lane in range(road.lanes):
            lx, ly = to_pixels(*road.world(middle - view / 2 + 2.0, road.center_y(lane))[:2])
            number = lane_number(lane) if lane_number is not None else road.lanes - lane
            draw.text((float(lx), float(ly)), f"lane {number}", fill=LINE, font=small, anchor="lm")
        for index, name in enumerate(names):
            columns = trace.actors[name]
            x, y, heading = (float(columns[c][k]) for c in ("world_x", "world_y", "world_heading"))
            rotation = np.array([[math.cos(heading), -math.sin(heading)], [math.sin(heading), math.cos(heading)]])
            box = corners @ rotation.T + [x, y]
            px, py = to_pixels(box[:, 0], box[:, 1])
            colour = FIRST_VEHICLE + index % len(VEHICLE_RGB)
            draw.polygon(list(zip(px.tolist(), py.tolist())), fill=colour)
            lx, ly = to_pixels(x, y)
            draw.text((float(lx), float(ly) - CAR_WIDTH * scale / 2 - 2), name, fill=colour, font=font, anchor="mb")
        phase = f"   {phases[k]}" if phases is not None else ""
        draw.text((8, MARGIN / 2), f"{title}   t = {trace.times[k]:5.1f} s{phase}", fill=TEXT, font=font, anchor="lm")
        bar = 10.0 if view < 150 else 50.0
        draw.line((8, height - MARGIN / 2, 8 + bar * scale, height - MARGIN / 2), fill=TEXT, width=2)
        draw.text((12 + bar * scale, height - MARGIN / 2), f"{bar:g} m", fill=TEXT, font=small, anchor="lm")
        images.append(image)
    return images


def _phases(verdict: Verdict, times: np.ndarray) -> list[str]:
    """For every sample, the last transition of the monitor's run taken by then (its events)."""
    labels = ["before the scenario"] * len(times)
    for t, events in verdict.run:
        k = int(np.searchsorted(times, t - 1e-9))
        labels[k:] = [events] * (len(times) - k)
    return labels
