#!/usr/bin/env bash
# CTest's emulator for the Windows build (CMAKE_CROSSCOMPILING_EMULATOR of the windows-cross
# preset): runs a Windows program under Wine with its standard error in a file, shown once the
# program has ended; standard output goes straight through (ref_check_sim reads fatek-sim's).
#   tools/windows/wine-run.sh PROGRAM.exe [ARGS...]
# Why: Wine gives every process a Windows program starts (each fatek-cli.exe a test runs) the
# program's own Unix standard error as its fd 2. CTest waits until a test's output is closed, so
# a child still going (under load) held tst_delivery past CTest's timeout although it had passed
# (2 of 3 loaded suite runs, 2026-11-28). A file has no reader to keep waiting.
set -u
err=$(mktemp "${TMPDIR:-/tmp}/wine-run.XXXXXX")
# In the background so that a TERM or INT (ref_check_sim stopping fatek-sim, CTest's timeout)
# reaches the program as it did when CTest ran wine itself; stdin stays the caller's.
wine "$@" 2>"$err" <&0 &
pid=$!
trap 'kill -TERM "$pid" 2>/dev/null' TERM
trap 'kill -INT "$pid" 2>/dev/null' INT
status=0
wait "$pid" || status=$?
# A trapped signal ends the wait early: wait for the program itself.
while kill -0 "$pid" 2>/dev/null; do
    status=0
    wait "$pid" || status=$?
done
cat "$err" >&2
# The trace of a child that outlived the program: who still has the file open.
for p in $(pgrep -f '\.exe' || true); do
    for fd in /proc/"$p"/fd/*; do
        if [ "$(readlink "$fd" 2>/dev/null)" = "$err" ]; then
            echo "== wine-run: after $(basename "$1") ended, pid $p still held its standard error:" \
                "$(ps -o etimes=,args= -p "$p" | cut -c1-100)" >&2
            break
        fi
    done
done
rm -f "$err"
exit "$status"
