#pragma once

#include "clicommand.h"

namespace Fatek {

// status: STATUS1 bits (40) and the detail status (53), which some PLCs refuse.
class CliStatusCommand : public CliCommand
{
    Q_OBJECT

public:
    using CliCommand::CliCommand;

protected:
    void run() override;
};

} // namespace Fatek
