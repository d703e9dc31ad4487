#pragma once

#include "clicommand.h"

#include <QByteArray>

namespace Fatek {

struct CliStepArgs;

// raw HEX|ASCII [--frame] [--hex|--ascii]: sends bytes as they are (or framed), shows the answer.
class CliRawCommand : public CliCommand
{
    Q_OBJECT

public:
    using CliCommand::CliCommand;

    static QString parse(CliStepArgs &args);
    // "01 40 0A" (two-digit hex tokens, or one token starting 0x / hex:) -> bytes; else the ASCII
    // text with <02>/<STX> escapes (FrameText::parse). `hex` (if given) tells which of the two it
    // was.
    static QByteArray parseRawText(const QString &text, bool forceHex, bool forceAscii,
                                   QString *error, bool *hex = nullptr);

protected:
    void run() override;
};

} // namespace Fatek
