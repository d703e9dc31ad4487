#!/usr/bin/env bash
# Install test of the Linux packages: builds the .deb and the .tar.gz with CPack from a configured
# build directory (BUILD_DIR, default build/release: run after the release workflow), checks
# their metadata and contents, unpacks the .deb into a temporary root and runs the installed
# programs from there. On CI (CI=true, as root) it also installs the .deb for real with dpkg,
# lets apt pull its dependencies, runs it from /usr/bin and removes it again.
set -euo pipefail
cd "$(dirname "$0")/.."

build=${BUILD_DIR:-build/release}
if [ ! -f "$build/CPackConfig.cmake" ]; then
    echo "package-test: $build is not a configured build directory (run the release workflow first)" >&2
    exit 1
fi

fail() {
    echo "package-test: FAIL: $*" >&2
    exit 1
}
step() { echo "== package-test: $*"; }

work=$(mktemp -d "${TMPDIR:-/tmp}/fatek-package-test.XXXXXX")
sim_pid=""
real_install=0
cleanup() {
    if [ -n "$sim_pid" ]; then kill "$sim_pid" 2>/dev/null || true; fi
    if [ "$real_install" = 1 ]; then dpkg -r fatek-studio >/dev/null 2>&1 || true; fi
    rm -rf "$work"
}
trap cleanup EXIT

