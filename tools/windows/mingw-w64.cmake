# CMake toolchain for the Windows cross build (64-bit, MinGW-w64 from Debian, posix threads so
# that std::thread and std::mutex exist). Used for Qt (tools/windows/build-qt.sh), libmosquitto
# and the project (tools/windows/build.sh). (build-qt.sh compiles SQLite's amalgamation with the
# same x86_64-w64-mingw32-gcc-posix directly; FindSQLite3 finds it in the prefix through the
# roots below.)
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(_fatek_mingw x86_64-w64-mingw32)
set(CMAKE_C_COMPILER ${_fatek_mingw}-gcc-posix)
set(CMAKE_CXX_COMPILER ${_fatek_mingw}-g++-posix)
set(CMAKE_RC_COMPILER ${_fatek_mingw}-windres)
set(CMAKE_AR ${_fatek_mingw}-gcc-ar-posix CACHE FILEPATH "")
set(CMAKE_RANLIB ${_fatek_mingw}-gcc-ranlib-posix CACHE FILEPATH "")
# Headers and libraries of the target come from the MinGW sysroot and the folders the caller
# names in CMAKE_PREFIX_PATH (the cross-built Qt); programs (moc, rcc, lrelease) from the host.
set(CMAKE_FIND_ROOT_PATH /usr/${_fatek_mingw})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# The cross prefix (CMAKE_PREFIX_PATH) is a root too, and pkg-config (libmosquitto) looks there
# only: the host's Linux libmosquitto would otherwise be found and fail at link time.
foreach(_fatek_prefix IN LISTS CMAKE_PREFIX_PATH)
    list(APPEND CMAKE_FIND_ROOT_PATH ${_fatek_prefix})
    set(ENV{PKG_CONFIG_LIBDIR} "${_fatek_prefix}/lib/pkgconfig")
    set(ENV{PKG_CONFIG_PATH} "")
endforeach()
