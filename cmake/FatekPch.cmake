# Precompiled headers (issue 28; figures in docs/development.md). Parsing the standard library and
# Qt's headers is a large part of every translation unit's compile time: a test program is one .cpp
# that parses QtTest (and QtWidgets) for a few hundred lines of its own.
#
# A few owners build a PCH; every other target of the same kind reuses the owner's (REUSE_FROM), so
# the 50 test programs share two PCHs instead of parsing the headers 50 times. A PCH is only valid
# with the compile options it was built with; GCC checks the macros it depends on and
# -Winvalid-pch with -Werror turns a mismatch into a build error, so a wrong grouping cannot pass
# unnoticed. Owners therefore carry the fewest macros of their kind (clang rejects a PCH that
# defines a macro the user of the PCH does not).
#
# The libraries' PCHs are clang's only: clang reads a PCH lazily and builds core/ in half the time
# with them, while GCC maps the whole 160-200 MB file into every compiler run and gained nothing
# (the user time it saved went to the kernel). The tests' PCHs pay with both compilers.
#
# The forced include hides a source's missing #include: tools/tidy.sh checks every source without
# the PCH, and -DFATEK_PCH=OFF builds without any.
option(FATEK_PCH "Build with precompiled headers" ON)
# The libraries' PCHs: by default with clang only (see above); a preset may turn them on.
if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    set(_fatek_pch_libraries_default ON)
else()
    set(_fatek_pch_libraries_default OFF)
endif()
option(FATEK_PCH_LIBRARIES "Precompiled headers for the libraries too" ${_fatek_pch_libraries_default})

# The standard headers most of core/ includes (fatekprotocol and fatekplanner stay Qt-free).
set(FATEK_PCH_STD
    <algorithm> <array> <cstdint> <functional> <map> <memory> <optional> <span> <string>
    <string_view> <utility> <vector>)
# Qt Core and Network: the simulator, sessions, watch lists, commissioning, MQTT, the apps.
set(FATEK_PCH_QTCORE ${FATEK_PCH_STD}
    <QByteArray> <QDateTime> <QElapsedTimer> <QFile> <QHash> <QJsonArray> <QJsonDocument>
    <QJsonObject> <QList> <QMetaType> <QObject> <QPointer> <QString> <QStringList> <QTimer>
    <QTcpSocket>)
set(FATEK_PCH_QTWIDGETS ${FATEK_PCH_QTCORE}
    <QAction> <QComboBox> <QDialog> <QDialogButtonBox> <QFileDialog> <QHBoxLayout> <QHeaderView>
    <QLabel> <QLineEdit> <QMenu> <QMessageBox> <QPushButton> <QSettings> <QSpinBox> <QTableView>
    <QVBoxLayout> <QWidget>)
set(FATEK_PCH_QTTEST ${FATEK_PCH_QTCORE}
    <QProcess> <QSignalSpy> <QTcpServer> <QTemporaryDir> <QTest>)
set(FATEK_PCH_QTTESTWIDGETS ${FATEK_PCH_QTTEST} ${FATEK_PCH_QTWIDGETS} <QApplication>)
list(REMOVE_DUPLICATES FATEK_PCH_QTTESTWIDGETS)

# fatek_pch(TARGET KIND): TARGET builds its own PCH of kind KIND (STD, QTCORE, QTWIDGETS: a
# library's, QTTEST, QTTESTWIDGETS: the tests'). fatek_pch(TARGET REUSE OWNER): TARGET uses OWNER's,
# if OWNER (defined before) has one.
function(fatek_pch target kind)
    if(NOT FATEK_PCH)
        return()
    endif()
    if(kind STREQUAL "REUSE")
        get_target_property(owner_headers ${ARGV2} PRECOMPILE_HEADERS)
        if(owner_headers)
            target_precompile_headers(${target} REUSE_FROM ${ARGV2})
        endif()
    elseif(kind MATCHES "^QTTEST" OR FATEK_PCH_LIBRARIES)
        target_precompile_headers(${target} PRIVATE ${FATEK_PCH_${kind}})
    endif()
endfunction()
