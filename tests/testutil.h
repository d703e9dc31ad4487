#pragma once

#include "core/protocol/request.h"

#include <QByteArray>
#include <QJsonObject>
#include <QList>
#include <QString>
#include <QStringList>

#include <span>

namespace TestUtil {

struct Vector
{
    QString what;
    Fatek::Bytes query;
    Fatek::Bytes response;
};

// Frames of tests/data/vectors.json for "binary" or "facon".
QList<Vector> loadVectors(const QString &protocol);

// "51 10 00 02" -> bytes.
Fatek::Bytes fromHex(const QString &hex);
// "<STX>0140C7<ETX>" -> bytes (only <STX> and <ETX> are recognised).
Fatek::Bytes fromFacon(const QString &text);
// Bytes -> "51 10 00 02" for failure messages.
QString toHex(std::span<const std::uint8_t> bytes);
// Bytes -> "<STX>0140C7<ETX>".
QString toFacon(std::span<const std::uint8_t> bytes);

// Points QSettings at INI files in `directory` under the test's own application name, so the
// developer's own settings never leak into a test (nor a test's into them).
void useTestSettings(const QString &directory, const QString &applicationName);

// One run of a command-line program: exit code (-1: did not start or end in time, -2: crashed),
// standard output and error.
struct ProgramRun
{
    int code = -1;
    QString out;
    QString err;

    QStringList lines() const;
    // The first line of standard output as a JSON object.
    QJsonObject json() const;
};

// Runs `program` with the event loop turning (an in-process simulator keeps answering); standard
// input is a pipe, not a terminal. Killed after `timeoutMs`.
ProgramRun runProgram(const QString &program, const QStringList &arguments, int timeoutMs = 30000);

} // namespace TestUtil
