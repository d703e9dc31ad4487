#!/usr/bin/env bash
# Installs what is missing, builds what the demo runs (fatek-studio, fatek-cli and fatek-sim with
# their libraries, release preset; not the tests or the bench) and opens the demo: the GUI against
# the embedded PLC simulator. Without a display it runs the CLI monitor instead. Each stage prints
# a line and, at its end, its time.
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/stage.sh
stage "installing packages" tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
source tools/ccache-env.sh
stage "configuring" cmake --preset release "${ccache_args[@]}" >/dev/null
# Ninja's progress line, as a new user reads it: "building 12 of 187 (34 s)".
export NINJA_STATUS="== building %f of %t (%es) "
stage "building fatek-studio, fatek-cli, fatek-sim" \
    cmake --build --preset release -j "$jobs" --target fatek-studio fatek-cli fatek-sim
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] || [ "${QT_QPA_PLATFORM:-}" = offscreen ]; then
    printf '== stage: starting fatek-studio --demo (%dm%02ds since tools/demo.sh started)\n' $((SECONDS / 60)) $((SECONDS % 60))
    exec build/release/app/fatek-studio/fatek-studio --demo "$@"
fi
printf '== stage: starting the simulator through fatek-cli, no display found (Ctrl-C to stop; %dm%02ds since tools/demo.sh started)\n' \
    $((SECONDS / 60)) $((SECONDS % 60))
exec build/release/app/fatek-cli/fatek-cli --sim monitor R0 R1 Y0 X0..X7 DR10 --interval 500 "$@"
