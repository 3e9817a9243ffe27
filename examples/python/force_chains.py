"""Post-processing of contacts into a force-chain picture: beads settle in a box (the scene
examples/box_fill.toml), then every pair contact is drawn as a segment between the two centres,
seen from the side, its width and shade by the normal force (force_chains.png).

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/force_chains.py [OUT_DIR]
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import LineCollection

import veridem

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    sim = veridem.Simulation(os.path.join(HERE, "..", "box_fill.toml"), quiet=True)
    sim.run()
    c = sim.contacts()
    row = {pid: k for k, pid in enumerate(sim.particles.id)}  # particle id -> row of the views
    x = sim.particles.position
    pairs = c["wall"] < 0
    i = np.array([row[p] for p in c["i"][pairs]])
    j = np.array([row[p] for p in c["j"][pairs]])
    fn = np.linalg.norm(c["normal_force"][pairs], axis=1)
    segments = np.stack([x[i][:, [0, 2]], x[j][:, [0, 2]]], axis=1) * 1e3
    fig, a = plt.subplots(figsize=(5, 5))
    scale = fn / fn.max()
    a.add_collection(LineCollection(segments, linewidths=0.3 + 3 * scale, colors=plt.cm.inferno_r(0.15 + 0.85 * scale)))
    a.set_xlim(0, 50), a.set_ylim(0, 35), a.set_aspect("equal")
    a.set_xlabel("x [mm]"), a.set_ylabel("z [mm]")
    a.set_title(f"{pairs.sum()} pair contacts, largest normal force {fn.max():.3g} N")
    fig.tight_layout()
    fig.savefig(f"{out}/force_chains.png", dpi=130)
    print(f"wrote {out}/force_chains.png")


if __name__ == "__main__":
    main()
