#!/usr/bin/env bash
# The main job: installs dependencies, builds, runs the whole verification catalogue at the given
# level (default quick) and writes the HTML report.
#   bash ci/run-catalogue.sh [quick|full]     -> results/<level>/*.json and report/index.html
# Exits non-zero if any case failed its tolerance or went unstable (the report is still written
# and marks the failing cases).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
LEVEL="${1:-quick}"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
RESULTS="${RESULTS:-$ROOT/results/$LEVEL}"
REPORT="${REPORT:-$ROOT/report}"
bash "$ROOT/ci/build.sh"
rm -rf "$RESULTS"
status=0
"$BUILD_DIR/solver/geosph" verify --level "$LEVEL" --walls all --out "$RESULTS" || status=$?
PYTHON=/usr/bin/python3
[ -x "$PYTHON" ] || PYTHON=python3
"$PYTHON" "$ROOT/reports/generate_report.py" "$RESULTS" --out "$REPORT"
echo "report: $REPORT/index.html"
exit $status
