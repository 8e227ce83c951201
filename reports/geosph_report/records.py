"""Load and validate GeoSPH result records (one JSON object per verification run).

Every number in the report comes from these records; validation is strict so that a
malformed record stops the report with a message naming the file and the field.
"""
import json
import math
from dataclasses import dataclass, field
from pathlib import Path

LEVELS = ("quick", "full", "convergence")
ROLES = ("simulation", "experiment", "analytical", "dem")
# Options that mark a run as relying on a stabilisation device (listed in the stability table).
STABILISATION_KEYS = frozenset({
    "artificial_stress", "density_diffusion", "tensile_correction", "kernel_gradient_correction",
})


class RecordError(ValueError):
    """A result record (or the results directory) is missing, unreadable or malformed."""


@dataclass
class Record:
    """One validated result record; optional fields default to None / empty."""
    path: str
    case: str
    level: str
    dx: float
    particles: int
    metrics: list
    stable: bool
    steps: int
    wall_s: float
    particle_steps_per_s: float
    threads: int
    dimension: int = None
    title: str = None
    reference: dict = None
    variant: str = None
    expected_order: float = None
    failure: dict = None
    options: dict = field(default_factory=dict)
    series: list = field(default_factory=list)
    snapshot: dict = None
    relpath: str = None  # path relative to the results directory, for display
    scored: bool = True  # False: a study run (e.g. a stabilisation switched off), reported, not judged
    provenance: dict = None  # solver_version, compiler, build_flags, threads, scene_hash
    wall_treatment: str = None  # the scene's walls.type (dummy, repulsive, morris, ghost), if it has walls
    wall_particles: int = None
    wall_comparison: bool = False  # run with a treatment other than the scene's own (geosph verify --walls)
    wall_treatment_open: str = None  # why that treatment misses the tolerance today (case.json open_wall_treatments)

    @property
    def passed(self):
        """True when the run was stable and every metric passed; a study run never fails."""
        if not self.scored:
            return True
        return self.stable and all(m["passed"] for m in self.metrics)

    @property
    def first(self):
        """The first metric: the one used for convergence and speed-vs-error."""
        return self.metrics[0]

    @property
    def label(self):
        """Short human label: variant and resolution."""
        return f"{self.variant or 'default'} dx={self.dx:.3g}"


_KINDS = {
    "number": lambda v: isinstance(v, (int, float)) and not isinstance(v, bool),
    "integer": lambda v: isinstance(v, int) and not isinstance(v, bool),
    "string": lambda v: isinstance(v, str),
    "boolean": lambda v: isinstance(v, bool),
    "object": lambda v: isinstance(v, dict),
    "list": lambda v: isinstance(v, list),
}


class _Checker:
    """Field accessor that raises RecordError naming the file and the dotted field path."""

    def __init__(self, path):
        self.path = path

    def fail(self, msg):
        raise RecordError(f"{self.path}: {msg}")

    def get(self, obj, key, kind, where="", required=True, nullable=False):
        name = where + key
        if key not in obj or (obj[key] is None and not nullable):
            if required:
                self.fail(f"missing field '{name}' ({kind})")
            return None
        val = obj[key]
        if val is not None and not _KINDS[kind](val):
            self.fail(f"field '{name}' must be a {kind}, got {json.dumps(val)[:60]}")
        return val

    def numbers(self, obj, key, where):
        vals = self.get(obj, key, "list", where)
        if not all(_KINDS["number"](v) for v in vals):
            self.fail(f"field '{where}{key}' must be a list of numbers")
        return [float(v) for v in vals]


def _metric(c, m, i):
    where = f"metrics[{i}]."
    if not isinstance(m, dict):
        c.fail(f"field 'metrics[{i}]' must be an object")
    return {
        "name": c.get(m, "name", "string", where),
        "value": c.get(m, "value", "number", where, nullable=True),  # null: not computable (blow-up)
        "tolerance": c.get(m, "tolerance", "number", where),
        "passed": c.get(m, "passed", "boolean", where),
        "why_tolerance": c.get(m, "why_tolerance", "string", where, required=False) or "",
    }


def _series(c, s, i):
    where = f"series[{i}]."
    if not isinstance(s, dict):
        c.fail(f"field 'series[{i}]' must be an object")
    out = {"name": c.get(s, "name", "string", where),
           "role": c.get(s, "role", "string", where),
           "x": c.numbers(s, "x", where), "y": c.numbers(s, "y", where),
           "xlabel": c.get(s, "xlabel", "string", where, required=False) or "",
           "ylabel": c.get(s, "ylabel", "string", where, required=False) or "",
           "plot": c.get(s, "plot", "string", where, required=False) or "main"}
    if out["role"] not in ROLES:
        c.fail(f"field '{where}role' must be one of {', '.join(ROLES)}, got {out['role']!r}")
    if len(out["x"]) != len(out["y"]):
        c.fail(f"fields '{where}x' and '{where}y' differ in length")
    return out


def _snapshot(c, s):
    if s is None:
        return None
    where = "snapshot."
    out = {"x": c.numbers(s, "x", where), "y": c.numbers(s, "y", where),
           "values": c.numbers(s, "values", where),
           "field": c.get(s, "field", "string", where),
           "units": c.get(s, "units", "string", where, required=False) or ""}
    if not len(out["x"]) == len(out["y"]) == len(out["values"]):
        c.fail("fields 'snapshot.x', 'snapshot.y', 'snapshot.values' differ in length")
    return out


