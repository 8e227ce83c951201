#!/usr/bin/python3
"""Build the GeoSPH V&V report from result records.

Usage: generate_report.py RESULTS_DIR --out REPORT_DIR

Reads every *.json result record under RESULTS_DIR (recursively) and writes
REPORT_DIR/index.html with PNG figures beside it. Exits 2 with a message naming the
file and field when RESULTS_DIR has no records or a record is malformed.
"""
import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from geosph_report.html import write_report  # noqa: E402
from geosph_report.records import RecordError, load_records  # noqa: E402


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("results_dir", help="directory holding *.json result records (searched recursively)")
    ap.add_argument("--out", required=True, help="report directory to write (created if needed)")
    args = ap.parse_args(argv)
    try:
        records = load_records(args.results_dir)
    except RecordError as e:
        print(f"generate_report: error: {e}", file=sys.stderr)
        return 2
    index = write_report(records, args.out, source=args.results_dir)
    print(index)
    return 0


if __name__ == "__main__":
    sys.exit(main())
