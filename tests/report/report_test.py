#!/usr/bin/python3
"""Smoke test of scripts/report.py on synthetic results: every kind of series it knows (turntable
trajectory, dish trajectory and final heights, many-ball paths, sliding block, Chung & Ooi sweeps,
force curves and restitution, convergence orders, rolling frames, dt sweeps) and one it does not
know must give a figure, and index.html must list every case and quantity."""
import json
import math
import os
import subprocess
import sys
import tempfile

script = sys.argv[1]
with tempfile.TemporaryDirectory() as out:
    data = os.path.join(out, "data")

    def series(case, name, header, rows):
        os.makedirs(os.path.join(data, case), exist_ok=True)
        with open(os.path.join(data, case, name + ".csv"), "w") as f:
            f.write(",".join(header) + "\n")
            for row in rows:
                f.write(",".join(str(v) for v in row) + "\n")

    t = [0.01 * i for i in range(400)]
    series("turntable_t2_tilted", "trajectory",
           ["t", "x", "y", "x_theory", "y_theory", "cx", "cy", "cx_theory", "cy_theory"],
           [[s, 0.03 * math.cos(3 * s) - 0.001 * s, 0.03 * math.sin(3 * s), 0.03 * math.cos(3 * s) - 0.001 * s,
             0.03 * math.sin(3 * s), -0.001 * s, 0, -0.001 * s, 1e-9] for s in t])
    series("dish_omega_0p9", "trajectory", ["t", "x", "y", "h", "x_theory", "y_theory", "h_theory"],
           [[s, s * math.cos(s), s * math.sin(s), 0.01 * s, "nan", "nan", "nan"] for s in t])
    series("dish_omega_0p9", "dish_final", ["omega", "h_final", "h_c_star", "h_paper", "r_final", "h_theory_final",
                                            "r_release"], [[0.9, 7.56, 7.886, 7.889, 15.9, 7.59, 1.0]])
    series("liquid_reflections", "trajectories_dish_frame", ["t", "x_0", "y_0", "x_1", "y_1"],
           [[s, math.cos(s), math.sin(s), -math.cos(s), -math.sin(s)] for s in t])
    series("sliding_block_stop", "sliding_block_dt1e-7", ["v", "L_theory", "L_measured"],
           [[v, v * v / (2 * 0.5 * 9.81), 1.01 * v * v / (2 * 0.5 * 9.81)] for v in (0.5, 1, 2, 3, 4, 5, 6)])
    series("sliding_block_stop", "sliding_block_dt1e-8", ["v", "L_theory", "L_measured"],
           [[v, v * v / (2 * 0.5 * 9.81), 1.001 * v * v / (2 * 0.5 * 9.81)] for v in (0.5, 1, 2, 3, 4, 5, 6)])
    series("chung_ooi_t4", "al_oxide_sweep", ["theta_deg", "e_t", "e_t_rigid", "omega", "omega_rigid", "rebound_deg",
                                              "rebound_deg_rigid", "slid"],
           [[th, 0.9, 0.8, 500, 480, 10, 9, 1] for th in (5, 45, 85)])
    series("chung_ooi_t4", "dt_sweep", ["quantity", "dt_scale", "difference", "difference_expected_slope"],
           [[0, 1, 1e-4, 1e-4], [0, 0.5, 5e-5, 5e-5]])
    series("chung_ooi_t1", "glass_force", ["t", "delta", "F", "F_hertz"], [[1e-6 * i, 1e-6 * i, i, i] for i in range(5)])
    series("chung_ooi_t3", "al_oxide_restitution", ["e_in", "e_out", "e_identity"], [[0.5, 0.5, 0.5], [1, 1, 1]])
    series("convergence_orders", "orders", ["study", "dt_over_tc", "error", "error_expected_slope"],
           [[0, 0.04, 4e-4, 4e-4], [0, 0.02, 1e-4, 1e-4], [0, 0.01, 2.5e-5, 2.5e-5]])
    series("rolling_turntable_frames", "frames",
           ["t", "rho_relative", "rho_relative_theory", "rho_absolute", "rho_absolute_theory", "spin_relative",
            "spin_absolute", "spin_absolute_theory"],
           [[s, 0.006 + 6e-4 * s, 0.006 + 6e-4 * s, 0.006 + 4e-4 * s, 0.006 + 4e-4 * s, 10, 10 - s, 10 - s]
            for s in t[:100]])
    series("bowling_ball", "dt_sweep", ["quantity", "dt_scale", "difference", "difference_expected_slope"],
           [[0, 1, 1e-4, 1e-4], [0, 0.5, 2.6e-5, 2.5e-5], [1, 1, 1e-6, "nan"], [1, 0.5, 4e-7, "nan"]])
    series("something_new", "energy", ["t", "kinetic", "potential"], [[s, s, 1 - s] for s in t])
    quantity = {"name": "q", "unit": "m", "expected": 1.0, "measured": 1.0, "tolerance": 0.01, "relative": True,
                "error": 0.0, "passed": True, "why": "because"}
    notes = ["a note", "dt sweep 0, t_star: differences 1e-4, 2.6e-5: order 1.94",
             "dt sweep 1, v_f: differences 1e-6, 4e-7: order 1.32 (not checked: no expected order declared)"]
    cases = [{"name": n, "summary": "s", "reference": "r", "passed": True, "seconds": 0.1, "notes": notes,
              "quantities": [quantity]}
             for n in ("turntable_t2_tilted", "dish_omega_0p9", "liquid_reflections", "sliding_block_stop",
                       "something_new", "rolling_turntable_frames", "bowling_ball", "chung_ooi_t4", "chung_ooi_t1", "chung_ooi_t3", "convergence_orders")]
    cases.append({"name": "broken", "summary": "s", "reference": "r", "passed": False, "seconds": 0,
                  "error": "it threw", "notes": [], "quantities": []})
    json_path = os.path.join(data, "results.json")
    with open(json_path, "w") as f:
        json.dump({"cases": cases}, f)
    subprocess.run(["/usr/bin/python3", script, out, json_path], check=True)
    page = open(os.path.join(out, "index.html")).read()
    for needle in ("turntable_t2_tilted", "broken", "it threw", "because", "Fig. 12", "FAIL", "PASS",
                   "href='#chung_ooi'", "<details"):
        assert needle in page, needle
    figures = set(os.listdir(os.path.join(out, "figures")))
    for expected in ("turntable_t2_tilted_trajectory.png", "dish_omega_0p9_xy.png", "fig12_height_vs_omega.png",
                     "liquid_reflections_trajectories_dish_frame.png",
                     "sliding_block_stop_sliding_block.png", "something_new_energy.png", "chung_ooi_t4_sweep.png",
                     "chung_ooi_t1_force.png", "chung_ooi_t3_restitution.png", "convergence_orders_orders.png",
                     "rolling_turntable_frames_radius.png", "dt_sweep_single.png"):
        assert expected in figures, (expected, sorted(figures))
print("report smoke test: OK")
