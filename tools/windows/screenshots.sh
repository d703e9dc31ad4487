#!/usr/bin/env bash
# Screenshots of the Windows build at Windows' display scalings, under Wine with Qt's windows
# platform plugin on Xvfb (what a user's desktop shows, not the offscreen platform):
#   tools/windows/screenshots.sh [OUT_DIR]     default docs/images
# For 100 % (96 dpi, 1366x768), 125 % (120 dpi) and 150 % (144 dpi, both 1920x1080, the laptop
# screens that come with those scalings): the main window with --demo, the forcing tool and the
# trend, as windows-dpi<percent>-{main,forcing,trend}.png. Wine's DPI is its registry's LogPixels,
# as Windows' own "Scale" setting; Qt scales by it (per-monitor DPI aware).
# Needs the Windows build (tools/windows/build.sh) and xvfb-run.
set -euo pipefail
cd "$(dirname "$0")/../.."
out=${1:-docs/images}
build=build/windows-cross
prefix=${FATEK_WIN_PREFIX:-$HOME/.cache/fatek-studio/qt6-mingw}
studio=$build/app/fatek-studio/fatek-studio.exe
[ -f "$studio" ] || { echo "no $studio: run tools/windows/build.sh" >&2; exit 2; }
export WINEPREFIX=${WINEPREFIX:-$PWD/$build/wine-shots} WINEARCH=win64 WINEDEBUG=-all
export WINEDLLOVERRIDES="mscoree,mshtml="
wineboot --init >/dev/null 2>&1
gcc_dir=$(dirname "$(x86_64-w64-mingw32-g++-posix -print-file-name=libstdc++-6.dll)")
pthread_dir=$(dirname "$(x86_64-w64-mingw32-g++-posix -print-file-name=libwinpthread-1.dll)")
WINEPATH="$(winepath -w "$prefix/bin");$(winepath -w "$gcc_dir");$(winepath -w "$pthread_dir")"
WINEQT_PLUGIN_PATH=$(winepath -w "$prefix/plugins")
export WINEPATH WINEQT_PLUGIN_PATH
mkdir -p "$out"
shot() { # PERCENT SCREEN NAME [ARGS...]
    local percent=$1 screen=$2 name=$3 dpi file
    shift 3
    dpi=$((96 * percent / 100))
    wineserver -k 2>/dev/null || true
    wine reg add 'HKCU\Control Panel\Desktop' /v LogPixels /t REG_DWORD /d "$dpi" /f >/dev/null 2>&1
    wine reg add 'HKLM\System\CurrentControlSet\Hardware Profiles\Current\Software\Fonts' \
        /v LogPixels /t REG_DWORD /d "$dpi" /f >/dev/null 2>&1
    wineserver -k 2>/dev/null || true
    file=$out/windows-dpi$percent-$name.png
    rm -f "$file"
    xvfb-run -a -s "-screen 0 ${screen}x24 -dpi $dpi" \
        wine "$studio" --demo --screenshot "$(winepath -w "$PWD/$file")" "$@" >/dev/null 2>&1 || true
    [ -s "$file" ] || { echo "!! no screenshot $file" >&2; return 1; }
    echo "$file: $(python3 -c 'import struct,sys; d=open(sys.argv[1],"rb").read(24); print("%dx%d" % struct.unpack(">II", d[16:24]))' "$file")"
}
for spec in "100 1366x768" "125 1920x1080" "150 1920x1080"; do
    read -r percent screen <<<"$spec"
    shot "$percent" "$screen" main
    shot "$percent" "$screen" forcing --tool forcing
    shot "$percent" "$screen" trend --tool trend
done
wineserver -k 2>/dev/null || true
