#!/usr/bin/env bash
# Packs the cross-built prefix of tools/windows/build-qt.sh for other machines:
#   tools/windows/pack-prefix.sh [OUT_DIR]     default build/windows-pack
# writes OUT_DIR/qt6-mingw-<recipe>.tar.zst, adds its sum to OUT_DIR/SHA256SUMS and a line to
# OUT_DIR/README.md (recipe, versions, patches, size). Placed in ../shared/windows/, it is what
# build-qt.sh (and so CI) unpacks instead of building for 50 minutes.
# The archive names no path of this machine: the text files that name the prefix (CMake
# packages, qmake's .pri/.prl, qt-cmake) get a placeholder that unpack-prefix.sh replaces with
# the prefix it unpacks to, and the packing fails when any file, binary or text, still names the
# prefix, the build folder, the checkout or the home folder. Entries are sorted, owned by root
# and dated SOURCE_DATE_EPOCH, so the same prefix packs to the same bytes.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
prefix=${FATEK_WIN_PREFIX:-$HOME/.cache/fatek-studio/qt6-mingw}
work=${FATEK_WIN_WORK:-$HOME/.cache/fatek-studio/win-work}
out=${1:-$root/build/windows-pack}
stamp=$prefix/fatek-prefix.txt
placeholder=@FATEK_WIN_PREFIX@
# Where qmake's .prl files and QT_SOURCE_TREE name the build folder, which no user of the prefix
# reads (they serve building Qt itself): a fixed name that is nobody's machine.
gone=/nonexistent/fatek-win-work
[ -f "$stamp" ] || { echo "no cross-built prefix in $prefix: make it with tools/windows/build-qt.sh" >&2; exit 2; }
recipe=$(sed -n 's/^recipe //p' "$stamp")
[ -n "$recipe" ] || { echo "$stamp names no recipe: make the prefix again with tools/windows/build-qt.sh" >&2; exit 2; }
command -v zstd >/dev/null || { echo "needs zstd" >&2; exit 2; }
mkdir -p "$out"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/fatek-pack.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
cp -a "$prefix" "$tmp/qt6-mingw"
cd "$tmp/qt6-mingw"
# Text files only (grep -I): a binary that names the prefix cannot be mended by substitution.
mapfile -t texts < <(grep -rlIF -- "$prefix" . | sed 's|^\./||' | sort)
for f in "${texts[@]}"; do
    sed -i "s|$prefix|$placeholder|g" "$f"
done
printf '%s\n' "${texts[@]}" >fatek-relocate.txt
grep -rlIF -- "$work" . | while read -r f; do sed -i "s|$work|$gone|g" "$f"; done
# Nothing may name this machine any more (binaries included: grep -a). (The home folder as the
# start of a path: "$$[QT_SYSROOT]/root/modules" in a device's qmake.conf is not /root.)
leaks=$(grep -rlaF -e "$prefix" -e "$work" -e "$root/" . || true)
leaks+=$(grep -rlaE "(^|[^A-Za-z0-9_.\$)\]-])$HOME/" . || true)
if [ -n "$leaks" ]; then
    echo "!! these files still name a path of this machine ($prefix, $work, $root or $HOME):" >&2
    echo "$leaks" | head -20 >&2
    exit 1
fi
cd "$tmp"
name=qt6-mingw-$recipe.tar.zst
epoch=${SOURCE_DATE_EPOCH:-1672531200}
tar --sort=name --mtime="@$epoch" --owner=0 --group=0 --numeric-owner \
    --pax-option=exthdr.name=%d/PaxHeaders/%f,delete=atime,delete=ctime -cf - qt6-mingw |
    zstd -q -19 -T0 >"$out/$name.tmp"
mv "$out/$name.tmp" "$out/$name"
sum=$(cd "$out" && sha256sum "$name")
{ [ ! -f "$out/SHA256SUMS" ] || grep -vF "  $name" "$out/SHA256SUMS" || true; echo "$sum"; } >"$tmp/sums"
mv "$tmp/sums" "$out/SHA256SUMS"
size=$(du -m "$out/$name" | cut -f1)
line="- \`$name\`: recipe $recipe; $(sed -n 's/^qt /Qt /p;' "$stamp" | head -1); $(sed -n 's/^sqlite /SQLite /p' "$stamp" | head -1); $(sed -n "s/^Debian's patches applied: /patches: /p" "$stamp"); $size MB; ${#texts[@]} text files relocated"
{
    [ -f "$out/README.md" ] && grep -vF "\`$name\`" "$out/README.md" ||
        printf '# Cross-built prefixes for the Windows part of CI\n\ntools/windows/build-qt.sh unpacks the one whose recipe it computes (tools/windows/prefix-recipe.sh) instead of building it.\n\n'
    echo "$line"
} >"$tmp/readme"
mv "$tmp/readme" "$out/README.md"
echo "$line"
echo "packed $out/$name"
