# The realistic cut-in (scenarios/realistic/cut_in.osc) as a Scenic user writes it: the ego holds
# 80-110 kph in the middle lane; the npc starts 20-40 m behind it in the left lane, 20-40 kph
# faster, for 4-8 s (approach); then changes to the ego's lane in 3-5 s, ending 10-25 m ahead of
# it (cut-in); then slows to 50-70 kph within 4-6 s (slow-down). The npc's lane change starts when
# the approach ends, its slowing when the cut-in ends; the monitor checks each phase's end.
param map = localPath('road.xodr')
model scenic.simulators.newtonian.driving_model
from scenic_support import Progress, collided, controls, lane_y, lane_of

behavior Cruise(speed, lane):
    while True:
        throttle, brake, steer = controls(self.speed, self.heading, self.position.y, self.speed, speed, lane_y(lane))
        take SetThrottleAction(throttle), SetBrakeAction(brake), SetSteerAction(steer)

behavior CutIn(speed, approach, cut, target):
    do Cruise(speed, 3) for approach seconds
    do Cruise(speed, 2) for cut seconds
    do Cruise(target, 2)

ego_speed = Range(80, 110) / 3.6
npc_speed = ego_speed + Range(20, 40) / 3.6
approach = Range(4, 8)
cut = Range(3, 5)
slow = Range(4, 6)
target = Range(50, 70) / 3.6
progress = Progress(3)

ego = new Car at (300, lane_y(2)), facing -90 deg, with speed ego_speed, with behavior Cruise(ego_speed, 2)
npc = new Car at (300 - Range(20, 40), lane_y(3)), facing -90 deg, with speed npc_speed,
    with behavior CutIn(npc_speed, approach, cut, target)

monitor Phases(host, cutter, progress, approach, cut, slow, target):
    progress.reset()
    while True:
        progress.collision = progress.collision or collided(host, cutter)
        time = simulation().currentTime * 0.1
        if progress.ended == 0 and time >= approach:
            progress.advance(lane_of(cutter.position.y) == 3)
        elif progress.ended == 1 and time >= approach + cut:
            ahead = cutter.position.x - host.position.x
            progress.advance(lane_of(cutter.position.y) == 2 and 10 <= ahead <= 25)
        elif progress.ended == 2 and time >= approach + cut + slow:
            progress.advance(abs(cutter.speed - target) <= 1.0 and lane_of(host.position.y) == 2)
            terminate
        if time > approach + cut + slow + 0.5:
            terminate
        wait
require monitor Phases(ego, npc, progress, approach, cut, slow, target)
require eventually progress.done
