"""Figures of the bulk checks (docs/bulk-checks.md) for scripts/report.py: Beverloo's discharge
rate against the orifice diameter with the fitted law and the discharged mass against time,
Janssen's base stress against the fill height with the fitted curve and hydrostatics, and the
angle of repose against the rolling and sliding friction with the piles' surfaces."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from report_util import column, save  # noqa: E402


def beverloo_figure(out_dir, case, named):
    if "beverloo_rate" not in named:
        return None
    header, data = named["beverloo_rate"]
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    ratio, rate, error, fit = (column(header, data, c) for c in ("D_over_d", "W", "W_error", "W_fit"))
    left.errorbar(ratio, 1e3 * rate, yerr=None if error is None else 1e3 * error, fmt="o", capsize=3,
                  label="W over the rate window: mean of the fills ± standard error")
    order = np.argsort(ratio)
    left.plot(ratio[order], 1e3 * fit[order], "-", label="Beverloo, C and k of the weighted fit")
    left.set_xlabel("orifice D / d")
    left.set_ylabel("discharge rate W [g/s]")
    left.grid(True, lw=0.3)
    left.legend(fontsize=8)
    if "beverloo_mass" in named:
        mh, md = named["beverloo_mass"]
        t = md[:, 0]
        for k, name in enumerate(mh[1:], start=1):
            ok = ~np.isnan(md[:, k])
            right.plot(t[ok], 1e3 * md[ok, k], lw=1.2, label=name.replace("m_D", "D/d = "))
        right.set_xlabel("time after opening [s] (first fill)")
        right.set_ylabel("discharged mass [g]")
        right.grid(True, lw=0.3)
        right.legend(fontsize=8)
    fig.suptitle(f"{case}: W = C ρ_b √g (D − k d)^(5/2)", fontsize=10)
    fig.tight_layout()
    return save(fig, out_dir, f"{case}_beverloo")


def janssen_figure(out_dir, case, named):
    if "janssen_load" not in named:
        return None
    header, data = named["janssen_load"]
    z, sigma, janssen, hydro = (column(header, data, c) for c in
                                ("z_over_D", "sigma", "sigma_janssen", "sigma_hydrostatic"))
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    ax.plot(z, sigma, "o", label="base load / area, after each stage")
    ax.plot(z, janssen, "-", label="Janssen, fitted K")
    ax.plot(z, hydro, "--", lw=0.9, label="hydrostatic ρ_b g z")
    ax.set_ylim(0, 1.3 * max(np.nanmax(sigma), np.nanmax(janssen)))
    ax.set_xlabel("fill height z / D")
    ax.set_ylabel("base stress σ [Pa]")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8)
    ax.set_title(f"{case}: σ = ρ_b g D/(4 μ_w K) (1 − exp(−4 μ_w K z/D))", fontsize=10)
    fig.tight_layout()
    return save(fig, out_dir, f"{case}_janssen")


def repose_figure(out_dir, case, named):
    if "repose_trend" not in named:
        return None
    header, data = named["repose_trend"]
    series, mu_s, mu_r, angle, error = (column(header, data, c) for c in
                                        ("series", "mu_s", "mu_r_mm", "angle", "uncertainty"))
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
    rolling, sliding = series == 0, series == 1
    axes[0].errorbar(mu_r[rolling], angle[rolling], yerr=error[rolling], fmt="o-", capsize=3)
    axes[0].set_xscale("log")
    axes[0].set_xlabel(f"rolling friction μ_r [mm] (μ_s = {mu_s[rolling][0]:.1f})")
    axes[1].errorbar(mu_s[sliding], angle[sliding], yerr=error[sliding], fmt="s-", capsize=3)
    axes[1].set_xlabel(f"sliding friction μ_s (μ_r = {mu_r[sliding][0]:.2f} mm)")
    for ax in axes[:2]:
        ax.axhspan(20, 40, color="0.9", zorder=0)
        ax.set_ylabel("angle of repose [deg]")
        ax.grid(True, lw=0.3)
    if "repose_profiles" in named:
        ph, pd = named["repose_profiles"]
        for k, name in enumerate(ph[1:], start=1):
            label = name.replace("top_mus", "μ_s ").replace("_mur", ", μ_r ") + " mm"
            axes[2].plot(1e3 * pd[:, 0], 1e3 * pd[:, k], lw=1, label=label)
        axes[2].set_aspect("equal")
        axes[2].set_ylim(0, 1.8 * np.nanmax(1e3 * pd[:, 1:]))
        axes[2].set_xlabel("x [mm] (first pile of each pair)")
        axes[2].set_ylabel("surface height [mm]")
        axes[2].grid(True, lw=0.3)
        axes[2].legend(fontsize=6, loc="upper center", ncol=2)
    fig.suptitle(f"{case}: piles in a slot, angle from the flanks' fitted lines", fontsize=10)
    fig.tight_layout()
    return save(fig, out_dir, f"{case}_repose")


FIGURES = {"beverloo_": beverloo_figure, "janssen_": janssen_figure, "angle_of_repose": repose_figure}


def bulk_figures(out_dir, series):
    """[(case, path, names used)] for every bulk case among `series` (case -> {name: (header, data)})."""
    made = []
    for case in sorted(series):
        for prefix, figure in FIGURES.items():
            if case.startswith(prefix):
                path = figure(out_dir, case, series[case])
                if path:
                    made.append((case, path, list(series[case])))
    return made
