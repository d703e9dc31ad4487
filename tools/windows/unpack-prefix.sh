#!/usr/bin/env bash
# Unpacks a prefix packed by tools/windows/pack-prefix.sh:
#   tools/windows/unpack-prefix.sh ARCHIVE PREFIX
# checks the archive against the SHA256SUMS beside it when one lists it, unpacks beside PREFIX,
# puts PREFIX's path in place of the packing placeholder in the files fatek-relocate.txt lists,
# and only then moves the result to PREFIX: an interrupted unpacking leaves no half prefix.
set -euo pipefail
archive=$1 prefix=$2
placeholder=@FATEK_WIN_PREFIX@
name=$(basename "$archive")
dir=$(dirname "$archive")
if [ -f "$dir/SHA256SUMS" ] && grep -qF "  $name" "$dir/SHA256SUMS"; then
    (cd "$dir" && grep -F "  $name" SHA256SUMS | sha256sum -c --quiet -) ||
        { echo "!! $archive does not match its sum in $dir/SHA256SUMS" >&2; exit 1; }
fi
mkdir -p "$(dirname "$prefix")"
tmp=$(mktemp -d "$prefix.unpack.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
zstd -dc "$archive" | tar -xf - -C "$tmp"
[ -f "$tmp/qt6-mingw/fatek-prefix.txt" ] && [ -f "$tmp/qt6-mingw/fatek-relocate.txt" ] ||
    { echo "!! $archive is not a packed prefix (no fatek-prefix.txt or fatek-relocate.txt)" >&2; exit 1; }
while read -r f; do
    [ -n "$f" ] || continue
    sed -i "s|$placeholder|$prefix|g" "$tmp/qt6-mingw/$f"
done <"$tmp/qt6-mingw/fatek-relocate.txt"
rm -rf "$prefix"
mv "$tmp/qt6-mingw" "$prefix"
echo "unpacked $name into $prefix ($(sed -n 's/^recipe //p' "$prefix/fatek-prefix.txt"))"
