"""Assemble index.html (string.Template page, sections built here) and its figures."""
import datetime
import math
from html import escape
from pathlib import Path
from string import Template

from . import figures
from .convergence import studies
from .records import (cheapest_passing, group_by, representative, scene_variant, stability_records, step_cost,
                      wall_comparisons)

TEMPLATE = Path(__file__).resolve().parent.parent / "templates" / "page.html"
SECTIONS = (("summary", "Summary"), ("cases", "Cases"), ("convergence", "Convergence studies"),
            ("speed", "Speed against error"), ("stability", "Stability of hard cases"),
            ("boundaries", "Wall treatments compared"))


def fmt(v, spec=".4g"):
    """Format a number (or None / NaN) for a table cell."""
    if v is None:
        return "&mdash;"
    if isinstance(v, float) and not math.isfinite(v):
        return escape(str(v))
    return format(v, spec)


def table(headers, rows, classes=None):
    """HTML table; rows are lists of (already escaped) cell HTML; a cell may be (html, td_class)."""
    head = "".join(f"<th>{escape(h)}</th>" for h in headers)
    body = []
    for i, row in enumerate(rows):
        cells = "".join(f'<td class="{c[1]}">{c[0]}</td>' if isinstance(c, tuple) else f"<td>{c}</td>"
                        for c in row)
        cls = f' class="{classes[i]}"' if classes else ""
        body.append(f"<tr{cls}>{cells}</tr>")
    return f"<table><thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody></table>"


def figure(name, caption):
    return (f'<figure><img src="{escape(name)}" alt="{escape(caption)}">'
            f"<figcaption>{escape(caption)}</figcaption></figure>")


def _status(ok, unstable=False):
    text = "PASS" if ok else ("FAIL (unstable)" if unstable else "FAIL")
    return (text, "status")


def _run_cells(r):
    return [(fmt(r.particles, "d"), "num"), (fmt(r.dx), "num"), (fmt(r.steps, "d"), "num"),
            (fmt(r.wall_s, ".3g"), "num"), (fmt(r.particle_steps_per_s, ".3g"), "num"),
            (fmt(r.threads, "d"), "num")]


def _metric_rows(recs, run_cells=_run_cells):
    """One row per metric of each record; a row fails if its metric failed or the run blew up."""
    rows, classes = [], []
    for r in recs:
        for m in r.metrics:
            ok = m["passed"] and r.stable
            status = _status(ok, not r.stable)
            if not r.scored:  # reported for information (e.g. the stability study), not judged
                status = ("study: " + status[0].lower(), "status")
            rows.append([escape(r.case), escape(r.level), escape(r.variant or "default"),
                         escape(m["name"]), (fmt(m["value"]), "num"), (fmt(m["tolerance"]), "num"),
                         escape(m["why_tolerance"]), status] + run_cells(r))
            classes.append("study" if not r.scored else ("pass" if ok else "fail"))
    return rows, classes


METRIC_HEADERS = ["case", "level", "variant", "metric", "value", "tolerance", "why this tolerance",
                  "status"]
RUN_HEADERS = ["particles", "dx", "steps", "wall [s]", "particle-steps/s", "threads"]


def provenance_line(records):
    """Which builds produced the records (solver version, compiler, flags): one line per build."""
    builds = sorted({(p.get("solver_version", "?"), p.get("compiler", "?"), p.get("build_flags", "?"))
                     for p in (r.provenance for r in records) if p})
    if not builds:
        return '<p class="muted">The records carry no provenance (written before GeoSPH recorded it).</p>'
    items = "".join(f"<li>GeoSPH {escape(v)}, {escape(c)}, <code>{escape(f)}</code></li>" for v, c, f in builds)
    return f"<p>Built by:</p><ul>{items}</ul>"


def summary_section(records):
    rows, classes = _metric_rows(records)
    return provenance_line(records) + table(METRIC_HEADERS + RUN_HEADERS, rows, classes)


