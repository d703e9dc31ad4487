# Puts what the MinGW-built programs load beside them, in the install tree (also CPack's staging
# tree): the DLLs they import, found by following the import tables (objdump -p) through the cross
# Qt's bin/ and the MinGW runtime; the Qt plugins they load at run time (which no import table
# names); Qt's own translations for the app's languages. This is the cross build's windeployqt:
# Qt's tool is a Windows program and Debian's host Qt does not ship it.
#
# Run as `cmake -P` or from install(CODE) with: FATEK_DEPLOY_BIN (the folder of the executables),
# FATEK_DEPLOY_EXES (their names), FATEK_QT_PREFIX (the cross Qt), FATEK_DEPLOY_SEARCH (more folders
# with DLLs: the MinGW runtime; libmosquitto and SQLite are in the cross Qt's bin/), FATEK_OBJDUMP, FATEK_QT_TRANSLATIONS (folder of the
# qtbase_*.qm files; optional), FATEK_DEPLOY_LANGUAGES.
cmake_minimum_required(VERSION 3.25)

foreach(_var FATEK_DEPLOY_BIN FATEK_DEPLOY_EXES FATEK_QT_PREFIX FATEK_OBJDUMP)
    if(NOT DEFINED ${_var} OR "${${_var}}" STREQUAL "")
        message(FATAL_ERROR "mingwdeploy.cmake: ${_var} is not set")
    endif()
endforeach()

# What Qt loads by name: the Windows platform (and the offscreen one, for runs without a
# desktop), the native style, SVG icons and images (every icon is an SVG), TLS through Windows'
# Schannel (QSslSocket; MQTT's TLS is libmosquitto's own, not built here).
set(_plugins
    platforms/qwindows.dll
    platforms/qoffscreen.dll
    styles/qwindowsvistastyle.dll
    iconengines/qsvgicon.dll
    imageformats/qsvg.dll
    imageformats/qico.dll
    tls/qschannelbackend.dll
    tls/qcertonlybackend.dll)

set(_search ${FATEK_QT_PREFIX}/bin ${FATEK_DEPLOY_SEARCH})
# Index of every DLL in the search folders by lower-case name (Windows names are not
# case-sensitive, and import tables spell them as the linker saw them).
foreach(_dir IN LISTS _search)
    file(GLOB _dlls "${_dir}/*.dll")
    foreach(_dll IN LISTS _dlls)
        get_filename_component(_name "${_dll}" NAME)
        string(TOLOWER "${_name}" _key)
        if(NOT DEFINED _where_${_key})
            set(_where_${_key} "${_dll}")
        endif()
    endforeach()
endforeach()

set(_queue "")
foreach(_exe IN LISTS FATEK_DEPLOY_EXES)
    if(NOT EXISTS "${FATEK_DEPLOY_BIN}/${_exe}")
        message(FATAL_ERROR "mingwdeploy.cmake: ${FATEK_DEPLOY_BIN}/${_exe} does not exist")
    endif()
    list(APPEND _queue "${FATEK_DEPLOY_BIN}/${_exe}")
endforeach()
foreach(_plugin IN LISTS _plugins)
    set(_from "${FATEK_QT_PREFIX}/plugins/${_plugin}")
    if(NOT EXISTS "${_from}")
        message(FATAL_ERROR "mingwdeploy.cmake: the cross Qt has no plugin ${_plugin} (${_from})")
    endif()
    get_filename_component(_kind "${_plugin}" DIRECTORY)
    file(COPY "${_from}" DESTINATION "${FATEK_DEPLOY_BIN}/${_kind}")
    list(APPEND _queue "${FATEK_DEPLOY_BIN}/${_plugin}")
endforeach()

set(_copied "")
while(_queue)
    list(POP_FRONT _queue _file)
    execute_process(COMMAND "${FATEK_OBJDUMP}" -p "${_file}" OUTPUT_VARIABLE _dump
                    RESULT_VARIABLE _rc ERROR_VARIABLE _err)
    if(NOT _rc EQUAL 0)
        message(FATAL_ERROR "mingwdeploy.cmake: ${FATEK_OBJDUMP} -p ${_file} failed: ${_err}")
    endif()
    string(REGEX MATCHALL "DLL Name: [^\r\n]+" _imports "${_dump}")
    foreach(_import IN LISTS _imports)
        string(REPLACE "DLL Name: " "" _name "${_import}")
        string(STRIP "${_name}" _name)
        string(TOLOWER "${_name}" _key)
        # Not in the search folders: a DLL of Windows itself (KERNEL32, USER32, msvcrt ...).
        if(NOT DEFINED _where_${_key} OR _key IN_LIST _copied)
            continue()
        endif()
        list(APPEND _copied "${_key}")
        file(COPY "${_where_${_key}}" DESTINATION "${FATEK_DEPLOY_BIN}")
        get_filename_component(_base "${_where_${_key}}" NAME)
        list(APPEND _queue "${FATEK_DEPLOY_BIN}/${_base}")
    endforeach()
endwhile()
list(LENGTH _copied _count)
message(STATUS "mingwdeploy: ${_count} DLLs and ${FATEK_DEPLOY_BIN}/{platforms,styles,...} plugins")

if(FATEK_QT_TRANSLATIONS)
    # Qt finds its translations at <prefix>/translations, the prefix being the folder above the
    # one that holds Qt6Core.dll.
    get_filename_component(_top "${FATEK_DEPLOY_BIN}" DIRECTORY)
    foreach(_lang IN LISTS FATEK_DEPLOY_LANGUAGES)
        if(EXISTS "${FATEK_QT_TRANSLATIONS}/qtbase_${_lang}.qm")
            file(COPY "${FATEK_QT_TRANSLATIONS}/qtbase_${_lang}.qm" DESTINATION "${_top}/translations")
        endif()
    endforeach()
endif()
