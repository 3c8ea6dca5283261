# The paper's overtake (scenarios/overtake.osc) as a Scenic user writes it: v1 starts 10-20 m behind
# v2 in its lane, pulls out to the left while speeding up, passes, and cuts back in once far enough
# ahead. Its phases as the .osc has them, in order: v1 left of v2 (A), 1-10 m ahead of it (B), back
# in v2's lane 8-13 m ahead (C); no collision; at most 40 s.
param map = localPath('road.xodr')
model scenic.simulators.newtonian.driving_model
from scenic_support import Progress, collided, controls, lane_y, lane_of

behavior Cruise(speed, lane):
    while True:
        throttle, brake, steer = controls(self.speed, self.heading, self.position.y, self.speed, speed, lane_y(lane))
        take SetThrottleAction(throttle), SetBrakeAction(brake), SetSteerAction(steer)

behavior Overtake(other, speed, gain, pull_out_after, lane, back_at):
    do Cruise(speed, lane) for pull_out_after seconds
    do Cruise(speed + gain, lane + 1) until self.position.x - other.position.x >= back_at
    do Cruise(speed, lane)

lane = DiscreteRange(1, 2)
speed = Range(80, 130) / 3.6
gain = Range(2, 8)
progress = Progress(3)

v2 = new Car at (300, lane_y(lane)), facing -90 deg, with speed speed, with behavior Cruise(speed, lane)
ego = new Car at (300 - Range(10, 20), lane_y(lane)), facing -90 deg, with speed speed,
    with behavior Overtake(v2, speed, gain, Range(0, 2), lane, Range(5, 13))

monitor Phases(v1, v2, progress):
    progress.reset()
    while not progress.done:
        progress.collision = progress.collision or collided(v1, v2)
        ahead = v1.position.x - v2.position.x
        same = lane_of(v1.position.y) == lane_of(v2.position.y)
        if progress.ended == 0:
            progress.advance(lane_of(v1.position.y) > lane_of(v2.position.y))
        elif progress.ended == 1:
            progress.advance(1 <= ahead <= 10)
        elif progress.ended == 2:
            progress.advance(same and 8 <= ahead <= 13)
        if simulation().currentTime >= 400:
            terminate
        wait
    terminate
require monitor Phases(ego, v2, progress)
require eventually progress.done
