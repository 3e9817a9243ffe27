"""The report's "Cross-code benchmark (DEM8)" section (scripts/report.py): Dosta et al., Comput.
Phys. Commun. 296 (2024) 109066, run in veridem and in its peers on this machine (bench/dem8/).

These runs are long (bench/dem8/README.md): they are not part of the verification suite. The
section draws from the latest results files in bench/results/ (the newest date in the file name
wins), or, for veridem's 25k curve, from a fresh run's out/dem8/impact_25k/tracked.csv when that is
newer (`ctest --preset release -L '^dem8$'` or bench/dem8/run.sh impact_25k writes it). Every entry
states the date and the machine it was made on: the date and machine tag of the file name
(YYYY-MM-DD-<machine>-dem8-...), and the machine's description from the line starting with
"# machine:" (any case) in a results log of the same date and tag, if one has it.

Files read (all optional; a missing one leaves its part out and says so):
  <date>-<machine>-dem8-impact25k-ball.csv     veridem, 25k bed: t,id,x,y,z,vx,vy,vz of the ball every
                                               0.5 ms (or t,z)
  <date>-<machine>-dem8-impact-liggghts.csv    LIGGGHTS, 25k bed: t,z (bench/dem8/peers/run_impact.sh)
  <date>-<machine>-dem8-impact-yade.csv        Yade, 25k bed: t,z
  <date>-<machine>-dem8-impact50k-ball.csv     veridem, 50k bed (t from the benchmark's t = 0)
  <date>-<machine>-dem8-impact50k-liggghts.csv LIGGGHTS, 50k bed
  <date>-<machine>-dem8-impact50k-yade.csv     Yade, 50k bed
  <date>-<machine>-dem8-silo-<run>-<code>.csv  a silo run (run: M1_small, M1_large, M2_small, M2_large;
                                               code: veridem, liggghts): t,retained, t from the gate's
                                               opening [s]; the discharge rate is fitted here
                                               (discharge_rate)
  <date>-<machine>-dem8-drum-<code>.csv       a drum run (code: veridem, liggghts): t,zone,material,count
                                               (veridem's zones.csv columns; run_drum.sh writes
                                               LIGGGHTS' in them); the table gives each code's counts
                                               at each time both codes reached
  <date>-<machine>-dem8-speed.csv              the speed table: case,pair,code,setup,cores,particles,
                                               steps,wall_s,particle_steps_per_s,date,machine (the rows
                                               of one pair were timed in turn in the same minutes)
"""

import csv
import datetime
import html
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from report_util import save  # noqa: E402

BALL_RADIUS = 0.01  # m (the organisers' projectile)
FLOOR_Z = -0.0902431  # m, the box's floor (../shared/dem8/impact/walls.txt)
CODES = (("veridem", "C0", "-"), ("LIGGGHTS", "C1", "--"), ("Yade", "C2", ":"))
# The results-file kind (after 'dem8-') of each code's ball curve on each bed.
KINDS = {"25k": {"veridem": "impact25k-ball", "LIGGGHTS": "impact-liggghts", "Yade": "impact-yade"},
         "50k": {"veridem": "impact50k-ball", "LIGGGHTS": "impact50k-liggghts", "Yade": "impact50k-yade"}}
SILO_RUNS = ("M1_small", "M1_large", "M2_small", "M2_large")
NAME = re.compile(r"^(\d{4}-\d{2}-\d{2})-(.+)-dem8-(.+)\.(csv|txt)$")


def latest(results_dir, kind):
    """The newest results file of this kind (the part after 'dem8-'), as (path, date, machine)."""
    found = []
    for file in os.listdir(results_dir) if os.path.isdir(results_dir) else []:
        m = NAME.match(file)
        if m and m.group(3) == kind and m.group(4) == "csv":
            found.append((m.group(1), file, m.group(2)))
    if not found:
        return None
    date, file, machine = max(found)
    return os.path.join(results_dir, file), date, machine


