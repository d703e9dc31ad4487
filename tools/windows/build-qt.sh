#!/usr/bin/env bash
# Cross-compiles what the Windows build links that Debian does not ship for MinGW: Qt 6.4.2
# (qtbase, qtserialport, qtsvg, qtcharts) and libmosquitto 2.0.11 (without TLS: Debian has no
# MinGW OpenSSL), with MinGW-w64 (GCC 12, posix threads), into one prefix:
#   tools/windows/build-qt.sh            builds it, or reuses it when it is there and complete
# Environment: FATEK_WIN_PREFIX (default ~/.cache/fatek-studio/qt6-mingw), FATEK_WIN_WORK (sources
# and build folders, default ~/.cache/fatek-studio/win-work, removed at the end), FATEK_THIRD_PARTY
# (the Qt module tarballs, default ../shared/third-party/qt-6.4.2 beside the clone).
# Needs: g++-mingw-w64-x86-64-posix, cmake, ninja-build, perl, Debian's Qt 6.4.2 as the host Qt
# (moc, rcc, uic: QT_HOST_PATH), and a deb-src entry for qtbase's and mosquitto's sources
# (tools/windows/install-deps.sh sets up all of it). What is left out of Qt and why:
# docs/windows.md.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
source "$root/tools/stage.sh"
prefix=${FATEK_WIN_PREFIX:-$HOME/.cache/fatek-studio/qt6-mingw}
work=${FATEK_WIN_WORK:-$HOME/.cache/fatek-studio/win-work}
third=${FATEK_THIRD_PARTY:-$root/../shared/third-party/qt-6.4.2}
toolchain=$here/mingw-w64.cmake
jobs=$(nproc 2>/dev/null || echo 2)
# The prefix is complete when this file names the same recipe (this script's text);
# a changed recipe builds again rather than mixing two.
recipe=$(sha256sum <"$0" | cut -c1-16)
stamp=$prefix/fatek-prefix.txt
if [ -f "$stamp" ] && grep -qx "recipe $recipe" "$stamp"; then
    echo "== Windows Qt and libmosquitto already in $prefix (recipe $recipe)"
    exit 0
fi

command -v x86_64-w64-mingw32-g++-posix >/dev/null ||
    { echo "needs g++-mingw-w64-x86-64-posix (tools/windows/install-deps.sh)"; exit 2; }
[ -x /usr/lib/qt6/libexec/moc ] || { echo "needs Debian's Qt 6.4.2 as host Qt (qt6-base-dev-tools)"; exit 2; }
host_qt=$(/usr/lib/qt6/libexec/moc --version | awk '{print $2}')
[ "$host_qt" = 6.4.2 ] || { echo "the host Qt is $host_qt; the cross build needs the same version, 6.4.2"; exit 2; }

rm -rf "$work" "$prefix"
mkdir -p "$work/src" "$prefix"

