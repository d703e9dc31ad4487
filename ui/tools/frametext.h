#pragma once

#include "result.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace Fatek {

// Text forms of raw frames for the console: hex and ASCII views, parsing what a user types, and a
// lenient look at a frame's station and command (also for broken frames, which the codecs reject).
class FrameText
{
public:
    struct Header
    {
        quint8 station = 0;
        quint8 command = 0;
    };

    // "02 30 31 34 30 43 37 03"
    static QString toHex(const QByteArray &bytes);
    // "<STX>0140C7<ETX>": printable ASCII as is, control characters by name, others as <xx>.
    static QString toAscii(const QByteArray &bytes);

    // "01 46 03 52 00 0C", "0146035200 0C", "0x01,0x46": pairs of hex digits, separators ignored.
    static Result<QByteArray> parseHex(const QString &text);
    // Printable ASCII plus <STX>/<ETX>/<CR>... and <1F>-style escapes, as toAscii() writes them.
    static Result<QByteArray> parseAscii(const QString &text);

    // Station and command of a FACON (STX ...) or binary (51/52 10 ...) frame, checksum not
    // checked.
    static std::optional<Header> header(const QByteArray &frame);
    // Station and command of a body typed for automatic framing, in the given protocol.
    static std::optional<Header> bodyHeader(const QByteArray &body, bool facon);
};

} // namespace Fatek