def cases_section(records, out):
    parts = []
    for case, recs in group_by(records, lambda r: r.case).items():
        rep = representative(recs)
        verdict = all(r.passed for r in recs)
        title = escape(rep.title or case)
        parts.append(f'<h3 id="case-{escape(figures.slug(case))}">{title} <code>{escape(case)}</code> '
                     f'<span class="{"pass" if verdict else "fail"}">{"PASS" if verdict else "FAIL"}'
                     "</span></h3>")
        if rep.reference:
            parts.append(f"<p>Reference ({escape(str(rep.reference.get('kind', '')))}): "
                         f"{escape(str(rep.reference.get('source', '')))}</p>")
        parts.append(f'<p class="muted">Figures from {escape(rep.relpath or rep.path)} '
                     f"(level {escape(rep.level)}, {escape(rep.label)}, {rep.particles} particles).</p>")
        for key, series in group_by(rep.series, lambda s: s["plot"]).items():
            png = figures.slug("case", case, key) + ".png"
            name = figures.series_plot(series, f"{case}: {key}", out, png)
            parts.append(figure(name, f"{case}: {key}"))
        if rep.snapshot:
            snap = rep.snapshot
            cap = f"{case}: particles coloured by {snap['field']}"
            name = figures.snapshot_plot(snap, cap, out, figures.slug("snap", case) + ".png")
            parts.append(figure(name, cap))
        rows, classes = _metric_rows(recs, lambda r: [(fmt(r.dx), "num"), (fmt(r.wall_s, ".3g"), "num")])
        parts.append(table(METRIC_HEADERS + ["dx", "wall [s]"], rows, classes))
    return "\n".join(parts)


def convergence_section(records, out):
    found = studies(records)
    if not found:
        return '<p class="muted">No case has records at two or more resolutions.</p>'
    parts = []
    for s in found:
        p = s.observed_order
        expected = "" if s.expected_order is None else f", expected order {s.expected_order:g}"
        parts.append(f"<h3>{escape(s.case)} ({escape(s.variant or 'default')}): {escape(s.metric)}</h3>")
        parts.append(f"<p>Observed order (least-squares slope of log error vs log dx, "
                     f"{len(s.dx)} resolutions): <b>{p:.3f}</b>{escape(expected)}.</p>")
        if len(s.dx) >= 3:
            png = figures.slug("conv", s.case, s.variant, s.metric) + ".png"
            name = figures.convergence_plot(s, out, png)
            parts.append(figure(name, f"{s.case}: {s.metric} against dx"))
        orders = [None] + s.local_orders
        rows = [[(fmt(d), "num"), (fmt(e), "num"), (fmt(o, ".3f"), "num"), escape(r.relpath or r.path)]
                for d, e, o, r in zip(s.dx, s.error, orders, s.records)]
        parts.append(table(["dx", s.metric, "local order (vs previous dx)", "record"], rows))
    return "\n".join(parts)


def speed_section(records, out):
    parts = []
    for case, recs in group_by(records, lambda r: r.case).items():
        if len(recs) < 2:
            continue
        best = cheapest_passing(recs)
        name = figures.speed_plot(case, recs, best, out, figures.slug("speed", case) + ".png")
        parts.append(f"<h3>{escape(case)}</h3>")
        parts.append(figure(name, f"{case}: wall time against {recs[0].first['name']}"))
        if best:
            parts.append(f"<p>Cheapest record meeting the tolerance: <b>{escape(best.label)}</b> "
                         f"(level {escape(best.level)}, {best.wall_s:.3g} s, "
                         f"{best.first['name']} = {fmt(best.first['value'])}).</p>")
        else:
            parts.append('<p><span class="fail">FAIL</span> no record of this case meets its tolerance.</p>')
        skipped = [r for r in recs if not (r.first["value"] or 0) > 0 or r.wall_s <= 0]
        if skipped:
            parts.append(f'<p class="muted">Not plotted (no positive error or wall time): '
                         f"{escape(', '.join(r.label for r in skipped))}.</p>")
    return "\n".join(parts) or '<p class="muted">No case has more than one record.</p>'


def stability_section(records):
    recs = stability_records(records)
    if not recs:
        return '<p class="muted">No record uses a stabilisation option or has variants.</p>'
    rows, classes = [], []
    for r in recs:
        f = r.failure or {}
        opts = ", ".join(f"{k}={v}" for k, v in sorted(r.options.items()))
        first = f'{r.first["name"]} = {fmt(r.first["value"])}'
        rows.append([escape(r.case), escape(r.variant or "default"), (fmt(r.dx), "num"),
                     f"<code>{escape(opts)}</code>", escape(first), ("yes" if r.stable else "NO", "status"),
                     (fmt(f.get("step")), "num"), (fmt(f.get("time")), "num"),
                     escape(str(f.get("message", "")))])
        classes.append("pass" if r.stable else "fail")
    return table(["case", "variant", "dx", "options", "result", "stable", "failure step", "failure time",
                  "failure message"], rows, classes)


