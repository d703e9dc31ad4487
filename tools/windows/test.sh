#!/usr/bin/env bash
# Runs the Windows build (tools/windows/build.sh) under Wine: the Qt Test suite (offscreen
# platform) apart from the tests tools/windows/wine-skip.txt lists with their reasons, then the
# serial path: fatek-cli.exe on the Wine port COM5, one end of a socat pty pair (Wine maps COMn
# to the device dosdevices/comn points at), and the Linux fatek-sim on the other end.
# (fatek-sim.exe on a Wine COM port receives nothing: Wine's serial events on a pty do not reach
# a port that only waits to read; docs/windows.md.)
#   tools/windows/test.sh [CTEST ARGS...]
set -euo pipefail
cd "$(dirname "$0")/../.."
source tools/stage.sh
build=build/windows-cross
prefix=${FATEK_WIN_PREFIX:-$HOME/.cache/fatek-studio/qt6-mingw}
[ -f $build/CTestTestfile.cmake ] || { echo "no Windows build with tests in $build: run tools/windows/build.sh"; exit 2; }
export WINEPREFIX=${WINEPREFIX:-$PWD/$build/wine}
export WINEARCH=win64 WINEDEBUG=-all
# No Mono or Gecko download prompt: nothing here needs .NET or Wine's HTML engine.
export WINEDLLOVERRIDES="mscoree,mshtml="
unset DISPLAY
tmp=$(mktemp -d "${TMPDIR:-/tmp}/fatek-wine.XXXXXX")
cleanup() {
    [ -z "${socat_pid:-}" ] || kill "$socat_pid" 2>/dev/null || true
    [ -z "${sim_pid:-}" ] || kill "$sim_pid" 2>/dev/null || true
    wineserver -k 2>/dev/null || true
    rm -rf "$tmp"
}
trap cleanup EXIT

# One wineserver for the whole run (each test program would otherwise start its own); it
# refuses when one already serves this prefix, which is as good.
wineserver -p 2>/dev/null || true
stage "Wine: prefix" wineboot --init
gcc_dir=$(dirname "$(x86_64-w64-mingw32-g++-posix -print-file-name=libstdc++-6.dll)")
pthread_dir=$(dirname "$(x86_64-w64-mingw32-g++-posix -print-file-name=libwinpthread-1.dll)")
WINEPATH="$(winepath -w "$prefix/bin");$(winepath -w "$gcc_dir");$(winepath -w "$pthread_dir")"
QT_PLUGIN_PATH=$(winepath -w "$prefix/plugins")
export WINEPATH QT_PLUGIN_PATH QT_QPA_PLATFORM=offscreen

# The tests Wine cannot run: first column of each line that is not a comment.
skip=$({ grep -vE '^\s*(#|$)' tools/windows/wine-skip.txt || true; } | awk '{print $1}' | paste -sd'|')
echo "== not run under Wine (tools/windows/wine-skip.txt): ${skip//|/ }"
stage "Wine: test suite" ctest --test-dir $build -j "$(nproc 2>/dev/null || echo 2)" \
    --output-on-failure --timeout 300 ${skip:+-E "^($skip)\$"} "$@"

serial_test() {
    socat pty,raw,echo=0,link="$tmp/a" pty,raw,echo=0,link="$tmp/b" 2>"$tmp/socat.log" &
    socat_pid=$!
    for _ in $(seq 50); do [ -e "$tmp/a" ] && [ -e "$tmp/b" ] && break; sleep 0.1; done
    ln -sfn "$(readlink -f "$tmp/a")" "$WINEPREFIX/dosdevices/com5"
    [ -x build/release/app/fatek-sim/fatek-sim ] || {
        [ -f build/release/build.ninja ] || cmake --preset release >/dev/null
        cmake --build build/release --target fatek-sim >/dev/null
    }
    build/release/app/fatek-sim/fatek-sim --serial "$tmp/b" --serial-baud 19200 --serial-format 7E1 \
        --station 3 --verbose >"$tmp/sim.log" 2>&1 &
    sim_pid=$!
    sleep 1
    local out status=0
    out=$(wine $build/app/fatek-cli/fatek-cli.exe --serial COM5 --baud 19200 --parity even \
              --data 7 --stop 1 --station 3 write R100 1234 2>&1 &&
          wine $build/app/fatek-cli/fatek-cli.exe --serial COM5 --baud 19200 --parity even \
              --data 7 --stop 1 --station 3 read R100 2>&1) || status=$?
    echo "$out" | tr -d '\r'
    kill "$sim_pid" 2>/dev/null || true
    if [ $status -ne 0 ] || ! echo "$out" | tr -d '\r' | grep -qE '(^|[^0-9])1234([^0-9]|$)'; then
        echo "!! fatek-cli.exe did not read back 1234 over COM5 (status $status); fatek-sim said:"
        cat "$tmp/sim.log"
        return 1
    fi
}
stage "Wine: serial COM5 <-> fatek-sim on a pty" serial_test
stage_total "tools/windows/test.sh"
