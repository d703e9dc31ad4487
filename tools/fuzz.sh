#!/usr/bin/env bash
# Builds the libFuzzer targets with clang and runs each for SECONDS (default 60), seeded with the
# frames of tests/data/vectors.json. Findings land in build/fuzz/findings/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
command -v clang++-14 >/dev/null || { echo "needs clang-14 and libclang-rt-14-dev (apt-get install clang-14 libclang-rt-14-dev)"; exit 2; }
cmake -S . -B build/fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DFATEK_FUZZ=ON -DFATEK_BUILD_TESTS=OFF -DFATEK_BUILD_BENCH=OFF >/dev/null
cmake --build build/fuzz --target fuzz_facon fuzz_binary fuzz_address
python3 - <<'PY'
import json, os
v = json.load(open("tests/data/vectors.json"))
for proto in ("facon", "binary"):
    d = f"build/fuzz/corpus/{proto}"; os.makedirs(d, exist_ok=True)
    for i, f in enumerate(v[proto]):
        for kind in ("query", "response"):
            s = f[kind]
            raw = bytes.fromhex(s) if proto == "binary" else s.replace("<STX>", "\x02").replace("<ETX>", "\x03").encode()
            open(f"{d}/{i}-{kind}", "wb").write(b"\x00" + raw)  # first byte: chunk size selector
d = "build/fuzz/corpus/address"; os.makedirs(d, exist_ok=True)
for i, t in enumerate(["R12", "r12", "DWM0", "X16", "D00012", "WY8", "DR15", "DRT9998", "F100"]):
    open(f"{d}/{i}", "w").write(t)
PY
mkdir -p build/fuzz/findings
for t in facon binary address; do
    echo "== fuzz_$t for ${seconds}s"
    build/fuzz/fuzz/fuzz_$t -max_total_time="$seconds" -print_final_stats=1 \
        -artifact_prefix=build/fuzz/findings/$t- build/fuzz/corpus/$t 2>&1 | tail -12
done
