#!/usr/bin/env bash
# Cross-compiles what the Windows build links that Debian does not ship for MinGW: Qt 6.4.2
# (qtbase, qtserialport, qtsvg, qtcharts), libmosquitto 2.0.11 (without TLS: Debian has no
# MinGW OpenSSL) and SQLite 3.40.1 (the alarm journal), with MinGW-w64 (GCC 12, posix threads),
# into one prefix:
#   tools/windows/build-qt.sh            builds it, or reuses it when it is there and complete
# Environment: FATEK_WIN_PREFIX (default ~/.cache/fatek-studio/qt6-mingw), FATEK_WIN_WORK (sources
# and build folders, default ~/.cache/fatek-studio/win-work, removed at the end), FATEK_THIRD_PARTY
# (the Qt module tarballs, default ../shared/third-party/qt-6.4.2 beside the clone).
# Needs: g++-mingw-w64-x86-64-posix, cmake, ninja-build, perl, Debian's Qt 6.4.2 as the host Qt
# (moc, rcc, uic: QT_HOST_PATH), tclsh and the host's gcc and make (SQLite's amalgamation is
# generated on the host), and a deb-src entry for qtbase's, mosquitto's and sqlite3's sources
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
    echo "== Windows Qt, libmosquitto and SQLite already in $prefix (recipe $recipe)"
    exit 0
fi

command -v x86_64-w64-mingw32-g++-posix >/dev/null ||
    { echo "needs g++-mingw-w64-x86-64-posix (tools/windows/install-deps.sh)"; exit 2; }
[ -x /usr/lib/qt6/libexec/moc ] || { echo "needs Debian's Qt 6.4.2 as host Qt (qt6-base-dev-tools)"; exit 2; }
host_qt=$(/usr/lib/qt6/libexec/moc --version | awk '{print $2}')
[ "$host_qt" = 6.4.2 ] || { echo "the host Qt is $host_qt; the cross build needs the same version, 6.4.2"; exit 2; }
command -v tclsh >/dev/null || { echo "needs tclsh for SQLite's amalgamation (tools/windows/install-deps.sh)"; exit 2; }

rm -rf "$work" "$prefix"
mkdir -p "$work/src" "$prefix"

fetch_sources() {
    # Module tarballs: checked against the sums that came with them.
    (cd "$third" && sha256sum -c --quiet SHA256SUMS) || return 1
    # qtbase, mosquitto and sqlite3 from Debian's source packages: apt checks the .dsc against the
    # signed archive index, and here each tarball is checked against the .dsc's SHA-256.
    (cd "$work/src" && apt-get source --download-only qt6-base mosquitto sqlite3 >/dev/null 2>&1) ||
        { echo "apt-get source failed: is there a deb-src entry? (tools/windows/install-deps.sh)"; return 1; }
    local dsc file sum
    for dsc in "$work"/src/*.dsc; do
        # (stage runs this with set -e off: every check returns by itself.)
        awk '/^Checksums-Sha256:/{on=1;next} /^[^ ]/{on=0} on{print $1"  "$3}' "$dsc" |
            (cd "$work/src" && sha256sum -c --quiet -) || { echo "!! $dsc: a tarball's sum differs"; return 1; }
    done
    local t
    # (sqlite3's orig is SQLite's full source tree; its orig-www, the documentation, is not needed.)
    for t in "$work"/src/qt6-base_*.orig.tar.xz "$work"/src/mosquitto_*.orig.tar.gz "$work"/src/sqlite3_*.orig.tar.xz \
             "$third"/qtserialport-*.tar.xz "$third"/qtsvg-*.tar.xz "$third"/qtcharts-*.tar.xz; do
        tar xf "$t" -C "$work/src" || return 1
    done
    # Debian's fixes, as the host's Linux Qt and libmosquitto have them; the orig tarballs alone
    # would ship their holes in the Windows build. qtbase: its series' security entries (cve-*;
    # the rest is Debian's own packaging). mosquitto: the whole series (security and client fixes
    # such as 0017, a SUBACK without reason codes; most of it touches only the broker, not built).
    # sqlite3: every patch that changes only SQLite's sources and tests (src/, ext/, test/: the
    # CVE and bug fixes, the 32 KiB page-size limit; 20-hurd-locking-style too, which touches only
    # the Unix VFS that a Windows build does not compile), so that a later security update's new
    # entry is taken without a change here. Left out: the build-system patches (configure.ac,
    # Makefile.in: the library is compiled below from the amalgamation, not by Debian's
    # autoreconf'd build) and 02-use-packaged-lempar.c (lemon.c reading Debian's lemon package).
    apply_debian_patches "$work/src/qtbase-everywhere-src-6.4.2" "$work"/src/qt6-base_*.debian.tar.xz '^cve-' || return 1
    apply_debian_patches "$work/src/mosquitto-2.0.11" "$work"/src/mosquitto_*.debian.tar.xz . || return 1
    apply_debian_patches "$work/src/sqlite3-3.40.1" "$work"/src/sqlite3_*.debian.tar.xz . '^(src|ext|test)/' || return 1
}

# Applies the patches of a Debian source package's series that match $3 (a grep pattern), in
# order, to the source folder $1 ($2: the package's debian tarball); each one's name goes into the
# stamp. With $4 (a grep pattern), only the patches whose every file (as -p1 names it) matches it;
# the others are named as left out. (patch: dpkg-dev depends on it.)
apply_debian_patches() {
    local src=$1 debian=$2 pattern=$3 files=${4:-} d p
    d=$(mktemp -d "$work/src/debian.XXXXXX")
    tar xf "$debian" -C "$d" || return 1
    for p in $(grep -vE '^\s*(#|$)' "$d/debian/patches/series" | grep -E "$pattern"); do
        # (grep without -q reads to the end: sed never gets a SIGPIPE that pipefail would count.)
        if [ -n "$files" ] && sed -n 's|^+++ [^/]*/\([^[:space:]]*\).*|\1|p' "$d/debian/patches/$p" |
                grep -vE "$files" >/dev/null; then
            echo "-- $(basename "$debian"): $p left out (it changes files outside $files)"
            continue
        fi
        patch -d "$src" -p1 --forward --quiet <"$d/debian/patches/$p" ||
            { echo "!! $(basename "$debian"): $p does not apply"; return 1; }
        applied+=("$p")
    done
}

