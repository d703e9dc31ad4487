#pragma once

#include "clicommand.h"

namespace Fatek {

// run, stop: switches the PLC to RUN or STOP (41).
class CliRunStopCommand : public CliCommand
{
    Q_OBJECT

public:
    using CliCommand::CliCommand;

protected:
    void run() override;
    bool changesPlc() const override { return true; }
};

} // namespace Fatek
