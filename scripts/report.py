#!/usr/bin/python3
"""Draws the verification report: DIR/index.html and PNG figures. The page opens with a summary per
family of cases (cases, passed, worst error over tolerance) linking to one section per family with
its figures and its detailed table folded (<details>). Helpers: report_util.py (series, saving),
report_families.py (FAMILIES, which sorts the cases, and the benchmark families' figures), report_bulk.py (the bulk checks' figures),
report_dem8.py (the cross-code benchmark DEM8, from bench/results/),
report_html.py (the page).

Usage: report.py DIR RESULTS_JSON

Called by `veridem verify --report DIR` after the cases ran. Inputs:
  RESULTS_JSON          {"cases": [{"name", "summary", "reference", "passed", "seconds", "notes",
                          "quantities": [{"name", "unit", "expected", "measured", "tolerance",
                          "relative", "error", "passed", "why"}]}]}
  DIR/data/<case>/<series>.csv   time series written by the cases (header line, then numbers)

Figures it knows (everything else is drawn as a plain line plot, so new cases appear without
editing this script):
  turntable_*/trajectory.csv   paper Figs. 3-9: ball path and orbit centre in the paper's
                               0.4 m x 0.4 m frame (table centre at (0.2, 0.2)), DEM over theory
  dish_*/trajectory.csv        Figs. 10-11 (x-y) and h(t); dish_*/dish_final.csv -> Fig. 12
  */trajectories.csv with x_0, y_0, ... columns   many-ball paths (Liquid Reflections)
  sliding_block*.csv with a column v and L_* columns   Fig. 1, stop distance vs initial velocity
  chung_ooi_t*/<material>_sweep|_force|_restitution.csv  Chung & Ooi's figures over the rigid lines
  convergence_*/orders.csv     log-log error against dt, with the expected slope
  */dt_sweep.csv               a case's dt sweep (verification/sweep.h): successive differences
                               against dt, one log-log figure per family
  rolling_turntable*/frames.csv   orbit radius and spin against time, relative and absolute frames

Only the Python standard library, numpy and matplotlib (Debian python3-matplotlib, Agg backend).
"""

import json
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from report_families import (CHUNG_OOI_PANELS, FAMILIES, chung_ooi_force_figure,  # noqa: E402
                             chung_ooi_restitution_figure, chung_ooi_sweep_figure, convergence_figure,
                             dt_sweep_figure, family_of, rolling_frames_figure)
from report_bulk import bulk_figures  # noqa: E402
from report_dem8 import dem8_section  # noqa: E402
from report_html import write_html  # noqa: E402
from report_util import column, read_series, save  # noqa: E402

GRAVITY = 9.81
DISH_RADIUS = 20.0
DISH_BALL_RADIUS = 3e-3
DISH_MU_R_PRIME = 5e-5 / DISH_BALL_RADIUS
TABLE_RADIUS = 0.2
FRAME_CENTRE = 0.2  # the paper draws the table centre at (0.2, 0.2) m

# Paper figure numbers and captions for the turntable cases (others are drawn without a number).
TURNTABLE_FIGURES = {
    "turntable_t1a_stationary": ("Fig. 3", "Test 1 as captioned: Ω = 10 rad/s, flat, v0 = 0, r0 = 0.04 m at 180°, μr = 0 "
                                 "(the ball stays put)"),
    "turntable_t1b_orbit": ("Fig. 3 (pushed)", "Test 1 with v0 = 0.107 m/s at 270°: orbit at 2Ω/7"),
    "turntable_t2_tilted": ("Fig. 4", "Test 2: Ω = 10 rad/s, tilt 0.17° toward 135°, v0 = 0.107 m/s at 270°, "
                            "r0 = 0.04 m at 180°, μr = 1.5e-6 m"),
    "turntable_t2_k1e4": ("Fig. 4 (k = 1e4 N/m)", "Test 2 with the contact stiffness 1e4 N/m instead of 1e5 N/m"),
    "turntable_t3_tilted": ("Fig. 5", "Test 3: Ω = 17.6 rad/s, tilt 0.52° toward 90°, v0 = 0.008 m/s at 90°, "
                            "r0 = 0.01 m at 0°, μr = 1.5e-6 m"),
    "turntable_t3b_rolling_friction": ("Fig. 6", "Test 3 with μr = 2.5e-5 m"),
    "turntable_t4_tilted": ("Fig. 7", "Test 4: Ω = 17.6 rad/s, tilt 0.17° toward 90°, v0 = 0.009 m/s at 270°, "
                            "r0 = 0.13 m at 180°, μr = 1.5e-6 m"),
    "turntable_t4b_flat": ("Fig. 8", "Test 4 with the table flat"),
    "turntable_t5_tilt_0p10": ("Fig. 9", "Test 5 as captioned: Ω = 17.6 rad/s, tilt 0.10° toward 180°, v0 = 0, "
                               "r0 = 0.08 m at 45°, μr = 1.5e-6 m"),
    "turntable_t5_tilt_0p010": ("Fig. 9 (0.010°)", "Test 5 at 0.010° tilt: approach to a point near the centre"),
    "turntable_radius_growth": ("", "Orbit centred on the axis growing at dρ/dt = V_r (Ω = 17.6 rad/s, μr = 1.5e-6 m)"),
}

