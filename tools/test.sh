#!/usr/bin/env bash
# Builds and runs every test: the release build (GCC 12) and clang-tidy on it, then the whole
# suite again under AddressSanitizer + UndefinedBehaviorSanitizer built with clang-14, again under
# ThreadSanitizer (GCC 12), the install test of the packages, and a short run of each fuzz target (clang-14).
# Prints each stage's wall time and the total; exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/stage.sh
stage "installing packages" tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
export CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-$jobs}
export CTEST_PARALLEL_LEVEL=${CTEST_PARALLEL_LEVEL:-$jobs}
source tools/ccache-env.sh
# One preset: configure, build, then its suite, each timed.
suite() {
    stage "$1 configure" cmake --preset "$1" "${ccache_args[@]}"
    stage "$1 build" cmake --build --preset "$1"
    stage "$1 tests" ctest --preset "$1"
}
suite release
# clang-tidy's short check list (.clang-tidy) on the release build's compile commands.
stage "clang-tidy" tools/tidy.sh build/release
suite asan
suite tsan
# Install test of the .deb/.tar.gz built from the release build (see docs/packaging.md).
stage "package install test" tools/package-test.sh
# Builds the fuzz targets and runs each briefly on the seed corpus (long runs: docs/reliability.md).
stage "fuzz smoke" tools/fuzz.sh "${FATEK_FUZZ_SECONDS:-10}"
stage_total "tools/test.sh"
