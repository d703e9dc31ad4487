#!/usr/bin/env bash
# Cross-builds FATEK Studio for 64-bit Windows on Linux (MinGW-w64, preset windows-cross):
# fatek-studio.exe, fatek-cli.exe, fatek-sim.exe, fatek-gateway.exe and the test programs, then
# the zip and the NSIS installer (build/windows-cross/fatek-studio-<version>-win64.{zip,exe}).
#   tools/windows/build.sh [--no-tests] [--no-packages]
# Needs the cross-built Qt of tools/windows/build-qt.sh (FATEK_WIN_PREFIX, default
# ~/.cache/fatek-studio/qt6-mingw) and the packages of tools/windows/install-deps.sh.
set -euo pipefail
cd "$(dirname "$0")/../.."
source tools/stage.sh
tests=ON
packages=1
for a in "$@"; do
    case $a in
    --no-tests) tests=OFF ;;
    --no-packages) packages=0 ;;
    *) echo "usage: tools/windows/build.sh [--no-tests] [--no-packages]" >&2; exit 2 ;;
    esac
done
prefix=${FATEK_WIN_PREFIX:-$HOME/.cache/fatek-studio/qt6-mingw}
if [ ! -f "$prefix/fatek-prefix.txt" ]; then
    echo "No cross-built Qt in $prefix: make it once with tools/windows/build-qt.sh (about 50 minutes on 2 cores)."
    exit 2
fi
tools/windows/install-deps.sh
build=build/windows-cross
jobs=$(nproc 2>/dev/null || echo 2)

# The icon renderer runs at build time, so it is built for this machine (release preset).
host_tools() {
    [ -f build/release/build.ninja ] || cmake --preset release >/dev/null
    cmake --build build/release --target fatek-rendericon
}
stage "Windows: host tools" host_tools
stage "Windows: configure" cmake --preset windows-cross -DCMAKE_PREFIX_PATH="$prefix" \
    -DFATEK_HOST_RENDERICON="$PWD/build/release/packaging/fatek-rendericon" \
    -DFATEK_BUILD_TESTS=$tests >/dev/null
stage "Windows: build" cmake --build $build -j "$jobs"
if [ $packages = 1 ]; then
    # CPack stages the install tree (with the deployed DLLs, plugins and licences) for each.
    stage "Windows: zip and installer" bash -c "cd $build && cpack -G 'ZIP;NSIS64' >cpack.log || { tail -30 cpack.log; exit 1; }"
    ls -l $build/fatek-studio-*-win64.*
fi
stage_total "tools/windows/build.sh"