# The licence texts the zip and the installer ship (docs/windows.md): each Qt module's LICENSES/,
# the licences of the third-party code bundled in qtbase, libmosquitto's EPL/EDL, SQLite's
# public-domain dedication (its LICENSE.md, the notice at the top of each of its sources).
collect_licences() {
    local dest=$prefix/licenses m d
    mkdir -p "$dest/mosquitto" "$dest/sqlite3"
    for m in qtbase qtserialport qtsvg qtcharts; do
        mkdir -p "$dest/$m"
        cp "$work/src/$m-everywhere-src-6.4.2"/LICENSES/*.txt "$dest/$m/"
    done
    (cd "$work/src/qtbase-everywhere-src-6.4.2/src/3rdparty" &&
        find . -maxdepth 2 -type f \( -iname 'licen[cs]e*' -o -iname 'copying*' -o -iname 'ftl.txt' \) |
        while read -r f; do d=$dest/qtbase/3rdparty/$(dirname "$f"); mkdir -p "$d"; cp "$f" "$d/"; done)
    cp "$work"/src/mosquitto-2.0.11/{LICENSE.txt,epl-v20,edl-v10} "$dest/mosquitto/"
    cp "$work"/src/sqlite3-3.40.1/LICENSE.md "$dest/sqlite3/"
}

# qtbase: only what the app uses. Off: SQL (Debian's dfsg source has no bundled SQLite; the
# alarm journal uses SQLite's own C API, built below, not Qt SQL), tablet events (no wintab headers in the dfsg source; no pen input needed),
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

# SQLite as libsqlite3-0.dll (the name MSYS2's and libtool's MinGW builds give it) with its import
# library libsqlite3.dll.a, sqlite3.h and sqlite3ext.h, where CMake's FindSQLite3 finds them
# through the toolchain's find roots (CMAKE_PREFIX_PATH is one). Debian's orig is SQLite's full
# tree, not the amalgamation: sqlite3.c is generated on the host (its configure and `make
# sqlite3.c`: lemon, mkkeywordhash and Tcl scripts, so tclsh and the host's gcc), then compiled
# alone with MinGW-w64. The options are Debian's (debian/rules' CFLAGS), so that the journal's
# SQLite is the same on Windows as the host's libsqlite3-0; threads through Win32 mutexes
# (SQLITE_THREADSAFE=1 needs no pthreads on Windows). Only the API is exported (SQLITE_API).
sqlite_options=(
    -DSQLITE_SECURE_DELETE -DSQLITE_ENABLE_COLUMN_METADATA
    -DSQLITE_ENABLE_FTS3 -DSQLITE_ENABLE_FTS3_PARENTHESIS
    -DSQLITE_ENABLE_RTREE=1 -DSQLITE_SOUNDEX=1
    -DSQLITE_ENABLE_UNLOCK_NOTIFY
    -DSQLITE_OMIT_LOOKASIDE=1 -DSQLITE_ENABLE_DBSTAT_VTAB
    -DSQLITE_ALLOW_ROWID_IN_VIEW
    -DSQLITE_ENABLE_UPDATE_DELETE_LIMIT=1
    -DSQLITE_ENABLE_LOAD_EXTENSION
    -DSQLITE_ENABLE_JSON1
    -DSQLITE_LIKE_DOESNT_MATCH_BLOBS
    -DSQLITE_THREADSAFE=1
    -DSQLITE_ENABLE_FTS3_TOKENIZER=1
    -DSQLITE_USE_URI=1
    -DSQLITE_MAX_SCHEMA_RETRY=25
    -DSQLITE_ENABLE_PREUPDATE_HOOK
    -DSQLITE_ENABLE_SESSION
    -DSQLITE_ENABLE_STMTVTAB
    -DSQLITE_MAX_VARIABLE_NUMBER=250000
    # what Debian's configure adds: --enable-fts4, --enable-fts5, the math functions (its default)
    -DSQLITE_ENABLE_FTS4 -DSQLITE_ENABLE_FTS5 -DSQLITE_ENABLE_MATH_FUNCTIONS
)
build_sqlite() {
    local src=$work/src/sqlite3-3.40.1 b=$work/build/sqlite3
    mkdir -p "$b" "$prefix/bin" "$prefix/lib" "$prefix/include"
    # (The host's configure only sets up the generators; --disable-tcl: no Tcl extension, so no
    # tcl-dev.)
    (cd "$b" && "$src/configure" --disable-tcl --disable-readline >"$work/sqlite3-configure.log" 2>&1 &&
        make sqlite3.c >"$work/sqlite3-amalgamation.log" 2>&1) ||
        { tail -40 "$work/sqlite3-configure.log" "$work/sqlite3-amalgamation.log" 2>/dev/null; return 1; }
    # -static-libgcc: the DLL imports only Windows' own DLLs.
    x86_64-w64-mingw32-gcc-posix -O2 -fno-strict-aliasing "${sqlite_options[@]}" \
        '-DSQLITE_API=__declspec(dllexport)' -shared -static-libgcc -o "$prefix/bin/libsqlite3-0.dll" \
        "$b/sqlite3.c" -Wl,--out-implib,"$prefix/lib/libsqlite3.dll.a" >"$work/sqlite3-build.log" 2>&1 ||
        { tail -40 "$work/sqlite3-build.log"; return 1; }
    cp "$b/sqlite3.h" "$src/src/sqlite3ext.h" "$prefix/include/"
}

applied=()
stage "Windows: sources" fetch_sources
collect_licences
stage "Windows: libmosquitto" build_mosquitto
stage "Windows: SQLite" build_sqlite
stage "Windows: qtbase" build_qtbase
stage "Windows: qtserialport" build_module qtserialport
stage "Windows: qtsvg" build_module qtsvg
stage "Windows: qtcharts" build_module qtcharts
{
    echo "recipe $recipe"
    echo "built $(date -u +%Y-%m-%dT%H:%M:%SZ) with $(x86_64-w64-mingw32-g++-posix --version | head -1)"
    echo "qt 6.4.2 (qtbase from Debian's 6.4.2+dfsg-10 source, modules from $third), mosquitto 2.0.11 without TLS"
    echo "sqlite $(sed -n 's/^#define SQLITE_VERSION  *"\(.*\)"/\1/p' "$prefix/include/sqlite3.h") ($(basename "$work"/src/sqlite3_*.dsc .dsc))"
    echo "Debian's patches applied: ${applied[*]}"
} >"$stamp"
rm -rf "$work"
stage_total "tools/windows/build-qt.sh"
