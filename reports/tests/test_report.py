"""Tests of the GeoSPH report generator on synthetic result records.

Run from the repository root:
    /usr/bin/python3 -m unittest discover -s reports/tests -t reports
"""
import contextlib
import io
import json
import re
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

from geosph_report import convergence, records
from geosph_report.html import SECTIONS, boundaries_section, write_report

from . import synthetic

SCRIPT = Path(__file__).resolve().parent.parent / "generate_report.py"


class ReportTest(unittest.TestCase):
    """Generate one report from the synthetic records and inspect it."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        root = Path(cls.tmp.name)
        cls.results, cls.out = root / "results", root / "report"
        synthetic.write(cls.results)
        cls.records = records.load_records(cls.results)
        cls.index = write_report(cls.records, cls.out, source=cls.results)
        cls.html = cls.index.read_text()

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_every_section_present(self):
        for sid, title in SECTIONS:
            self.assertIn(f'<section id="{sid}">', self.html)
        self.assertIn(f"Generated from {len(synthetic.all_records())} result records", self.html)
        self.assertIn("no number in this report was typed by hand", self.html)
        self.assertIn("9 passed", self.html)
        self.assertIn("3 failed", self.html)

    def test_provenance_shown(self):
        summary = self.html.split('<section id="summary">')[1].split("</section>")[0]
        self.assertIn("GeoSPH 0.1.0 (git synthetic), GNU 12.2.0, <code>Release: -O3</code>", summary)

    def test_figures_exist_and_are_linked_relatively(self):
        pngs = re.findall(r'<img src="([^"]+)"', self.html)
        self.assertTrue(any(p.startswith("conv_poiseuille") for p in pngs))
        self.assertTrue(any(p.startswith("snap_dam_break") for p in pngs))
        self.assertTrue(any(p.startswith("speed_granular") for p in pngs))
        for p in pngs:
            self.assertNotIn("/", p)
            self.assertTrue((self.out / p).stat().st_size > 1000, p)
        self.assertNotIn("http", self.html)  # self-contained: no external resources

    def test_failing_rows_marked(self):
        summary = self.html.split('<section id="summary">')[1].split("</section>")[0]
        rows = re.findall(r"<tr( class=\"(\w+)\")?>(.*?)</tr>", summary)
        failing = [r for r in rows if r[1] == "fail"]
        self.assertEqual(len(failing), 3)
        for _, _, cells in failing:
            self.assertIn(">FAIL", cells)
        self.assertTrue(any("no_stress" in c and "FAIL (unstable)" in c for _, _, c in failing))
        self.assertTrue(all("FAIL" not in c for _, cls, c in rows if cls == "pass"))
        self.assertIn("tr.fail td { background", self.html)

    def test_cheapest_passing_named(self):
        speed = self.html.split('<section id="speed">')[1]
        self.assertIn("Cheapest record meeting the tolerance: <b>with_stress dx=0.005</b>", speed)

    def test_stability_table(self):
        stab = self.html.split('<section id="stability">')[1].split("</section>")[0]
        self.assertIn("tensile instability: particle clumping", stab)
        self.assertIn("5120", stab)
        self.assertIn("delta_off", stab)
        self.assertNotIn("poiseuille", stab)


class BoundaryComparisonTest(unittest.TestCase):

    def test_treatments_side_by_side_and_cheapest_named(self):
        with tempfile.TemporaryDirectory() as tmp:
            synthetic.write(Path(tmp) / "results", synthetic.wall_treatments())
            recs = records.load_records(Path(tmp) / "results")
            html = write_report(recs, Path(tmp) / "report").read_text()
        sec = html.split('<section id="boundaries">')[1].split("</section>")[0]
        rows = re.findall(r"<tr( class=\"(\w+)\")?>(.*?)</tr>", sec)
        self.assertEqual(len(rows), 4)  # header + one per treatment
        self.assertEqual([r[1] for r in rows[1:]], ["pass", "fail", "pass"])  # dummy, morris, repulsive
        self.assertIn(">300<", rows[3][2])  # repulsive: its wall particles
        self.assertIn(">20<", rows[3][2])   # and 20 s / 1000 steps = 20 ms per step
        self.assertIn("<b>repulsive</b> (20 ms per step; passing: dummy, repulsive)", sec)
        self.assertIn("<b>morris</b>: synthetic reason: capped wall velocity", sec)
        stab = html.split('<section id="stability">')[1].split("</section>")[0]
        self.assertNotIn("walls=", stab)  # the comparison runs are not stability variants

    def test_scene_variants_judged_apart(self):
        recs = []
        for scene, errs in (("trapezoid", {"dummy": 0.01, "ghost": 0.03}), ("v_shape", {"dummy": 0.01, "ghost": 0.015})):
            for walls, err in errs.items():
                variant = scene if walls == "dummy" else f"{scene} walls={walls}"
                rec = synthetic.base("tank", 0.01, wall_treatment=walls, variant=variant,
                                     metrics=synthetic._metric("pressure_rel_l2", err, 0.02, "synthetic"))
                rec["steps"], rec["wall_s"] = 1000, 10.0 if walls == "ghost" else 20.0
                if walls != "dummy":
                    rec["wall_comparison"] = True
                recs.append(records.parse_record(rec, f"{scene}-{walls}.json"))
        self.assertEqual(records.scene_variant(recs[1]), "trapezoid")
        sec = boundaries_section(recs)
        self.assertIn("quick, trapezoid, dx = 0.01: <b>dummy</b>", sec)  # ghost misses the tolerance there
        self.assertIn("quick, v_shape, dx = 0.01: <b>ghost</b>", sec)    # and is the cheaper one here

    def test_no_comparison_without_several_treatments(self):
        recs = [records.parse_record(r, p) for p, r in synthetic.all_records().items()]
        self.assertIn("No case was run with more than one wall treatment", boundaries_section(recs))


class ConvergenceTest(unittest.TestCase):

    def test_exact_power_law_order(self):
        for p in (1.0, 2.0, 1.5, 4.0):
            dx = [0.08, 0.04, 0.02, 0.01, 0.005]
            err = [2.5 * d ** p for d in dx]
            order, const = convergence.fit_order(dx, err)
            self.assertAlmostEqual(order, p, delta=1e-9)
            self.assertAlmostEqual(const, 2.5, delta=1e-9)
            for q in convergence.local_orders(dx, err):
                self.assertAlmostEqual(q, p, delta=1e-9)

    def test_study_from_records(self):
        recs = [records.parse_record(r, k) for k, r in synthetic.all_records().items()]
        by_case = {s.case: s for s in convergence.studies(recs)}
        poise = by_case["poiseuille_2d"]
        self.assertEqual(len(poise.dx), 4)
        self.assertEqual(poise.dx, sorted(poise.dx, reverse=True))
        self.assertAlmostEqual(poise.observed_order, synthetic.POISEUILLE_P, delta=1e-9)
        self.assertEqual(poise.expected_order, 2.0)
        self.assertEqual(len(by_case["hydrostatic_2d"].dx), 2)
        self.assertNotIn("granular_collapse_2d", by_case)  # one dx per variant


class MalformedTest(unittest.TestCase):

    def _run(self, files):
        with tempfile.TemporaryDirectory() as d:
            for name, text in files.items():
                (Path(d) / name).write_text(text)
            return subprocess.run([sys.executable, str(SCRIPT), d, "--out", str(Path(d) / "out")],
                                  capture_output=True, text=True)

    def _error(self, mutate):
        rec = synthetic.base("case_a", 0.01)
        mutate(rec)
        with self.assertRaises(records.RecordError) as cm:
            records.parse_record(json.loads(json.dumps(rec)), "bad.json")
        return str(cm.exception)

    def test_missing_fields_named(self):
        self.assertIn("bad.json: missing field 'case'", self._error(lambda r: r.pop("case")))
        self.assertIn("missing field 'resolution.dx'", self._error(lambda r: r["resolution"].pop("dx")))
        self.assertIn("missing field 'metrics[0].tolerance'",
                      self._error(lambda r: r["metrics"][0].pop("tolerance")))

    def test_bad_values_named(self):
        self.assertIn("'level' must be one of", self._error(lambda r: r.update(level="huge")))
        self.assertIn("'stable' must be a boolean", self._error(lambda r: r.update(stable="yes")))
        self.assertIn("'metrics' must hold at least one", self._error(lambda r: r.update(metrics=[])))
        self.assertIn("'series[0].x' and 'series[0].y' differ",
                      self._error(lambda r: r.update(series=[{"name": "a", "role": "simulation",
                                                              "x": [1, 2], "y": [1]}])))

    def test_cli_exit_codes(self):
        empty = self._run({})
        self.assertNotEqual(empty.returncode, 0)
        self.assertIn("no result records", empty.stderr)
        rec = synthetic.base("case_a", 0.01)
        del rec["wall_s"]
        bad = self._run({"r.json": json.dumps(rec)})
        self.assertNotEqual(bad.returncode, 0)
        self.assertIn("r.json: missing field 'wall_s'", bad.stderr)
        broken = self._run({"r.json": "{not json"})
        self.assertIn("r.json: cannot read JSON", broken.stderr)
        ok = self._run({"r.json": json.dumps(synthetic.base("case_a", 0.01))})
        self.assertEqual(ok.returncode, 0, ok.stderr)
        self.assertTrue(ok.stdout.strip().endswith("index.html"))

    def test_main_in_process(self):
        sys.path.insert(0, str(SCRIPT.parent))
        import generate_report
        with tempfile.TemporaryDirectory() as d, contextlib.redirect_stderr(io.StringIO()) as err:
            self.assertEqual(generate_report.main([d, "--out", str(Path(d) / "o")]), 2)
        self.assertIn("no result records", err.getvalue())


if __name__ == "__main__":
    unittest.main()


class StudyRecordTest(unittest.TestCase):
    """A record with "scored": false (a stabilisation switched off) is shown, never counted as failing."""

    def test_unscored_failing_record_is_a_study(self):
        with tempfile.TemporaryDirectory() as tmp:
            root = Path(tmp)
            recs = {
                "plate/ok.json": synthetic.base("plate", 0.002),
                "plate/off.json": synthetic.base(
                    "plate", 0.002, variant="no_artificial_stress", scored=False,
                    options={"artificial_stress": 0.0},
                    metrics=synthetic._metric("frequency_rel_error", 0.26, 0.05, "synthetic")),
            }
            synthetic.write(root / "results", recs)
            loaded = records.load_records(root / "results")
            self.assertTrue(all(r.passed for r in loaded))
            html = write_report(loaded, root / "report", source=root / "results").read_text()
            summary = html.split('<section id="summary">')[1].split("</section>")[0]
            self.assertIn("study: fail", html)
            self.assertIn("1 passed</span>", html)
            self.assertIn("0 failed</span> 1 unscored studies", html)
            stability = html.split('<section id="stability">')[1].split("</section>")[0]
            self.assertIn("frequency_rel_error = 0.26", stability)
