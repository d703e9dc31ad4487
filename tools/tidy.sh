#!/usr/bin/env bash
# Runs clang-tidy-14 with the project's short check list (.clang-tidy: bugs and needless copies)
# over every source of core/, ui/ and app/, using the compile commands of a configured and built
# tree (the moc/uic outputs must exist). Any finding fails it.
#   tools/tidy.sh [BUILD_DIR]            every source (default build/release)
#   tools/tidy.sh --record [BUILD_DIR]   every source, and when they pass, writes .ci/tidy-baseline
#                                        (commit it: CI's --changed runs compare with it)
#   tools/tidy.sh --changed [BUILD_DIR]  CI: only the sources whose compile command, text or
#                                        included headers differ from .ci/tidy-baseline; every
#                                        source when .clang-tidy, the presets, tidybatch.py or a
#                                        compiler changed, or the record is 100 commits old
#                                        (FATEK_TIDY_COMMITS, given by .ci/run; about ten
#                                        landings) - tools/tidyscope.py
set -euo pipefail
cd "$(dirname "$0")/.."
mode=full
case ${1:-} in
--record | --changed) mode=${1#--}; shift ;;
esac
build=${1:-build/release}
baseline=.ci/tidy-baseline
[ -f "$build/compile_commands.json" ] || { echo "tidy: no $build/compile_commands.json (build first)" >&2; exit 2; }
jobs=$(nproc 2>/dev/null || echo 2)
# find, not git ls-files: CI's fresh root gets the sources without .git.
mapfile -t files < <(find core ui app -name '*.cpp' | sort)
[ ${#files[@]} -gt 0 ] || { echo "tidy: no sources found" >&2; exit 2; }
if [ $mode = changed ]; then
    if [ -z "${FATEK_TIDY_COMMITS:-}" ] && base=$(sed -n 's/^commit //p' "$baseline" 2>/dev/null); then
        FATEK_TIDY_COMMITS=$(git rev-list --count "$base..HEAD" 2>/dev/null || true)
        export FATEK_TIDY_COMMITS
    fi
    mapfile -t scope < <(python3 tools/tidyscope.py changed "$build" "$baseline" 100 "${files[@]}")
    if [[ ${scope[0]:-} == full:* ]]; then
        echo "tidy: every source: ${scope[0]#full: }"
    else
        if [ ${#scope[@]} -eq 0 ]; then
            echo "tidy: none of the ${#files[@]} sources differs from $baseline: nothing to check"
            exit 0
        fi
        echo "tidy: ${#scope[@]} of ${#files[@]} sources differ from $baseline: ${scope[*]:0:20}$([ ${#scope[@]} -le 20 ] || echo " ...")"
        files=("${scope[@]}")
    fi
fi
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
if [ $mode = record ]; then
    python3 tools/tidyscope.py record "$build" "$baseline" "$(git rev-parse HEAD 2>/dev/null || echo unknown)" "${files[@]}"
fi