# Axis labels for series columns a generic plot recognises (column name or prefix before "_").
UNITS = {"t": "t (s)", "h": "height h (m)", "x": "x (m)", "y": "y (m)", "z": "z (m)", "v": "v (m/s)",
         "omega": "Ω (rad/s)", "rho": "ρ (m)", "energy": "energy (J)"}

def compass(ax):
    """N/E/S/W marks around the paper's 0.4 m x 0.4 m frame."""
    for label, x, y in (("N", 0.2, 0.388), ("S", 0.2, 0.012), ("E", 0.388, 0.2), ("W", 0.012, 0.2)):
        ax.text(x, y, label, ha="center", va="center", fontsize=12, fontweight="bold",
                bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.8))


def turntable_figure(out_dir, case, header, data):
    number, caption = TURNTABLE_FIGURES.get(case, ("", case))
    x, y = column(header, data, "x"), column(header, data, "y")
    if x is None or y is None:
        return None
    xt, yt = column(header, data, "x_theory"), column(header, data, "y_theory")
    cx, cy = column(header, data, "cx"), column(header, data, "cy")
    cxt, cyt = column(header, data, "cx_theory"), column(header, data, "cy_theory")
    zoom = case.startswith("turntable_t5") or case in ("turntable_t4b_flat", "turntable_radius_growth")
    fig, axes = plt.subplots(1, 2 if zoom else 1, figsize=(12.5 if zoom else 6.6, 6.2))
    axes = np.atleast_1d(axes)
    for k, ax in enumerate(axes):
        s = FRAME_CENTRE
        if xt is not None:
            ax.plot(xt + s, yt + s, color="0.55", lw=2.4, label="ball, rigid-rolling theory (RK4)")
        ax.plot(x + s, y + s, color="tab:blue", lw=0.7, label="ball, DEM")
        if cxt is not None:
            ax.plot(cxt + s, cyt + s, color="tab:orange", lw=3.0, alpha=0.6, label="orbit centre, theory")
        if cx is not None:
            ax.plot(cx + s, cy + s, color="tab:red", lw=0.9, ls="--", label="orbit centre c = r + k×v/ω_o, DEM")
        ax.plot([x[0] + s], [y[0] + s], "o", color="k", ms=4, label="start")
        ax.set_aspect("equal")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)  [paper: z]")
        if k == 0:
            circle = plt.Circle((s, s), TABLE_RADIUS, fill=False, color="0.3", lw=1)
            ax.add_patch(circle)
            ax.plot([s], [s], "+", color="0.3", ms=10)
            ax.set_xlim(0, 0.4)
            ax.set_ylim(0, 0.4)
            ax.set_xticks(np.arange(0, 0.41, 0.05))
            ax.set_yticks(np.arange(0, 0.41, 0.05))
            compass(ax)
            ax.grid(True, lw=0.3)
        else:
            # Zoom on the orbit-centre path, like the paper's inset in Fig. 9.
            xs = np.concatenate([x, cx if cx is not None else x]) + s
            ys = np.concatenate([y, cy if cy is not None else y]) + s
            mx, my = 0.5 * (xs.min() + xs.max()), 0.5 * (ys.min() + ys.max())
            half = max(0.5 * (xs.max() - xs.min()), 0.5 * (ys.max() - ys.min()), 0.01) * 1.1
            ax.set_xlim(mx - half, mx + half)
            ax.set_ylim(my - half, my + half)
            ax.plot([s], [s], "+", color="0.3", ms=12)
            ax.set_title("zoom (+ = table centre)")
            ax.grid(True, lw=0.3)
    axes[0].legend(loc="lower left", fontsize=7.5, framealpha=0.9)
    fig.suptitle(f"{number + ': ' if number else ''}{caption}", fontsize=10)
    return save(fig, out_dir, f"{case}_trajectory")


