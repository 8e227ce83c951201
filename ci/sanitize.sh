#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer pass (CMake preset "sanitize", build-sanitize/): builds
# geosph and the unit tests with -fsanitize=address,undefined, runs the unit tests and two small
# scenes (a fluid and a two-phase one, 200 steps each). Any sanitizer report fails the script.
# Run by CI (.ci/run) after the test command; by hand: bash ci/sanitize.sh
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${SANITIZE_BUILD_DIR:-$ROOT/build-sanitize}"
JOBS="${JOBS:-$(nproc)}"
bash "$ROOT/ci/install-deps.sh"
cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGEOSPH_SANITIZE=ON -DGEOSPH_BUILD_TESTS=ON \
      -DGEOSPH_BUILD_BENCHMARKS=OFF
cmake --build "$BUILD_DIR" -j "$JOBS" --target geosph geosph_unit_tests
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:halt_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# one OpenMP thread per test while the tests run side by side (ci/test.sh says why)
OMP_NUM_THREADS=1 ctest --test-dir "$BUILD_DIR" -L unit --output-on-failure -j "$JOBS"
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
for case in dam_break_2d terzaghi_consolidation; do
  "$BUILD_DIR/solver/geosph" --threads 2 run "$ROOT/verification/cases/$case/scene.json" --out "$OUT/$case" \
      --stop-after-steps 200 --quiet || [ $? -eq 4 ]   # 4: stopped after 200 steps with a checkpoint
  "$BUILD_DIR/solver/geosph" --threads 2 run "$ROOT/verification/cases/$case/scene.json" --out "$OUT/$case" \
      --restart "$OUT/$case" --stop-after-steps 250 --quiet || [ $? -eq 4 ]
done
echo "sanitize: unit tests and 2 scenes clean under ASan + UBSan"
