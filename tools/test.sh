#!/usr/bin/env bash
# Builds and runs every test: the release build, then the whole suite again under
# AddressSanitizer + UndefinedBehaviorSanitizer, and again under ThreadSanitizer.
# Exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
export CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-$jobs}
export CTEST_PARALLEL_LEVEL=${CTEST_PARALLEL_LEVEL:-$jobs}
cmake --workflow --preset release
cmake --workflow --preset asan
cmake --workflow --preset tsan
# Install test of the .deb/.tar.gz built from the release build (see docs/packaging.md).
tools/package-test.sh
# EXTRA CI STEPS (keep this marker line)
