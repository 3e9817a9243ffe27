"""The HTML page of the verification report (scripts/report.py): a summary per family linking to
one section per family with its figures and its folded table."""

import html
import math
import os

from report_families import FAMILIES, family_of
from report_util import fmt

CONVENTIONS = [
    "SI units throughout; angles in the table plane from east (+x) counter-clockwise; tables and dishes "
    "turn counter-clockwise seen from above.",
    "Contact radius: a sphere-wall contact uses the undeformed radius as the lever arm and for the contact-point "
    "velocity; a sphere-sphere contact splits the centre distance in proportion to the radii.",
    "Rolling friction (type A, the paper's eq. 3): M = −μr F_n ω̂_rel, where ω_rel is the angular velocity "
    "relative to the contact partner (the wall's own angular velocity for a turning wall), twist about the "
    "normal included; μr is a length in m (μr' = μr/a is the dimensionless form).",
    "Normal dashpot not clipped: the normal force may be slightly attractive just before separation, so e equals "
    "the value set.",
    "The wall's surface velocity is taken at the half-step contact point, consistent with the half-step "
    "particle velocities of velocity Verlet.",
]

DECISIONS = [
    "Flat-turntable stiffness k = 1.0e5 N/m (the paper's table is truncated), kt = 2/7 k.",
    "Initial velocities in the captions are lab-frame; the no-slip start sets the spin so that the contact point "
    "moves with the table, with zero spin about the table normal.",
    "Test 1 is run twice: T1a literal (v0 = 0: the ball must stay put) and T1b (v0 = 0.107 m/s at 270°: the orbit "
    "at 2Ω/7).",
    "Test 2 uses the caption: 0.17° tilt, downhill toward 135°. Test 5 is run at the caption's 0.10° and at 0.010°.",
    "Rolling friction opposes the angular velocity relative to the contact partner including twist; the dish "
    "test without twist resistance locks at a wrong height (regression case dish_twist_regression).",
]


def ratio_of(q):
    """Error over tolerance of a quantity (how much of its tolerance it uses)."""
    tolerance, error = q.get("tolerance", 0), q.get("error")
    if error is None or not isinstance(error, (int, float)) or not math.isfinite(error):
        return math.inf
    return abs(error) / tolerance if tolerance else (0.0 if error == 0 else math.inf)


def case_table(w, cases):
    w("<table><tr><th>case</th><th>quantity</th><th>theory</th><th>measured</th><th>error</th>"
      "<th>tolerance</th><th>result</th><th>why this tolerance</th></tr>")
    for c in cases:
        quantities = c.get("quantities", [])
        rows = max(len(quantities), 1)
        head = (f"<td rowspan='{rows}' id='case-{html.escape(c['name'])}'><b>{html.escape(c['name'])}</b><br>"
                f"<span class='why'>{html.escape(c.get('summary', ''))}<br>{html.escape(c.get('reference', ''))}<br>"
                f"{c.get('seconds', 0):.2f} s</span></td>")
        if not quantities:
            msg = html.escape(c.get("error", "the case measured nothing"))
            w(f"<tr>{head}<td colspan='5'>{msg}</td><td class='fail'>FAIL</td><td></td></tr>")
            continue
        for k, q in enumerate(quantities):
            unit = f" [{html.escape(q.get('unit', ''))}]" if q.get("unit") else ""
            kind = "rel." if q.get("relative") else "abs."
            result = "<td class='pass'>PASS</td>" if q.get("passed") else "<td class='fail'>FAIL</td>"
            w("<tr>" + (head if k == 0 else "") + f"<td>{html.escape(q['name'])}{unit}</td>"
              f"<td class='num'>{fmt(q.get('expected'))}</td><td class='num'>{fmt(q.get('measured'))}</td>"
              f"<td class='num'>{fmt(q.get('error'))}</td><td class='num'>{fmt(q.get('tolerance'))} {kind}</td>"
              f"{result}<td class='why'>{html.escape(q.get('why', ''))}</td></tr>")
    w("</table>")