def machine_line(results_dir, date, machine):
    """The '# machine:' line of a dem8 results log of this date and machine tag, or ''."""
    for file in sorted(os.listdir(results_dir)):
        if file.startswith(f"{date}-{machine}-dem8") and file.endswith(".txt"):
            with open(os.path.join(results_dir, file)) as stream:
                for line in stream:
                    if line.lower().startswith("# machine:"):
                        return line.split(":", 1)[1].strip()
    return ""


def read_curve(path):
    """(t [s], z [m]) lists of a ball curve: t,z or t,id,x,y,z,... columns."""
    t, z = [], []
    with open(path) as stream:
        for row in csv.DictReader(stream):
            t.append(float(row["t"]))
            z.append(float(row["z"]))
    return t, z


def bed_top(shared_dir, bed):
    """The bed's top, max(z + r) of its beads [m] (convert_impact.py's bed_top), or None."""
    path = os.path.join(shared_dir, "impact", f"particles_{bed}.txt")
    if not os.path.isfile(path):
        return None
    top = None
    with open(path) as stream:
        for no, line in enumerate(stream):
            fields = line.split()
            if no == 0 or len(fields) != 4:  # header; the projectile row has six columns
                continue
            r, z = float(fields[0]), float(fields[3])
            top = z + r if top is None else max(top, z + r)
    return top


def curves(root, results_dir, bed):
    """code -> (t, z, date, machine, source) for the impact on the bed ('25k' or '50k')."""
    out = {}
    for code, _, _ in CODES:
        found = latest(results_dir, KINDS[bed][code])
        if found:
            path, date, machine = found
            t, z = read_curve(path)
            out[code] = (t, z, date, machine, os.path.relpath(path, root))
    fresh = os.path.join(root, "out", "dem8", "impact_25k", "tracked.csv")
    if bed == "25k" and os.path.isfile(fresh):
        made = datetime.datetime.fromtimestamp(os.path.getmtime(fresh), datetime.timezone.utc).date().isoformat()
        if "veridem" not in out or made > out["veridem"][2]:
            t, z = read_curve(fresh)
            out["veridem"] = (t, z, made, f"this machine ({os.uname().nodename}, {os.cpu_count()} CPUs)",
                              os.path.relpath(fresh, root))
    return out


def impact_figure(out_dir, data, top, bed):
    """The ball's centre height against time, whole run and around the deepest point, each code."""
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for code, colour, style in CODES:
        if code not in data:
            continue
        t, z = data[code][:2]
        for ax in axes:
            ax.plot([v * 1e3 for v in t], z, style, color=colour, label=code, lw=1.6)
    for ax in axes:
        if top is not None:
            ax.axhline(top + BALL_RADIUS, color="0.5", lw=0.8, ls="-.", label="ball touches the bed top")
        ax.axhline(FLOOR_Z + BALL_RADIUS, color="k", lw=0.8, label="ball touches the floor")
        ax.set_xlabel("t (ms)")
        ax.set_ylabel("ball centre z (m)")
        ax.grid(alpha=0.3)
    axes[0].set_title(f"Impact on the {bed} bed: the ball's height")
    lowest = min(deepest(*data[code][:2]) for code in data)  # (z, t) of the lowest curve
    axes[1].set_xlim((lowest[1] - 0.011) * 1e3, (lowest[1] + 0.006) * 1e3)
    axes[1].set_ylim(FLOOR_Z + BALL_RADIUS - 0.004, lowest[0] + 0.04)
    axes[1].set_title("around the deepest point")
    axes[0].legend(fontsize=8)
    return save(fig, out_dir, f"dem8_impact{bed}_height")


def deepest(t, z):
    k = min(range(len(z)), key=z.__getitem__)
    return z[k], t[k]


