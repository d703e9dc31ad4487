#!/usr/bin/env bash
# Builds the libFuzzer targets with clang and runs each for SECONDS (default 60), as many at once
# as there are cores, seeded with the frames of tests/data/vectors.json and sample watch lists.
#   tools/fuzz.sh [SECONDS] [TARGET...]      TARGET: facon binary address simquery watchlist
#                                            gatewaypayload (default all)
# Environment: FUZZ_BUILD_ONLY=1 (build, do not run), FUZZ_JOBS (targets at once; default the
# number of cores), FUZZ_BUILD (default build/fuzz), FUZZ_LOGS (directory for one log per target; default
# only the summary is printed). Findings land in $FUZZ_BUILD/findings/; the script exits 1 if any.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(facon binary address simquery watchlist gatewaypayload)
build=${FUZZ_BUILD:-build/fuzz}
command -v clang++-14 >/dev/null || { echo "needs clang-14 and libclang-rt-14-dev (apt-get install clang-14 libclang-rt-14-dev)"; exit 2; }
# Line tables only (-g1): a finding's stack names file and line; full debug info only costs time.
cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" \
      -DFATEK_FUZZ=ON -DFATEK_BUILD_TESTS=OFF -DFATEK_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j "$(nproc 2>/dev/null || echo 2)" --target $(printf 'fuzz_%s ' "${targets[@]}")
FUZZ_BUILD=$build python3 - <<'PY'
import json, os
b = os.environ["FUZZ_BUILD"]
v = json.load(open("tests/data/vectors.json"))
def raw(proto, s):
    return bytes.fromhex(s) if proto == "binary" else s.replace("<STX>", "\x02").replace("<ETX>", "\x03").encode()
for proto in ("facon", "binary"):
    d = f"{b}/corpus/{proto}"; os.makedirs(d, exist_ok=True)
    for i, f in enumerate(v[proto]):
        for kind in ("query", "response"):
            open(f"{d}/{i}-{kind}", "wb").write(b"\x00" + raw(proto, f[kind]))  # first byte: chunk size selector
# Simulator: the queries of both protocols (first byte: model and RUN/STOP), and both in one stream.
d = f"{b}/corpus/simquery"; os.makedirs(d, exist_ok=True)
both = b""
for proto in ("facon", "binary"):
    for i, f in enumerate(v[proto]):
        q = raw(proto, f["query"]); both += q
        open(f"{d}/{proto}-{i}", "wb").write(bytes([i % 4]) + q)
open(f"{d}/mixed", "wb").write(b"\x02" + both)
d = f"{b}/corpus/address"; os.makedirs(d, exist_ok=True)
for i, t in enumerate(["R12", "r12", "DWM0", "X16", "D00012", "WY8", "DR15", "DRT9998", "F100"]):
    open(f"{d}/{i}", "w").write(t)
# Watch lists: first byte 0 JSON, 1 CSV, 2 range text.
d = f"{b}/corpus/watchlist"; os.makedirs(d, exist_ok=True)
doc = {"format": "fatek-studio-watchlist", "version": 1, "tables": [
    {"name": "Main", "intervalMs": 500, "confirmWrites": True, "items": [
        {"address": "R100", "station": 1, "format": "signed", "swapWords": False, "name": "Tank level", "comment": "m"},
        {"address": "DR10", "station": 2, "format": "float", "swapWords": True, "name": "Flow"},
        {"address": "Y0", "format": "bool"}, {"address": "WX16", "format": "hex"}]},
    {"name": "Second", "intervalMs": 100, "items": [{"address": "D12"}]}]}
open(f"{d}/json-full", "wb").write(b"\x00" + json.dumps(doc, indent=1).encode())
open(f"{d}/json-min", "wb").write(b'\x00{"format":"fatek-studio-watchlist","version":1,"tables":[]}')
csvs = ["address,station,format,name,comment\nR100,1,signed,Tank,\"a, b\"\nDR10,2,float,Flow,x\n",
        "\ufeffname;address;comment\nPump;Y0;\"say \"\"hi\"\"\"\n# comment\n\nLevel;R100..R103;\n",
        "R100\nWY0..WY32\nX0,3,bool\n"]
