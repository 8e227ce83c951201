#!/usr/bin/python3
"""Post-process LIGGGHTS dumps of the GeoSPH DEM references.

Sub-commands
  collapse  final free-surface profile, run-out and final height of a column
            collapse (collapse_2d.in) -> CSV with a provenance header
  repose    angle of repose of the ledge test (calibration.in): least-squares
            line fit to the free surface of the wedge left on the ledge
  wall      retaining wall translated into or away from a backfill
            (retaining_wall_2d.in): earth-pressure coefficient against wall
            displacement, and the slip line of the failure wedge from the
            grains' displacements -> two CSVs with a provenance header

Reads text dumps written by `dump custom` / `write_dump custom` with at least
the columns x y radius (id, type, z optional).  If a file has several
snapshots, the last one is used.  Only numpy is needed.

Free-surface profile: x-bins of width = mean grain diameter d starting at the
back wall (x = 0); in each bin the profile height is max(y + r) of the grains
whose centre lies in the bin.  Run-out (runout_m): the deposit is followed from
the back wall bin by bin and ends at the first empty bin (a gap of at least one
grain diameter); run-out is the largest x + r of the grains in that contiguous
deposit, so isolated grains that rolled/bounced away are ignored.  A stricter
value (runout_2layer_m: furthest bin whose height is at least 1.5 d, i.e. two
grain layers) is also written.  final_height_m is the maximum of the profile.
"""
import argparse
import datetime
import hashlib
import math
import os
import re
import sys

import numpy as np


def read_dump(path):
    """Return dict of column -> np.array for the last snapshot in a dump."""
    with open(path) as f:
        lines = f.read().splitlines()
    starts = [i for i, l in enumerate(lines) if l.startswith("ITEM: TIMESTEP")]
    if not starts:
        raise ValueError("%s: not a LIGGGHTS/LAMMPS text dump" % path)
    i = starts[-1]
    timestep = int(lines[i + 1].split()[0])
    j = i + 2
    natoms = None
    cols = None
    while j < len(lines):
        l = lines[j]
        if l.startswith("ITEM: NUMBER OF ATOMS"):
            natoms = int(lines[j + 1].split()[0])
            j += 2
            continue
        if l.startswith("ITEM: ATOMS"):
            cols = l.split()[2:]
            j += 1
            break
        j += 1
    if cols is None or natoms is None:
        raise ValueError("%s: malformed dump" % path)
    rows = [lines[k].split() for k in range(j, j + natoms)]
    data = np.array(rows, dtype=float).reshape(natoms, len(cols))
    out = {c: data[:, n] for n, c in enumerate(cols)}
    out["_timestep"] = timestep
    out["_natoms"] = natoms
    for need in ("x", "y", "radius"):
        if need not in out:
            raise ValueError("%s: dump lacks column %s" % (path, need))
    return out


def read_log(path):
    """Scrape version, parameters, particle counts and loop times from a log."""
    info = {"version": None, "params": {}, "n_initial": None,
            "n_final": None, "t_release": None, "vrms_final": None,
            "loop_time_s": 0.0}
    if not path or not os.path.exists(path):
        return info
    with open(path) as f:
        for line in f:
            if line.startswith("LIGGGHTS (") and info["version"] is None:
                info["version"] = line.strip()
            elif line.startswith("DEM_PARAMS"):
                tok = line.split()[1:]
                info["params"] = dict(zip(tok[0::2], tok[1::2]))
            elif line.startswith("DEM_INITIAL_PARTICLES"):
                t = line.split()
                info["n_initial"] = int(t[1])
                if len(t) >= 4 and t[2] == "MASS":
                    info["mass_kg"] = float(t[3])
            elif line.startswith("DEM_FINAL_PARTICLES"):
                t = line.split()
                info["n_final"] = int(t[1])
                if len(t) >= 6:
                    info["t_release"] = float(t[3])
                    info["vrms_final"] = float(t[5])
            elif line.startswith("Loop time of"):
                m = re.match(r"Loop time of ([0-9.eE+-]+)", line)
                if m:
                    info["loop_time_s"] += float(m.group(1))
    return info


def liggghts_version():
    import subprocess
    try:
        p = subprocess.run(["liggghts", "-h", "-log", "none"],
                           capture_output=True, text=True, timeout=30)
        for l in p.stdout.splitlines():
            if l.startswith("LIGGGHTS ("):
                return l.strip()
    except Exception:
        pass
    return "unknown"


def sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        h.update(f.read())
    return h.hexdigest()


def surface_profile(x, y, r, dbin, x0=0.0):
    """Bin centres, heights (nan = empty bin) of max(y + r) per x-bin."""
    k = np.floor((x - x0) / dbin).astype(int)
    keep = k >= 0
    k, top = k[keep], (y + r)[keep]
    nb = int(k.max()) + 1 if k.size else 0
    h = np.full(nb, np.nan)
    for b, t in zip(k, top):
        if np.isnan(h[b]) or t > h[b]:
            h[b] = t
    xc = x0 + (np.arange(nb) + 0.5) * dbin
    return xc, h


def contiguous_end(h):
    """Index one past the last bin of the deposit connected to bin 0."""
    n = 0
    while n < len(h) and not np.isnan(h[n]):
        n += 1
    return n


def analyse_collapse(dump, dbin=None, ymin=-1e30):
    x, y, r = dump["x"], dump["y"], dump["radius"]
    sel = y > ymin
    x, y, r = x[sel], y[sel], r[sel]
    dmean = 2.0 * float(np.mean(r))
    if dbin is None:
        dbin = dmean
    xc, h = surface_profile(x, y, r, dbin)
    n = contiguous_end(h)
    xc, h = xc[:n], h[:n]
    in_dep = np.floor(x / dbin).astype(int) < n
    runout = float(np.max(x[in_dep] + r[in_dep]))
    two = np.where(h >= 1.5 * dmean)[0]
    runout2 = float(xc[two[-1]] + 0.5 * dbin) if two.size else 0.0
    area = float(np.sum(h) * dbin)
    return {"x": xc, "h": h, "runout": runout, "runout2": runout2,
            "height": float(np.max(h)), "area": area, "dmean": dmean,
            "dbin": dbin, "n": int(x.size), "n_isolated": int(np.sum(~in_dep))}


def analyse_repose(dump, ledge, dbin=None, fit_lo=0.15, fit_hi=0.85):
    """Angle of the wedge left on a ledge 0 <= x <= ledge (grains above y>0)."""
    x, y, r = dump["x"], dump["y"], dump["radius"]
    if "type" in dump:
        sel = dump["type"] == 1
        x, y, r = x[sel], y[sel], r[sel]
    sel = (y > 0.0) & (x <= ledge + 1e-9)
    x, y, r = x[sel], y[sel], r[sel]
    dmean = 2.0 * float(np.mean(r))
    if dbin is None:
        dbin = dmean
    xc, h = surface_profile(x, y, r, dbin)
    ok = (~np.isnan(h)) & (xc >= fit_lo * ledge) & (xc <= fit_hi * ledge)
    if np.sum(ok) < 3:
        raise ValueError("too few surface bins for a fit")
    p = np.polyfit(xc[ok], h[ok], 1)
    resid = h[ok] - np.polyval(p, xc[ok])
    ang = math.degrees(math.atan(-p[0]))
    # standard error of the slope -> of the angle
    nfit = int(np.sum(ok))
    sxx = np.sum((xc[ok] - xc[ok].mean()) ** 2)
    se = math.sqrt(np.sum(resid ** 2) / max(nfit - 2, 1) / sxx)
    se_ang = math.degrees(se / (1.0 + p[0] ** 2))
    return {"x": xc, "h": h, "angle": ang, "angle_se": se_ang,
            "slope": p[0], "intercept": p[1], "nfit": nfit,
            "n": int(x.size), "dmean": dmean}


def write_csv(path, hdr, columns, rows):
    """A CSV: the provenance header, the column-name line, then the pre-formatted rows."""
    with open(path, "w") as f:
        f.write("\n".join(hdr) + "\n")
        f.write(columns + "\n")
        for row in rows:
            f.write(row + "\n")