def write_html(out_dir, cases, figures, dem8=""):
    """dem8: the cross-code benchmark section's HTML (report_dem8.py), after the families, or ''."""
    passed = sum(1 for c in cases if c.get("passed"))
    total_seconds = sum(c.get("seconds", 0) for c in cases)
    by_family = {key: [c for c in cases if family_of(c["name"]) == key] for key, _, _, _ in FAMILIES}
    out = []
    w = out.append
    w("<!DOCTYPE html><html><head><meta charset='utf-8'><title>veridem verification report</title><style>"
      "body{font-family:sans-serif;max-width:1300px;margin:auto;padding:1em;color:#222}"
      "table{border-collapse:collapse;font-size:12px;width:100%}td,th{border:1px solid #ccc;padding:3px 5px;"
      "vertical-align:top}th{background:#eee}.pass{color:#070;font-weight:bold}.fail{color:#b00;font-weight:bold}"
      "td.num{text-align:right;font-family:monospace;white-space:nowrap}.why{color:#555;font-size:11px}"
      "figure{display:inline-block;margin:6px;vertical-align:top}figure img{max-width:600px;border:1px solid #ddd}"
      "figure img.wide{max-width:1240px}"
      "figcaption{font-size:12px;color:#444}.notes{font-size:12px;color:#333}"
      "table.summary{font-size:14px;width:auto}table.summary td{padding:5px 10px}"
      "details{margin:0.8em 0}summary{cursor:pointer;font-weight:bold;color:#245}"
      "h2{border-bottom:2px solid #ccd;padding-bottom:3px;margin-top:2em}.top{font-size:12px}</style></head><body>")
    w("<h1>veridem verification report</h1>")
    w("<p>Cases compare DEM runs with analytical solutions, after Xiang, Munjiza, Latham &amp; Guises, "
      "<i>On the validation of DEM and FEM/DEM models in 2D and 3D</i>, and the benchmark families of "
      f"BENCHMARKS.md. <b>{passed} of {len(cases)} cases passed</b>; the cases took {total_seconds:.1f} s in total.</p>")
    w("<h2 id='summary'>Summary by family</h2>")
    w("<table class='summary'><tr><th>family</th><th>cases</th><th>passed</th><th>worst error / tolerance</th>"
      "<th>at</th><th>dt orders checked (passed / checked)</th></tr>")
    for key, title, _, _ in FAMILIES:
        members = by_family[key]
        if not members:
            continue
        ok = sum(1 for c in members if c.get("passed"))
        worst, where = 0.0, ""
        for c in members:
            if not c.get("quantities"):
                worst, where = math.inf, c["name"] + " (no result)"
            for q in c.get("quantities", []):
                r = ratio_of(q)
                if r > worst:
                    worst, where = r, f"{c['name']}: {q['name']}"
        cls = "pass" if ok == len(members) else "fail"
        orders = [q for c in members for q in c.get("quantities", []) if q["name"].startswith("dt order")]
        good = sum(1 for q in orders if q.get("passed"))
        order_cell = (f"<td class='num {'pass' if good == len(orders) else 'fail'}'>{good} / {len(orders)}</td>"
                      if orders else "<td class='num'>–</td>")
        w(f"<tr><td><a href='#{key}'>{html.escape(title)}</a></td><td class='num'>{len(members)}</td>"
          f"<td class='num {cls}'>{ok}</td><td class='num'>{fmt(worst)}</td><td class='why'>{html.escape(where)}</td>"
          f"{order_cell}</tr>")
    w("</table>")
    if dem8:
        w("<p><a href='#dem8'>Cross-code benchmark (DEM8)</a>: the long runs beside the peers, from the latest "
          "results files (not rerun by the suite).</p>")
    w("<p class='why'>error / tolerance: the largest share of its tolerance any check of the family uses "
      "(above 1 fails). One-sided checks (a sign, or a miss that must exceed a bound) are written as windows "
      "and use much of their tolerance by construction. Failing cases are listed in their family's section. dt orders: "
      "the collision, friction and rolling cases run at dt, dt/2 and dt/4; their observed orders are drawn in the "
      "convergence section.</p>")
    w("<details><summary>Conventions and decisions</summary>")
    w("<h3>Conventions</h3><ul>" + "".join(f"<li>{html.escape(c)}</li>" for c in CONVENTIONS) + "</ul>")
    w("<h3>Decisions (BENCHMARKS.md)</h3><ul>" + "".join(f"<li>{html.escape(c)}</li>" for c in DECISIONS) + "</ul>")
    w("</details>")
    for key, title, blurb, _ in FAMILIES:
        members = by_family[key]
        if not members:
            continue
        ok = sum(1 for c in members if c.get("passed"))
        w(f"<h2 id='{key}'>{html.escape(title)}</h2>")
        w(f"<p>{html.escape(blurb)} <b>{ok} of {len(members)} passed.</b> <a class='top' href='#summary'>"
          "(back to the summary)</a></p>")
        failed = [c["name"] for c in members if not c.get("passed")]
        if failed:
            w("<p class='fail'>Failing: " + ", ".join(
                f"<a href='#case-{html.escape(n)}'>{html.escape(n)}</a>" for n in failed) + "</p>")
        subsection = None
        for fam, sub, fig_title, path in figures:
            if fam != key:
                continue
            if sub and sub != subsection:
                w(f"<h3>{html.escape(sub)}</h3>")
                subsection = sub
            wide = (" class='wide'" if path.endswith(("_sweep.png", "_force.png", "_orders.png", "_radius.png"))
                    or "/dt_sweep_" in path else "")
            w(f"<figure><a href='{path}'><img{wide} src='{path}' alt='{html.escape(fig_title)}'></a>"
              f"<figcaption>{html.escape(fig_title)}</figcaption></figure>")
        quantities = sum(len(c.get("quantities", [])) for c in members)
        w(f"<details{' open' if failed else ''}><summary>Detailed table: {len(members)} cases, {quantities} "
          "checks</summary>")
        case_table(w, members)
        noted = [c for c in members if c.get("notes") or c.get("error")]
        for c in noted:
            notes = ([f"ERROR: {c['error']}"] if c.get("error") else []) + c.get("notes", [])
            w(f"<p class='notes'><b>{html.escape(c['name'])}</b></p><ul class='notes'>" +
              "".join(f"<li>{html.escape(n)}</li>" for n in notes) + "</ul>")
        w("</details>")
    if dem8:
        w(dem8)
    w("</body></html>")
    with open(os.path.join(out_dir, "index.html"), "w") as f:
        f.write("\n".join(out))