for i, c in enumerate(csvs):
    open(f"{d}/csv-{i}", "wb").write(b"\x01" + c.encode())
for i, t in enumerate(["R100..R163", "WY0..WY32", "DR0..DR4", "R100..163", "R100"]):
    open(f"{d}/range-{i}", "wb").write(b"\x02" + t.encode())
# Gateway payloads: first byte 0 item, 1 write command, 2 status/reply, 3 message, 4 topic.
d = f"{b}/corpus/gatewaypayload"; os.makedirs(d, exist_ok=True)
err = {"id": "Joined", "args": ["R100", {"id": "MqttClosed", "args": ["mqtt://x"], "text": "Disconnected"}], "text": "R100: Disconnected"}
seeds = [(0, {"station": 1, "address": "R100", "name": "Tank", "format": "float", "swapWords": False,
              "value": 12.5, "text": "12.5", "words": [0, 16712], "quality": "good", "time": "2026-11-25T23:00:00.123Z"}),
         (0, {"station": 2, "address": "Y3", "format": "bit", "words": [1], "quality": "stale",
              "time": "2026-11-25T23:00:00.123Z", "error": err}),
         (1, {"value": "12.5", "format": "float", "swapWords": True, "id": "a1"}),
         (2, {"state": "down", "link": "TCP 127.0.0.1:500, FACON", "reason": err, "time": "2026-11-25T23:00:00.000Z"}),
         (2, {"id": "7", "ok": False, "station": 1, "address": "R100", "value": "5", "error": err}),
         (3, err)]
for i, (k, obj) in enumerate(seeds):
    open(f"{d}/json-{i}", "wb").write(bytes([k]) + json.dumps(obj).encode())
open(f"{d}/set-text", "wb").write(b"\x01 ON\n")
for i, t in enumerate(["fatek/line1/1/R100", "fatek/line1/3/WY16/set", "fatek/line1/status"]):
    open(f"{d}/topic-{i}", "wb").write(b"\x04" + t.encode())
PY
# FUZZ_BUILD_ONLY=1: build the targets and their corpus, run nothing (tools/test.sh builds them
# beside other work and runs them later).
[ "${FUZZ_BUILD_ONLY:-0}" = 1 ] && exit 0
mkdir -p "$build/findings"
[ -z "${FUZZ_LOGS:-}" ] || mkdir -p "$FUZZ_LOGS"
# A libFuzzer run uses one core: as many targets run at once as there are cores (FUZZ_JOBS), each
# for its full SECONDS; the summaries print in the targets' order.
jobs=${FUZZ_JOBS:-$(nproc 2>/dev/null || echo 2)}
logOf() {
    local log=${FUZZ_LOGS:+$FUZZ_LOGS/fuzz_$1.log}
    echo "${log:-$build/fuzz_$1.log}"
}
fuzzOne() {
    # -rss_limit_mb: the simulator holds a full PLC memory image per model; 2 GB is libFuzzer's default.
    "$build/fuzz/fuzz_$1" -max_total_time="$seconds" -print_final_stats=1 -timeout=10 \
        -artifact_prefix="$build/findings/$1-" "$build/corpus/$1" >"$(logOf "$1")" 2>&1
}
echo "== fuzzing ${targets[*]} for ${seconds}s each, $jobs at a time"
declare -A pids
for t in "${targets[@]}"; do
    while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do
        wait -n || true
    done
    fuzzOne "$t" &
    pids[$t]=$!
done
status=0
for t in "${targets[@]}"; do
    echo "== fuzz_$t for ${seconds}s"
    log=$(logOf "$t")
    if ! wait "${pids[$t]}"; then
        status=1
        echo "!! fuzz_$t found a problem: see $log and $build/findings/"
    fi
    grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb|Done [0-9]+ runs|ERROR" "$log" | head -5 || true
done
exit $status
