"""Verification case `python_restitution`, written against the public Python API only: one ball
strikes a floor without gravity, with the linear spring and a dashpot set from the coefficient of
restitution e (docs/models.md), for e = 0.2, 0.5, 0.8. Theory: the rebound speed over the impact
speed is e (the damped oscillator's closed form: the dashpot is chosen to give it). Checked:
- e at 100 steps per contact time within 0.3 %, normal_restitution's tolerance
  (verification/dem/normal_restitution.cpp);
- the error's order in dt from 50 and 100 steps per contact: 2 +- 0.3 (the end-of-step dashpot
  speed makes the damping second order, docs/models.md; 0.3 is the dt sweeps' margin). At
  e = 0.2 the error at 50 steps is 3.4e-3: the second-order term grows with the damping ratio,
  which is why the accuracy is asked at 100 steps;
- the contact time against the damped half period pi / sqrt(k/m - (c/2m)^2), from the steps during
  which the floor carried a load: to one step (1 %).

Prints one line per quantity for the runner:
quantity<TAB>name<TAB>unit<TAB>expected<TAB>measured<TAB>tolerance<TAB>relative|absolute<TAB>why
"""
import math

import veridem

RADIUS, DENSITY, KN, SPEED = 0.01, 2500.0, 1e4, 1.0  # m, kg/m^3, N/m, m/s


def bounce(e, steps_per_contact):
    mass = DENSITY * 4.0 / 3.0 * math.pi * RADIUS**3
    # The dashpot a linear contact gets from e (a wall is a partner of infinite mass: m* = m):
    # c = 2 sqrt(m k) (-ln e) / sqrt(pi^2 + ln^2 e), so the damped half period is
    # pi / sqrt(k/m - (c/2m)^2).
    ln_e = math.log(e)
    c = 2 * math.sqrt(mass * KN) * (-ln_e) / math.sqrt(math.pi**2 + ln_e**2)
    contact_time = math.pi / math.sqrt(KN / mass - (c / (2 * mass)) ** 2)
    dt = contact_time / steps_per_contact
    scene = {
        "simulation": {"dt": dt, "duration": 3 * contact_time + 0.0005 / SPEED, "output_interval": 1.0,
                       "gravity": [0, 0, 0]},
        "material": [{"name": "ball", "density": DENSITY, "kn": KN, "restitution": e, "friction": 0.0}],
        "wall": [{"name": "floor", "material": "ball", "normal": [0, 0, 1]}],
        "sphere": [{"material": "ball", "radius": RADIUS, "position": [0, 0, RADIUS + 0.0005],
                    "velocity": [0, 0, -SPEED]}],
    }
    sim = veridem.Simulation(scene, quiet=True)
    loaded = 0
    while sim.step_count < sim.end_step:
        sim.step(1)
        loaded += sim.wall_load("floor")[0][2] != 0.0
    return sim.particles.velocity[0, 2] / SPEED, loaded * dt, contact_time


def main():
    for e in (0.2, 0.5, 0.8):
        coarse, _, _ = bounce(e, 50)
        measured, duration, expected_duration = bounce(e, 100)
        order = math.log2(abs(coarse - e) / abs(measured - e))
        print(f"quantity\te = {e}: rebound / impact speed\t\t{e}\t{measured}\t0.003\trelative\t"
              "normal_restitution's tolerance")
        print(f"quantity\te = {e}: order of the error in dt\t\t2\t{order}\t0.3\tabsolute\t"
              "second-order dashpot (docs/models.md); the dt sweeps' margin")
        print(f"quantity\te = {e}: contact time\ts\t{expected_duration}\t{duration}\t0.01\trelative\t"
              "counted in whole steps (dt = tc/100)")


if __name__ == "__main__":
    main()
