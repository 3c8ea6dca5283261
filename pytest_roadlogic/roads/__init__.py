"""Roads: the road model the planner, the simulator, the monitor and the artifacts share, and
OpenDRIVE in and out."""
