"""Smoke test of the DEM reference pipeline (LIGGGHTS input + postprocess.py).

Runs TINY versions of reference/dem/collapse_2d.in (d = 10 mm, ~500 grains)
and of reference/dem/retaining_wall_2d.in (d = 10 mm, ~900 grains, active and
passive) for real in a temporary directory, a few seconds each, post-processes
their dumps and checks that the deposit and the wall force are sane.  Skipped
when LIGGGHTS is not installed.

Run from the repository root with
    /usr/bin/python3 -m unittest discover -s reference/dem/tests -t reference/dem
"""
import importlib.util
import os
import shutil
import subprocess
import tempfile
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
DEM = os.path.dirname(HERE)
INPUT = os.path.join(DEM, "collapse_2d.in")
WALL_INPUT = os.path.join(DEM, "retaining_wall_2d.in")
LIGGGHTS = shutil.which(os.environ.get("LIGGGHTS", "liggghts"))

D, L0, H0 = 0.01, 0.2, 0.1


def load_postprocess():
    spec = importlib.util.spec_from_file_location(
        "dem_postprocess", os.path.join(DEM, "postprocess.py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@unittest.skipIf(LIGGGHTS is None,
                 "LIGGGHTS not installed (sudo apt-get install liggghts); "
                 "the DEM references are the committed reference/dem/*.csv")
class TestDemPipeline(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="geosph-dem-test-")
        cmd = [LIGGGHTS, "-in", INPUT, "-var", "d", str(D), "-var", "L0",
               str(L0), "-var", "H0", str(H0), "-var", "tmax", "1.5",
               "-var", "out", "tiny", "-log", "tiny.log"]
        cls.cmd = cmd
        t0 = time.time()
        # no `-screen none`: LIGGGHTS 3.8.0 segfaults with it in insert/pack
        p = subprocess.run(cmd, cwd=cls.tmp, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True, timeout=300)
        cls.runtime = time.time() - t0
        if p.returncode != 0:
            raise RuntimeError("LIGGGHTS failed (rc %d):\n%s" %
                               (p.returncode, p.stdout[-3000:]))
        cls.pp = load_postprocess()
        cls.csv = os.path.join(cls.tmp, "tiny.csv")
        cls.pp.main(["collapse", os.path.join(cls.tmp, "tiny_final.dump"),
                     "--initial", os.path.join(cls.tmp, "tiny_initial.dump"),
                     "--log", os.path.join(cls.tmp, "tiny.log"),
                     "--input", INPUT, "--command", " ".join(cmd),
                     "--calibration-note", "test run, not calibrated",
                     "-o", cls.csv])
        cls.final = cls.pp.analyse_collapse(
            cls.pp.read_dump(os.path.join(cls.tmp, "tiny_final.dump")))
        cls.initial = cls.pp.analyse_collapse(
            cls.pp.read_dump(os.path.join(cls.tmp, "tiny_initial.dump")))

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_runtime_and_size(self):
        self.assertLess(self.runtime, 120.0)
        self.assertGreater(self.initial["n"], 100)
        self.assertLess(self.initial["n"], 2000)

    def test_initial_column(self):
        # trimmed column: top close to H0, deposit starts at the back wall
        self.assertLessEqual(self.initial["height"], H0 + D)
        self.assertGreater(self.initial["height"], H0 - 3 * D)
        self.assertLess(self.initial["runout"], L0 + D)

    def test_area_roughly_conserved(self):
        ratio = self.final["area"] / self.initial["area"]
        self.assertGreater(ratio, 0.6, ratio)
        self.assertLess(ratio, 1.5, ratio)

    def test_runout_and_height(self):
        self.assertGreater(self.final["runout"], L0)
        self.assertLessEqual(self.final["height"], H0 + D)
        self.assertGreater(self.final["height"], 0.0)
        self.assertLessEqual(self.final["runout2"], self.final["runout"] + D)

    def test_csv_header(self):
        with open(self.csv) as f:
            lines = f.read().splitlines()
        keys = {l[2:].split(":", 1)[0] for l in lines if l.startswith("# ")}
        for k in ("source", "input_script", "random_seed", "particle_count",
                  "command", "date", "calibration", "runout_m",
                  "final_height_m"):
            self.assertIn(k, keys)
        self.assertIn("LIGGGHTS", [l for l in lines
                                   if l.startswith("# source:")][0])
        i = lines.index("x,y")
        rows = [tuple(map(float, l.split(","))) for l in lines[i + 1:]]
        self.assertGreater(len(rows), 5)
        xs = [r[0] for r in rows]
        self.assertEqual(xs, sorted(xs))
        run = [l for l in lines if l.startswith("# runout_m:")][0]
        self.assertAlmostEqual(float(run.split(":")[1]),
                               self.final["runout"], places=3)


def run_liggghts(cmd, cwd):
    # no `-screen none`: LIGGGHTS 3.8.0 segfaults with it in insert/pack
    p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True, timeout=300)
    if p.returncode != 0:
        raise RuntimeError("LIGGGHTS failed (rc %d):\n%s" %
                           (p.returncode, p.stdout[-3000:]))


