#!/usr/bin/env bash
# Installs the Debian dependencies (if missing), configures and builds GeoSPH in build/ (Release).
# Usage: bash ci/build.sh            (BUILD_DIR and JOBS may be set in the environment)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
JOBS="${JOBS:-$(nproc)}"
bash "$ROOT/ci/install-deps.sh"
cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DGEOSPH_BUILD_TESTS=ON -DGEOSPH_BUILD_BENCHMARKS=ON
cmake --build "$BUILD_DIR" -j "$JOBS"
