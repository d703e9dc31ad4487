#!/usr/bin/env bash
# Installs what the Windows cross build, its Wine test run and its installer need (on top of
# tools/install-deps.sh, whose host Qt 6.4.2 gives moc, rcc, uic and lrelease), and a deb-src
# entry for Debian's own archive so that tools/windows/build-qt.sh can fetch qtbase's,
# mosquitto's and sqlite3's sources with apt-get source. Only what is missing.
set -euo pipefail
packages=(
    # MinGW-w64 with posix threads (std::thread, std::mutex); objdump for the DLL deployment
    g++-mingw-w64-x86-64-posix binutils-mingw-w64-x86-64
    # the tests and the programs under Wine, a display for the windows platform plugin
    wine wine64 xvfb xauth
    # the installer (CPack's NSIS64 generator) and the zip
    nsis zip
    # apt-get source (dpkg-source), the serial test's pty pair, Qt's translations for the zip
    dpkg-dev socat qt6-translations-l10n
    # SQLite's amalgamation (sqlite3.c) is generated from Debian's full source tree by Tcl scripts
    tcl
    # fonts for the offscreen platform under Wine (QT_QPA_FONTDIR in tools/windows/test.sh),
    # Latin and Traditional Chinese; the host's pdftotext reads the checkout reports back
    fonts-liberation fonts-noto-cjk poppler-utils
)
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
# deb-src beside the deb entries of the Debian archive the machine already uses.
if ! grep -rqsE '^(deb-src|Types:.*deb-src)' /etc/apt/sources.list /etc/apt/sources.list.d/; then
    # (grep says 2 for a glob that matched nothing, which pipefail and set -e would make fatal:
    # a fresh root has only sources.list.)
    mirror=$({ grep -rhsE '^URIs:|^deb ' /etc/apt/sources.list /etc/apt/sources.list.d/*.sources \
                   /etc/apt/sources.list.d/*.list 2>/dev/null || true; } |
                 { grep -v security || true; } | { grep -oE 'https?://[^ ]+' || true; } | head -1)
    mirror=${mirror:-http://deb.debian.org/debian}
    echo "Adding a deb-src entry for $mirror (bookworm)"
    printf 'Types: deb-src\nURIs: %s\nSuites: bookworm bookworm-updates\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
        "$mirror" | "${sudo_cmd[@]}" tee /etc/apt/sources.list.d/fatek-deb-src.sources >/dev/null
    need_update=1
fi
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ] || [ -n "${need_update:-}" ]; then
    export DEBIAN_FRONTEND=noninteractive
    "${sudo_cmd[@]}" apt-get update -qq
fi
if [ ${#missing[@]} -gt 0 ]; then
    echo "Installing Debian packages: ${missing[*]}"
    "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
