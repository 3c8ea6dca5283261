"""The sizes every stage means by "a car" and "a lane": the simulation's box, the monitor's
incidents, the plots and exports, and the conditions that measure between bumpers
(``space_gap``) all read them from here, so that they cannot disagree."""

from __future__ import annotations

CAR_LENGTH = 4.5  # m
CAR_WIDTH = 1.8  # m
LANE_WIDTH = 3.5  # m