def parse_record(obj, path="<record>"):
    """Validate one decoded JSON object and return a Record (raises RecordError)."""
    c = _Checker(path)
    if not isinstance(obj, dict):
        c.fail("a result record must be a JSON object")
    res = c.get(obj, "resolution", "object")
    metrics = c.get(obj, "metrics", "list")
    if not metrics:
        c.fail("field 'metrics' must hold at least one metric")
    rec = Record(
        path=str(path),
        case=c.get(obj, "case", "string"),
        level=c.get(obj, "level", "string"),
        dx=float(c.get(res, "dx", "number", "resolution.")),
        particles=c.get(res, "particles", "integer", "resolution."),
        dimension=c.get(res, "dimension", "integer", "resolution.", required=False),
        metrics=[_metric(c, m, i) for i, m in enumerate(metrics)],
        stable=c.get(obj, "stable", "boolean"),
        steps=c.get(obj, "steps", "integer"),
        wall_s=float(c.get(obj, "wall_s", "number")),
        particle_steps_per_s=float(c.get(obj, "particle_steps_per_s", "number")),
        threads=c.get(obj, "threads", "integer"),
        title=c.get(obj, "title", "string", required=False),
        reference=c.get(obj, "reference", "object", required=False),
        variant=c.get(obj, "variant", "string", required=False),
        expected_order=c.get(obj, "expected_order", "number", required=False),
        failure=c.get(obj, "failure", "object", required=False),
        options=c.get(obj, "options", "object", required=False) or {},
        series=[_series(c, s, i) for i, s in
                enumerate(c.get(obj, "series", "list", required=False) or [])],
        snapshot=_snapshot(c, c.get(obj, "snapshot", "object", required=False)),
        scored=c.get(obj, "scored", "boolean", required=False) is not False,
        provenance=c.get(obj, "provenance", "object", required=False),
        wall_treatment=c.get(obj, "wall_treatment", "string", required=False),
        wall_particles=c.get(res, "wall_particles", "integer", "resolution.", required=False),
        wall_comparison=c.get(obj, "wall_comparison", "boolean", required=False) is True,
        wall_treatment_open=c.get(obj, "wall_treatment_open", "string", required=False),
    )
    if rec.level not in LEVELS:
        c.fail(f"field 'level' must be one of {', '.join(LEVELS)}, got {rec.level!r}")
    if not (rec.dx > 0 and math.isfinite(rec.dx)):
        c.fail(f"field 'resolution.dx' must be positive, got {rec.dx}")
    return rec


def load_records(results_dir):
    """Read every *.json under results_dir (recursively), sorted by path."""
    root = Path(results_dir)
    if not root.is_dir():
        raise RecordError(f"{root}: results directory does not exist")
    paths = sorted(root.rglob("*.json"))
    if not paths:
        raise RecordError(f"{root}: no result records (*.json) found")
    out = []
    for p in paths:
        try:
            obj = json.loads(p.read_text(encoding="utf-8"))
        except (OSError, UnicodeDecodeError, json.JSONDecodeError) as e:
            raise RecordError(f"{p}: cannot read JSON: {e}") from None
        rec = parse_record(obj, p)
        rec.relpath = str(p.relative_to(root))
        out.append(rec)
    return sorted(out, key=display_order)


def display_order(r):
    """Sort key: case, default variant first, then variant name, coarse to fine, path."""
    return (r.case, r.variant is not None, r.variant or "", -r.dx, r.path)


def group_by(records, key):
    """Group records into a dict {key(record): [records]} preserving first-seen order."""
    groups = {}
    for r in records:
        groups.setdefault(key(r), []).append(r)
    return groups


def representative(recs):
    """The record shown for a case: default variant, with plots, finest dx, level quick first."""
    pool = [r for r in recs if r.variant is None] or recs
    pool = [r for r in pool if r.series or r.snapshot] or pool
    return min(pool, key=lambda r: (r.dx, LEVELS.index(r.level), r.path))


def cheapest_passing(recs):
    """The passing record with the smallest wall time, or None."""
    ok = [r for r in recs if r.passed]
    return min(ok, key=lambda r: r.wall_s) if ok else None


def stability_records(records):
    """Hard cases: records using a stabilisation option, or of a case with several variants (the
    boundary comparison's runs with another wall treatment have their own section)."""
    own = [r for r in records if not r.wall_comparison]
    variants = {case: {r.variant for r in rs} for case, rs in group_by(own, lambda r: r.case).items()}
    return [r for r in own
            if STABILISATION_KEYS & set(r.options) or len(variants[r.case]) > 1]


def wall_comparisons(records):
    """{case: records} for the cases whose records use two or more wall treatments."""
    out = {}
    for case, recs in group_by([r for r in records if r.wall_treatment], lambda r: r.case).items():
        if len({r.wall_treatment for r in recs}) > 1:
            out[case] = recs
    return out


def scene_variant(r):
    """The record's variant without the boundary comparison's walls=T token ("" for the case's own)."""
    return " ".join(t for t in (r.variant or "").split() if not t.startswith("walls="))


def step_cost(r):
    """Wall time per step [s], or None without steps."""
    return r.wall_s / r.steps if r.steps > 0 else None
