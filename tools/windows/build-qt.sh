#!/usr/bin/env bash
# Cross-compiles what the Windows build links that Debian does not ship for MinGW: Qt 6.4.2
# (qtbase, qtserialport, qtsvg, qtcharts), libmosquitto 2.0.11 (without TLS: Debian has no
# MinGW OpenSSL) and SQLite 3.40.1 (the alarm journal), with MinGW-w64 (GCC 12, posix threads),
# into one prefix:
#   tools/windows/build-qt.sh            builds it, or reuses it when it is there and complete
# The prefix is relocatable: it can be packed (tools/windows/pack-prefix.sh) and, when
# ../shared/windows/ holds qt6-mingw-<recipe>.tar.zst for the recipe of prefix-recipe.sh, this
# unpacks it instead of building (about 50 minutes on 2 cores).
# Environment: FATEK_WIN_PREFIX (default ~/.cache/fatek-studio/qt6-mingw), FATEK_WIN_WORK (sources
# and build folders, default ~/.cache/fatek-studio/win-work, removed at the end), FATEK_THIRD_PARTY
# (the Qt module tarballs, default ../shared/third-party/qt-6.4.2 beside the clone),
# FATEK_WIN_SHARED (where packed prefixes are offered, default ../shared/windows).
# Needs: g++-mingw-w64-x86-64-posix, cmake, ninja-build, perl, Debian's Qt 6.4.2 as the host Qt
# (moc, rcc, uic: QT_HOST_PATH), tclsh and the host's gcc and make (SQLite's amalgamation is
# generated on the host), and a deb-src entry for qtbase's, mosquitto's and sqlite3's sources
# (tools/windows/install-deps.sh sets up all of it). What is left out of Qt and why:
# docs/windows.md.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
source "$root/tools/stage.sh"
source "$here/prefix-recipe.sh"
prefix=${FATEK_WIN_PREFIX:-$HOME/.cache/fatek-studio/qt6-mingw}
work=${FATEK_WIN_WORK:-$HOME/.cache/fatek-studio/win-work}
third=${FATEK_THIRD_PARTY:-$root/../shared/third-party/qt-$qt_version}
shared=${FATEK_WIN_SHARED:-$root/../shared/windows}
jobs=$(nproc 2>/dev/null || echo 2)
# The prefix is complete when its stamp names the recipe of what would be built now
# (prefix-recipe.sh); a changed recipe builds again rather than mixing two.
recipe=$(recipe_id "$third")
stamp=$prefix/fatek-prefix.txt
if [ -f "$stamp" ] && grep -qx "recipe $recipe" "$stamp"; then
    echo "== Windows Qt, libmosquitto and SQLite already in $prefix (recipe $recipe)"
    exit 0
fi
# A prefix packed elsewhere by pack-prefix.sh for this very recipe is unpacked, not built.
if [ -f "$shared/qt6-mingw-$recipe.tar.zst" ]; then
    stage "Windows: unpack the prefix" "$here/unpack-prefix.sh" "$shared/qt6-mingw-$recipe.tar.zst" "$prefix"
    exit 0
fi

command -v x86_64-w64-mingw32-g++-posix >/dev/null ||
    { echo "needs g++-mingw-w64-x86-64-posix (tools/windows/install-deps.sh)"; exit 2; }
[ -x /usr/lib/qt6/libexec/moc ] || { echo "needs Debian's Qt 6.4.2 as host Qt (qt6-base-dev-tools)"; exit 2; }
host_qt=$(/usr/lib/qt6/libexec/moc --version | awk '{print $2}')
[ "$host_qt" = 6.4.2 ] || { echo "the host Qt is $host_qt; the cross build needs the same version, 6.4.2"; exit 2; }
command -v tclsh >/dev/null || { echo "needs tclsh for SQLite's amalgamation (tools/windows/install-deps.sh)"; exit 2; }

rm -rf "$work" "$prefix"
mkdir -p "$work/src" "$prefix/lib/cmake"
# Qt records its toolchain file in the prefix (qt.toolchain.cmake): a copy inside the prefix,
# not this checkout's path, so the packed prefix names nothing of this machine.
toolchain=$prefix/lib/cmake/fatek-mingw-w64.cmake
cp "$here/mingw-w64.cmake" "$toolchain"
cflags=$(reloc_cflags "$work" "$prefix")
reloc_args=("-DCMAKE_C_FLAGS=$cflags" "-DCMAKE_CXX_FLAGS=$cflags" "-DCMAKE_SHARED_LINKER_FLAGS=$reloc_ldflags"
    "-DCMAKE_EXE_LINKER_FLAGS=$reloc_ldflags" "-DCMAKE_MODULE_LINKER_FLAGS=$reloc_ldflags")
export SOURCE_DATE_EPOCH=${SOURCE_DATE_EPOCH:-1672531200}

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
    local sel pkg pattern files
    for sel in "${patch_selection[@]}"; do
        IFS='|' read -r pkg pattern files <<<"$sel"
        apply_debian_patches "$(src_dir "$pkg")" "$work"/src/"${pkg}"_*.debian.tar.xz "$pattern" "$files" || return 1
    done
}

