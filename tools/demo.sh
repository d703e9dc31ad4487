#!/usr/bin/env bash
# Installs what is missing, builds FATEK Studio (release preset) and opens the demo: the GUI
# against the embedded PLC simulator. Without a display it runs the CLI monitor instead.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake --preset release >/dev/null
cmake --build --preset release -j "$jobs"
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] || [ "${QT_QPA_PLATFORM:-}" = offscreen ]; then
    exec build/release/app/fatek-studio/fatek-studio --demo "$@"
fi
echo "No display found: showing the simulator through fatek-cli instead (Ctrl-C to stop)."
exec build/release/app/fatek-cli/fatek-cli --sim monitor R0 R1 Y0 X0..X7 DR10 --interval 500 "$@"
