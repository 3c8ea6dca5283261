# The paper's follow with an end gap of 5-15 m (benchmarks/scenarios/follow_close.osc), as a Scenic
# user writes it: the lead cruises at 30-45 kph, the tail starts 10-30 m behind it in its lane and
# drives at a speed near the lead's; the run ends after 2-10 s, the tail 5-15 m behind the lead.
param map = localPath('road.xodr')
model scenic.simulators.newtonian.driving_model
from scenic_support import Progress, collided, controls, lane_y, lane_of

behavior Cruise(speed, lane):
    while True:
        throttle, brake, steer = controls(self.speed, self.heading, self.position.y, self.speed, speed, lane_y(lane))
        take SetThrottleAction(throttle), SetBrakeAction(brake), SetSteerAction(steer)

lane = DiscreteRange(1, 3)
lead_speed = Range(30, 45) / 3.6
start_gap = Range(10, 30)
tail_speed = lead_speed + Range(-2, 2)
duration = Range(2, 10)
progress = Progress(1)

lead = new Car at (200, lane_y(lane)), facing -90 deg, with speed lead_speed, with behavior Cruise(lead_speed, lane)
ego = new Car at (200 - start_gap, lane_y(lane)), facing -90 deg, with speed lead_speed, with behavior Cruise(tail_speed, lane)

monitor Ends(lead, tail, progress, duration):
    progress.reset()
    while True:
        progress.collision = progress.collision or collided(lead, tail)
        if simulation().currentTime * 0.1 >= duration:
            gap = lead.position.x - tail.position.x
            progress.advance(5 <= gap <= 15 and lane_of(tail.position.y) == lane_of(lead.position.y))
            terminate
        wait
require monitor Ends(lead, ego, progress, duration)
require eventually progress.done