# The source folder of a Debian source package's orig tarball.
src_dir() {
    case $1 in
    qt6-base) echo "$work/src/qtbase-everywhere-src-$qt_version" ;;
    mosquitto) echo "$work/src/mosquitto-$mosquitto_version" ;;
    sqlite3) echo "$work/src/sqlite3-$sqlite_version" ;;
    esac
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
        cp "$work/src/$m-everywhere-src-$qt_version"/LICENSES/*.txt "$dest/$m/"
    done
    (cd "$work/src/qtbase-everywhere-src-$qt_version/src/3rdparty" &&
        find . -maxdepth 2 -type f \( -iname 'licen[cs]e*' -o -iname 'copying*' -o -iname 'ftl.txt' \) |
        while read -r f; do d=$dest/qtbase/3rdparty/$(dirname "$f"); mkdir -p "$d"; cp "$f" "$d/"; done)
    cp "$work"/src/mosquitto-$mosquitto_version/{LICENSE.txt,epl-v20,edl-v10} "$dest/mosquitto/"
    cp "$work"/src/sqlite3-$sqlite_version/LICENSE.md "$dest/sqlite3/"
}

# qtbase: only what the app uses. Off: SQL (Debian's dfsg source has no bundled SQLite; the
# alarm journal uses SQLite's own C API, built below, not Qt SQL), tablet events (no wintab headers in the dfsg source; no pen input needed),
# D-Bus (not on Windows), Concurrent, OpenSSL (TLS goes through Windows' Schannel instead),
# examples and tests. zlib, libpng, libjpeg, freetype, harfbuzz, pcre2 are Qt's bundled copies.
build_qtbase() {
    cmake -S "$work/src/qtbase-everywhere-src-$qt_version" -B "$work/build/qtbase" -G Ninja \
        -DCMAKE_TOOLCHAIN_FILE="$toolchain" \
        -DQT_HOST_PATH=/usr -DQT_HOST_PATH_CMAKE_DIR=/usr/lib/x86_64-linux-gnu/cmake \
        -DCMAKE_INSTALL_PREFIX="$prefix" "${qtbase_options[@]}" "${reloc_args[@]}" >"$work/qtbase-configure.log"
    cmake --build "$work/build/qtbase" -j "$jobs" >"$work/qtbase-build.log" ||
        { tail -40 "$work/qtbase-build.log"; return 1; }
    cmake --install "$work/build/qtbase" >/dev/null
}

build_module() {
    local m=$1
    "$prefix/bin/qt-cmake" -S "$work/src/$m-everywhere-src-$qt_version" -B "$work/build/$m" -G Ninja \
        "${module_options[@]}" "${reloc_args[@]}" >"$work/$m-configure.log"
    cmake --build "$work/build/$m" -j "$jobs" >"$work/$m-build.log" || { tail -40 "$work/$m-build.log"; return 1; }
    cmake --install "$work/build/$m" >/dev/null
}

# libmosquitto alone (no broker, clients, plugins or docs), without TLS and without its own
# thread (its Windows build names a pthreads-win32 at C:\pthreads): MqttClient drives the loop
# from Qt's event loop (mosquitto_loop_read/write/misc), never mosquitto_loop_start.
build_mosquitto() {
    cmake -S "$work/src/mosquitto-$mosquitto_version" -B "$work/build/mosquitto" -G Ninja \
        -DCMAKE_TOOLCHAIN_FILE="$toolchain" -DCMAKE_INSTALL_PREFIX="$prefix" \
        "${mosquitto_options[@]}" "${reloc_args[@]}" >"$work/mosquitto-configure.log"
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
# alone with MinGW-w64 with Debian's options (prefix-recipe.sh). Only the API is exported
# (SQLITE_API).
build_sqlite() {
    local src=$work/src/sqlite3-$sqlite_version b=$work/build/sqlite3
    mkdir -p "$b" "$prefix/bin" "$prefix/lib" "$prefix/include"
    # (The host's configure only sets up the generators; --disable-tcl: no Tcl extension, so no
    # tcl-dev.)
    (cd "$b" && "$src/configure" --disable-tcl --disable-readline >"$work/sqlite3-configure.log" 2>&1 &&
        make sqlite3.c >"$work/sqlite3-amalgamation.log" 2>&1) ||
        { tail -40 "$work/sqlite3-configure.log" "$work/sqlite3-amalgamation.log" 2>/dev/null; return 1; }
    # -static-libgcc: the DLL imports only Windows' own DLLs.
    # shellcheck disable=SC2086 # (the flags are words)
    x86_64-w64-mingw32-gcc-posix "${sqlite_options[@]}" $cflags $reloc_ldflags \
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
for m in "${qt_modules[@]}"; do
    stage "Windows: $m" build_module "$m"
done
# The stamp: the recipe id, then what it was computed from, then what the build found.
{
    echo "recipe $recipe"
    recipe_text "$third" | sed 's/^/  /'
    echo "built $(date -u +%Y-%m-%dT%H:%M:%SZ) with $(x86_64-w64-mingw32-g++-posix --version | head -1)"
    echo "qt $qt_version (qtbase from Debian's $(basename "$work"/src/qt6-base_*.dsc .dsc) source, the modules' tarballs of ../shared/third-party), mosquitto $mosquitto_version without TLS"
    echo "sqlite $(sed -n 's/^#define SQLITE_VERSION  *"\(.*\)"/\1/p' "$prefix/include/sqlite3.h") ($(basename "$work"/src/sqlite3_*.dsc .dsc))"
    echo "Debian's patches applied: ${applied[*]}"
} >"$stamp"
rm -rf "$work"
stage_total "tools/windows/build-qt.sh"
