#!/usr/bin/env bash
# Runs a command of this checkout inside a brand-new Debian 12 root (debootstrap --variant=minbase
# bookworm), as on a new user's machine: nothing is installed but what the command installs itself.
#   tools/fresh-root.sh                  runs tools/test.sh
#   tools/fresh-root.sh tools/demo.sh    any command, run from the checkout's copy in the root
# Needs root (it re-runs itself with sudo) and debootstrap (installed when missing).
# Environment: FRESH_ROOT_MIRROR (Debian mirror; default: the host's own, see host_mirror),
# FRESH_ROOT_CCACHE=DIR (a host directory bind-mounted as the root's ccache directory, and
# FATEK_CCACHE=1: repeated runs reuse the compiler's work; CI's cold figure is without it),
# FRESH_ROOT_WIN_PREFIX (the host's cross-built Qt of tools/windows/build-qt.sh, mounted read-only
# when given and it holds the current recipe; by default none, as on a new machine: the Windows
# part then unpacks ../shared/windows' packed prefix), FATEK_TIDY_COMMITS (passed on to
# tools/tidy.sh --changed), FRESH_ROOT_KEEP=1, FRESH_ROOT_DIR.
#
# The untouched debootstrap output is cached as a tarball in ~/.cache/fatek-studio/ and made again
# when older than 30 days; the root itself is unpacked anew every run and removed afterwards
# (FRESH_ROOT_KEEP=1 keeps it). The checkout (tracked and untracked files, not build/) and
# ../shared are copied in, as a clean clone would be. /proc, /dev (with /dev/pts for the serial
# ptys) and a tmpfs /tmp are mounted in a private mount and PID namespace: when the command ends,
# or this script is stopped in any way, the namespace ends and the mounts and processes with it.
set -euo pipefail

if [ "${1:-}" = --inside ]; then
    # Second stage, in the new namespaces: mount, then run the command as root of the new system.
    root=$2 dest=$3
    shift 3
    mount -t proc proc "$root/proc"
    mount --rbind /dev "$root/dev"
    mount -t tmpfs -o mode=1777 tmpfs "$root/tmp"
    ccache=0
    if [ -n "${FRESH_ROOT_CCACHE:-}" ]; then
        mkdir -p "$FRESH_ROOT_CCACHE" "$root/root/.cache/ccache"
        mount --bind "$FRESH_ROOT_CCACHE" "$root/root/.cache/ccache"
        ccache=1
    fi
    # The Windows cross build's Qt (tools/windows/build-qt.sh), read-only at the same path (its
    # pkg-config file names it), when the host has made it: tools/windows/ci.sh uses it.
    if [ -n "${FRESH_ROOT_WIN_PREFIX:-}" ] && [ -f "$FRESH_ROOT_WIN_PREFIX/fatek-prefix.txt" ]; then
        mkdir -p "$root$FRESH_ROOT_WIN_PREFIX"
        mount --bind -o ro "$FRESH_ROOT_WIN_PREFIX" "$root$FRESH_ROOT_WIN_PREFIX"
        win_prefix=$FRESH_ROOT_WIN_PREFIX
    fi
    exec chroot "$root" /usr/bin/env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
        HOME=/root LANG=C.UTF-8 TERM="${TERM:-dumb}" CI="${CI:-}" FATEK_TIDY_COMMITS="${FATEK_TIDY_COMMITS:-}" FATEK_CCACHE="$ccache" FATEK_WIN_PREFIX="${win_prefix:-/root/.cache/fatek-studio/qt6-mingw}" \
        /bin/bash -c 'cd "$0" && exec "$@"' "$dest" "$@"
fi

