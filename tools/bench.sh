#!/usr/bin/env bash
# Builds the release preset and runs the performance bench (docs/performance.md).
#   tools/bench.sh            full run (about 2-3 minutes on 2 cores)
#   tools/bench.sh --quick    short run; other options go to fatek-bench (--help, --only 1,3)
# Prints one table, then one "RESULT <name> <value> <target> PASS|FAIL" line per target.
# Exit status: 0 when every target passes.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
export CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-$jobs}
cmake --preset release >/dev/null
cmake --build build/release --target fatek-bench
QT_QPA_PLATFORM=offscreen exec build/release/bench/fatek-bench "$@"
