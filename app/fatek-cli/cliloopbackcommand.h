#pragma once

#include "clicommand.h"
#include "core/session/loopbackstats.h"

namespace Fatek {

struct CliStepArgs;

// loopback [TEXT] [--count N]: round trips (4E), counted as the GUI's loopback dialog counts.
class CliLoopbackCommand : public CliCommand
{
    Q_OBJECT

public:
    using CliCommand::CliCommand;

    static QString parse(CliStepArgs &args);

protected:
    void run() override;

private:
    // The next round trip, or the statistics once every one has its outcome.
    void next();

    LoopbackStats m_stats;
    QString m_lastError;
};

} // namespace Fatek
