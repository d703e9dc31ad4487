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
# A Qt Test program with no console window (Wine run without a terminal) writes its report
# with OutputDebugString instead of stdout: +debugstr shows it (and qDebug) on stderr, so CTest's
# --output-on-failure has the failure text.
export WINEARCH=win64 WINEDEBUG=-all,warn+debugstr
# No Mono or Gecko download prompt: nothing here needs .NET or Wine's HTML engine.
export WINEDLLOVERRIDES="mscoree,mshtml="
unset DISPLAY
tmp=$(mktemp -d "${TMPDIR:-/tmp}/fatek-wine.XXXXXX")
cleanup() {
    [ -z "${socat_pid:-}" ] || kill "$socat_pid" 2>/dev/null || true
    [ -z "${sim_pid:-}" ] || kill "$sim_pid" 2>/dev/null || true
    [ -z "${watch_pid:-}" ] || kill "$watch_pid" 2>/dev/null || true
    wineserver -k 2>/dev/null || true
    # A test that crashed leaves its Linux broker (tests/mosquittobroker.cpp) behind.
    pkill -f "mosquitto -c $WINEPREFIX/" 2>/dev/null || true
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
# Wine hands a Windows program no QT_* variable of the Unix environment (they would reach the
# host's Qt too); it takes them with a WINE prefix instead, as it does WINEPATH for PATH.
# Without this the tests ran on the windows platform plugin, with no display (most UI tests
# failed on qWaitForWindowExposed).
export WINEPATH WINEQT_PLUGIN_PATH=$QT_PLUGIN_PATH WINEQT_QPA_PLATFORM=offscreen
# The offscreen platform on Windows reads fonts only from QT_QPA_FONTDIR (default: the Qt
# prefix's lib/fonts, absent), and without one draws every glyph as a box as wide as it is high.
# Liberation Sans has the metrics of Arial, a Windows font; Noto Sans CJK stands in for Windows'
# Chinese fonts (the zh_TW screens and reports).
mkdir -p "$tmp/fonts"
ln -s /usr/share/fonts/truetype/liberation/LiberationSans-*.ttf "$tmp/fonts/"
ln -s /usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc "$tmp/fonts/"
WINEQT_QPA_FONTDIR=$(winepath -w "$tmp/fonts")
export WINEQT_QPA_FONTDIR
# Qt's own translations (qtbase_zh_TW.qm, tst_ui_translation): QLibraryInfo looks beside the
# cross Qt, which has none; the .qm files are the same on every platform, so the tests take the
# host's (qt6-translations-l10n) through a qt.conf beside them.
printf '[Paths]\nPrefix = %s\nTranslations = %s\n' "$(winepath -w "$prefix" | tr '\\' /)" \
    "$(winepath -w /usr/share/qt6/translations | tr '\\' /)" >$build/tests/qt.conf

# The tests Wine cannot run: first column of each line that is not a comment.
skip=$({ grep -vE '^\s*(#|$)' tools/windows/wine-skip.txt || true; } | awk '{print $1}' | paste -sd'|')
echo "== not run under Wine (tools/windows/wine-skip.txt): ${skip//|/ }"
# A test program that itself hangs under Wine leaves no trace of why in CTest's timeout, so a
# program still running after 150 s gets its threads' kernel wait channels, and every process
# that holds its output pipe, written to the log once. (A child that outlives a program that has
# ended is wine-run.sh's to name: CTest's emulator, tools/windows/wine-run.sh.)
watch_hangs() {
    local p pipe q seen=" "
    while sleep 20; do
        for p in $(pgrep -f "$PWD/$build/tests/.*\.exe" || true); do
            [ "$(ps -o etimes= -p "$p" 2>/dev/null || echo 0)" -gt 150 ] && [[ $seen != *" $p "* ]] || continue
            seen+="$p "
            echo "== still running after 150 s: $(ps -o args= -p "$p" | cut -c1-120)"
            ps -L -o tid=,stat=,wchan:32=,comm= -p "$p" | sed 's/^/   thread /'
            pipe=$(readlink "/proc/$p/fd/1" 2>/dev/null || true)
            for q in $(pgrep -f 'wine|\.exe' || true); do
                [ "$q" != "$p" ] && ls -l "/proc/$q/fd" 2>/dev/null | grep -qF "$pipe" &&
                    echo "   its output $pipe is also held by $q: $(ps -o args= -p "$q" | cut -c1-80)"
            done
        done
    done
}
watch_hangs &
watch_pid=$!
stage "Wine: test suite" ctest --test-dir $build -j "$(nproc 2>/dev/null || echo 2)" \
    --output-on-failure --timeout 300 ${skip:+-E "^($skip)\$"} "$@" || suite_status=$?
kill "$watch_pid" 2>/dev/null || true
[ -z "${suite_status:-}" ] || exit "$suite_status"

serial_test() {
    socat pty,raw,echo=0,link="$tmp/a" pty,raw,echo=0,link="$tmp/b" 2>"$tmp/socat.log" &
    socat_pid=$!
    for _ in $(seq 50); do [ -e "$tmp/a" ] && [ -e "$tmp/b" ] && break; sleep 0.1; done
    # COM12: a port above COM9, which Windows names \\.\COM12 (written both ways below).
    ln -sfn "$(readlink -f "$tmp/a")" "$WINEPREFIX/dosdevices/com12"
    [ -x build/release/app/fatek-sim/fatek-sim ] || {
        [ -f build/release/build.ninja ] || cmake --preset release >/dev/null
        cmake --build build/release --target fatek-sim >/dev/null
    }
    build/release/app/fatek-sim/fatek-sim --serial "$tmp/b" --baud 19200 --parity E --data 7 --stop 1 \
        --station 3 --verbose >"$tmp/sim.log" 2>&1 &
    sim_pid=$!
    sleep 1
    local out status=0
    out=$(wine $build/app/fatek-cli/fatek-cli.exe --serial COM12 --baud 19200 --parity even \
              --data 7 --stop 1 --station 3 write R100 1234 2>&1 &&
          wine $build/app/fatek-cli/fatek-cli.exe --serial '\\.\COM12' --baud 19200 --parity even \
              --data 7 --stop 1 --station 3 read R100 2>&1) || status=$?
    echo "$out" | tr -d '\r'
    kill "$sim_pid" 2>/dev/null || true
    if [ $status -ne 0 ] || ! echo "$out" | tr -d '\r' | grep -qE '(^|[^0-9])1234([^0-9]|$)'; then
        echo "!! fatek-cli.exe did not read back 1234 over COM12 (status $status); fatek-sim said:"
        cat "$tmp/sim.log"
        return 1
    fi
}
stage "Wine: serial COM12 <-> fatek-sim on a pty" serial_test

# The installer as a user runs it (silently here), into a folder with a space in its name; the
# installed programs then run with nothing but what the installer put beside them; the
# uninstaller takes everything away again.
installer_test() {
    local setup dir="C:\\FATEK Studio test" unixdir key out
    setup=$(ls $build/fatek-studio-*-win64.exe 2>/dev/null | head -1)
    [ -n "$setup" ] || { echo "!! no installer in $build: run tools/windows/build.sh"; return 1; }
    # NSIS takes /D=PATH unquoted, spaces and all, as the command line's end; wine would quote an
    # argument with spaces, cmd passes the line as written.
    wine cmd /c "$(winepath -w "$setup") /S /D=$dir"
    unixdir=$(winepath -u "$dir")
    local f
    for f in bin/fatek-studio.exe bin/fatek-cli.exe bin/fatek-sim.exe bin/fatek-gateway.exe \
        bin/Qt6Core.dll bin/platforms/qwindows.dll bin/tls/qschannelbackend.dll \
        translations/qtbase_zh_TW.qm licenses Uninstall.exe; do
        [ -e "$unixdir/$f" ] || { echo "!! the installer did not install $f"; return 1; }
    done
    key='HKLM\Software\Classes\FatekStudio.WatchList\shell\open\command'
    out=$(wine reg query "$key" | tr -d '\r')
    echo "$out" | grep -qF "\"$dir\\bin\\fatek-studio.exe\" \"%1\"" ||
        { echo "!! \"Open with\" for watch lists not registered: $out"; return 1; }
    wine reg query 'HKLM\Software\Classes\.json\OpenWithProgids' | grep -q FatekStudio.WatchList ||
        { echo "!! FATEK Studio is not in the \"Open with\" list of .json"; return 1; }
    local menu="$WINEPREFIX/drive_c/ProgramData/Microsoft/Windows/Start Menu/Programs"
    ls "$menu"/FATEK*/"FATEK Studio.lnk" "$menu"/FATEK*/"FATEK Studio (demo).lnk" >/dev/null ||
        { echo "!! Start-menu entries missing"; return 1; }
    # Only the installed DLLs and plugins: no WINEPATH, no plugin path.
    out=$(env -u WINEPATH -u WINEQT_PLUGIN_PATH wine "$unixdir/bin/fatek-cli.exe" --sim read R0 2>&1 | tr -d '\r')
    echo "$out"
    echo "$out" | grep -qE '^R0 ' || { echo "!! the installed fatek-cli.exe did not read R0"; return 1; }
    # The installed studio opens a watch list, as "Open with" starts it, and draws its window.
    env -u WINEPATH -u WINEQT_PLUGIN_PATH wine "$unixdir/bin/fatek-studio.exe" \
        --screenshot "$(winepath -w "$tmp/installed.png")" \
        "$(winepath -w "$PWD/packaging/linux/fatek-gateway.line1.json")"
    [ -s "$tmp/installed.png" ] || { echo "!! the installed fatek-studio.exe drew no window"; return 1; }
    # The uninstaller copies itself away and returns at once: wait for the folder to go.
    wine "$unixdir/Uninstall.exe" /S
    for _ in $(seq 120); do [ -e "$unixdir" ] || break; sleep 0.5; done
    [ ! -e "$unixdir" ] || { echo "!! the uninstaller left $unixdir:"; find "$unixdir" | head; return 1; }
    if wine reg query 'HKLM\Software\Classes\FatekStudio.WatchList' >/dev/null 2>&1 ||
        wine reg query 'HKLM\Software\Microsoft\Windows\CurrentVersion\Uninstall\FATEK Studio' >/dev/null 2>&1 ||
        ls "$menu"/FATEK* >/dev/null 2>&1; then
        echo "!! the uninstaller left registry keys or Start-menu entries"
        return 1
    fi
    echo "installed into $dir, ran fatek-cli.exe and fatek-studio.exe from there, uninstalled"
}
stage "Wine: installer install, run, uninstall" installer_test
stage_total "tools/windows/test.sh"
