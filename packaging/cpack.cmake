# CPack: a .deb and a .tar.gz on Linux, an NSIS installer and a .zip on Windows.
#   cmake --build build/release && (cd build/release && cpack)      # both Linux packages
#   cd build/release && cpack -G DEB                                  # only the .deb
# See docs/packaging.md and docs/windows.md.

set(CPACK_PACKAGE_NAME fatek-studio)
set(CPACK_PACKAGE_VENDOR "FATEK Studio")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Commissioning and monitoring tool for FATEK PLCs")
set(CPACK_PACKAGE_DESCRIPTION
    "FATEK Studio talks to FATEK PLCs (FBs and compatible) over RS-232/RS-485, TCP and UDP with the FACON ASCII and the FATEK binary protocol: watch tables, RUN/STOP control, forcing, loop-back link test and a raw frame console. It includes fatek-cli, a scriptable command-line client, fatek-gateway, an MQTT gateway, and fatek-sim, a simulated PLC with fault injection for testing without hardware.")
set(CPACK_PACKAGE_INSTALL_DIRECTORY "FATEK Studio")
set(CPACK_STRIP_FILES ON) # the release preset is RelWithDebInfo: ship without the debug info
# The same contact as packaging/linux/copyright and changelog (a reserved .invalid domain until the
# project has a public address; lintian accepts it as a host name).
set(FATEK_PACKAGE_MAINTAINER "FATEK Studio developers <maintainers@fatek-studio.invalid>"
    CACHE STRING "Maintainer field of the .deb (Name <e-mail>)")
set(CPACK_PACKAGE_CONTACT "${FATEK_PACKAGE_MAINTAINER}")

if(WIN32)
    set(CPACK_GENERATOR "NSIS64;ZIP")
    include(${CMAKE_CURRENT_LIST_DIR}/windows/nsis.cmake)
else()
    set(CPACK_GENERATOR "DEB;TGZ")
endif()

# --- .tar.gz: bin/, share/ under fatek-studio-<version>-Linux-<arch>/ ---
set(CPACK_ARCHIVE_COMPONENT_INSTALL OFF)

# --- .deb ---
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # fatek-studio_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION electronics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${FATEK_PACKAGE_MAINTAINER}")
# CPack puts the summary on the first line itself; Debian wants the rest wrapped below 80 columns.
string(CONCAT CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "FATEK Studio talks to FATEK PLCs (FBs and compatible) over RS-232/RS-485,\n"
    "TCP and UDP with the FACON ASCII and the FATEK binary protocol: watch\n"
    "tables, RUN/STOP control, forcing, loop-back link test and a raw frame\n"
    "console. It includes fatek-cli, a scriptable command-line client,\n"
    "fatek-gateway, an MQTT gateway (systemd unit fatek-gateway.service), and\n"
    "fatek-sim, a simulated PLC with fault injection for testing without hardware.")
# The Qt libraries the executables link (libqt6core6, libqt6widgets6, libqt6serialport6 ...)
# come from dpkg-shlibdeps. What Qt loads as plugins it cannot see: the SVG icon engine and
# image format (every icon is an SVG) are in libqt6svg6; the xcb and offscreen platform
# plugins are in libqt6gui6, which shlibdeps already lists.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libqt6svg6 (>= 6.4)")
# qt6-qpa-plugins (VNC, touch) is what libqt6gui6 itself recommends; qt6-translations-l10n
# gives Qt's own dialogs (file, colour, message buttons) in the user's language.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "qt6-qpa-plugins, qt6-translations-l10n")
# Native Wayland; without it Qt runs through XWayland.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "qt6-wayland")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
# fatek-gateway's configuration (packaging/CMakeLists.txt): dpkg keeps the administrator's copy
# on upgrades and asks before replacing a changed one.
file(WRITE ${CMAKE_BINARY_DIR}/debian/conffiles
     "/etc/fatek-gateway/config.json\n/etc/fatek-gateway/line1.json\n")
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${CMAKE_BINARY_DIR}/debian/conffiles)

include(CPack)
