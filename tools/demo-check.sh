#!/usr/bin/env bash
# CI check of the README's demo command: runs tools/demo.sh as a user would (it installs, builds
# and, with no display, shows the simulator through the CLI monitor), lets the values run for
# SECONDS (default 6), stops it with Ctrl-C (SIGINT) and checks that live values arrived: at least
# five cycles in which the demo ladder's counter R0 and sine R1 keep changing.
#   tools/demo-check.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-6}
log=$(mktemp "${TMPDIR:-/tmp}/fatek-demo-check.XXXXXX")
# Started in the background without job control, the demo inherits an ignored SIGINT: fatek-cli
# installs its own handler, since a Ctrl-C must stop it however it was started.
env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM tools/demo.sh >"$log" 2>&1 &
demo=$!
trap 'kill -INT "$demo" 2>/dev/null || true; rm -f "$log"' EXIT

# The first run installs and builds: wait for the monitor's first value line, however long that is.
start=$SECONDS
until grep -qE '^1 +[0-9:.]+ ' "$log"; do
    if ! kill -0 "$demo" 2>/dev/null; then
        tail -40 "$log"
        echo "demo-check: FAIL: tools/demo.sh ended before showing any value" >&2
        exit 1
    fi
    sleep 1
done
first=$((SECONDS - start))
sleep "$seconds"
kill -INT "$demo"
# A clean stop takes well under a second; give it 15 s before calling it hung.
for _ in $(seq 150); do
    kill -0 "$demo" 2>/dev/null || break
    sleep 0.1
done
if kill -0 "$demo" 2>/dev/null; then
    kill -KILL "$demo" 2>/dev/null || true
    echo "demo-check: FAIL: the monitor kept running 15 s after Ctrl-C" >&2
    exit 1
fi
rc=0
wait "$demo" || rc=$?
grep '^== stage' "$log" || true
printf 'demo-check: first live value %dm%02ds after tools/demo.sh started\n' $((first / 60)) $((first % 60))
sed -n '/^cycle /,$p' "$log"
echo "tools/demo.sh ended with status $rc after Ctrl-C"

# Columns: cycle time R0 R1 ...; a value line starts with its cycle number.
awk -v seconds="$seconds" '
    $1 ~ /^[0-9]+$/ { cycles++; r0[$3] = 1; r1[$4] = 1 }
    END {
        n0 = length(r0); n1 = length(r1)
        printf "demo-check: %d cycles in %d s, %d distinct R0 values, %d distinct R1 values\n", cycles, seconds, n0, n1
        if (cycles < 5 || n0 < 3 || n1 < 3) { print "demo-check: FAIL: the values did not arrive live" > "/dev/stderr"; exit 1 }
    }' "$log"
case $rc in
0 | 130) echo "demo-check: PASS" ;;
*)
    echo "demo-check: FAIL: the monitor did not stop cleanly on Ctrl-C (status $rc)" >&2
    exit 1
    ;;
esac
