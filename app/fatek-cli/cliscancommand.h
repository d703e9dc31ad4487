#pragma once

#include "clicommand.h"
#include "core/session/stationscanner.h"

#include <memory>

namespace Fatek {

struct CliStepArgs;

// scan [FROM..TO]: which stations answer.
class CliScanCommand : public CliCommand
{
    Q_OBJECT

public:
    using CliCommand::CliCommand;

    static QString parse(CliStepArgs &args);
    void abandon() override;

protected:
    void run() override;

private:
    std::unique_ptr<StationScanner> m_scanner;
};

} // namespace Fatek
