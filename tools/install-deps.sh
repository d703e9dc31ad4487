#!/usr/bin/env bash
# Installs the Debian 12 packages FATEK Studio needs to build, test, package and run the demo
# (only the missing ones). This list is the only place anything is installed: tools/demo.sh and
# tools/test.sh call it, and CI runs them on a fresh debootstrap root (tools/fresh-root.sh), so a
# package missing here fails there. docs/packaging.md says why each one is here.
set -euo pipefail

packages=(
    # compilers and build tools: GCC 12 (release, tsan) and clang-14 (asan, fuzz targets)
    build-essential cmake ninja-build pkg-config clang-14 libclang-rt-14-dev
    # LLVM's linker (CMakeLists.txt uses it when present: links take a quarter of GNU ld's time)
    lld
    # the optional compiler cache for repeated builds (FATEK_CCACHE=1, tools/ccache-env.sh)
    ccache
    # Qt 6.4; qt6-charts-dev's CMake package needs Qt6OpenGL, which apt does not pull in
    # without recommends, and Qt6Gui's needs the GL and xkbcommon headers
    qt6-base-dev qt6-serialport-dev qt6-charts-dev libqt6opengl6-dev qt6-svg-dev qt6-tools-dev
    qt6-l10n-tools qt6-translations-l10n libgl-dev libxkbcommon-dev
    # fonts for the offscreen UI tests and screenshots (Latin and Traditional Chinese)
    fonts-dejavu-core fonts-noto-cjk
    # ThreadSanitizer names glibc's own functions (and tools/tsan.supp matches them) only with
    # glibc's symbols
    libc6-dbg
    # tests: serial pty pairs, the independent Python reference; git for the format check
    socat python3 git clang-format
    # the I/O checkout's PDF report, read back as text by its tests (pdftotext)
    poppler-utils
    # tools/tidy.sh: clang-tidy with the checks in .clang-tidy
    clang-tidy-14
    # packaging and its install test (tools/package-test.sh), which runs lintian on the .deb
    dpkg-dev file desktop-file-utils groff-base man-db gzip lintian
    # the watch-list MIME type: update-mime-database, xmllint, gio (content sniffing)
    shared-mime-info libxml2-utils libglib2.0-bin
    # the MQTT gateway: the client library, the broker its integration tests start, and
    # mosquitto_pub, the independent client that acknowledges alarms in tst_gatewayalarms
    libmosquitto-dev mosquitto mosquitto-clients
    # certificates for the TLS tests of the MQTT client (a CA and a broker certificate per test),
    # and OpenSSL's library: the gateway checks its TLS files as libmosquitto will load them
    openssl libssl-dev
    # the alarm journal (SQLite's C library), and the sqlite3 program its tests lock a file with
    libsqlite3-dev sqlite3
    # history stores in PostgreSQL (libpq's C library), and the server tst_historypostgres starts
    # on a free port (initdb into a temporary folder)
    postgresql libpq-dev
)

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing Debian packages: ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
    sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