def band_text(value, peers, unit, scale, digits):
    """Whether `value` lies in the peers' spread [min, max] (scaled to `unit`), as a phrase."""
    if not peers:
        return "–"
    lo, hi = min(peers), max(peers)
    if len(peers) == 1:
        return f"one peer only: {(value - lo) * scale:+.{digits}f} {unit} from it"
    if lo <= value <= hi:
        return f"yes: the peers span {lo * scale:.{digits}f} to {hi * scale:.{digits}f} {unit}"
    outside = value - hi if value > hi else value - lo
    return (f"no, {outside * scale:+.{digits}f} {unit} outside: the peers span {lo * scale:.{digits}f} to "
            f"{hi * scale:.{digits}f} {unit}")


def impact_table(w, data, top):
    """Each code's deepest point: centre height, time, penetration below the bed top, and veridem's
    place against the peers' spread (the band; a point with one peer)."""
    rows = {code: deepest(*data[code][:2]) for code in data}
    peers = [rows[c] for c in ("LIGGGHTS", "Yade") if c in rows]
    w("<table class='summary'><tr><th>code</th><th>deepest centre z (m)</th><th>at t (ms)</th>"
      "<th>penetration below the bed top (mm)</th><th>depth inside the peers' band</th>"
      "<th>time inside the peers' band</th><th>made</th><th>file</th></tr>")
    for code, _, _ in CODES:
        if code not in rows:
            continue
        z, t = rows[code]
        depth = f"{(top - (z - BALL_RADIUS)) * 1e3:.2f}" if top is not None else "–"
        depth_band = time_band = "–"
        if code == "veridem":
            depth_band = band_text(z, [p[0] for p in peers], "mm", 1e3, 3) + " (centre z)"
            time_band = band_text(t, [p[1] for p in peers], "ms", 1e3, 1)
        _, _, date, machine, source = data[code]
        w(f"<tr><td>{code}</td><td class='num'>{z:.6f}</td><td class='num'>{t * 1e3:.1f}</td>"
          f"<td class='num'>{depth}</td><td class='why'>{html.escape(depth_band)}</td>"
          f"<td class='why'>{html.escape(time_band)}</td>"
          f"<td class='why'>{date}, {html.escape(machine)}</td><td class='why'>{html.escape(source)}</td></tr>")
    w("</table>")


def discharge_rate(t, retained, high=0.9, low=0.2):
    """The silo's discharge rate over the steady part [particles/s] and its standard error, as
    (rate, standard error, t_first, t_last, samples), or None with fewer than 3 samples in it.

    The steady part is the window where the retained count lies between `low` and `high` times its
    value at the gate's opening (t = 0): it leaves out the start (the flow accelerating from rest)
    and the end (the cone emptying, the rate falling as the head drops below the orifice's few
    diameters, Beverloo's regime no longer holding). Over it the count is fitted by least squares
    with a line N = a - q t; the rate is q and its standard error is that of the slope,
    sqrt(sum of squared residuals / (n - 2) / sum (t - mean t)^2)."""
    if not retained:
        return None
    start = retained[0]
    window = [(ti, n) for ti, n in zip(t, retained) if low * start <= n <= high * start]
    if len(window) < 3:
        return None
    n = len(window)
    mean_t = sum(p[0] for p in window) / n
    mean_n = sum(p[1] for p in window) / n
    sxx = sum((p[0] - mean_t) ** 2 for p in window)
    slope = sum((p[0] - mean_t) * (p[1] - mean_n) for p in window) / sxx
    residual = sum((p[1] - mean_n - slope * (p[0] - mean_t)) ** 2 for p in window)
    error = (residual / (n - 2) / sxx) ** 0.5 if n > 2 else float("nan")
    return -slope, error, window[0][0], window[-1][0], n


