# Sourced by tools/demo.sh and tools/test.sh: with FATEK_CCACHE=1 every configure gets ccache as
# the compiler launcher (ccache_args), for repeated runs on one machine; tools/fresh-root.sh sets
# it when FRESH_ROOT_CCACHE names a host directory to keep the cache in. Off by default: a cold
# build is what CI measures, and a cache miss costs a little.
ccache_args=()
if [ "${FATEK_CCACHE:-0}" = 1 ] && command -v ccache >/dev/null; then
    ccache_args=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    # The precompiled headers (cmake/FatekPch.cmake) are cached only with these.
    export CCACHE_SLOPPINESS=${CCACHE_SLOPPINESS:-pch_defines,time_macros,include_file_mtime,include_file_ctime}
    export CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-5G}
else
    # A build directory configured with the launcher keeps it otherwise: clear it.
    ccache_args=(-UCMAKE_CXX_COMPILER_LAUNCHER)
fi
