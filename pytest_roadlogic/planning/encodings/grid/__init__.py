"""The grid encoding: the paper's integer grid of 1 m cells and 1 s steps, with a run-up from standstill."""

from ...protocol import Encoding
from .settings import GridSettings


def _planner():
    from .planner import GridPlanner

    return GridPlanner


ENCODING = Encoding(
    "grid",
    GridSettings,
    _planner,
    "the paper's integer grid with a run-up from standstill (asp/grid/)",
)

__all__ = ["ENCODING", "GridSettings"]
