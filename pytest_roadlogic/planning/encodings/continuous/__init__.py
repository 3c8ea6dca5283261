"""The continuous encoding (the default): real-valued positions and speeds in linear rows."""

from ...protocol import Encoding
from .settings import ContinuousSettings


def _planner():
    from .planner import ContinuousPlanner

    return ContinuousPlanner


ENCODING = Encoding(
    "continuous",
    ContinuousSettings,
    _planner,
    "real-valued speeds and positions (asp/continuous/)",
)

__all__ = ["ENCODING", "ContinuousSettings"]