def silo_table(w, results_dir):
    """The silo runs' discharge rates (discharge_rate) of each code whose results file is here."""
    found = []
    for run in SILO_RUNS:
        for code in ("veridem", "LIGGGHTS"):
            hit = latest(results_dir, f"silo-{run}-{code.lower()}")
            if hit:
                found.append((run, code, hit))
    if not found:
        w("<p class='why'>No silo results yet (bench/results/*-dem8-silo-RUN-CODE.csv): the four runs, "
          "100,000 spheres filled behind the gate for 1 s and discharged for 5 s (4e6 steps of 1.5e-6 s), "
          "are about a day each on this machine (bench/dem8/README.md).</p>")
        return
    w("<table class='summary'><tr><th>run</th><th>code</th><th>discharge rate (particles/s)</th>"
      "<th>standard error</th><th>fitted over t (s)</th><th>samples</th><th>made</th></tr>")
    for run, code, (path, date, machine) in found:
        t, n = [], []
        with open(path) as stream:
            for row in csv.DictReader(stream):
                t.append(float(row["t"]))
                n.append(float(row["retained"]))
        fit = discharge_rate(t, n)
        if fit is None:
            w(f"<tr><td>{run}</td><td>{code}</td><td colspan='4' class='why'>too few samples in the steady "
              f"part</td><td class='why'>{date}, {html.escape(machine)}</td></tr>")
            continue
        rate, error, first, last, samples = fit
        w(f"<tr><td>{run}</td><td>{code}</td><td class='num'>{rate:.1f}</td><td class='num'>{error:.1f}</td>"
          f"<td class='num'>{first:.2f} to {last:.2f}</td><td class='num'>{samples}</td>"
          f"<td class='why'>{date}, {html.escape(machine)}</td></tr>")
    w("</table><p class='why'>The steady part: the samples whose retained count lies between 90 % and 20 % of "
      "the count at the gate's opening, fitted by least squares with a line; the rate is its slope, with the "
      "slope's standard error (scripts/report_dem8.py, discharge_rate).</p>")


def drum_table(w, results_dir):
    """The drum's zone counts of each code whose results file is here, at the times all reached."""
    runs = {}
    for code in ("veridem", "LIGGGHTS"):
        hit = latest(results_dir, f"drum-{code.lower()}")
        if hit:
            counts = {}
            with open(hit[0]) as stream:
                for row in csv.DictReader(stream):
                    counts[(round(float(row["t"]), 6), row["zone"], row["material"])] = int(row["count"])
            runs[code] = (counts, hit)
    if not runs:
        w("<p class='why'>No drum results yet (bench/results/*-dem8-drum-CODE.csv): the 5 s run, 6.25e6 steps of "
          "38,000 spheres, is about 6 h on 2 threads of this machine (bench/dem8/README.md).</p>")
        return
    times = sorted(set.intersection(*[{k[0] for k in counts} for counts, _ in runs.values()]))
    keys = [("zone1", "M1"), ("zone1", "M2"), ("zone2", "M1"), ("zone2", "M2")]
    w("<table class='summary'><tr><th>t (s)</th><th>code</th>" +
      "".join(f"<th>{m} in {z}</th>" for z, m in keys) + "<th>made</th></tr>")
    for t in times:
        for code, (counts, (_, date, machine)) in runs.items():
            w(f"<tr><td class='num'>{t:g}</td><td>{code}</td>" +
              "".join(f"<td class='num'>{counts.get((t, z, m), '–')}</td>" for z, m in keys) +
              f"<td class='why'>{date}, {html.escape(machine)}</td></tr>")
    w("</table><p class='why'>Particle centres in zone 1 (x &gt; 0, z &gt; 0) and zone 2 (x &lt; 0, z &lt; 0), at the "
      "times both runs reached.</p>")