def turntable_deviation_figure(out_dir, series):
    fig, ax = plt.subplots(figsize=(8, 4.5))
    drawn = False
    for case, (header, data) in sorted(series.items()):
        cx, cy = column(header, data, "cx"), column(header, data, "cy")
        cxt, cyt = column(header, data, "cx_theory"), column(header, data, "cy_theory")
        t = column(header, data, "t")
        if cx is None or cxt is None:
            continue
        deviation = np.hypot(cx - cxt, cy - cyt)
        ax.semilogy(t, np.maximum(deviation, 1e-13), lw=0.8, label=case.replace("turntable_", ""))
        drawn = True
    if not drawn:
        plt.close(fig)
        return None
    ax.axhline(5e-4, color="k", ls=":", lw=1, label="tolerance 0.5 mm")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("|c_DEM − c_theory| (m)")
    ax.set_title("Orbit-centre path: DEM vs rigid-rolling theory along the whole run")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=7.5, ncol=2)
    return save(fig, out_dir, "turntable_centre_deviation")


def dish_xy_figure(out_dir, case, header, data, title):
    x, y = column(header, data, "x"), column(header, data, "y")
    xt, yt = column(header, data, "x_theory"), column(header, data, "y_theory")
    fig, ax = plt.subplots(figsize=(6.4, 6.2))
    if xt is not None:
        ax.plot(xt, yt, color="0.6", lw=2.2, label="rigid-rolling reference (from the end of the slide)")
    ax.plot(x, y, color="tab:blue", lw=0.6, label="DEM")
    ax.plot([x[0]], [y[0]], "o", color="k", ms=4, label="release (at rest)")
    ax.plot([0], [0], "+", color="0.3", ms=10)
    ax.set_aspect("equal")
    span = max(np.nanmax(np.abs(x)), np.nanmax(np.abs(y))) * 1.1
    ax.set_xlim(-span, span)
    ax.set_ylim(-span, span)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=7.5, loc="lower left")
    ax.set_title(title, fontsize=10)
    return save(fig, out_dir, f"{case}_xy")


def dish_height_figure(out_dir, series):
    fig, ax = plt.subplots(figsize=(9, 5.5))
    colours = plt.cm.viridis(np.linspace(0, 0.95, max(len(series), 1)))
    for colour, (case, (header, data)) in zip(colours, sorted(series.items(), key=lambda kv: kv[0])):
        t, h = column(header, data, "t"), column(header, data, "h")
        ht = column(header, data, "h_theory")
        if t is None or h is None:
            continue
        ax.plot(t, h, color=colour, lw=1.0, label=case.replace("dish_", ""))
        if ht is not None:
            ax.plot(t, ht, color=colour, lw=2.5, alpha=0.35)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("height of the ball centre h (m)")
    ax.set_title("Dish: h(t), DEM (thin) over the rigid-rolling reference (thick, faint)")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=7, ncol=3, loc="center right")
    return save(fig, out_dir, "dish_height_vs_time")


