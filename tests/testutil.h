#pragma once

#include "core/protocol/request.h"

#include <QByteArray>
#include <QList>
#include <QString>

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

} // namespace TestUtil