fetch_sources() {
    # Module tarballs: checked against the sums that came with them.
    (cd "$third" && sha256sum -c --quiet SHA256SUMS) || return 1
    # qtbase and mosquitto from Debian's source packages: apt checks the .dsc against the signed
    # archive index, and here each tarball is checked against the .dsc's SHA-256.
    (cd "$work/src" && apt-get source --download-only qt6-base mosquitto >/dev/null 2>&1) ||
        { echo "apt-get source failed: is there a deb-src entry? (tools/windows/install-deps.sh)"; return 1; }
    local dsc file sum
    for dsc in "$work"/src/*.dsc; do
        # (stage runs this with set -e off: every check returns by itself.)
        awk '/^Checksums-Sha256:/{on=1;next} /^[^ ]/{on=0} on{print $1"  "$3}' "$dsc" |
            (cd "$work/src" && sha256sum -c --quiet -) || { echo "!! $dsc: a tarball's sum differs"; return 1; }
    done
    local t
    for t in "$work"/src/qt6-base_*.orig.tar.xz "$work"/src/mosquitto_*.orig.tar.gz \
             "$third"/qtserialport-*.tar.xz "$third"/qtsvg-*.tar.xz "$third"/qtcharts-*.tar.xz; do
        tar xf "$t" -C "$work/src" || return 1
    done
    # Debian's fixes, as the host's Linux Qt and libmosquitto have them; the orig tarballs alone
    # would ship their holes in the Windows build. qtbase: its series' security entries (cve-*;
    # the rest is Debian's own packaging). mosquitto: the whole series (security and client fixes
    # such as 0017, a SUBACK without reason codes; most of it touches only the broker, not built).
    apply_debian_patches "$work/src/qtbase-everywhere-src-6.4.2" "$work"/src/qt6-base_*.debian.tar.xz '^cve-' || return 1
    apply_debian_patches "$work/src/mosquitto-2.0.11" "$work"/src/mosquitto_*.debian.tar.xz . || return 1
}

# Applies the patches of a Debian source package's series that match $3 (a grep pattern), in
# order, to the source folder $1 ($2: the package's debian tarball); each one's name goes into the
# stamp. (patch: dpkg-dev depends on it.)
apply_debian_patches() {
    local src=$1 debian=$2 pattern=$3 d p
    d=$(mktemp -d "$work/src/debian.XXXXXX")
    tar xf "$debian" -C "$d" || return 1
    for p in $(grep -vE '^\s*(#|$)' "$d/debian/patches/series" | grep -E "$pattern"); do
        patch -d "$src" -p1 --forward --quiet <"$d/debian/patches/$p" ||
            { echo "!! $(basename "$debian"): $p does not apply"; return 1; }
        applied+=("$p")
    done
}

# The licence texts the zip and the installer ship (docs/windows.md): each Qt module's LICENSES/,
# the licences of the third-party code bundled in qtbase, libmosquitto's EPL/EDL.
collect_licences() {
    local dest=$prefix/licenses m d
    mkdir -p "$dest/mosquitto"
    for m in qtbase qtserialport qtsvg qtcharts; do
        mkdir -p "$dest/$m"
        cp "$work/src/$m-everywhere-src-6.4.2"/LICENSES/*.txt "$dest/$m/"
    done
    (cd "$work/src/qtbase-everywhere-src-6.4.2/src/3rdparty" &&
        find . -maxdepth 2 -type f \( -iname 'licen[cs]e*' -o -iname 'copying*' -o -iname 'ftl.txt' \) |
        while read -r f; do d=$dest/qtbase/3rdparty/$(dirname "$f"); mkdir -p "$d"; cp "$f" "$d/"; done)
    cp "$work"/src/mosquitto-2.0.11/{LICENSE.txt,epl-v20,edl-v10} "$dest/mosquitto/"
}

# qtbase: only what the app uses. Off: SQL (Debian's dfsg source has no bundled SQLite; the app
# uses no database), tablet events (no wintab headers in the dfsg source; no pen input needed),
# D-Bus (not on Windows), Concurrent, OpenSSL (TLS goes through Windows' Schannel instead),
# examples and tests. zlib, libpng, libjpeg, freetype, harfbuzz, pcre2 are Qt's bundled copies.
build_qtbase() {
    cmake -S "$work"/src/qtbase-everywhere-src-6.4.2 -B "$work/build/qtbase" -G Ninja \
        -DCMAKE_TOOLCHAIN_FILE="$toolchain" \
        -DQT_HOST_PATH=/usr -DQT_HOST_PATH_CMAKE_DIR=/usr/lib/x86_64-linux-gnu/cmake \
        -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=ON \
        -DQT_BUILD_EXAMPLES=OFF -DQT_BUILD_TESTS=OFF \
        -DFEATURE_sql=OFF -DFEATURE_tabletevent=OFF -DFEATURE_dbus=OFF -DFEATURE_concurrent=OFF \
        -DFEATURE_printsupport=OFF -DFEATURE_system_zlib=OFF -DINPUT_openssl=no >"$work/qtbase-configure.log"
    cmake --build "$work/build/qtbase" -j "$jobs" >"$work/qtbase-build.log" ||
        { tail -40 "$work/qtbase-build.log"; return 1; }
    cmake --install "$work/build/qtbase" >/dev/null
}

build_module() {
    local m=$1
    "$prefix/bin/qt-cmake" -S "$work/src/$m-everywhere-src-6.4.2" -B "$work/build/$m" -G Ninja \
        -DQT_BUILD_EXAMPLES=OFF -DQT_BUILD_TESTS=OFF >"$work/$m-configure.log"
    cmake --build "$work/build/$m" -j "$jobs" >"$work/$m-build.log" || { tail -40 "$work/$m-build.log"; return 1; }
    cmake --install "$work/build/$m" >/dev/null
}

# libmosquitto alone (no broker, clients, plugins or docs), without TLS and without its own
# thread (its Windows build names a pthreads-win32 at C:\pthreads): MqttClient drives the loop
# from Qt's event loop (mosquitto_loop_read/write/misc), never mosquitto_loop_start.
build_mosquitto() {
    cmake -S "$work"/src/mosquitto-2.0.11 -B "$work/build/mosquitto" -G Ninja \
        -DCMAKE_TOOLCHAIN_FILE="$toolchain" -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_BUILD_TYPE=Release \
        -DWITH_TLS=OFF -DWITH_TLS_PSK=OFF -DWITH_CJSON=OFF -DWITH_BROKER=OFF -DWITH_APPS=OFF \
        -DWITH_CLIENTS=OFF -DWITH_PLUGINS=OFF -DDOCUMENTATION=OFF -DWITH_LIB_CPP=OFF \
        -DWITH_THREADING=OFF -DWITH_STATIC_LIBRARIES=OFF >"$work/mosquitto-configure.log"
    cmake --build "$work/build/mosquitto" -j "$jobs" >"$work/mosquitto-build.log" ||
        { tail -40 "$work/mosquitto-build.log"; return 1; }
    cmake --install "$work/build/mosquitto" >/dev/null
    # Its install rule names the DLL but not the import library the linker needs.
    cp "$work/build/mosquitto/lib/libmosquitto.dll.a" "$prefix/lib/"
}

applied=()
stage "Windows: sources" fetch_sources
collect_licences
stage "Windows: libmosquitto" build_mosquitto
stage "Windows: qtbase" build_qtbase
stage "Windows: qtserialport" build_module qtserialport
stage "Windows: qtsvg" build_module qtsvg
stage "Windows: qtcharts" build_module qtcharts
{
    echo "recipe $recipe"
    echo "built $(date -u +%Y-%m-%dT%H:%M:%SZ) with $(x86_64-w64-mingw32-g++-posix --version | head -1)"
    echo "qt 6.4.2 (qtbase from Debian's 6.4.2+dfsg-10 source, modules from $third), mosquitto 2.0.11 without TLS"
    echo "Debian's patches applied: ${applied[*]}"
} >"$stamp"
rm -rf "$work"
stage_total "tools/windows/build-qt.sh"
