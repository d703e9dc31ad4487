#!/usr/bin/env bash
# The Windows part of tools/test.sh (and so of CI): the cross-built Qt of the recipe in
# tools/windows/prefix-recipe.sh is taken from the cache (FATEK_WIN_PREFIX, default
# ~/.cache/fatek-studio/qt6-mingw) or unpacked from ../shared/windows/qt6-mingw-<recipe>.tar.zst
# (tools/windows/pack-prefix.sh made it); then the programs, the tests, the zip and the installer
# are cross-built and the suite runs under Wine. With neither, it does not spend 50 minutes
# building the prefix: it says in red that the Windows part is skipped, and why.
#   tools/windows/ci.sh            all of it
#   tools/windows/ci.sh check      exits 0 when a prefix for the recipe is at hand, else 3 (red lines)
#   tools/windows/ci.sh build      the prefix (unpacked when needed), then the cross build
#   tools/windows/ci.sh test       the suite, the serial path and the installer under Wine
set -euo pipefail
cd "$(dirname "$0")/../.."
source tools/stage.sh
source tools/windows/prefix-recipe.sh
prefix=${FATEK_WIN_PREFIX:-$HOME/.cache/fatek-studio/qt6-mingw}
shared=${FATEK_WIN_SHARED:-../shared/windows}
third=${FATEK_THIRD_PARTY:-../shared/third-party/qt-$qt_version}
red() { if [ -t 1 ] || [ -n "${CI:-}" ]; then printf '\033[1;31m%s\033[0m\n' "$*"; else echo "$*"; fi; }

check() {
    local recipe have
    # (The recipe names the Debian sources apt would fetch now, so it needs the deb-src entry of
    # install-deps.sh.)
    recipe=$(recipe_id "$third") || return 1
    have=$(sed -n 's/^recipe //p' "$prefix/fatek-prefix.txt" 2>/dev/null || true)
    if [ "$have" = "$recipe" ]; then
        echo "== Windows: prefix for recipe $recipe in $prefix"
    elif [ -f "$shared/qt6-mingw-$recipe.tar.zst" ]; then
        echo "== Windows: prefix for recipe $recipe offered as $shared/qt6-mingw-$recipe.tar.zst"
    else
        red "== Windows: SKIPPED: no cross-built prefix for recipe $recipe: none in $prefix${have:+ (it holds recipe $have)} and no $shared/qt6-mingw-$recipe.tar.zst."
        red "   The recipe changed or the prefix was never packed: make it with tools/windows/build-qt.sh (about 50 minutes on 2 cores), pack it with tools/windows/pack-prefix.sh and place the file in ../shared/windows/."
        red "   What the recipe is made of: tools/windows/prefix-recipe.sh (recipe_text)."
        return 3
    fi
}
build() {
    stage "Windows: prefix" tools/windows/build-qt.sh
    stage "Windows: build" tools/windows/build.sh
}
run_tests() {
    stage "Windows: tests under Wine" tools/windows/test.sh
}

case ${1:-all} in
check) stage "Windows: packages" tools/windows/install-deps.sh && check ;;
build) build ;;
test) run_tests ;;
all)
    stage "Windows: packages" tools/windows/install-deps.sh
    check || { [ $? -eq 3 ] && exit 0; exit 1; }
    build
    run_tests
    stage_total "tools/windows/ci.sh"
    ;;
*) echo "usage: tools/windows/ci.sh [check|build|test]" >&2; exit 2 ;;
esac
