#pragma once

#include "clicommand.h"

namespace Fatek {

// forced ADDR [COUNT]: which discretes are disabled (forced) (43). It takes
// read's arguments (CliReadCommand::parse).
class CliForcedCommand : public CliCommand
{
    Q_OBJECT

public:
    using CliCommand::CliCommand;

protected:
    void run() override;
};

} // namespace Fatek
