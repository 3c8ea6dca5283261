"""The recorded simulation: every actor's state every ``dt`` seconds, plus incidents."""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass, field

import numpy as np

COLUMNS = ("x", "y", "heading", "speed", "acceleration", "lane")
# on a map, every sample's pose in the map's coordinates too (x, y, heading above being the road's)
WORLD_COLUMNS = ("world_x", "world_y", "world_heading")


@dataclass(frozen=True)
class ActorSnapshot:
    """An actor's state at one instant, as guards see it (``position`` is the centre's x;
    ``traveled``, that x minus the x of the trace's first sample)."""

    position: float
    lane: int
    speed: float
    traveled: float = 0.0


@dataclass(frozen=True)
class Incident:
    time: float
    kind: str  # "collision" or "off-road"
    actors: tuple[str, ...]

    def __str__(self) -> str:
        return f"{self.kind} of {' and '.join(self.actors)} at t={self.time:.1f} s"


@dataclass
class Trace:
    """Time-stamped states (constant between samples, as the paper assumes)."""

    times: np.ndarray
    # actor -> column -> array aligned with ``times``
    actors: dict[str, dict[str, np.ndarray]]
    incidents: list[Incident] = field(default_factory=list)

    def __len__(self) -> int:
        return len(self.times)

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(self.actors)

    def snapshot(self, index: int) -> dict[str, ActorSnapshot]:
        return {
            name: ActorSnapshot(
                float(c["x"][index]), int(c["lane"][index]), float(c["speed"][index]), float(c["x"][index] - c["x"][0])
            )
            for name, c in self.actors.items()
        }

    def snapshots(self) -> list[dict[str, ActorSnapshot]]:
        return [self.snapshot(k) for k in range(len(self))]

    @property
    def on_map(self) -> bool:
        """Whether it carries world poses (a run on a map)."""
        return any(WORLD_COLUMNS[0] in c for c in self.actors.values())

    def to_csv(self) -> str:
        out = io.StringIO()
        writer = csv.writer(out, lineterminator="\n")
        columns = COLUMNS + (WORLD_COLUMNS if self.on_map else ())
        writer.writerow(["time", "actor", *columns])
        for k, t in enumerate(self.times):
            for name, c in self.actors.items():
                row = [f"{t:.2f}", name]
                row += [f"{c[col][k]:.4f}" if col != "lane" else str(int(c[col][k])) for col in columns]
                writer.writerow(row)
        return out.getvalue()