def header_lines(args, info, extra):
    params = info["params"]
    lines = [
        ("source", "DEM simulation with %s (GeoSPH reference/dem)" %
         (info["version"] or liggghts_version())),
        ("input_script", "%s sha256 %s" % (os.path.basename(args.input),
                                           sha256(args.input))
         if args.input and os.path.exists(args.input) else "unknown"),
        ("random_seed", params.get("seed", "unknown")),
        ("parameters", " ".join("%s=%s" % kv for kv in params.items())
         or "unknown"),
        ("command", args.command or "unknown"),
        ("date", args.date or datetime.datetime.now(datetime.timezone.utc)
         .strftime("%Y-%m-%dT%H:%M:%SZ")),
        ("run_time_s", "%.1f (sum of LIGGGHTS loop times, all stages)" %
         info["loop_time_s"]),
    ]
    if args.calibration_note:
        lines.append(("calibration", args.calibration_note))
    lines += extra
    return ["# %s: %s" % (k, str(v).replace("\n", " ")) for k, v in lines]


def cmd_collapse(args):
    fin = read_dump(args.dump)
    info = read_log(args.log)
    res = analyse_collapse(fin)
    L0 = float(info["params"].get("L0", "nan"))
    H0 = float(info["params"].get("H0", "nan"))
    extra = [
        ("particle_count", "%d final (%s after trimming, before release)" %
         (fin["_natoms"], info["n_initial"])),
        ("geometry", "quasi-2D slab periodic in z; column L0 = %g m x H0 = %g m"
         " (a = %.3g) against a back wall at x = 0, released by removing a "
         "wall at x = L0 instantly; flat frictional floor y = 0" %
         (L0, H0, H0 / L0 if L0 > 0 else float("nan"))),
        ("time_after_release_s", "%s (rms grain speed at end %s m/s)" %
         (info["t_release"], info["vrms_final"])),
        ("profile_method", "x-bins of width %.4g m (= mean grain diameter); "
         "y = max(y + r) of grains whose centre is in the bin; only bins of "
         "the deposit contiguous with the back wall are listed" % res["dbin"]),
        ("runout_method", "largest x + r of the grains in the contiguous "
         "deposit (%d isolated grains beyond the first empty bin ignored); "
         "runout_2layer_m = right edge of the furthest bin with height >= "
         "1.5 d" % res["n_isolated"]),
        ("runout_m", "%.4f" % res["runout"]),
        ("runout_2layer_m", "%.4f" % res["runout2"]),
        ("final_height_m", "%.4f" % res["height"]),
        ("deposit_area_m2", "%.5g (profile integral; initial L0*H0 = %.5g)" %
         (res["area"], L0 * H0)),
        ("units", "x [m], y [m]"),
    ]
    if args.initial:
        ini = analyse_collapse(read_dump(args.initial))
        extra.append(("initial_profile_area_m2", "%.5g (same method on the "
                      "dump before release)" % ini["area"]))
    write_csv(args.output, header_lines(args, info, extra), "x,y",
              ("%.6f,%.6f" % (xc, h) for xc, h in zip(res["x"], res["h"])))
    print("collapse: N=%d runout=%.4f m runout_2layer=%.4f m final_height="
          "%.4f m area=%.5g m2 -> %s" % (res["n"], res["runout"],
                                         res["runout2"], res["height"],
                                         res["area"], args.output))
    return res


def cmd_repose(args):
    fin = read_dump(args.dump)
    info = read_log(args.log)
    ledge = float(info["params"].get("W", args.ledge))
    res = analyse_repose(fin, ledge)
    extra = [
        ("particle_count", "%d grains left on the ledge (%s before release)" %
         (res["n"], info["n_initial"])),
        ("test", "ledge (draining) angle of repose: column on a rough ledge "
         "of frozen grains, gate removed, grains flow off the edge"),
        ("fit", "least-squares line through the surface profile bins with "
         "0.15 W <= x <= 0.85 W (W = %g m), %d bins" % (ledge, res["nfit"])),
        ("repose_angle_deg", "%.2f" % res["angle"]),
        ("repose_angle_se_deg", "%.2f" % res["angle_se"]),
        ("units", "x [m], y [m]"),
    ]
    write_csv(args.output, header_lines(args, info, extra), "x,y",
              ("%.6f,%.6f" % (xc, h) for xc, h in zip(res["x"], res["h"]) if not np.isnan(h)))
    print("repose: mu=%s mur=%s angle=%.2f +- %.2f deg (N=%d) -> %s" % (
        info["params"].get("mu"), info["params"].get("mur"), res["angle"],
        res["angle_se"], res["n"], args.output))
    return res


