#!/usr/bin/env python3
"""Timed whole run of DualSPHysics' 2D dam-break validation case written as a GeoSPH scene.

DualSPHysics v5.4, CaseDambreakVal2D: tank 4 x 3 m, water column 1 x 2 m, dp = 0.01, Wendland C2
with h = 1.41 dp, CFL 0.2, Fourtakas density diffusion delta = 0.1, artificial viscosity
alpha = 0.02, c0 = 88.4 m/s; here with Adami dummy walls (free slip) instead of its DBC wall.
DualSPHysics' own figures were measured on the same 2-core machine class, unloaded, 2026-11-23
(issue 21): 0.2 s in about 112 s with 1 thread and 56 s with 2 threads at dp = 0.01 (21,001
particles, 1.19 M and 2.37 M particle-steps/s), 2.45 M particle-steps/s with 2 threads at
dp = 0.007.

Prints, per thread count, the wall time of `geosph run` (whole run: set-up, time loop, the 21
snapshots), the particle-steps per second (all particles, as DualSPHysics counts them, and fluid
only), the speed ratio to DualSPHysics, and the surge front Z = x/a at the Martin & Moyce (1952,
Table 2; reference/experimental/dam_break_martin_moyce_1952.csv) times T = t sqrt(2g/a) the run
covers, so that a faster build can be seen to give the same front.

    python3 verification/benchmark/dualsphysics_dambreak/run.py [--threads 1 2] [--dx 0.01] [--reps 3]
"""
import argparse
import csv
import json
import os
import pathlib
import subprocess
import sys
import tempfile

import h5py
import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[2]
# DualSPHysics v5.4 on this machine class (issue 21, measured 2026-11-23): wall seconds for 0.2 s
DUALSPHYSICS_WALL_S = {(0.01, 1): 112.0, (0.01, 2): 56.0}
DUALSPHYSICS_RATE = {(0.01, 1): 1.19e6, (0.01, 2): 2.37e6, (0.007, 2): 2.45e6}  # particle-steps/s


def martin_moyce():
    rows = [r for r in open(ROOT / "reference/experimental/dam_break_martin_moyce_1952.csv") if not r.startswith("#")]
    data = list(csv.DictReader(rows))
    return np.array([float(r["T"]) for r in data]), np.array([float(r["Z"]) for r in data])


def front_series(out, scene):
    """Z(T) of the surge front in every snapshot: the largest x of the fluid within 2 dx of the floor,
    plus dx/2 (as the catalogue's dam_break_2d case)."""
    dx = scene["dx"]
    x0, y0 = scene["bodies"][0]["min"]
    a = scene["bodies"][0]["max"][0] - x0
    g = -scene["gravity"][1]
    T, Z = [], []
    for f in sorted(out.glob("particles_*.h5")):
        with h5py.File(f) as h:
            pos, kind = h["position"][()], h["kind"][()]
            fluid = (kind == 0) & (pos[:, 1] < y0 + 2 * dx)
            T.append(float(h.attrs["time"]) * np.sqrt(2 * g / a))
            Z.append((pos[fluid, 0].max() + 0.5 * dx - x0) / a)
    return np.array(T), np.array(Z)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--geosph", default=str(ROOT / "build/solver/geosph"))
    ap.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--dx", type=float, default=0.01)
    ap.add_argument("--reps", type=int, default=1, help="runs per thread count; the fastest is reported")
    ap.add_argument("--json", help="also write the rows to this file")
    args = ap.parse_args()
    scene = json.loads((HERE / "scene.json").read_text())
    scene["dx"] = args.dx
    Te, Ze = martin_moyce()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        (tmp / "scene.json").write_text(json.dumps(scene))
        for threads in args.threads:
            best = None
            for _ in range(args.reps):
                out = tmp / f"run_{threads}"
                env = dict(os.environ, OMP_NUM_THREADS=str(threads))
                subprocess.run([args.geosph, "run", str(tmp / "scene.json"), "--out", str(out), "--quiet",
                                "--overwrite", "--threads", str(threads)], check=True, env=env)
                s = json.loads((out / "summary.json").read_text())
                if best is None or s["wall_s"] < best["wall_s"]:
                    best = s
                    T, Z = front_series(out, scene)
            row = {"dx": args.dx, "threads": threads, "particles": best["particles"],
                   "fluid": best["material_particles"], "steps": best["steps"], "wall_s": best["wall_s"],
                   "rate_all": best["particles"] * best["steps"] / best["wall_s"],
                   "rate_fluid": best["particle_steps_per_s"], "version": best["provenance"]["solver_version"]}
            key = (args.dx, threads)
            if key in DUALSPHYSICS_WALL_S:
                row["speed_vs_dualsphysics"] = DUALSPHYSICS_WALL_S[key] / best["wall_s"]
            elif key in DUALSPHYSICS_RATE:
                row["speed_vs_dualsphysics"] = row["rate_all"] / DUALSPHYSICS_RATE[key]
            inside = (Te > 0) & (Te <= T[-1])
            row["front"] = [{"T": float(t), "Z_martin_moyce": float(z), "Z_geosph": float(np.interp(t, T, Z))}
                            for t, z in zip(Te[inside], Ze[inside])]
            row["front_end"] = {"T": float(T[-1]), "Z_geosph": float(Z[-1])}
            rows.append(row)
    print("| dx | threads | particles (fluid) | steps | wall [s] | M particle-steps/s (all / fluid) | x DualSPHysics |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        ratio = f"{r['speed_vs_dualsphysics']:.2f}" if "speed_vs_dualsphysics" in r else "-"
        print(f"| {r['dx']} | {r['threads']} | {r['particles']} ({r['fluid']}) | {r['steps']} | {r['wall_s']:.1f} | "
              f"{r['rate_all'] / 1e6:.2f} / {r['rate_fluid'] / 1e6:.2f} | {ratio} |")
    print("\nsurge front Z = x/a against Martin & Moyce (1952) at their T (lifted-gate release: the experiment lags):")
    for r in rows[:1]:
        for f in r["front"]:
            print(f"  T = {f['T']:.2f}: GeoSPH {f['Z_geosph']:.3f}, experiment {f['Z_martin_moyce']:.2f}")
        print(f"  T = {r['front_end']['T']:.3f} (end of run): GeoSPH {r['front_end']['Z_geosph']:.3f}")
    print(f"GeoSPH {rows[0]['version']}")
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(rows, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
