"""An oedometric test driven from Python: spheres in a box without gravity, compressed by a lid
whose speed a servo sets from the measured stress until the packing carries each target pressure
in turn; the stress-strain path is plotted (oedometer.png).

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/oedometer_servo.py [OUT_DIR]

The lid is the plane wall 'lid'; its load is what the particles exert on it (wall_load), the
stress that load over the box's section. The servo is proportional: v = -0.005 m/s (p_target - p) / p_target.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import veridem

SIDE = 0.0194  # m, the box's side: 8 spheres of radius 1.2 mm across, 0.02 mm apart
TOP = 0.0146  # m, the lid's start height, just above 6 layers


def scene(duration):
    walls = [{"name": n, "material": "grain", "point": p, "normal": nn} for n, p, nn in [
        ("floor", [0, 0, 0], [0, 0, 1]), ("west", [0, 0, 0], [1, 0, 0]), ("east", [SIDE, 0, 0], [-1, 0, 0]),
        ("south", [0, 0, 0], [0, 1, 0]), ("north", [0, SIDE, 0], [0, -1, 0]), ("lid", [0, 0, TOP], [0, 0, -1])]]
    return {
        "simulation": {"dt": 1e-5, "duration": duration, "output_interval": duration, "gravity": [0, 0, 0],
                       "skin": 2e-4},
        "material": [{"name": "grain", "density": 2500, "kn": 2e3, "restitution": 0.3, "friction": 0.3}],
        "wall": walls,
        "lattice": [{"material": "grain", "radius": 1.2e-3, "min": [0, 0, 0], "max": [SIDE, SIDE, TOP],
                     "spacing": 2.42e-3, "jitter": 1e-5}],
    }


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    targets = [500.0, 1000.0, 2000.0, 4000.0]  # Pa
    stage = 0.08  # s per target
    sim = veridem.Simulation(scene(stage * len(targets)), quiet=True)
    history = []

    def servo(s):
        target = targets[min(int(s.time / stage), len(targets) - 1)]
        p = s.wall_load("lid")[0][2] / SIDE**2
        s.set_wall_velocity("lid", (0, 0, -0.005 * (target - p) / target))
        strain = -s.wall_displacement("lid")[2] / TOP
        history.append((s.time, target, p, strain))

    sim.run(every=20, callback=servo)
    h = np.array(history)
    for k, target in enumerate(targets):
        held = h[(h[:, 0] > (k + 0.75) * stage) & (h[:, 0] <= (k + 1) * stage)]
        print(f"target {target:6.0f} Pa: held {held[:, 2].mean():7.1f} Pa (std {held[:, 2].std():5.1f}), "
              f"strain {held[:, 3].mean():.4f}")
    fig, (a, b) = plt.subplots(1, 2, figsize=(9, 3.6))
    a.plot(h[:, 0], h[:, 2], lw=0.8, label="measured")
    a.plot(h[:, 0], h[:, 1], "k--", lw=0.8, label="target")
    a.set_xlabel("t [s]"), a.set_ylabel("lid stress [Pa]"), a.legend()
    b.plot(h[:, 3], h[:, 2], lw=0.8)
    b.set_xlabel("vertical strain [-]"), b.set_ylabel("lid stress [Pa]")
    fig.tight_layout()
    fig.savefig(f"{out}/oedometer.png", dpi=120)
    print(f"wrote {out}/oedometer.png")


if __name__ == "__main__":
    main()