def read_ave_time(path):
    """Rows (step, values...) of a `fix ave/time` file."""
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            rows.append([float(v) for v in line.split()])
    if not rows:
        raise ValueError("%s: no data rows" % path)
    return np.array(rows)


def analyse_wall(ini, fin, Lb, thick, mass, dmax, g=9.81, rows=10):
    """Earth-pressure normalisation and slip line of a translated wall.

    gamma H = M g / (Lb t) is the weight per unit floor area; H_eff is the mean
    height of the surface profile before the wall moves, so that
    K = F / (0.5 gamma H_eff^2 t) = 2 F Lb / (M g H_eff).
    Slip line: grains are matched by id; in each of `rows` horizontal strips
    (0.1 H_eff high) the slip point is where the grains' horizontal
    displacement, towards the wall side of the strip, first falls below half
    the wall's travel (a running median over x-bins one grain wide).  The
    wedge angle is the least-squares slope of height against slip-point x
    over the eight strips centred at 0.15-0.85 H_eff (the top strip is
    disturbed by the settling surface, the bottom one by the wall-floor
    corner); the window 0.1 < y/H_eff < 0.9 has its edges between strip
    centres, so rounding cannot move a strip in or out.
    """
    dmean = float(np.mean(2 * ini["radius"]))
    xb, hb = surface_profile(ini["x"], ini["y"], ini["radius"], dmean)
    keep = ~np.isnan(hb) & (xb > 2 * dmean) & (xb < Lb - 2 * dmean)
    H_eff = float(np.mean(hb[keep]))
    order_i = np.argsort(ini["id"])
    order_f = np.argsort(fin["id"])
    ids_i = ini["id"][order_i]
    ids_f = fin["id"][order_f]
    common, ii, jf = np.intersect1d(ids_i, ids_f, return_indices=True)
    x0 = ini["x"][order_i][ii]
    y0 = ini["y"][order_i][ii]
    ux = fin["x"][order_f][jf] - x0
    half = 0.5 * abs(dmax)
    sign = np.sign(dmax)
    slip = []
    for k in range(rows):
        ylo, yhi = k * H_eff / rows, (k + 1) * H_eff / rows
        sel = (y0 >= ylo) & (y0 < yhi)
        if sel.sum() < 10:
            continue
        nb = int(np.ceil(Lb / dmean))
        xs = None
        med = []
        for b in range(nb):
            inb = sel & (x0 >= b * dmean) & (x0 < (b + 1) * dmean)
            med.append(np.median(sign * ux[inb]) if inb.any() else np.nan)
        med = np.array(med)
        # running median over three bins smooths single-grain noise
        sm = np.array([np.nanmedian(med[max(0, b - 1):b + 2]) for b in range(nb)])
        for b in range(nb):
            if not np.isnan(sm[b]) and sm[b] < half:
                if b == 0:
                    xs = 0.0
                else:  # linear interpolation between bin centres
                    x1, x2 = (b - 0.5) * dmean, (b + 0.5) * dmean
                    f1, f2 = sm[b - 1], sm[b]
                    xs = x1 + (f1 - half) / (f1 - f2) * (x2 - x1) if f1 != f2 else x2
                break
        if xs is not None:
            slip.append((xs, 0.5 * (ylo + yhi)))
    slip = np.array(slip)
    fit = slip[(slip[:, 1] > 0.1 * H_eff) & (slip[:, 1] < 0.9 * H_eff)] if slip.size else slip
    angle = float("nan")
    if len(fit) >= 3:
        slope = np.polyfit(fit[:, 0], fit[:, 1], 1)[0]
        angle = math.degrees(math.atan(abs(slope)))
    return {"H_eff": H_eff, "dmean": dmean, "slip": slip, "angle": angle,
            "n": int(common.size), "Kfac": 2 * Lb / (mass * g * H_eff),
            "unit_weight": mass * g / (Lb * thick * H_eff)}