def speed_table(w, root, results_dir):
    found = latest(results_dir, "speed")
    if not found:
        w("<p class='why'>No speed results (bench/results/*-dem8-speed.csv).</p>")
        return
    path, _, _ = found
    with open(path) as stream:
        rows = list(csv.DictReader(stream))
    reference = {(r["case"], r["pair"]): float(r["particle_steps_per_s"]) for r in rows if r["code"] == "LIGGGHTS"}
    w("<table class='summary'><tr><th>case</th><th>code</th><th>set-up</th><th>cores</th><th>particles x steps</th>"
      "<th>wall (s)</th><th>particle-steps/s</th><th>/ LIGGGHTS on as many cores, same run</th><th>made</th></tr>")
    for r in rows:
        rate = float(r["particle_steps_per_s"])
        ref = reference.get((r["case"], r["pair"]))
        ratio = f"{rate / ref:.2f}x" if ref and r["code"] != "LIGGGHTS" else "–"
        w(f"<tr><td>{html.escape(r['case'])}</td><td>{html.escape(r['code'])}</td><td class='why'>"
          f"{html.escape(r['setup'])}</td><td class='num'>{r['cores']}</td><td class='num'>{int(r['particles']):,} x "
          f"{int(r['steps']):,}</td><td class='num'>{float(r['wall_s']):.2f}</td><td class='num'>{rate:.3g}</td>"
          f"<td class='num'>{ratio}</td><td class='why'>{html.escape(r['date'])}, {html.escape(r['machine'])}</td></tr>")
    w(f"</table><p class='why'>From {html.escape(os.path.relpath(path, root))}: whole-process wall times, the "
      "median of runs alternating with the peer's in the same minutes (docs/performance.md, DEM8). The goal "
      "(issue 47): 3x LIGGGHTS per core or more.</p>")


def dem8_section(out_dir, root):
    """The section's HTML (its figures written under out_dir/figures), or '' with no results at all."""
    results_dir = os.path.join(root, "bench", "results")
    shared = os.environ.get("VERIDEM_SHARED_DEM8_DIR", os.path.join(os.path.dirname(root), "shared", "dem8"))
    data = {bed: curves(root, results_dir, bed) for bed in KINDS}
    if not any(data.values()) and not latest(results_dir, "speed"):
        return ""
    out = []
    w = out.append
    w("<h2 id='dem8'>Cross-code benchmark (DEM8)</h2>")
    w("<p>The bulk processes of Dosta et al., <i>Comparing open-source DEM frameworks for simulations of common "
      "bulk processes</i>, Comput. Phys. Commun. 296 (2024) 109066, as veridem scenes (bench/dem8/) and as the "
      "peers' decks (bench/dem8/peers/), from the organisers' input. The runs are long and outside the "
      "verification suite (<code>ctest -L '^dem8$'</code>); this section draws from the latest results files "
      "in bench/results/, each with the date and machine it was made on. <a class='top' href='#summary'>"
      "(back to the summary)</a></p>")
    starts = {"25k": "t = 20 ms, 1 mm above the bed (bench/dem8/peers/README.md); veridem from t = 0",
              "50k": "t = 14 ms, 1 mm above the bed, and so does veridem (bench/dem8/README.md)"}
    for bed, curves_of_bed in data.items():
        top = bed_top(shared, bed)
        w(f"<h3>Impact on the {bed} bed: the steel ball (r = 10 mm, 5 m/s) into the M1 beads</h3>")
        if not curves_of_bed:
            w(f"<p class='why'>No {bed} impact curves in bench/results/.</p>")
            continue
        path = impact_figure(out_dir, curves_of_bed, top, bed)
        if path:
            w(f"<figure><a href='{path}'><img class='wide' src='{path}' alt='DEM8 impact {bed}'></a><figcaption>"
              "The ball's centre height every 0.5 ms. The peers start on the ball's free-flight parabola at "
              f"{starts[bed]}.</figcaption></figure>")
        impact_table(w, curves_of_bed, top)
    w("<h3>Rotating drum</h3>")
    drum_table(w, results_dir)
    w("<h3>Silo discharge</h3>")
    silo_table(w, results_dir)
    w("<h3>Speed</h3>")
    speed_table(w, root, results_dir)
    return "\n".join(out)
