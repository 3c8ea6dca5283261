"""The paper's diversity metric: the occupancy grid of a simulation, and the Jaccard index of two.

A simulation occupies a cell (1 lane x 1 m of road, the planning grid) when any vehicle's body
covers part of it at any recorded instant. Two simulations are as similar as the share of cells
they have in common: 1 for the same ground, 0 for disjoint ground. Time is left out on purpose
(as in the paper): two runs that cover the same road at different speeds count as similar.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..simulation.geometry import CAR_LENGTH
from ..simulation.trace import Trace


@dataclass(frozen=True)
class Occupancy:
    """The occupied cells of one simulation, kept as runs of cells per lane: ``lane -> ((first, last), ...)``.

    Runs keep a results file small (a vehicle covers hundreds of cells) and are exact.
    """

    runs: dict[int, tuple[tuple[int, int], ...]]

    @classmethod
    def of_trace(cls, trace: Trace, cell: float = 1.0, length: float = CAR_LENGTH) -> Occupancy:
        cells: dict[int, set[int]] = {}
        for columns in trace.actors.values():
            lanes = columns["lane"].astype(int)
            first = np.floor((columns["x"] - length / 2) / cell).astype(int)
            last = np.floor((columns["x"] + length / 2) / cell).astype(int)
            for lane, low, high in zip(lanes, first, last):
                cells.setdefault(int(lane), set()).update(range(int(low), int(high) + 1))
        return cls({lane: _runs(sorted(found)) for lane, found in sorted(cells.items())})

    def cells(self) -> set[tuple[int, int]]:
        return {(lane, k) for lane, runs in self.runs.items() for low, high in runs for k in range(low, high + 1)}

    def to_json(self) -> dict[str, list[list[int]]]:
        return {str(lane): [list(run) for run in runs] for lane, runs in self.runs.items()}

    @classmethod
    def from_json(cls, data: dict[str, list[list[int]]]) -> Occupancy:
        return cls({int(lane): tuple((low, high) for low, high in runs) for lane, runs in data.items()})


def _runs(cells: list[int]) -> tuple[tuple[int, int], ...]:
    runs: list[tuple[int, int]] = []
    for k in cells:
        if runs and runs[-1][1] == k - 1:
            runs[-1] = (runs[-1][0], k)
        else:
            runs.append((k, k))
    return tuple(runs)


def jaccard(a: set, b: set) -> float:
    """|a & b| / |a | b|; two empty grids are the same (1.0)."""
    union = len(a | b)
    return len(a & b) / union if union else 1.0


def similarity_matrix(grids: list[Occupancy]) -> list[list[float]]:
    """The Jaccard index of every pair of grids (symmetric, 1 on the diagonal: each pair computed once)."""
    cells = [grid.cells() for grid in grids]
    matrix = [[1.0] * len(cells) for _ in cells]
    for i in range(len(cells)):
        for j in range(i + 1, len(cells)):
            matrix[i][j] = matrix[j][i] = jaccard(cells[i], cells[j])
    return matrix


def mean_pairwise(matrix: list[list[float]]) -> float:
    """The mean over distinct pairs (NaN with fewer than two instances)."""
    n = len(matrix)
    pairs = [matrix[i][j] for i in range(n) for j in range(i + 1, n)]
    return sum(pairs) / len(pairs) if pairs else math.nan
