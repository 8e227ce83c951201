#!/usr/bin/env bash
# The test command: installs dependencies, builds, and runs the default test set (unit tests,
# report-generator tests and the verification catalogue at its quick level). CI (.ci/run) runs the
# sanitizer pass (ci/sanitize.sh) after it. Heavier studies carry the ctest label `convergence` and
# are excluded here; run them with
#   ctest --test-dir build -L convergence
# The soak test (10^6 steps: constant memory, readable output at every moment) has the label `soak`:
#   ctest --test-dir build -L soak
# The boundary comparison (each case with every other wall treatment its case.json lists) has the
# label `walls`:
#   ctest --test-dir build -L walls
# Catalogue cases that fail today, each tracked by an open issue, carry the label `open` (in their
# case.json "labels"; listed in the README); the main job (ci/run-catalogue.sh) still runs them
# and the report marks them failing. Run them with
#   ctest --test-dir build -L open
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
bash "$ROOT/ci/build.sh"
# The tests run side by side, one per core, each on one OpenMP thread (a test that checks thread-count
# independence sets its own). Two processes each spinning two OpenMP threads on two cores wait at every
# barrier (hydrostatic_long_time: 116 s alone, 505 s so); one thread per test: 12.3 min for the gate on
# 2 cores, against 17.2 min for the tests one after another on two threads each.
OMP_NUM_THREADS=1 ctest --test-dir "$BUILD_DIR" -LE 'convergence|open|soak|walls' --output-on-failure \
  -j "$(nproc)"
