#!/usr/bin/python3
"""Synthetic result records for tests and demos (clearly fake numbers, valid schema).

Run as a script to write them: synthetic.py OUT_DIR
"""
import copy
import json
import math
import sys
from pathlib import Path

POISEUILLE_C, POISEUILLE_P = 3.0, 2.0   # exact power law error = C * dx**p


def base(case, dx, **kw):
    """A minimal valid, passing record; keyword arguments override fields."""
    rec = {"case": case, "level": "quick",
           "resolution": {"dx": dx, "particles": int(round(1.0 / dx ** 2)), "dimension": 2},
           "metrics": [{"name": "rel_l2", "value": 0.01, "tolerance": 0.05, "passed": True,
                        "why_tolerance": "synthetic"}],
           "steps": int(100 / dx), "wall_s": 0.5 / dx ** 1.5, "particle_steps_per_s": 5e6,
           "threads": 2, "stable": True, "options": {"kernel": "wendland_c2", "boundary": "dummy"},
           "provenance": {"solver_version": "0.1.0 (git synthetic)", "compiler": "GNU 12.2.0",
                          "build_flags": "Release: -O3", "threads": 2, "scene_hash": "0123456789abcdef"}}
    rec.update(kw)
    return rec


def _metric(name, value, tol, why):
    return [{"name": name, "value": value, "tolerance": tol, "passed": value <= tol, "why_tolerance": why}]


