#!/usr/bin/env bash
# CTest packaging_files: the packaged text files are valid and the man pages are complete.
# Usage: check-files.sh FATEK_CLI FATEK_SIM FATEK_STUDIO FATEK_GATEWAY
#  - the desktop file passes desktop-file-validate (when installed);
#  - the watch-list MIME type XML is valid and registered by update-mime-database (when installed);
#  - every man page renders with groff -man -ww without a warning;
#  - every long option a program's --help lists is in its man page (so a new option cannot
#    ship undocumented), and every command fatek-cli's --help lists is in its COMMANDS section
#    with the same synopsis (check-man-commands.py).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
[ $# -eq 4 ] || { echo "usage: check-files.sh FATEK_CLI FATEK_SIM FATEK_STUDIO FATEK_GATEWAY" >&2; exit 2; }
status=0

if command -v desktop-file-validate >/dev/null; then
    desktop-file-validate "$here/linux/fatek-studio.desktop" || status=1
else
    echo "desktop-file-validate not installed: desktop file not checked"
fi

# The watch-list MIME type: well-formed XML that update-mime-database accepts and that recognises
# a saved watch list (by content: it keeps the .json extension).
mime_xml="$here/linux/fatek-studio.xml"
if command -v xmllint >/dev/null; then
    xmllint --noout "$mime_xml" || status=1
else
    echo "xmllint not installed: MIME XML well-formedness not checked"
fi
grep -q '^MimeType=application/x-fatek-watchlist;$' "$here/linux/fatek-studio.desktop" ||
    { echo "fatek-studio.desktop does not open application/x-fatek-watchlist" >&2; status=1; }
grep -q 'type="application/x-fatek-watchlist"' "$mime_xml" ||
    { echo "$mime_xml does not define application/x-fatek-watchlist" >&2; status=1; }
if command -v update-mime-database >/dev/null; then
    mime_tmp=$(mktemp -d)
    mkdir -p "$mime_tmp/mime/packages"
    cp "$mime_xml" "$mime_tmp/mime/packages/"
    if ! XDG_DATA_HOME="$mime_tmp" update-mime-database "$mime_tmp/mime" 2>"$mime_tmp/err" || [ -s "$mime_tmp/err" ]; then
        echo "update-mime-database refuses $mime_xml:" >&2
        cat "$mime_tmp/err" >&2
        status=1
    fi
    grep -q '^application/x-fatek-watchlist$' "$mime_tmp/mime/types" 2>/dev/null ||
        { echo "update-mime-database did not register application/x-fatek-watchlist" >&2; status=1; }
    rm -rf "$mime_tmp"
else
    echo "update-mime-database not installed: MIME type not checked"
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
# fatek-cli's commands: the man page's COMMANDS against --help's (printed from the command table).
python3 "$here/check-man-commands.py" "$1" "$here/man/fatek-cli.1" || status=1
check_page "$2" "$here/man/fatek-sim.1"
check_page "$3" "$here/man/fatek-studio.1"
check_page "$4" "$here/man/fatek-gateway.1"

# The gateway's systemd unit and example configuration.
if command -v systemd-analyze >/dev/null; then
    # Before installation the program and its man page are not where the unit names them.
    unit_err=$(systemd-analyze verify "$here/linux/fatek-gateway.service" 2>&1 | grep -v -e '/usr/bin/fatek-gateway is not executable' -e "Command 'man fatek-gateway(1)'" || true)
    [ -z "$unit_err" ] || { echo "fatek-gateway.service: $unit_err" >&2; status=1; }
else
    echo "systemd-analyze not installed: fatek-gateway.service not checked"
fi
grep -qx 'ExecStart=/usr/bin/fatek-gateway /etc/fatek-gateway/config.json' "$here/linux/fatek-gateway.service" ||
    { echo "fatek-gateway.service does not run /etc/fatek-gateway/config.json" >&2; status=1; }
# The example configuration loads (its watch list beside it, as installed under /etc).
example_tmp=$(mktemp -d)
cp "$here/linux/fatek-gateway.example.json" "$example_tmp/config.json"
cp "$here/linux/fatek-gateway.line1.json" "$example_tmp/line1.json"
"$4" --check "$example_tmp/config.json" >/dev/null || { echo "the example gateway configuration does not load" >&2; status=1; }
rm -rf "$example_tmp"
[ $status -eq 0 ] && echo "desktop file, MIME type, man pages and the gateway unit OK"
exit $status
