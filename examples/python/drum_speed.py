"""A rotating drum whose speed is set from Python: the drum (a cylinder wall with caps) turns
faster in steps, and the bed's centre of mass is followed as it is carried up the wall; plotted
in drum_speed.png.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/drum_speed.py [OUT_DIR]
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import veridem

scene = {
    "simulation": {"dt": 2e-5, "duration": 1.2, "output_interval": 0.1, "gravity": [0, 0, -9.81], "skin": 3e-4},
    "material": [{"name": "glass", "density": 2500, "kn": 500, "restitution": 0.5, "friction": 0.4,
                  "rolling_friction_dimensionless": 0.05, "rolling_model": "epsd"}],
    "wall": [{"name": "drum", "type": "cylinder", "material": "glass", "point": [0, -0.006, 0], "axis": [0, 1, 0],
              "radius": 0.03, "length": 0.012, "caps": True}],
    "lattice": [{"material": "glass", "radius": 1.5e-3, "min": [-0.015, -0.004, -0.022],
                 "max": [0.015, 0.004, 0.0], "spacing": 3.4e-3, "jitter": 1e-4}],
}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    sim = veridem.Simulation(scene, quiet=True)
    track = []

    def follow(s):
        omega = 0.0 if s.time < 0.3 else (2.0 if s.time < 0.75 else 5.0)  # rad/s about +y
        s.set_wall_angular_velocity("drum", (0, omega, 0))
        x = s.particles.position
        m = s.particles.mass
        c = (m[:, None] * x).sum(axis=0) / m.sum()
        track.append((s.time, omega, c[0], c[2]))

    sim.run(every=250, callback=follow)
    t = np.array(track)
    fig, a = plt.subplots(figsize=(5.5, 3.6))
    a.plot(t[:, 0], 1e3 * t[:, 2], label="centre of mass x [mm]")
    a.plot(t[:, 0], 1e3 * t[:, 3], label="centre of mass z [mm]")
    a2 = a.twinx()
    a2.step(t[:, 0], t[:, 1], "k--", lw=0.8, where="post")
    a2.set_ylabel("drum speed [rad/s]")
    a.set_xlabel("t [s]"), a.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(f"{out}/drum_speed.png", dpi=120)
    print(f"centre of mass at the end: x = {1e3 * t[-1, 2]:.2f} mm, z = {1e3 * t[-1, 3]:.2f} mm; wrote {out}/drum_speed.png")


if __name__ == "__main__":
    main()
