"""Families of verification cases and the figures of the benchmark families (Chung & Ooi,
convergence orders, rolling frames) for scripts/report.py."""

import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from report_util import column, save  # noqa: E402

# Families of cases: (key, title, what it checks, name prefixes). A case belongs to the first family
# whose prefix it starts with; the last family takes the rest.
FAMILIES = [
    ("paper", "The paper's 3D tests (turntable, dish, many balls)",
     "Xiang, Munjiza, Latham & Guises: the flat turntable Tests 1-5 (Figs. 3-9) against the rigid-rolling "
     "equations, the rotating concave dish (Figs. 10-12) and the Liquid Reflections scene.",
     ("turntable_", "dish_", "liquid_")),
    ("fdem", "2D FEM/DEM (the paper's sliding block and element checks)",
     "The paper's Fig. 1 sliding block, L = v²/(2μg), and the constant-strain-triangle checks.",
     ("sliding_block", "fdem_")),
    ("chung_ooi", "Chung & Ooi (2011) impact benchmarks 1-8",
     "Hertz-Mindlin impacts of Chung & Ooi, each for both of its materials: tests 1-3 against the Hertz closed "
     "forms, tests 4-8 as sweeps drawn over the rigid-body lines. Tangential quantities use contact-point "
     "velocities unless named v_t (centre).",
     ("chung_ooi_",)),
    ("asmar", "Asmar-style tests",
     "Analytic single-situation tests in the spirit of Asmar et al. (2002): bouncing ball, vibrating plate, "
     "Newton's cradle, energy over many elastic collisions.",
     ("asmar_",)),
    ("rolling", "Rolling resistance (Ai, Chen, Rotter & Ooi 2011)",
     "Type B (viscous) and the absolute-frame type A against closed forms, and the turntable case that separates "
     "the relative and absolute frames. Types A and C: rolling_resistance_stop (single-particle family).",
     ("rolling_resistance_models", "rolling_turntable")),
    ("bulk", "Bulk checks (many particles against published laws)",
     "Beverloo's discharge rate through four orifices, Janssen's saturating base load, and the angle of repose "
     "against rolling and sliding friction (docs/bulk-checks.md).",
     ("beverloo_", "janssen_", "angle_of_repose")),
    ("convergence", "Convergence orders in dt",
     "Collision, friction and rolling errors at dt, dt/2, dt/4 (more levels where the error scatters); the observed "
     "order against the scheme's.",
     ("convergence_",)),
    ("single", "Single-particle and contact-law checks",
     "Free fall, restitution, sliding-to-rolling, inclines, rolling types A and C, moving walls, two-sphere "
     "collisions.",
     ()),
]


def family_of(case):
    for key, _, _, prefixes in FAMILIES[:-1]:
        if any(case.startswith(p) for p in prefixes):
            return key
    return FAMILIES[-1][0]


def material_of(name):
    for suffix in ("_sweep", "_force", "_restitution", "_energy", "_orbit"):
        if name.endswith(suffix):
            return name[: -len(suffix)]
    return name


# Chung & Ooi sweeps: per case, panels (x column, y column, rigid column or None, x label, y label, log x).
CHUNG_OOI_PANELS = {
    "chung_ooi_t4": [("theta_deg", "e_t", "e_t_rigid", "incidence angle θ (deg)", "tangential COR e_t = v_t'/v_t", False),
                     ("theta_deg", "omega", "omega_rigid", "incidence angle θ (deg)", "rebound angular velocity ω' (rad/s)", False),
                     ("theta_deg", "rebound_deg", "rebound_deg_rigid", "incidence angle θ (deg)",
                      "rebound angle of the contact point (deg)", False)],
    "chung_ooi_t5": [("psi1", "psi2", "psi2_rigid", "ψ1 = V_t/(μ V_n)", "ψ2 = V_t'/(μ V_n')", False),
                     ("psi1", "spin", "spin_rigid", "ψ1 = V_t/(μ V_n)", "−R ω'/(μ V_n)", False)],
    "chung_ooi_t6": [("X", "beta", "beta_rigid", "X = 3.5 μ (1+e) V_n / V_t", "β = −V_t'/V_t", True),
                     ("tan_incidence", "tan_recoil", "tan_recoil_rigid", "tan(incidence) = V_t/V_n",
                      "tan(recoil) = V_t'/V_n'", False)],
    "chung_ooi_t7": [("omega", "omega_out_1", "omega", "initial spin ω (rad/s)", "ω' (rad/s)", True),
                     ("omega", "vt_out_1", None, "initial spin ω (rad/s)", "v_t' (m/s)", True)],
}
CHUNG_OOI_PANELS["chung_ooi_t8"] = CHUNG_OOI_PANELS["chung_ooi_t6"]
MARKERS = ["o", "s", "^", "D"]


