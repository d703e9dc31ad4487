#!/usr/bin/env bash
# Installs what is missing, builds what the demo runs and opens it: with a display the GUI
# (fatek-studio --demo, against its embedded PLC simulator), without one the CLI monitor
# (fatek-cli --sim). Only that program and its libraries are built (release preset), not the
# tests, the bench or the other programs: tools/test.sh builds the rest. Each stage prints a line
# and, at its end, its time.
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/stage.sh
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] || [ "${QT_QPA_PLATFORM:-}" = offscreen ]; then
    program=fatek-studio
    run=(build/release/app/fatek-studio/fatek-studio --demo "$@")
else
    program=fatek-cli
    run=(build/release/app/fatek-cli/fatek-cli --sim monitor R0 R1 Y0 X0..X7 DR10 --interval 500 "$@")
fi
stage "installing packages" tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
source tools/ccache-env.sh
configure() { cmake --preset release "${ccache_args[@]}" >/dev/null; }
stage "configuring" configure
# Ninja's progress line, as a new user reads it: "building 12 of 187 (34 s)".
export NINJA_STATUS="== building %f of %t (%es) "
stage "building $program" cmake --build --preset release -j "$jobs" --target "$program"
if [ "$program" = fatek-cli ]; then
    echo "No display found: showing the simulator through fatek-cli instead (Ctrl-C to stop)."
fi
printf '== stage: starting %s (%dm%02ds since tools/demo.sh started)\n' "$program" $((SECONDS / 60)) $((SECONDS % 60))
exec "${run[@]}"