def boundaries_section(records):
    """Per case run with several wall treatments (case.json wall_treatments): error, cost and stability
    of each, and the cheapest treatment meeting the case's tolerance at each level and spacing."""
    cases = wall_comparisons(records)
    if not cases:
        return ('<p class="muted">No case was run with more than one wall treatment '
                "(<code>geosph verify --walls all</code>).</p>")
    parts = []
    for case, recs in cases.items():
        parts.append(f"<h3>{escape(case)}</h3>")
        rows, classes = [], []
        for r in sorted(recs, key=lambda r: (r.level, scene_variant(r), -r.dx, r.wall_treatment)):
            cost = step_cost(r)
            for m in r.metrics:
                ok = m["passed"] and r.stable
                rows.append([escape(r.wall_treatment), escape(r.level), escape(scene_variant(r)), (fmt(r.dx), "num"),
                             escape(m["name"]),
                             (fmt(m["value"]), "num"), (fmt(m["tolerance"]), "num"), _status(ok, not r.stable),
                             ("yes" if r.stable else "NO", "status"), (fmt(r.wall_particles, "d"), "num"),
                             (fmt(r.particles, "d"), "num"), (fmt(r.steps, "d"), "num"),
                             (fmt(None if cost is None else 1e3 * cost, ".3g"), "num")])
                classes.append("pass" if ok else "fail")
        parts.append(table(["walls", "level", "scene", "dx", "metric", "value", "tolerance", "status", "stable",
                            "wall particles", "moving particles", "steps", "wall time per step [ms]"],
                           rows, classes))
        verdicts = []
        for (level, scene, dx), group in group_by(recs, lambda r: (r.level, scene_variant(r), r.dx)).items():
            where = f"{escape(level)}, {escape(scene) + ', ' if scene else ''}dx = {fmt(dx)}"
            ok = [r for r in group if r.passed and step_cost(r) is not None]
            if ok:
                best = min(ok, key=step_cost)
                verdicts.append(f"<li>{where}: <b>{escape(best.wall_treatment)}</b> "
                                f"({1e3 * step_cost(best):.3g} ms per step; passing: "
                                f"{escape(', '.join(sorted(r.wall_treatment for r in ok)))})</li>")
            else:
                verdicts.append(f'<li>{where}: <span class="fail">no treatment meets '
                                "the tolerance</span></li>")
        parts.append(f"<p>Cheapest treatment meeting the tolerance:</p><ul>{''.join(verdicts)}</ul>")
        known = {r.wall_treatment: r.wall_treatment_open for r in recs if r.wall_treatment_open}
        if known:
            items = "".join(f"<li><b>{escape(t)}</b>: {escape(why)}</li>" for t, why in sorted(known.items()))
            parts.append(f"<p>Known to miss the tolerance (case.json open_wall_treatments):</p><ul>{items}</ul>")
    return "\n".join(parts)


def write_report(records, out_dir, source=""):
    """Write out_dir/index.html and its PNG figures; return the index path."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    bodies = {"summary": summary_section(records), "cases": cases_section(records, out),
              "convergence": convergence_section(records, out), "speed": speed_section(records, out),
              "stability": stability_section(records), "boundaries": boundaries_section(records)}
    body = "\n".join(f'<section id="{sid}">\n<h2>{escape(title)}</h2>\n{bodies[sid]}\n</section>'
                     for sid, title in SECTIONS)
    n_fail = sum(not r.passed for r in records)
    n_study = sum(not r.scored for r in records)
    cases = group_by(records, lambda r: r.case)
    c_fail = sum(not all(r.passed for r in rs) for rs in cases.values())
    totals = (f'<span class="pass">{len(records) - n_fail - n_study} passed</span> '
              f'<span class="fail">{n_fail} failed</span> '
              + (f"{n_study} unscored studies " if n_study else "")
              + f"records &middot; {len(cases) - c_fail} of {len(cases)} cases passing")
    page = Template(TEMPLATE.read_text(encoding="utf-8")).substitute(
        title="GeoSPH verification &amp; validation report",
        generated=datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M:%S UTC"),
        source=escape(str(source)), count=len(records), totals=totals,
        nav="".join(f'<a href="#{sid}">{escape(t)}</a>' for sid, t in SECTIONS), body=body)
    index = out / "index.html"
    index.write_text(page, encoding="utf-8")
    return index