[ $# -gt 0 ] || set -- tools/test.sh
if [ "$(id -u)" -ne 0 ]; then
    exec sudo --preserve-env=CI,FATEK_TIDY_COMMITS,FRESH_ROOT_KEEP,FRESH_ROOT_DIR,FRESH_ROOT_MIRROR,FRESH_ROOT_CCACHE,FRESH_ROOT_WIN_PREFIX "$0" "$@"
fi
repo=$(cd "$(dirname "$0")/.." && pwd)
export FRESH_ROOT_WIN_PREFIX=${FRESH_ROOT_WIN_PREFIX:-}
say() { echo "== fresh-root: $*"; }

if ! command -v debootstrap >/dev/null; then
    say "installing debootstrap on the host"
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends debootstrap >/dev/null ||
        { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends debootstrap >/dev/null; }
fi

# The Debian mirror: FRESH_ROOT_MIRROR, else the first one the host's own apt sources use for
# bookworm (one-line sources.list and deb822 .sources files), so that a host behind a local
# mirror builds its root from it too; deb.debian.org only when the host names none.
host_mirror() {
    local f
    for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
        [ -f "$f" ] || continue
        awk '$1 == "deb" { i = 2; if ($i ~ /^\[/) { while ($i !~ /\]$/) i++; i++ }
                          if ($(i + 1) == "bookworm") { print $i; exit } }' "$f"
    done
    for f in /etc/apt/sources.list.d/*.sources; do
        [ -f "$f" ] || continue
        # deb822 stanzas are separated by blank lines; Enabled: no switches one off.
        awk 'BEGIN { RS = ""; FS = "\n" }
             { types = uris = suites = ""; on = 1
               for (i = 1; i <= NF; i++) {
                   if ($i ~ /^Types:/) types = $i
                   else if ($i ~ /^URIs:/) { uris = $i; sub(/^URIs:[ \t]*/, "", uris) }
                   else if ($i ~ /^Suites:/) suites = " " $i " "
                   else if ($i ~ /^Enabled:[ \t]*no/) on = 0 }
               if (on && types ~ /[ \t]deb([ \t]|$)/ && suites ~ /[ \t]bookworm[ \t]/) {
                   split(uris, u, /[ \t]+/); print u[1]; exit } }' "$f"
    done
}
mirror=${FRESH_ROOT_MIRROR:-$(host_mirror | head -1)}
mirror=${mirror:-http://deb.debian.org/debian}

arch=$(dpkg --print-architecture)
cache=${XDG_CACHE_HOME:-$HOME/.cache}/fatek-studio
# One cached root per mirror: the root's own sources.list names the mirror it came from.
tarball=$cache/debootstrap-bookworm-minbase-$arch-$(printf '%s' "$mirror" | md5sum | cut -c1-8).tar
mkdir -p "$cache"
if [ -z "$(find "$tarball" -mtime -30 2>/dev/null)" ]; then
    say "debootstrap --variant=minbase bookworm from $mirror (cached in $tarball)"
    fresh=$(mktemp -d "$cache/debootstrap.XXXXXX")
    debootstrap --variant=minbase bookworm "$fresh" "$mirror" >"$fresh.log" 2>&1 ||
        { tail -20 "$fresh.log" >&2; rm -rf --one-file-system "$fresh" "$fresh.log"; exit 1; }
    say "debootstrap took $((SECONDS / 60))m$((SECONDS % 60))s"
    chmod 755 "$fresh" # mktemp's 0700 would become the root's "/"
    tar -C "$fresh" -cf "$tarball.tmp" .
    mv "$tarball.tmp" "$tarball"
    rm -rf --one-file-system "$fresh" "$fresh.log"
fi

work=$(mktemp -d "${FRESH_ROOT_DIR:-/var/tmp}/fatek-fresh-root.XXXXXX")
root=$work/root
child=""
cleanup() {
    local status=$?
    if [ -n "$child" ]; then
        # unshare ignores SIGINT/SIGTERM while it waits for its child: SIGKILL it, and --kill-child
        # kills the namespace's first process, which takes every process in the namespace along.
        kill -KILL "$child" 2>/dev/null || true
        wait "$child" 2>/dev/null || true
    fi
    if findmnt -rno TARGET | grep -q "^$root/"; then
        echo "fresh-root: something is still mounted under $root; not removing it" >&2
        exit 1
    fi
    if [ "${FRESH_ROOT_KEEP:-0}" = 1 ]; then
        say "kept $root"
    else
        rm -rf --one-file-system "$work"
    fi
    exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

say "unpacking a new root in $root ($(date -r "$tarball" +%F) debootstrap)"
mkdir "$root"
tar -C "$root" -xf "$tarball"
# "/" as on every Debian machine: a tarball made from mktemp's folder says 0700, and then no
# other user can reach anything (PostgreSQL, which the tests run as nobody, could not start).
chmod 755 "$root"
cp /etc/resolv.conf "$root/etc/resolv.conf" # as DHCP would have set it on a new machine
# The root is thrown away: dpkg need not sync every file it unpacks to the disk.
echo force-unsafe-io >"$root/etc/dpkg/dpkg.cfg.d/fresh-root-unsafe-io"
dest=/work/$(basename "$repo")
mkdir -p "$root$dest"
git -C "$repo" ls-files -z --cached --others --exclude-standard |
    tar -C "$repo" --null --ignore-failed-read -T - -cf - 2>/dev/null | tar -C "$root$dest" -xf -
if [ -d "$repo/../shared" ]; then
    # (-L: a ../shared that is a symbolic link, or holds some, is copied as what it points to.)
    cp -aL "$repo/../shared" "$root/work/shared"
fi
installed=$(chroot "$root" dpkg-query -W -f='${Package}\n' | wc -l)
say "$installed Debian packages installed; root ready after $((SECONDS / 60))m$((SECONDS % 60))s; running $* in $dest"

unshare --mount --pid --fork --kill-child --propagation private -- "$0" --inside "$root" "$dest" "$@" &
child=$!
status=0
wait "$child" || status=$?
child=""
exit "$status"
