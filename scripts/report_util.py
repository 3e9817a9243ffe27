"""Shared helpers of the verification report (scripts/report.py): series files, columns, number
formatting and figure saving."""

import csv
import html
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_series(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        return [], np.zeros((0, 0))
    header = rows[0]
    data = []
    for row in rows[1:]:
        try:
            data.append([float(v) if v not in ("", "nan") else math.nan for v in row])
        except ValueError:
            continue
    array = np.array(data, dtype=float) if data else np.zeros((0, len(header)))
    return header, array


def column(header, data, name):
    return data[:, header.index(name)] if name in header else None


def fmt(value):
    if value is None:
        return "–"
    if isinstance(value, bool):
        return str(value)
    if isinstance(value, (int, float)):
        if not math.isfinite(value):
            return "–"
        if value == 0:
            return "0"
        return f"{value:.6g}"
    return html.escape(str(value))


def save(fig, out_dir, name):
    path = os.path.join(out_dir, "figures", name + ".png")
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return "figures/" + name + ".png"
