"""CARLA's scenario-runner dialect: the same constructs, two conventions read differently.

- Lanes are numbered from the left: ``lane(1)`` is the leftmost lane (``from: right`` counts
  from the right). A third of the public CARLA files put one car in ``lane(1)`` and another
  ``right_of`` it, which has no plan under the standard's numbering.
- ``speed(v)`` without ``at:`` is a target speed the car drives towards: it holds at the phase's
  end, not throughout (``at: all`` written out still means throughout).

Everything else is the standard's. The dialect is chosen by ``--dialect carla`` /
``roadlogic_dialect = carla`` or, per file, by a ``conftest.py`` (``pytest_roadlogic_dialect``).
"""

from __future__ import annotations

from ..settings import CARLA_DIALECT
from .lanes import Lane
from .speed import Speed

DIALECT = CARLA_DIALECT
CARLA_LANE_CONVENTION = "in CARLA's dialect lanes are numbered from 1 on the left (lane(1) is the leftmost); lane(k, from: right) counts from the right"


class CarlaLane(Lane):
    __doc__ = Lane.__doc__
    counted_from = "left"
    convention = CARLA_LANE_CONVENTION


class CarlaSpeed(Speed):
    """``speed(v)``: the target speed, reached by the phase's end; with ``at:``, as the standard reads it."""

    default_anchor = "end"


CONSTRUCTS = (CarlaLane(), CarlaSpeed())
