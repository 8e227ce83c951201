"""Soak test (ctest label `soak`, not in the default gate): 10^6 steps of a small scene.

While `geosph run` works, this script samples the process's resident memory once a second and opens
the XDMF index as a reader (ParaView) would: every snapshot the index names must exist and hold the
particle count the index gives, at every moment. It fails if the resident memory grows by more than
GROWTH_MB between the first tenth of the run and its end (a leak), if any reading of the index finds
an incomplete series, or if the run does not finish.

    /usr/bin/python3 verification/soak/long_run.py build/solver/geosph [steps]
"""
import json
import sys
import tempfile
import time
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import h5py

GROWTH_MB = 8.0  # the index's entries (~200 B per snapshot) and allocator noise stay well below it

SCENE = {
    "name": "soak_tank", "dimension": 2, "dx": 0.02,
    "domain": {"min": [-0.1, -0.1], "max": [0.5, 0.5]},
    "gravity": [0, -9.81], "time": {"end": 1e9, "max_steps": 1000000},
    "output": {"interval": 1.0},
    "materials": {"water": {"model": "tait_fluid", "density": 1000, "sound_speed": 20,
                            "artificial_viscosity": 0.05, "density_diffusion": 0.1,
                            "density_diffusion_hydrostatic": True}},
    "bodies": [{"material": "water", "shape": "box", "min": [0, 0], "max": [0.2, 0.2], "initial": "hydrostatic"}],
    "walls": {"type": "dummy", "containers": [{"min": [0, 0], "max": [0.3, 0.3], "open": ["top"]}]},
}


def rss_mb(pid):
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return float(line.split()[1]) / 1024
    return 0.0


def check_index(out):
    """Opens the index as a reader would; returns the number of snapshots, raises on inconsistency."""
    index = out / "particles.xdmf"
    if not index.exists():
        return 0
    root = ET.parse(index).getroot()
    grids = root.findall(".//Grid[@GridType='Uniform']")
    for g in grids:
        n = int(g.find("Topology").get("NumberOfElements"))
        item = g.find("Geometry/DataItem").text
        name, dataset = item.split(":/")
        with h5py.File(out / name, "r") as f:
            if f[dataset].shape[0] != n:
                raise AssertionError(f"{name}: {f[dataset].shape[0]} particles, the index says {n}")
    return len(grids)


def main():
    exe = sys.argv[1]
    steps = int(sys.argv[2]) if len(sys.argv) > 2 else 1000000
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        scene = dict(SCENE, time=dict(SCENE["time"], max_steps=steps))
        (tmp / "scene.json").write_text(json.dumps(scene))
        out = tmp / "out"
        proc = subprocess.Popen([exe, "--threads", "1", "run", str(tmp / "scene.json"), "--out", str(out), "--quiet",
                                 "--checkpoint-every", str(max(steps // 10, 1)), "--checkpoint-keep", "2"],
                                stderr=subprocess.PIPE, text=True)
        samples, reads, t0 = [], 0, time.time()
        while proc.poll() is None:
            time.sleep(1.0)
            try:
                m = rss_mb(proc.pid)
            except FileNotFoundError:
                break
            if m > 0:  # 0 once the process has exited (a zombie has no resident set)
                samples.append((time.time() - t0, m))
            check_index(out)
            reads += 1
        err = proc.stderr.read()
        if proc.returncode != 0:
            raise SystemExit(f"geosph exited with {proc.returncode}: {err}")
        summary = json.loads((out / "summary.json").read_text())
        snapshots = check_index(out)
        checkpoints = sorted((out / "checkpoints").glob("checkpoint_*.h5"))
        if len(samples) < 10:
            raise SystemExit(f"run too short to judge memory ({len(samples)} samples)")
        early = max(m for t, m in samples[: max(1, len(samples) // 10)])
        late = max(m for t, m in samples[-max(1, len(samples) // 10):])
        print(f"{summary['steps']} steps in {summary['wall_s']:.0f} s, {snapshots} snapshots, {reads} reads of the "
              f"index mid-run, {len(checkpoints)} checkpoints kept; resident memory {early:.1f} MB early, "
              f"{late:.1f} MB late (allowed growth {GROWTH_MB} MB)")
        if summary["steps"] != steps:
            raise SystemExit(f"the run made {summary['steps']} steps, not {steps}")
        if len(checkpoints) != 2:
            raise SystemExit(f"{len(checkpoints)} checkpoints kept, --checkpoint-keep 2 asked for 2")
        if late - early > GROWTH_MB:
            raise SystemExit(f"resident memory grew by {late - early:.1f} MB")


if __name__ == "__main__":
    main()
