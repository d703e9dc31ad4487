#!/usr/bin/env bash
# Builds and runs every test: the release build (GCC 12) and clang-tidy on it, then the whole
# suite again under AddressSanitizer + UndefinedBehaviorSanitizer built with clang-14, again under
# ThreadSanitizer (GCC 12), the install test of the packages, and a short run of each fuzz target
# (clang-14), then the Windows part (tools/windows/ci.sh: the cross build, the zip and the
# installer, the suite under Wine) when a cross-built prefix for its recipe is at hand
# (FATEK_WINDOWS=0 leaves it out; without a prefix it says in red why it is skipped). Prints each
# stage's wall time and the total; exits non-zero on the first failure. clang-tidy checks only
# the sources that differ from the last full run (tools/tidy.sh --changed).
#
# The test suites mostly wait (timers, sockets, child processes) and leave a core idle. Work that
# no suite needs yet (clang-tidy, the tsan build, the fuzz build) runs meanwhile in a background
# lane at the lowest priority (nice 19): the suites get the CPU first, the lane what they leave.
# A lane's stages print when the lane is joined, each with its own wall time (overlapping the
# foreground's).
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/stage.sh
stage "installing packages" tools/install-deps.sh
windows=0
if [ "${FATEK_WINDOWS:-1}" != 0 ]; then
    win_status=0
    tools/windows/ci.sh check || win_status=$?
    case $win_status in
    0) windows=1 ;;
    3) ;;
    # (The recipe needs apt's source index: a mirror without deb-src skips the part, loudly,
    # rather than failing the Linux checks.)
    *) printf '\033[1;31m== Windows: SKIPPED: tools/windows/ci.sh check failed (status %s)\033[0m\n' "$win_status" ;;
    esac
fi
jobs=$(nproc 2>/dev/null || echo 2)
export CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-$jobs}
export CTEST_PARALLEL_LEVEL=${CTEST_PARALLEL_LEVEL:-$jobs}
source tools/ccache-env.sh
export ccache_args_text="${ccache_args[*]}"
lanes=$(mktemp -d "${TMPDIR:-/tmp}/fatek-test-lanes.XXXXXX")
lane_pid=""
trap '[ -z "$lane_pid" ] || kill -- -"$lane_pid" 2>/dev/null || true; rm -rf "$lanes"' EXIT

# lane_start NAME COMMAND...: runs COMMAND (a function of this script) niced in the background,
# in its own process group, output to its log.
lane_start() {
    local name=$1
    shift
    echo "== lane: $name started in the background (nice 19)"
    set -m
    nice -n 19 bash -c "$(declare -f stage configure_preset); set -euo pipefail; $*" >"$lanes/$name.log" 2>&1 &
    lane_pid=$!
    set +m
    lane_name=$name
}
# lane_join: waits for the lane, prints its log, fails if it failed.
lane_join() {
    local start=$SECONDS status=0
    wait "$lane_pid" || status=$?
    lane_pid=""
    cat "$lanes/$lane_name.log"
    echo "== lane: $lane_name joined (waited $((SECONDS - start)) s for it)"
    return "$status"
}
configure_preset() { cmake --preset "$1" $ccache_args_text >/dev/null; }

stage "release configure" configure_preset release
stage "release build" cmake --build --preset release
lane_start "tidy+tsan-build" 'stage "clang-tidy" tools/tidy.sh --changed build/release &&
    stage "tsan configure" configure_preset tsan && stage "tsan build" cmake --build --preset tsan'
stage "release tests" ctest --preset release
stage "asan configure" configure_preset asan
stage "asan build" cmake --build --preset asan
stage "asan tests" ctest --preset asan
# Install test of the .deb/.tar.gz built from the release build (see docs/packaging.md); here, while
# the lane still builds, rather than at the end.
stage "package install test" tools/package-test.sh
lane_join
# The Windows cross build (about 20 core-minutes) takes what the TSan suite leaves.
lane_start "fuzz+windows-build" 'export FUZZ_BUILD_ONLY=1; stage "fuzz build" tools/fuzz.sh' \
    "$([ $windows = 0 ] || echo '&& tools/windows/ci.sh build')"
stage "tsan tests" ctest --preset tsan
lane_join
# Each fuzz target briefly on the seed corpus (long runs: docs/reliability.md).
stage "fuzz smoke" tools/fuzz.sh "${FATEK_FUZZ_SECONDS:-10}"
[ $windows = 0 ] || tools/windows/ci.sh test
rm -rf "$lanes"
stage_total "tools/test.sh"