def chung_ooi_sweep_figure(out_dir, case, named):
    panels = CHUNG_OOI_PANELS[case]
    fig, axes = plt.subplots(1, len(panels), figsize=(5.2 * len(panels), 4.4))
    axes = np.atleast_1d(axes)
    for ax, (xc, yc, rc, xl, yl, logx) in zip(axes, panels):
        rigid_drawn = False
        for k, (name, (header, data)) in enumerate(sorted(named.items())):
            x, y = column(header, data, xc), column(header, data, yc)
            if x is None or y is None:
                continue
            order = np.argsort(x)
            colour = plt.cm.tab10(k)
            ax.plot(x[order], y[order], MARKERS[k % 4], color=colour, mfc="none", ms=6, label=f"DEM, {material_of(name)}")
            rigid = column(header, data, rc) if rc else None
            if rigid is not None and not rigid_drawn:
                ax.plot(x[order], rigid[order], "-", color="k", lw=1.3, label="rigid body")
                rigid_drawn = True
        if logx:
            ax.set_xscale("log")
        ax.set_xlabel(xl)
        ax.set_ylabel(yl)
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=7.5)
    fig.suptitle(f"{case.replace('chung_ooi_t', 'Chung & Ooi test ')}: DEM (markers) over the rigid-body line",
                 fontsize=10)
    fig.tight_layout()
    return save(fig, out_dir, f"{case}_sweep")


def chung_ooi_force_figure(out_dir, case, named):
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.4))
    for k, (name, (header, data)) in enumerate(sorted(named.items())):
        t, d, f, fh = (column(header, data, c) for c in ("t", "delta", "F", "F_hertz"))
        if d is None or f is None:
            continue
        colour = plt.cm.tab10(k)
        a1.plot(d * 1e6, f, color=colour, lw=1.0, label=f"DEM, {material_of(name)}")
        if fh is not None:
            a1.plot(d * 1e6, fh, "--", color="k", lw=0.8, label="Hertz (4/3) E*√R* δ^1.5" if k == 0 else None)
        a2.plot((t - t[0]) * 1e6, f, color=colour, lw=1.0, label=material_of(name))
    a1.set_xlabel("overlap δ (µm)")
    a1.set_ylabel("normal force F (N)")
    a2.set_xlabel("time since first touch (µs)")
    a2.set_ylabel("normal force F (N)")
    for ax in (a1, a2):
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=7.5)
    fig.suptitle(f"{case.replace('chung_ooi_t', 'Chung & Ooi test ')}: force-overlap and force-time", fontsize=10)
    fig.tight_layout()
    return save(fig, out_dir, f"{case}_force")


def chung_ooi_restitution_figure(out_dir, case, named):
    fig, ax = plt.subplots(figsize=(5.6, 5))
    ax.plot([0, 1], [0, 1], "-", color="k", lw=1.2, label="e_out = e_in")
    for k, (name, (header, data)) in enumerate(sorted(named.items())):
        ax.plot(column(header, data, "e_in"), column(header, data, "e_out"), MARKERS[k % 4], mfc="none",
                color=plt.cm.tab10(k), ms=7, label=f"DEM, {material_of(name)}")
    ax.set_xlabel("input restitution e_in")
    ax.set_ylabel("measured restitution e_out")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8)
    ax.set_title("Chung & Ooi test 3: e_out against e_in", fontsize=10)
    return save(fig, out_dir, f"{case}_restitution")


def convergence_figure(out_dir, case, header, data, notes):
    names = {}
    for note in notes:
        m = re.match(r"study (\d+): (.*)", note)
        if m:
            names[int(m.group(1))] = m.group(2)
    fig, ax = plt.subplots(figsize=(8.5, 6))
    study = column(header, data, "study")
    for k, index in enumerate(sorted(set(study.astype(int)))):
        rows = study == index
        dt, err = column(header, data, "dt_over_tc")[rows], column(header, data, "error")[rows]
        ref = column(header, data, "error_expected_slope")
        colour = plt.cm.tab10(k)
        ax.loglog(dt, err, "o-", color=colour, lw=1.2, label=names.get(index, f"study {index}"))
        if ref is not None:
            ax.loglog(dt, ref[rows], ":", color=colour, lw=1)
    ax.set_xlabel("dt / reference time (contact time; τ for rolling)")
    ax.set_ylabel("|error|")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=7, loc="upper left")
    ax.set_title("Observed convergence (solid) against the scheme's expected order (dotted)", fontsize=10)
    return save(fig, out_dir, f"{case}_orders")


