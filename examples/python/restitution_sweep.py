"""A parameter sweep from Python: the coefficient of restitution a ball shows against the one its
material is given, for several values, with the linear spring-dashpot contact; plotted with
matplotlib (restitution_sweep.png).

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/restitution_sweep.py [OUT_DIR]

For a linear spring and a dashpot set from e (docs/models.md), the rebound speed over the impact
speed is e exactly; what the plot shows is the time integration's error at ~100 steps per contact.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import veridem


def bounce(e, kn=1e4, radius=0.01, density=2500.0, speed=1.0):
    """Measured restitution of one ball hitting a floor at `speed` [m/s] without gravity."""
    mass = density * 4 / 3 * np.pi * radius**3
    contact_time = np.pi / np.sqrt(2 * kn / mass)  # ~ the undamped half period (docs/models.md)
    scene = {
        "simulation": {"dt": contact_time / 100, "duration": 4 * contact_time + 0.002 / speed,
                       "output_interval": 1.0, "gravity": [0, 0, 0]},
        "material": [{"name": "ball", "density": density, "kn": kn, "restitution": e, "friction": 0.0}],
        "wall": [{"name": "floor", "material": "ball", "normal": [0, 0, 1]}],
        "sphere": [{"material": "ball", "radius": radius, "position": [0, 0, radius + 0.001],
                    "velocity": [0, 0, -speed]}],
    }
    sim = veridem.Simulation(scene, quiet=True)
    sim.run()
    return sim.particles.velocity[0, 2] / speed


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    set_e = np.linspace(0.1, 0.95, 12)
    measured = np.array([bounce(e) for e in set_e])
    for e, m in zip(set_e, measured):
        print(f"e = {e:.3f}: measured {m:.6f} (relative error {abs(m - e) / e:.2e})")
    fig, (a, b) = plt.subplots(1, 2, figsize=(9, 3.6))
    a.plot(set_e, set_e, "k-", lw=0.8, label="theory: e")
    a.plot(set_e, measured, "o", label="veridem")
    a.set_xlabel("restitution given"), a.set_ylabel("rebound / impact speed"), a.legend()
    b.semilogy(set_e, np.abs(measured - set_e) / set_e, "o-")
    b.set_xlabel("restitution given"), b.set_ylabel("relative error")
    fig.tight_layout()
    fig.savefig(f"{out}/restitution_sweep.png", dpi=120)
    print(f"wrote {out}/restitution_sweep.png")


if __name__ == "__main__":
    main()
