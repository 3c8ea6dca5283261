"""Plug-in drivers for tests: deliberately bad vehicles under test."""

from pytest_roadlogic.simulation.driver import Trajectory, VehicleState


class NeverChangesLane:
    """Speeds up to 15 m/s and holds it, straight ahead in its start lane, whatever the plan says."""

    def start(self, vehicle, reference, road, dt):
        self.dt = dt

    def plan(self, time, state, others):
        speed = min(state.speed + 2.0 * self.dt, 15.0)
        ahead = VehicleState(state.x + speed * self.dt, state.y, 0.0, speed, (speed - state.speed) / self.dt)
        return Trajectory.standing(ahead, 2)