step "building the packages from $build"
cmake --build "$build" >"$work/build.log" 2>&1 || {
    tail -40 "$work/build.log" >&2
    fail "the build in $build failed"
}
out="$build/packages"
rm -rf "$out"
(cd "$build" && cpack -G "DEB;TGZ" -B "$PWD/packages" >"$work/cpack.log" 2>&1) || {
    cat "$work/cpack.log" >&2
    fail "cpack failed"
}
shopt -s nullglob
debs=("$out"/fatek-studio_*.deb)
tgzs=("$out"/fatek-studio-*.tar.gz)
shopt -u nullglob
[ ${#debs[@]} -eq 1 ] || fail "expected one .deb in $out, found ${#debs[@]}"
[ ${#tgzs[@]} -eq 1 ] || fail "expected one .tar.gz in $out, found ${#tgzs[@]}"
deb=${debs[0]}
tgz=${tgzs[0]}
echo "$(basename "$deb") $(du -h "$deb" | cut -f1), $(basename "$tgz") $(du -h "$tgz" | cut -f1)"

step "control fields"
dpkg-deb -I "$deb" >"$work/info.txt"
version=$(dpkg-deb -f "$deb" Version)
depends=$(dpkg-deb -f "$deb" Depends)
echo "Version: $version"
echo "Depends: $depends"
echo "Recommends: $(dpkg-deb -f "$deb" Recommends)"
[ "$(dpkg-deb -f "$deb" Package)" = fatek-studio ] || fail "package name is not fatek-studio"
[ "$(dpkg-deb -f "$deb" Architecture)" = "$(dpkg --print-architecture)" ] || fail "wrong architecture"
# Package names only, one a line ("libqt6core6 (>= 6.4.0)" -> "libqt6core6").
depends_names=$(tr ',' '\n' <<<"$depends" | sed 's/^ *//; s/ .*//')
for p in libc6 libstdc++6 libqt6core6 libqt6gui6 libqt6widgets6 libqt6network6 libqt6serialport6 libqt6svg6 libmosquitto1; do
    grep -Fxq "$p" <<<"$depends_names" || fail "Depends lacks $p"
done

step "lintian"
# Debian's own package checker: an error fails the test; warnings are shown.
lintian --tag-display-limit 0 "$deb" >"$work/lintian.txt" 2>&1 || true
cat "$work/lintian.txt"
if grep -q "^E: " "$work/lintian.txt"; then
    fail "lintian reports errors (above)"
fi
grep -q "^[EW]: " "$work/lintian.txt" || echo "lintian: no error, no warning"

step "contents"
dpkg-deb -c "$deb" | awk '{print $1, $6}' >"$work/contents.txt"
expected=(
    ./usr/bin/fatek-studio ./usr/bin/fatek-cli ./usr/bin/fatek-sim ./usr/bin/fatek-gateway
    ./usr/lib/systemd/system/fatek-gateway.service
    ./etc/fatek-gateway/config.json ./etc/fatek-gateway/line1.json
    ./usr/share/applications/fatek-studio.desktop
    ./usr/share/mime/packages/fatek-studio.xml
    ./usr/share/icons/hicolor/scalable/apps/fatek-studio.svg
    ./usr/share/man/man1/fatek-cli.1.gz ./usr/share/man/man1/fatek-sim.1.gz
    ./usr/share/man/man1/fatek-studio.1.gz ./usr/share/man/man1/fatek-gateway.1.gz
    ./usr/share/bash-completion/completions/fatek-cli ./usr/share/zsh/vendor-completions/_fatek-cli
    ./usr/share/doc/fatek-studio/copyright ./usr/share/doc/fatek-studio/changelog.gz
)
for size in 16 22 24 32 48 64 128 256; do
    expected+=("./usr/share/icons/hicolor/${size}x${size}/apps/fatek-studio.png")
done
for f in "${expected[@]}"; do
    grep -q " $f\$" "$work/contents.txt" || fail "the .deb lacks $f"
done
for f in fatek-studio fatek-cli fatek-sim fatek-gateway; do
    grep -q "^-rwxr-xr-x ./usr/bin/$f\$" "$work/contents.txt" || fail "/usr/bin/$f is not mode 755"
done
# Nothing but bin/ and share/ under /usr (and the gateway's unit and configuration): no test,
# bench or build-tool binaries.
if grep -v -E " \./usr/(bin|share)(/|$)| \./$| \./usr/$| \./usr/lib/(systemd/(system/?)?)?$| \./usr/lib/systemd/system/fatek-gateway\.service$| \./etc/(fatek-gateway/(config|line1)\.json|fatek-gateway/)?$" "$work/contents.txt"; then
    fail "unexpected files in the .deb (above)"
fi
echo "$(wc -l <"$work/contents.txt") entries, all expected files present"
# The gateway's configuration survives upgrades: dpkg treats it as a conffile.
dpkg-deb -e "$deb" "$work/control"
for f in /etc/fatek-gateway/config.json /etc/fatek-gateway/line1.json; do
    grep -qx "$f" "$work/control/conffiles" || fail "$f is not a conffile"
done
tar -tzf "$tgz" >"$work/tgz.txt"
for f in bin/fatek-studio bin/fatek-cli bin/fatek-sim bin/fatek-gateway share/applications/fatek-studio.desktop \
    share/mime/packages/fatek-studio.xml \
    share/man/man1/fatek-cli.1.gz share/icons/hicolor/48x48/apps/fatek-studio.png; do
    grep -q "/$f\$" "$work/tgz.txt" || fail "the .tar.gz lacks $f"
done
echo ".tar.gz: $(wc -l <"$work/tgz.txt") entries"

step "unpacking into a temporary root"
root="$work/root"
dpkg-deb -x "$deb" "$root"
if command -v desktop-file-validate >/dev/null; then
    desktop-file-validate "$root/usr/share/applications/fatek-studio.desktop" || fail "invalid .desktop file"
fi
# The desktop entry opens watch lists (a file argument, their MIME type), and that type is
# installed and registered by update-mime-database (what dpkg's shared-mime-info trigger runs).
grep -qx 'Exec=fatek-studio %f' "$root/usr/share/applications/fatek-studio.desktop" ||
    fail "the .desktop Exec= takes no file argument"
grep -qx 'MimeType=application/x-fatek-watchlist;' "$root/usr/share/applications/fatek-studio.desktop" ||
    fail "the .desktop file does not list application/x-fatek-watchlist"
mime_xml="$root/usr/share/mime/packages/fatek-studio.xml"
[ -s "$mime_xml" ] || fail "the .deb lacks the watch-list MIME type"
if command -v update-mime-database >/dev/null; then
    mkdir -p "$work/xdg/mime/packages"
    cp "$mime_xml" "$work/xdg/mime/packages/"
    XDG_DATA_HOME="$work/xdg" update-mime-database "$work/xdg/mime" ||
        fail "update-mime-database refuses the installed MIME type"
    grep -qx 'application/x-fatek-watchlist' "$work/xdg/mime/types" ||
        fail "update-mime-database did not register application/x-fatek-watchlist"
    if command -v gio >/dev/null; then
        # A saved watch list (it keeps .json) is told from other JSON by its content.
        printf '{\n    "format": "fatek-studio-watchlist",\n    "tables": [\n    ],\n    "version": 1\n}\n' \
            >"$work/line3.json"
        echo '{"other": 1}' >"$work/other.json"
        XDG_DATA_HOME="$work/xdg" gio info -a standard::content-type "$work/line3.json" |
            grep -q 'application/x-fatek-watchlist' || fail "a saved watch list is not recognised"
        XDG_DATA_HOME="$work/xdg" gio info -a standard::content-type "$work/other.json" |
            grep -q 'application/json' || fail "other JSON is taken for a watch list"
    fi
    echo "MIME type application/x-fatek-watchlist registered"
fi
for page in fatek-cli fatek-sim fatek-studio fatek-gateway; do
    warnings=$(zcat "$root/usr/share/man/man1/$page.1.gz" | groff -man -Tutf8 -ww -z 2>&1 || true)
    [ -z "$warnings" ] || fail "man page $page: $warnings"
done
file "$root/usr/share/icons/hicolor/256x256/apps/fatek-studio.png" | grep -q "256 x 256" ||
    fail "256x256 icon is not 256 x 256 pixels"
for f in fatek-studio fatek-cli fatek-sim fatek-gateway; do
    if ldd "$root/usr/bin/$f" | grep "not found"; then
        fail "$f needs a library that is not installed"
    fi
done

# Runs the installed programs of one tree (the temporary root or the real /usr).
check_tree() {
    local bin=$1 etc=$2
    local status rc
    echo "\$ fatek-cli --sim status"
    rc=0
    status=$("$bin/fatek-cli" --sim status 2>&1) || rc=$?
    echo "$status" | head -4
    [ "$rc" -eq 0 ] || fail "fatek-cli --sim status exited with $rc"
    grep -Eq "^mode +RUN$" <<<"$status" || fail "fatek-cli --sim status does not show RUN"
    grep -Eq "^protocol +FACON$" <<<"$status" || fail "fatek-cli --sim status does not show FACON"

    local v
    v=$("$bin/fatek-cli" --version 2>&1)
    [ "$v" = "fatek-cli $version" ] || fail "fatek-cli --version says \"$v\", the package is $version"

    # The simulator on a free TCP port, queried by the CLI over the network.
    "$bin/fatek-sim" --tcp 0 --demo-ladder >"$work/sim.log" 2>&1 &
    sim_pid=$!
    local port="" _
    for _ in $(seq 1 100); do
        port=$(sed -n 's/^listening on tcp 127\.0\.0\.1:\([0-9]*\)$/\1/p' "$work/sim.log")
        [ -n "$port" ] && break
        sleep 0.1
    done
    [ -n "$port" ] || fail "fatek-sim did not start: $(cat "$work/sim.log")"
    echo "\$ fatek-cli --tcp 127.0.0.1:$port --protocol binary read R100 2"
    "$bin/fatek-cli" --tcp "127.0.0.1:$port" --protocol binary read R100 2 ||
        fail "fatek-cli could not read from fatek-sim"
    # The operator's shortcut: a link and a watch list given at start, values shown from fatek-sim.
    printf '{"format": "fatek-studio-watchlist", "version": 1, "tables": [{"name": "Line", "items": [{"address": "R100"}, {"address": "M0"}]}]}\n' \
        >"$work/startup.json"
    echo "\$ fatek-studio --tcp 127.0.0.1:$port startup.json --screenshot"
    local err
    err=$(HOME="$work/home" XDG_RUNTIME_DIR="$work/run" QT_QPA_PLATFORM=offscreen \
        timeout 120 "$bin/fatek-studio" --tcp "127.0.0.1:$port" --station 1 "$work/startup.json" \
        --screenshot "$work/startup.png" 2>&1 >/dev/null) ||
        fail "fatek-studio --tcp ... FILE --screenshot failed: $err"
    ! grep -q "no values arrived" <<<"$err" || fail "fatek-studio showed no values from fatek-sim: $err"
    file "$work/startup.png" | grep -q "PNG image data" || fail "no screenshot of the start-up list"
    kill "$sim_pid"
    wait "$sim_pid" || true
    sim_pid=""
    grep -q "^stopped$" "$work/sim.log" || fail "fatek-sim did not stop cleanly on SIGTERM"

    # The gateway: its version, and the configuration the package installs checks out.
    v=$("$bin/fatek-gateway" --version 2>&1)
    [ "$v" = "fatek-gateway $version" ] || fail "fatek-gateway --version says \"$v\""
    echo "\$ fatek-gateway --check $etc/fatek-gateway/config.json"
    "$bin/fatek-gateway" --check "$etc/fatek-gateway/config.json" ||
        fail "the installed gateway configuration does not check out"

    echo "\$ fatek-studio --version"
    v=$(QT_QPA_PLATFORM=offscreen "$bin/fatek-studio" --version 2>/dev/null)
    echo "$v"
    [ "$v" = "fatek-studio $version" ] || fail "fatek-studio --version says \"$v\""
    echo "\$ fatek-studio --demo --screenshot"
    HOME="$work/home" XDG_RUNTIME_DIR="$work/run" QT_QPA_PLATFORM=offscreen \
        timeout 120 "$bin/fatek-studio" --demo --screenshot "$work/shot.png" 2>/dev/null ||
        fail "fatek-studio --demo --screenshot failed"
    file "$work/shot.png" | grep -q "PNG image data" || fail "no screenshot written"
    file "$work/shot.png" | sed 's|.*: ||'
}

mkdir -p "$work/home" "$work/run"
chmod 700 "$work/run"
step "running from the temporary root"
check_tree "$root/usr/bin" "$root/etc"

# A real install only on CI (a throw-away machine), as root, and never over an installed copy.
if [ "${CI:-}" = true ] && [ "$(id -u)" -eq 0 ] && ! dpkg-query -W fatek-studio >/dev/null 2>&1; then
    step "installing with dpkg (CI)"
    real_install=1
    export DEBIAN_FRONTEND=noninteractive
    if ! dpkg -i "$deb"; then
        apt-get -f install -y -qq --no-install-recommends
    fi
    dpkg-query -W -f='${Status}\n' fatek-studio | grep -q "install ok installed" ||
        fail "dpkg did not install the package"
    check_tree /usr/bin /etc
    man -w fatek-cli >/dev/null || fail "man fatek-cli does not find the page"
    step "removing the package"
    dpkg -r fatek-studio
    real_install=0
    [ ! -e /usr/bin/fatek-cli ] || fail "dpkg -r left /usr/bin/fatek-cli behind"
else
    echo "(real dpkg -i skipped: only on CI as root without an installed fatek-studio)"
fi
step "OK"