def fig12(out_dir, finals, regression):
    if not finals:
        return None
    fig, ax = plt.subplots(figsize=(8.5, 5.5))
    omega = np.linspace(0.05, 10.5, 2000)
    rho_s = DISH_RADIUS - DISH_BALL_RADIUS
    h_paper = np.where(omega ** 2 * DISH_RADIUS >= GRAVITY, DISH_RADIUS - GRAVITY / omega ** 2, 0.0)
    h_c = np.where(omega ** 2 * rho_s >= GRAVITY, rho_s - GRAVITY / omega ** 2, 0.0)
    cos_theta = np.clip(GRAVITY / (omega ** 2 * rho_s), 0, 1)
    sin_theta = np.sqrt(1 - cos_theta ** 2)
    band = np.where(sin_theta > 1e-3, rho_s * DISH_MU_R_PRIME / np.maximum(sin_theta, 1e-3), np.nan)
    above = omega ** 2 * rho_s > GRAVITY
    ax.fill_between(omega[above], (h_c - band)[above], h_c[above], color="tab:green", alpha=0.15,
                    label="rolling-resistance band h_c* − Δh … h_c*")
    ax.plot(omega, h_paper, color="k", lw=1.5, label="paper eq. 6: h = R − g/Ω² (0 below √(g/R))")
    ax.plot(omega, h_c, color="tab:green", lw=1, ls="--", label="ball centre h_c* = R − a − g/Ω²")
    for row in finals:
        release = row.get("r_release", 1.0)
        marker = "o" if abs(release - 1.0) < 1e-9 else "s"
        ax.plot(row["omega"], row["h_final"], marker, color="tab:blue" if marker == "o" else "tab:purple", ms=7,
                mfc="none" if marker == "s" else "tab:blue")
    ax.plot([], [], "o", color="tab:blue", label="DEM, released at r = 1 m (mean of the last 20 s of 600 s)")
    if any(abs(row.get("r_release", 1.0) - 1.0) > 1e-9 for row in finals):
        ax.plot([], [], "s", color="tab:purple", mfc="none", label="DEM, released at r = 2 m")
    if regression is not None:
        ax.plot([regression[0]], [regression[1]], "x", color="tab:red", ms=9, mew=2,
                label="no twist resistance (regression case): spurious lock")
    ax.axvline(math.sqrt(GRAVITY / rho_s), color="0.5", lw=0.8, ls=":")
    ax.text(math.sqrt(GRAVITY / rho_s) + 0.05, 1.0, "Ω_c", color="0.4")
    ax.set_xlabel("dish angular velocity Ω (rad/s)")
    ax.set_ylabel("final height h (m)")
    ax.set_xlim(0, 10.5)
    ax.set_ylim(-0.5, 21)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=7.5, loc="lower right")
    ax.set_title("Fig. 12: stable height of a ball in the rotating concave dish (R = 20 m)")
    return save(fig, out_dir, "fig12_height_vs_omega")


def many_ball_figure(out_dir, case, name, header, data):
    xs = sorted((c for c in header if re.fullmatch(r"x_\d+", c)), key=lambda c: int(c[2:]))
    if not xs:
        return None
    fig, ax = plt.subplots(figsize=(7, 6.6))
    colours = plt.cm.tab10(np.arange(len(xs)) % 10)
    for colour, xc in zip(colours, xs):
        index = xc[2:]
        x, y = column(header, data, xc), column(header, data, "y_" + index)
        if y is None:
            continue
        ax.plot(x, y, color=colour, lw=0.6, label=f"ball {index}")
        ax.plot([x[0]], [y[0]], "o", color=colour, ms=4)
        ax.plot([x[-1]], [y[-1]], "s", color=colour, ms=5)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=7, loc="upper right", ncol=2)
    frame = name.replace("trajectories", "").replace("_", " ").strip() or "lab frame"
    ax.set_title(f"{case}: paths seen from above, {frame} (o start, □ end)", fontsize=10)
    return save(fig, out_dir, f"{case}_{name}")


def sliding_block_figure(out_dir, case, named_series):
    """Fig. 1: every sliding_block* series of a case in one plot (theory lines once per name)."""
    fig, ax = plt.subplots(figsize=(7.5, 5))
    drawn_theory = set()
    drawn = False
    for name, (header, data) in sorted(named_series.items()):
        v = column(header, data, "v")
        if v is None or data.shape[0] == 0:
            continue
        order = np.argsort(v)
        for c in header:
            if c == "v":
                continue
            y = column(header, data, c)
            if "theory" in c or "analytic" in c:
                if c not in drawn_theory:
                    ax.plot(v[order], y[order], color="k", lw=1.5, label=c)
                    drawn_theory.add(c)
            elif c.startswith("L") or "dist" in c:
                ax.plot(v[order], y[order], "o--", ms=5, lw=0.8, label=f"{c} ({name})" if len(named_series) > 1 else c)
            drawn = True
    if not drawn:
        plt.close(fig)
        return None
    ax.set_xlabel("initial velocity v_i (m/s)")
    ax.set_ylabel("stop distance L (m)")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8)
    ax.set_title(f"Fig. 1: sliding block stop distance vs initial velocity ({case})", fontsize=10)
    return save(fig, out_dir, f"{case}_sliding_block")


