"""PNG figures for the report (matplotlib, Agg backend). Each function returns the file name."""
import re

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# Line style per series role: simulation=line, experiment=markers, analytical=black dashed, dem=grey.
ROLE_STYLE = {
    "simulation": dict(linestyle="-", linewidth=1.8, zorder=3),
    "experiment": dict(linestyle="none", marker="o", markersize=5, markerfacecolor="none", zorder=4),
    "analytical": dict(linestyle="--", color="black", linewidth=1.4, zorder=2),
    "dem": dict(linestyle="-", color="0.55", linewidth=2.0, zorder=1),
}


def slug(*parts):
    """File-name-safe slug from parts."""
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", "_".join(str(p) for p in parts if p is not None))


def _save(fig, out_dir, name):
    fig.tight_layout()
    fig.savefig(out_dir / name, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return name


def series_plot(series, title, out_dir, name):
    """Overlay series sharing one "plot" key; styles by role."""
    fig, ax = plt.subplots(figsize=(6, 4))
    for s in series:
        ax.plot(s["x"], s["y"], label=f"{s['name']} ({s['role']})", **ROLE_STYLE[s["role"]])
    ax.set_xlabel(series[0]["xlabel"])
    ax.set_ylabel(series[0]["ylabel"])
    ax.set_title(title, fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return _save(fig, out_dir, name)


def snapshot_plot(snap, title, out_dir, name):
    """Particle positions coloured by a field, with a colourbar."""
    fig, ax = plt.subplots(figsize=(6, 4))
    size = float(np.clip(4000.0 / max(len(snap["x"]), 1), 0.5, 20.0))
    sc = ax.scatter(snap["x"], snap["y"], c=snap["values"], s=size, cmap="viridis", linewidths=0)
    units = f" [{snap['units']}]" if snap["units"] else ""
    fig.colorbar(sc, ax=ax, label=snap["field"] + units)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_title(title, fontsize=10)
    return _save(fig, out_dir, name)


def convergence_plot(study, out_dir, name):
    """Error against dx on log-log axes with the fitted and (if given) expected order."""
    fig, ax = plt.subplots(figsize=(6, 4))
    dx, err = np.array(study.dx), np.array(study.error)
    p, c = study.observed_order, study.constant
    ax.loglog(dx, err, "o", color="C0", label=study.metric)
    fine = np.geomspace(dx.min(), dx.max(), 50)
    ax.loglog(fine, c * fine ** p, "-", color="C0", alpha=0.6, label=f"fit: observed order {p:.2f}")
    if study.expected_order is not None:
        q = study.expected_order
        ax.loglog(fine, err[-1] * (fine / dx[-1]) ** q, ":", color="black",
                  label=f"expected order {q:g}")
    ax.set_xlabel("dx")
    ax.set_ylabel(study.metric)
    ax.set_title(f"{study.case} ({study.variant or 'default'})", fontsize=10)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    return _save(fig, out_dir, name)


def speed_plot(case, recs, best, out_dir, name):
    """Wall time against first-metric value (log-log), tolerance lines, cheapest passing marked."""
    fig, ax = plt.subplots(figsize=(6, 4))
    pts = [r for r in recs if r.first["value"] is not None and r.first["value"] > 0 and r.wall_s > 0]
    for r in pts:
        style = dict(marker="o", color="tab:green") if r.passed else dict(marker="x", color="tab:red")
        ax.plot(r.wall_s, r.first["value"], linestyle="none", markersize=7, **style)
        text = r.label + ("" if r.stable else " (unstable)")
        ax.annotate(text, (r.wall_s, r.first["value"]), textcoords="offset points",
                    xytext=(5, 4), fontsize=7)
    for tol in sorted({r.first["tolerance"] for r in recs if r.first["tolerance"] > 0}):
        ax.axhline(tol, color="black", linestyle="--", linewidth=1, label=f"tolerance {tol:g}")
    if best is not None and best in pts:
        ax.plot(best.wall_s, best.first["value"], marker="o", markersize=16, markerfacecolor="none",
                markeredgecolor="tab:blue", markeredgewidth=2, linestyle="none",
                label=f"cheapest passing: {best.label}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.margins(x=0.3, y=0.15)  # room for the point labels
    ax.set_xlabel("wall time [s]")
    ax.set_ylabel(recs[0].first["name"])
    ax.set_title(case, fontsize=10)
    ax.grid(alpha=0.3, which="both")
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.18), ncol=2)
    return _save(fig, out_dir, name)
