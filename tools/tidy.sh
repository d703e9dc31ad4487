#!/usr/bin/env bash
# Runs clang-tidy-14 with the project's short check list (.clang-tidy: bugs and needless copies)
# over every source of core/, ui/ and app/, using the compile commands of a configured and built
# tree (the moc/uic outputs must exist). Any finding fails it.
#   tools/tidy.sh [BUILD_DIR]      default build/release
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
[ -f "$build/compile_commands.json" ] || { echo "tidy: no $build/compile_commands.json (build first)" >&2; exit 2; }
jobs=$(nproc 2>/dev/null || echo 2)
# find, not git ls-files: CI's fresh root gets the sources without .git.
mapfile -t files < <(find core ui app -name '*.cpp' | sort)
[ ${#files[@]} -gt 0 ] || { echo "tidy: no sources found" >&2; exit 2; }
start=$(date +%s)
log=$(mktemp "${TMPDIR:-/tmp}/fatek-tidy.XXXXXX")
trap 'rm -f "$log"' EXIT
status=0
# Batches go to a temporary folder (tools/tidybatch.py also drops the precompiled header).
db=$(mktemp -d "${TMPDIR:-/tmp}/fatek-tidy-db.XXXXXX")
trap 'rm -f "$log"; rm -rf "$db"' EXIT
# In batches of sources that share a compile command (tools/tidybatch.py says why and how).
python3 tools/tidybatch.py "$build/compile_commands.json" "$db" "$jobs" "${FATEK_TIDY_BATCH:-8}" "${files[@]}" >"$log" 2>&1 || status=$?
# Only our own findings: "file:line:col: warning|error: text [check]" (colour codes removed).
findings=$(sed 's/\x1b\[[0-9;]*m//g' "$log" | grep -E '^/.*:[0-9]+:[0-9]+: (warning|error): ' | sort -u || true)
count=$(printf '%s' "$findings" | grep -c . || true)
echo "tidy: ${#files[@]} files, $count findings, $(($(date +%s) - start)) s"
grep "^tidy: .* clang-tidy runs" "$log" || true
if [ "$count" -ne 0 ] || [ "$status" -ne 0 ]; then
    [ -n "$findings" ] && printf '%s\n' "$findings" || tail -40 "$log"
    exit 1
fi