def generic_figure(out_dir, case, name, header, data):
    """A series the report has no figure for: the first column on x; the other columns grouped by
    their prefix (x, x_theory; v, v_theory ...), one panel per group so that no panel mixes units."""
    if data.shape[0] == 0 or data.shape[1] < 2:
        return None
    groups = {}
    for k, c in enumerate(header[1:9], start=1):
        groups.setdefault(re.split(r"[_\d]", c)[0], []).append((k, c))
    panels = list(groups.items()) if 1 < len(groups) <= 4 else [("", [(k, c) for k, c in enumerate(header[1:9], 1)])]
    fig, axes = plt.subplots(1, len(panels), figsize=(7.5 if len(panels) == 1 else 4.2 * len(panels), 3.8))
    axes = np.atleast_1d(axes)
    x = data[:, 0]
    stride = max(1, data.shape[0] // 5000)
    for ax, (prefix, columns) in zip(axes, panels):
        for k, c in columns:
            theory = "theory" in c or "expected" in c
            ax.plot(x[::stride], data[::stride, k], "--" if theory else "-", lw=1.4 if theory else 0.9,
                    marker="o" if data.shape[0] < 30 and not theory else None, ms=3, label=c)
        ax.set_xlabel(UNITS.get(header[0], header[0]))
        label = prefix or ({re.split(r"[_\d]", c)[0] for _, c in columns}.pop() if len(
            {re.split(r"[_\d]", c)[0] for _, c in columns}) == 1 else "")
        ax.set_ylabel(UNITS.get(label, label))
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=8)
    fig.suptitle(f"{case}: {name}", fontsize=10)
    fig.tight_layout()
    return save(fig, out_dir, f"{case}_{name}")


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    out_dir, json_path = sys.argv[1], sys.argv[2]
    with open(json_path) as f:
        results = json.load(f)
    cases = results.get("cases", [])
    data_dir = os.path.join(out_dir, "data")
    os.makedirs(os.path.join(out_dir, "figures"), exist_ok=True)

    # Load every series.
    series = {}  # case -> {name: (header, data)}
    for case in cases:
        folder = os.path.join(data_dir, case["name"])
        if not os.path.isdir(folder):
            continue
        for file in sorted(os.listdir(folder)):
            if file.endswith(".csv"):
                try:
                    series.setdefault(case["name"], {})[file[:-4]] = read_series(os.path.join(folder, file))
                except OSError:
                    pass

    figures = []  # (family, subsection, title, path)
    notes_of = {c["name"]: c.get("notes", []) for c in cases}
    used = set()
    # Turntable, Figs. 3-9.
    turntable = {c: s["trajectory"] for c, s in series.items() if c.startswith("turntable_") and "trajectory" in s}
    order = list(TURNTABLE_FIGURES) + sorted(set(turntable) - set(TURNTABLE_FIGURES))
    for case in order:
        if case in turntable:
            path = turntable_figure(out_dir, case, *turntable[case])
            if path:
                figures.append(("paper", "Flat turntable (paper Figs. 3-9)", case, path))
                used.add((case, "trajectory"))
    path = turntable_deviation_figure(out_dir, turntable)
    if path:
        figures.append(("paper", "Flat turntable (paper Figs. 3-9)", "whole-path comparison", path))

    # Dish, Figs. 10-12.
    dish = {c: s["trajectory"] for c, s in series.items() if c.startswith("dish_") and "trajectory" in s}
    for case, title in (("dish_omega_0p5", "Fig. 10: Ω = 0.5 rad/s (< Ω_c), released at rest at r = 1 m, 180°"),
                        ("dish_omega_0p9", "Fig. 11: Ω = 0.9 rad/s, released at rest at r = 1 m, 180°"),
                        ("dish_twist_regression", "Ω = 0.9 rad/s without twist resistance: spurious lock")):
        if case in dish:
            path = dish_xy_figure(out_dir, case, *dish[case], title)
            if path:
                figures.append(("paper", "Concave dish (paper Figs. 10-12)", case, path))
    for case in dish:
        used.add((case, "trajectory"))
    if dish:
        figures.append(("paper", "Concave dish (paper Figs. 10-12)", "h(t)", dish_height_figure(out_dir, dish)))
    finals = []
    for case, s in series.items():
        if "dish_final" in s:
            header, data = s["dish_final"]
            for row in data:
                finals.append(dict(zip(header, row)))
            used.add((case, "dish_final"))
    regression = None
    if "dish_twist_regression" in dish:
        header, data = dish["dish_twist_regression"]
        t, h = column(header, data, "t"), column(header, data, "h")
        regression = (0.9, float(np.mean(h[t > t[-1] - 20])))
    path = fig12(out_dir, finals, regression)
    if path:
        figures.append(("paper", "Concave dish (paper Figs. 10-12)", "Fig. 12", path))

    # Fig. 1: all sliding_block* series of a case in one figure.
    for case in sorted(series):
        blocks = {n: s for n, s in series[case].items() if n.startswith("sliding_block") and "v" in s[0]}
        if blocks:
            path = sliding_block_figure(out_dir, case, blocks)
            if path:
                figures.append((family_of(case), "Sliding block (paper Fig. 1)", case, path))
                used.update((case, n) for n in blocks)

    # Chung & Ooi, drawn as the paper draws them.
    for case in sorted(series):
        if not case.startswith("chung_ooi_"):
            continue
        named = series[case]
        if case in CHUNG_OOI_PANELS:
            sweeps = {n: v for n, v in named.items() if n.endswith("_sweep") and n != "dt_sweep"}
            path = chung_ooi_sweep_figure(out_dir, case, sweeps) if sweeps else None
        else:
            sweeps = {n: v for n, v in named.items() if n.endswith("_force")}
            path = chung_ooi_force_figure(out_dir, case, sweeps) if sweeps else None
            if not sweeps:
                sweeps = {n: v for n, v in named.items() if n.endswith("_restitution")}
                path = chung_ooi_restitution_figure(out_dir, case, sweeps) if sweeps else None
        if path:
            figures.append(("chung_ooi", "", case, path))
            used.update((case, n) for n in sweeps)
    # Convergence orders (log-log) and the turntable frames.
    for case in sorted(series):
        if "orders" in series[case] and case.startswith("convergence_"):
            path = convergence_figure(out_dir, case, *series[case]["orders"], notes_of.get(case, []))
            if path:
                figures.append(("convergence", "", case, path))
                used.add((case, "orders"))
        if case.startswith("rolling_turntable"):
            path = rolling_frames_figure(out_dir, case, series[case])
            if path:
                figures.append(("rolling", "", case, path))
                used.update((case, n) for n in series[case])

    # The dt sweeps of the collision, friction and rolling cases, one figure per family, in the
    # convergence section.
    for key, title, _, _ in FAMILIES:
        sweeps = {c: (*s["dt_sweep"], notes_of.get(c, [])) for c, s in series.items()
                  if "dt_sweep" in s and family_of(c) == key}
        if sweeps:
            path = dt_sweep_figure(out_dir, key, title, sweeps)
            if path:
                figures.append(("convergence", "dt sweeps of the cases (dt, dt/2, dt/4)", title, path))
        used.update((c, "dt_sweep") for c in sweeps)

    # The bulk checks: Beverloo, Janssen, angle of repose.
    for case, path, names in bulk_figures(out_dir, series):
        figures.append(("bulk", "", case, path))
        used.update((case, n) for n in names)

    # Everything else: many-ball paths, generic plots.
    for case in sorted(series):
        for name, (header, data) in sorted(series[case].items()):
            if (case, name) in used:
                continue
            if any(re.fullmatch(r"x_\d+", c) for c in header):
                path, section = many_ball_figure(out_dir, case, name, header, data), "Many balls"
            else:
                path, section = generic_figure(out_dir, case, name, header, data), ""
            if path:
                figures.append((family_of(case), section, f"{case}: {name}", path))

    # The cross-code benchmark, from the latest results files (report_dem8.py).
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    write_html(out_dir, cases, figures, dem8_section(out_dir, root))
    print(f"report: {os.path.join(out_dir, 'index.html')} ({len(figures)} figures)")
    return 0



if __name__ == "__main__":
    sys.exit(main())
