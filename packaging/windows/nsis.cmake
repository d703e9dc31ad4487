# NSIS installer (cpack -G NSIS64 on Windows, with NSIS 3 on the PATH). Included by
# packaging/cpack.cmake. It packs the install tree as it is: bin\ with the three executables,
# the Qt DLLs and plugins windeployqt put beside them (packaging/CMakeLists.txt) and, with
# MSVC, the Visual C++ runtime DLLs.

set(CPACK_NSIS_PACKAGE_NAME "FATEK Studio ${PROJECT_VERSION}")
set(CPACK_NSIS_DISPLAY_NAME "FATEK Studio")
set(CPACK_NSIS_INSTALLED_ICON_NAME "bin\\\\fatek-studio.exe")
set(CPACK_NSIS_MUI_ICON "${FATEK_WINDOWS_ICON}")
set(CPACK_NSIS_MUI_UNIICON "${FATEK_WINDOWS_ICON}")
set(CPACK_NSIS_ENABLE_UNINSTALL_BEFORE_INSTALL ON)
set(CPACK_NSIS_MODIFY_PATH ON) # offers to put bin\ on the PATH for fatek-cli and fatek-sim
set(CPACK_NSIS_MUI_FINISHPAGE_RUN "fatek-studio.exe")
set(CPACK_NSIS_MENU_LINKS
    "bin/fatek-studio.exe" "FATEK Studio")
# A second Start-menu entry that opens the demo (embedded simulator), like the Linux
# desktop action.
set(CPACK_NSIS_CREATE_ICONS_EXTRA
    "CreateShortCut '$SMPROGRAMS\\\\$STARTMENU_FOLDER\\\\FATEK Studio (demo).lnk' '$INSTDIR\\\\bin\\\\fatek-studio.exe' '--demo'")
set(CPACK_NSIS_DELETE_ICONS_EXTRA
    "Delete '$SMPROGRAMS\\\\$START_MENU\\\\FATEK Studio (demo).lnk'")
set(CPACK_RESOURCE_FILE_LICENSE "${CMAKE_CURRENT_LIST_DIR}/notice.txt")
