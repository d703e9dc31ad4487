#!/usr/bin/env bash
# CTest packaging_files: the packaged text files are valid and the man pages are complete.
# Usage: check-files.sh FATEK_CLI FATEK_SIM FATEK_STUDIO
#  - the desktop file passes desktop-file-validate (when installed);
#  - every man page renders with groff -man -ww without a warning;
#  - every long option a program's --help lists is in its man page (so a new option cannot
#    ship undocumented).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
[ $# -eq 3 ] || { echo "usage: check-files.sh FATEK_CLI FATEK_SIM FATEK_STUDIO" >&2; exit 2; }
status=0

if command -v desktop-file-validate >/dev/null; then
    desktop-file-validate "$here/linux/fatek-studio.desktop" || status=1
else
    echo "desktop-file-validate not installed: desktop file not checked"
fi

check_page() {
    local program=$1 page=$2
    local warnings options text missing=""
    warnings=$(groff -man -Tutf8 -ww -z "$page" 2>&1 || true)
    if [ -n "$warnings" ]; then
        echo "$page: groff warnings:" >&2
        echo "$warnings" >&2
        status=1
    fi
    options=$(QT_QPA_PLATFORM=offscreen "$program" --help 2>/dev/null | grep -oE -- '--[a-z][a-z-]*' | sort -u)
    [ -n "$options" ] || { echo "$program --help lists no options" >&2; status=1; return; }
    # In the page source a hyphen is written \-.
    text=$(sed 's/\\-/-/g' "$page")
    for o in $options; do
        grep -qE -- "(^|[^a-z-])$o([^a-z-]|$)" <<<"$text" || missing+=" $o"
    done
    if [ -n "$missing" ]; then
        echo "$(basename "$page") does not document:$missing" >&2
        status=1
    fi
}
check_page "$1" "$here/man/fatek-cli.1"
check_page "$2" "$here/man/fatek-sim.1"
check_page "$3" "$here/man/fatek-studio.1"
[ $status -eq 0 ] && echo "desktop file and man pages OK"
exit $status
