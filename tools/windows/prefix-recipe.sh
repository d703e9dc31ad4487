# Sourced by tools/windows/build-qt.sh, pack-prefix.sh and ci.sh: what determines the cross-built
# prefix (versions, sources, patch selection, configure options, compiler), as data, and its
# recipe id, the hash of that data. A comment or a log line in the scripts changes nothing; a
# change of what is built changes the id, so a packed prefix is never taken for another.
# When build-qt.sh changes *how* it builds in a way these lines do not show, raise `layout`.

# Bumped by hand: 2 = relocatable (no build path inside, placeholders in text files).
prefix_layout=2
qt_version=6.4.2
mosquitto_version=2.0.11
sqlite_version=3.40.1
# Debian's source packages of qtbase, mosquitto and SQLite, with the patch selection of each:
# "package|series pattern|files pattern" (see apply_debian_patches in build-qt.sh).
debian_sources=(qt6-base mosquitto sqlite3)
patch_selection=(
    "qt6-base|^cve-|"
    "mosquitto|.|"
    "sqlite3|.|^(src|ext|test)/"
)
# Build paths are mapped away so that no DLL names the machine it was built on (__FILE__ in
# Q_ASSERT and qWarning's context); the PE header carries no link time.
reloc_cflags() { echo "-ffile-prefix-map=$1/= -ffile-prefix-map=$2/="; }
reloc_ldflags="-Wl,--no-insert-timestamp"
qtbase_options=(
    -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=ON
    -DQT_BUILD_EXAMPLES=OFF -DQT_BUILD_TESTS=OFF
    -DFEATURE_sql=OFF -DFEATURE_tabletevent=OFF -DFEATURE_dbus=OFF -DFEATURE_concurrent=OFF
    -DFEATURE_printsupport=OFF -DFEATURE_system_zlib=OFF -DINPUT_openssl=no
)
qt_modules=(qtserialport qtsvg qtcharts)
module_options=(-DQT_BUILD_EXAMPLES=OFF -DQT_BUILD_TESTS=OFF)
mosquitto_options=(
    -DCMAKE_BUILD_TYPE=Release
    -DWITH_TLS=OFF -DWITH_TLS_PSK=OFF -DWITH_CJSON=OFF -DWITH_BROKER=OFF -DWITH_APPS=OFF
    -DWITH_CLIENTS=OFF -DWITH_PLUGINS=OFF -DDOCUMENTATION=OFF -DWITH_LIB_CPP=OFF
    -DWITH_THREADING=OFF -DWITH_STATIC_LIBRARIES=OFF
)
# SQLite as Debian builds it (debian/rules' CFLAGS), so the journal's SQLite is the same on
# Windows as the host's libsqlite3-0; threads through Win32 mutexes.
sqlite_options=(
    -O2 -fno-strict-aliasing
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

# recipe_text THIRD_PARTY_DIR: the canonical description, one fact per line. Needs apt's source
# index (the deb-src entry of tools/windows/install-deps.sh) for the .dsc sums, the exact
# Debian sources apt-get source would fetch now: a security update gives a new recipe.
recipe_text() {
    local third=$1 p
    echo "layout $prefix_layout"
    echo "qt $qt_version; mosquitto $mosquitto_version; sqlite $sqlite_version"
    sed 's/^/module /' "$third/SHA256SUMS"
    apt-get source --print-uris "${debian_sources[@]}" 2>/dev/null |
        awk '$2 ~ /\.dsc$/ {print "debian " $2 " " $4}' | sort
    printf 'patches %s\n' "${patch_selection[@]}"
    echo "qtbase ${qtbase_options[*]}"
    echo "modules ${qt_modules[*]}: ${module_options[*]}"
    echo "mosquitto ${mosquitto_options[*]}"
    echo "sqlite ${sqlite_options[*]}"
    echo "flags $(reloc_cflags BUILD PREFIX) $reloc_ldflags"
    # The compiler, binutils, the MinGW runtime and the host Qt (moc, rcc, uic run at build time).
    for p in g++-mingw-w64-x86-64-posix gcc-mingw-w64-x86-64-posix-runtime binutils-mingw-w64-x86-64 \
        mingw-w64-x86-64-dev qt6-base-dev-tools; do
        echo "tool $p $(dpkg-query -W -f='${Version}' "$p" 2>/dev/null || echo missing)"
    done
    echo "toolchain $(grep -vE '^\s*(#|$)' "$(dirname "${BASH_SOURCE[0]}")/mingw-w64.cmake" | sha256sum | cut -c1-16)"
}

# recipe_id THIRD_PARTY_DIR: 16 hex digits of the text's SHA-256; fails when apt knows no
# Debian source (no deb-src entry), since the id would then not pin the sources.
recipe_id() {
    local text
    text=$(recipe_text "$1")
    [ "$(grep -c '^debian ' <<<"$text")" -eq ${#debian_sources[@]} ] || {
        echo "apt knows no source of ${debian_sources[*]}: is there a deb-src entry? (tools/windows/install-deps.sh)" >&2
        return 1
    }
    sha256sum <<<"$text" | cut -c1-16
}
