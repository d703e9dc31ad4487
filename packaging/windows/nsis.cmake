# NSIS installer (cpack -G NSIS64 on Windows, with NSIS 3 on the PATH). Included by
# packaging/cpack.cmake. It packs the install tree as it is: bin\ with the three executables,
# the Qt DLLs and plugins windeployqt put beside them (packaging/CMakeLists.txt) and, with
# MSVC, the Visual C++ runtime DLLs.

# A 64-bit installer (NSIS's amd64-unicode stub): it installs 64-bit programs, writes the native
# registry view, and needs no 32-bit half of Windows (or of Wine, which tools/windows/test.sh
# installs it under).
set(CPACK_NSIS_DEFINES "Target amd64-unicode")
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
# Watch lists are .json files (packaging/linux/fatek-studio.xml tells them apart by content), so
# the installer adds FATEK Studio to the "Open with" list of .json (OpenWithProgids) instead of
# taking .json over from the editor the user has.
set(_fatek_progid "Software\\\\Classes\\\\FatekStudio.WatchList")
set(CPACK_NSIS_EXTRA_INSTALL_COMMANDS "
  WriteRegStr SHCTX '${_fatek_progid}' '' 'FATEK Studio watch list'
  WriteRegStr SHCTX '${_fatek_progid}\\\\DefaultIcon' '' '$INSTDIR\\\\bin\\\\fatek-studio.exe,0'
  WriteRegStr SHCTX '${_fatek_progid}\\\\shell\\\\open\\\\command' '' '\\\"$INSTDIR\\\\bin\\\\fatek-studio.exe\\\" \\\"%1\\\"'
  WriteRegStr SHCTX 'Software\\\\Classes\\\\.json\\\\OpenWithProgids' 'FatekStudio.WatchList' ''
  System::Call 'shell32::SHChangeNotify(i 0x08000000, i 0, p 0, p 0)'")
set(CPACK_NSIS_EXTRA_UNINSTALL_COMMANDS "
  DeleteRegValue SHCTX 'Software\\\\Classes\\\\.json\\\\OpenWithProgids' 'FatekStudio.WatchList'
  DeleteRegKey SHCTX '${_fatek_progid}'
  System::Call 'shell32::SHChangeNotify(i 0x08000000, i 0, p 0, p 0)'")
set(CPACK_RESOURCE_FILE_LICENSE "${CMAKE_CURRENT_LIST_DIR}/notice.txt")
