#!/usr/bin/python3
"""Draws veridem_bench's per-window rates in run order (VERIDEM_BENCH_WINDOWS=file).

    VERIDEM_BENCH_WINDOWS=bed.txt build/release/bench/veridem_bench --threads 1
    /usr/bin/python3 bench/plot_windows.py out.png bed.txt "bed, 1 thread" [more.txt "label" ...]

One panel per file: each 100-step window's rate [particle-steps/s] against the step at its end,
with the run's median and best window marked. Slow windows that come in stretches are other load
on the host (the whole run's CPU time stays equal to its wall time); single slow windows are list
rebuilds. Needs Debian's python3-matplotlib and python3-numpy (hence /usr/bin/python3).
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main(argv):
    if len(argv) < 4 or len(argv) % 2 != 0:
        sys.exit(__doc__)
    out, pairs = argv[1], list(zip(argv[2::2], argv[3::2]))
    fig, axes = plt.subplots(len(pairs), 1, figsize=(9, 2.6 * len(pairs)), squeeze=False)
    for ax, (path, label) in zip(axes[:, 0], pairs):
        try:
            rates = np.loadtxt(path, ndmin=1)
        except (OSError, ValueError) as e:
            sys.exit(f"plot_windows.py: {path}: {e}")
        if rates.size == 0:
            sys.exit(f"plot_windows.py: {path}: no windows (a run shorter than 100 steps?)")
        steps = 100 * np.arange(1, rates.size + 1)
        median, best = np.median(rates), rates.max()
        ax.plot(steps, rates, lw=0.6, color="tab:blue")
        ax.axhline(median, color="tab:orange", lw=1, label=f"median window {median:.3g}")
        ax.axhline(best, color="tab:green", lw=1, ls="--", label=f"best window {best:.3g}")
        ax.set_title(label, fontsize=10)
        ax.set_ylabel("particle-steps/s")
        ax.set_ylim(0, 1.1 * best)
        ax.legend(loc="lower right", fontsize=8)
    axes[-1, 0].set_xlabel("step")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main(sys.argv)