@unittest.skipIf(LIGGGHTS is None,
                 "LIGGGHTS not installed (sudo apt-get install liggghts); "
                 "the DEM references are the committed reference/dem/*.csv")
class TestWallPipeline(unittest.TestCase):
    """Tiny active and passive wall runs through `postprocess.py wall`."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="geosph-dem-wall-test-")
        cls.pp = load_postprocess()
        cls.res, cls.csv = {}, {}
        for mode, vw in (("active", -0.02), ("passive", 0.02)):
            out = "tiny_" + mode
            cmd = [LIGGGHTS, "-in", WALL_INPUT, "-var", "d", str(D),
                   "-var", "vw", str(vw), "-var", "dmax", "0.005",
                   "-var", "out", out, "-log", out + ".log"]
            run_liggghts(cmd, cls.tmp)
            f = lambda suffix: os.path.join(cls.tmp, out + suffix)
            cls.csv[mode] = f(".csv")
            cls.res[mode] = cls.pp.main([
                "wall", f("_final.dump"), "--initial", f("_initial.dump"),
                "--force", f("_force.txt"), "--log", f(".log"),
                "--input", WALL_INPUT, "--command", " ".join(cmd),
                "--calibration-note", "test run", "-o", cls.csv[mode]])

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def curve(self, mode):
        with open(self.csv[mode]) as f:
            lines = f.read().splitlines()
        header = {l[2:].split(":", 1)[0]: l.split(":", 1)[1].strip()
                  for l in lines if l.startswith("# ")}
        i = lines.index("displacement_over_H,K")
        rows = [tuple(map(float, l.split(","))) for l in lines[i + 1:]]
        return header, rows

    def test_header_and_rows(self):
        for mode in ("active", "passive"):
            header, rows = self.curve(mode)
            for k in ("source", "input_script", "random_seed", "command",
                      "K_initial", "K_final", "wedge_angle_deg", "bulk"):
                self.assertIn(k, header, mode)
            self.assertGreater(len(rows), 5)
            ds = [r[0] for r in rows]
            self.assertEqual(ds, sorted(ds))
            # 5 mm of travel over a ~0.1 m backfill
            self.assertAlmostEqual(ds[-1], 0.005 / self.res[mode]["H_eff"], delta=0.01)
            self.assertTrue(os.path.exists(self.csv[mode][:-4] + "_slip.csv"))

    def test_earth_pressure_moves_the_right_way(self):
        # at rest, a settled granular backfill presses with K0 of order 0.3-1;
        # moving the wall away lowers K, pushing it in raises K
        ha, ra = self.curve("active")
        hp, rp = self.curve("passive")
        k0a, k0p = float(ha["K_initial"]), float(hp["K_initial"])
        for k0 in (k0a, k0p):
            self.assertGreater(k0, 0.2)
            self.assertLess(k0, 1.5)
        self.assertLess(float(ha["K_final"].split()[0]), k0a)
        self.assertGreater(float(hp["K_final"].split()[0]), k0p)


if __name__ == "__main__":
    unittest.main()
