#!/usr/bin/env bash
# Builds and runs every test: the release build (GCC 12) and clang-tidy on it, then the whole
# suite again under AddressSanitizer + UndefinedBehaviorSanitizer built with clang-14, again under
# ThreadSanitizer (GCC 12), the install test of the packages, and a short run of each fuzz target (clang-14).
# Exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
export CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-$jobs}
export CTEST_PARALLEL_LEVEL=${CTEST_PARALLEL_LEVEL:-$jobs}
cmake --workflow --preset release
# clang-tidy's short check list (.clang-tidy) on the release build's compile commands.
tools/tidy.sh build/release
cmake --workflow --preset asan
cmake --workflow --preset tsan
# Install test of the .deb/.tar.gz built from the release build (see docs/packaging.md).
tools/package-test.sh
# Builds the fuzz targets and runs each briefly on the seed corpus (long runs: docs/reliability.md).
tools/fuzz.sh "${FATEK_FUZZ_SECONDS:-10}"