def dam_break():
    t = [0.25 * i for i in range(13)]
    exp_t = [0.0, 0.41, 0.84, 1.19, 1.43, 1.63, 1.83, 1.98, 2.20, 2.32, 2.51, 2.65]
    exp_z = [1.0, 1.11, 1.22, 1.44, 1.67, 1.89, 2.11, 2.33, 2.56, 2.78, 3.0, 3.22]
    n = 40
    xs = [(i % n) * 0.025 for i in range(n * n // 2)]
    ys = [(i // n) * 0.025 for i in range(n * n // 2)]
    out = {}
    for name, dx, lvl, err in (("quick", 0.02, "quick", 0.06), ("full", 0.01, "full", 0.035)):
        sim_z = [1 + 0.6 * tt ** 1.35 * (1 - err) for tt in t]
        rec = base("dam_break_2d", dx, level=lvl, title="2D dam break (Martin & Moyce 1952)",
                   reference={"kind": "experimental", "source": "Martin & Moyce 1952, Phil. Trans. A 244"},
                   metrics=_metric("front_position_rel_l2", err, 0.08, "digitised data scatter ~5%"),
                   options={"kernel": "wendland_c2", "boundary": "dummy", "density_diffusion": 0.1})
        rec["series"] = [
            {"name": "SPH", "role": "simulation", "x": t, "y": sim_z, "xlabel": "T", "ylabel": "Z", "plot": "front"},
            {"name": "Martin & Moyce 1952", "role": "experiment", "x": exp_t, "y": exp_z,
             "xlabel": "T", "ylabel": "Z", "plot": "front"},
            {"name": "SPH", "role": "simulation", "x": t, "y": [max(0.0, 1 - 0.08 * tt ** 1.6) for tt in t],
             "xlabel": "T", "ylabel": "H", "plot": "height"}]
        rec["snapshot"] = {"x": xs, "y": ys, "field": "pressure", "units": "Pa",
                           "values": [1000 * 9.81 * (0.5 - y) for y in ys]}
        out[f"dam_break/{name}.json"] = rec
    bad = base("dam_break_2d", 0.02, variant="delta_off", stable=False,
               metrics=[{"name": "front_position_rel_l2", "value": None, "tolerance": 0.08,
                         "passed": False, "why_tolerance": "digitised data scatter ~5%"}],
               failure={"step": 1234, "time": 0.41, "message": "pressure noise: negative density"},
               options={"kernel": "wendland_c2", "boundary": "dummy", "density_diffusion": 0.0})
    out["dam_break/delta_off.json"] = bad
    return out


def poiseuille():
    out = {}
    for dx in (0.04, 0.02, 0.01, 0.005):
        err = POISEUILLE_C * dx ** POISEUILLE_P
        ys = [i / 20 for i in range(21)]
        rec = base("poiseuille_2d", dx, level="convergence", expected_order=2.0,
                   title="Body-force Poiseuille flow", reference={"kind": "analytical", "source": "Morris et al. 1997"},
                   metrics=_metric("velocity_rel_l2", err, 0.01, "second-order scheme at dx=0.01: 3e-4"))
        rec["series"] = [
            {"name": "analytical", "role": "analytical", "x": ys, "y": [4 * y * (1 - y) for y in ys],
             "xlabel": "y / H", "ylabel": "u / u_max", "plot": "profile"},
            {"name": "SPH", "role": "simulation", "x": ys, "y": [4 * y * (1 - y) * (1 - err) for y in ys],
             "xlabel": "y / H", "ylabel": "u / u_max", "plot": "profile"}]
        out[f"poiseuille/dx{dx}.json"] = rec
    return out


def column_collapse():
    t = [0.05 * i for i in range(21)]
    dem = [1 + 1.8 * (1 - math.exp(-3 * tt)) for tt in t]
    out = {}
    for variant, stress, err, stable in (("with_stress", 0.3, 0.09, True), (None, 0.2, 0.14, True),
                                         ("no_stress", None, 0.4, False)):
        opts = {"kernel": "wendland_c2", "constitutive": "drucker_prager"}
        if stress is not None:
            opts["artificial_stress"] = stress
        rec = base("granular_collapse_2d", 0.005, level="full", variant=variant, options=opts,
                   title="Granular column collapse (a=2)", reference={"kind": "dem", "source": "LIGGGHTS run, reference/dem"},
                   metrics=_metric("runout_rel_err", err, 0.12, "DEM ensemble spread ~10%"), stable=stable)
        rec["wall_s"] = {"with_stress": 400.0, None: 320.0, "no_stress": 90.0}[variant]
        if not stable:
            rec["metrics"][0]["passed"] = False
            rec["failure"] = {"step": 5120, "time": 0.21, "message": "tensile instability: particle clumping"}
        rec["series"] = [
            {"name": "DEM", "role": "dem", "x": t, "y": dem, "xlabel": "t [s]", "ylabel": "L/L0", "plot": "runout"},
            {"name": "SPH", "role": "simulation", "x": t, "y": [d * (1 - err) for d in dem],
             "xlabel": "t [s]", "ylabel": "L/L0", "plot": "runout"}]
        out[f"granular/{variant or 'default'}.json"] = rec
    return out


def hydrostatic():
    return {f"hydrostatic/dx{dx}.json": base(
        "hydrostatic_2d", dx, level="full", expected_order=1.0,
        metrics=_metric("pressure_rel_l2", 0.2 * dx, 0.01, "first order at the wall"))
        for dx in (0.02, 0.01)}


def wall_treatments():
    """One case run with three wall treatments (the boundary comparison); morris fails its tolerance."""
    out = {}
    for walls, err, wall_s, n_wall in (("dummy", 0.012, 30.0, 900), ("repulsive", 0.018, 20.0, 300),
                                       ("morris", 0.03, 31.0, 900)):
        rec = base("tank_2d", 0.01, wall_treatment=walls, variant=None if walls == "dummy" else f"walls={walls}",
                   metrics=_metric("pressure_rel_l2", err, 0.02, "synthetic"))
        rec["resolution"]["wall_particles"] = n_wall
        rec["steps"], rec["wall_s"] = 1000, wall_s
        if rec["variant"] is None:
            del rec["variant"]
        else:
            rec["wall_comparison"] = True
        if walls == "morris":
            rec["wall_treatment_open"] = "synthetic reason: capped wall velocity"
        out[f"tank/{walls}.json"] = rec
    return out


def all_records():
    """{relative path: record dict} for every synthetic case."""
    out = {}
    for make in (dam_break, poiseuille, column_collapse, hydrostatic):
        out.update(make())
    return copy.deepcopy(out)


def write(out_dir, records=None):
    """Write records (default: all_records()) as JSON files under out_dir."""
    for rel, rec in (records or all_records()).items():
        p = Path(out_dir) / rel
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text(json.dumps(rec, indent=1))


if __name__ == "__main__":
    write(sys.argv[1])
    print(f"wrote {len(all_records())} synthetic records to {sys.argv[1]}")