def rolling_frames_figure(out_dir, case, named):
    """Orbit radius and spin about the normal against time, relative and absolute frames, DEM
    (solid) over the closed forms (dashed), as a radius-growth plot in the style of BENCHMARKS 1b."""
    if "frames" not in named:
        return None
    header, data = named["frames"]
    t = column(header, data, "t")
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11.5, 4.4))
    for k, frame in enumerate(("relative", "absolute")):
        rho, rho_t = column(header, data, f"rho_{frame}"), column(header, data, f"rho_{frame}_theory")
        spin = column(header, data, f"spin_{frame}")
        colour = plt.cm.tab10(k)
        if rho is not None:
            a1.plot(t, rho * 1e3, color=colour, lw=1.2, label=f"DEM, {frame} frame")
        if rho_t is not None:
            a1.plot(t, rho_t * 1e3, "--", color="k" if k == 0 else "0.45", lw=1.0,
                    label="ρ0 + V_r t" if k == 0 else "ρ⁷s⁵ = const, t(s)")
        if spin is not None:
            a2.plot(t, spin, color=colour, lw=1.2, label=f"DEM, {frame} frame")
    spin_t = column(header, data, "spin_absolute_theory")
    if spin_t is not None:
        a2.plot(t, spin_t, "--", color="0.45", lw=1.0, label="absolute: ds/dt = −(5/2)(μr g/a²) s/|ω|")
    a1.set_ylabel("orbit radius ρ = |v|/ω_o (mm)")
    a2.set_ylabel("spin about the table normal s = ω·k (rad/s)")
    for ax in (a1, a2):
        ax.set_xlabel("t (s)")
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Turntable (Ω = 10 rad/s, μr = 1.5e-6 m), orbit centred on the axis, ball sharing the table's "
                 "spin: both frames orbit at 2Ω/7", fontsize=10)
    fig.tight_layout()
    return save(fig, out_dir, f"{case}_radius")


def sweep_orders(header, data, notes):
    """A case's dt sweep as rows (label, observed order, expected order or None), from its notes
    ("dt sweep K, NAME: differences d1, d2: order p") and its dt_sweep series (the expected slope
    column is finite for the checked quantities)."""
    names = {}
    for note in notes:
        m = re.match(r"dt sweep (\d+), (.*?): differences ([^,]+), ([^:]+): order", note)
        if m:
            names[int(m.group(1))] = m.group(2)
    index, diff = column(header, data, "quantity"), column(header, data, "difference")
    ref = column(header, data, "difference_expected_slope")
    rows = []
    if index is None or diff is None:
        return rows
    for i in sorted(set(index.astype(int))):
        d = diff[index == i]
        r = ref[index == i] if ref is not None else np.array([np.nan, np.nan])
        if len(d) < 2 or d[1] <= 0:
            continue
        observed = float(np.log2(d[0] / d[1]))
        expected = float(np.log2(r[0] / r[1])) if np.all(np.isfinite(r)) and r[1] > 0 else None
        rows.append((names.get(i, f"quantity {i}"), observed, expected))
    return rows


def dt_sweep_figure(out_dir, family, title, sweeps, margin=0.3):
    """One family's dt sweeps: the observed order p = log2(|q(dt) - q(dt/2)| / |q(dt/2) - q(dt/4)|)
    of every quantity (filled: checked against the scheme's order, the bar marking p_expected - margin
    and p_expected; open: printed only), grouped by case."""
    rows = []
    for case, (header, data, notes) in sorted(sweeps.items()):
        for label, observed, expected in sweep_orders(header, data, notes):
            rows.append((f"{case.replace('chung_ooi_', 'C&O ')}: {label}", observed, expected))
    if not rows:
        return None
    fig, ax = plt.subplots(figsize=(11, 1.2 + 0.27 * len(rows)))
    y = np.arange(len(rows))[::-1]
    for k, (label, observed, expected) in zip(y, rows):
        shown = min(max(observed, -1.0), 5.0)
        if expected is not None:
            ax.plot([expected - margin, expected], [k, k], "-", color="0.6", lw=6, solid_capstyle="butt")
            ax.plot([expected], [k], "|", color="k", ms=12, mew=2)
            ok = observed >= expected - margin
            ax.plot([shown], [k], "o", color="tab:green" if ok else "tab:red", ms=7)
        else:
            ax.plot([shown], [k], "o", mfc="none", color="tab:blue", ms=7)
        if shown != observed:
            ax.annotate(f"{observed:.1f}", (shown, k), textcoords="offset points", xytext=(6, -3), fontsize=7)
    ax.set_yticks(y)
    ax.set_yticklabels([r[0][:95] for r in rows], fontsize=7)
    ax.set_xlim(-1.2, 5.2)
    ax.set_ylim(-0.8, len(rows) - 0.2)
    ax.axvline(1, color="0.85", lw=0.8, zorder=0)
    ax.axvline(2, color="0.85", lw=0.8, zorder=0)
    ax.set_xlabel("observed order p = log2(|q(dt) − q(dt/2)| / |q(dt/2) − q(dt/4)|)")
    ax.grid(True, axis="x", lw=0.3)
    ax.plot([], [], "o", color="tab:green", label="checked, p ≥ expected − 0.3")
    ax.plot([], [], "|", color="k", ms=10, mew=2, label="the scheme's order (grey: the margin)")
    ax.plot([], [], "o", mfc="none", color="tab:blue", label="not checked (max over a set, statistic, varying phase)")
    ax.legend(fontsize=7.5, loc="upper center", bbox_to_anchor=(0.5, -0.8 / (1.2 + 0.27 * len(rows)) - 0.02), ncol=3)
    ax.set_title(f"{title}: observed dt orders (dt, dt/2, dt/4); quantities at rounding level are listed in the "
                 "case notes", fontsize=9)
    return save(fig, out_dir, f"dt_sweep_{family}")