def cmd_wall(args):
    info = read_log(args.log)
    pr = info["params"]
    Lb, H0 = float(pr["Lb"]), float(pr["H0"])  # H0: the trimming height, for the geometry line
    thick = float(pr["nz"]) * float(pr["d"])
    dmax = math.copysign(float(pr["dmax"]), float(pr["vw"]))
    vw = float(pr["vw"])
    dt = float(pr["dt"])
    mass = info.get("mass_kg")
    if mass is None:
        raise ValueError("%s: no 'DEM_INITIAL_PARTICLES n MASS m' line" % args.log)
    ini = read_dump(args.initial)
    fin = read_dump(args.dump)
    res = analyse_wall(ini, fin, Lb, thick, mass, dmax)
    F = read_ave_time(args.force)
    t = F[:, 0] * dt
    disp = np.abs(vw) * t
    K = np.abs(F[:, 1]) * res["Kfac"]  # |x-force| of the grains on the wall
    last = disp >= 0.9 * disp[-1]
    K_end = float(np.mean(K[last]))
    mode = "active" if vw < 0 else "passive"
    extra = [
        ("particle_count", "%d grains (%s after trimming)" % (fin["_natoms"], info["n_initial"])),
        ("geometry", "quasi-2D slab %g m thick between frictionless planes; backfill Lb = %g m x "
         "H0 = %g m behind a frictionless rigid wall at x = 0 (mesh), on a rough floor y = 0 (one "
         "layer of frozen grains) against a frictionless far wall x = Lb; the wall is translated at %g m/s (%s) by %g m" %
         (thick, Lb, H0, vw, mode, abs(dmax))),
        ("bulk", "grain mass %.5g kg; surface height before the move H_eff = %.5f m; bulk unit "
         "weight M g / (Lb t H_eff) = %.1f N/m3" % (mass, res["H_eff"], res["unit_weight"])),
        ("K_method", "K = F / (0.5 gamma H_eff^2 t) = 2 F Lb / (M g H_eff); F: x-force of the grains "
         "on the wall (fix mesh/surface/stress), averaged over each output interval"),
        ("K_initial", "%.4f" % K[0]),
        ("K_final", "%.4f (mean over the last 10%% of the travel)" % K_end),
        ("slip_method", "grains matched by id between the dumps before and after the move; per "
         "0.1 H_eff strip, the x where the median horizontal displacement (one-grain bins, running "
         "median of three) falls below half the wall travel; angle = least-squares slope of height "
         "on x over the strips centred at 0.15-0.85 H_eff"),
        ("wedge_angle_deg", "%.2f (from the horizontal)" % res["angle"]),
        ("units", "displacement_over_H = wall travel / H_eff; K dimensionless"),
    ]
    hdr = header_lines(args, info, extra)
    write_csv(args.output, hdr, "displacement_over_H,K",
              ("%.6f,%.5f" % (a, b) for a, b in zip(disp / res["H_eff"], K)))
    slip_out = args.output[:-4] + "_slip.csv" if args.output.endswith(".csv") else args.output + "_slip"
    write_csv(slip_out, hdr, "x_over_H,y_over_H",
              ("%.5f,%.5f" % (xs / res["H_eff"], ys / res["H_eff"]) for xs, ys in res["slip"]))
    print("wall %s: N=%d H_eff=%.4f K0=%.3f K_end=%.3f wedge=%.1f deg -> %s, %s" % (
        mode, res["n"], res["H_eff"], K[0], K_end, res["angle"], args.output, slip_out))
    return res


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    sub = ap.add_subparsers(dest="mode", required=True)
    for name in ("collapse", "repose", "wall"):
        s = sub.add_parser(name)
        s.add_argument("dump", help="final text dump")
        s.add_argument("-o", "--output", required=True, help="CSV to write")
        s.add_argument("--log", help="LIGGGHTS log (version, params, counts)")
        s.add_argument("--input", help="LIGGGHTS input script (for sha256)")
        s.add_argument("--command", help="command line used for the run")
        s.add_argument("--date", help="run date (default: now, UTC)")
        s.add_argument("--calibration-note", help="text for '# calibration:'")
        if name == "collapse":
            s.add_argument("--initial", help="dump before release (optional)")
        elif name == "wall":
            s.add_argument("--initial", required=True, help="dump before the wall moves")
            s.add_argument("--force", required=True, help="fix ave/time file of the wall force")
        else:
            s.add_argument("--ledge", type=float, default=0.1,
                           help="ledge length if not in the log")
    args = ap.parse_args(argv)
    if args.mode == "collapse":
        return cmd_collapse(args)
    if args.mode == "wall":
        return cmd_wall(args)
    return cmd_repose(args)


if __name__ == "__main__":
    main()
