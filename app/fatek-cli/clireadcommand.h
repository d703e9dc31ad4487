#pragma once

#include "clicommand.h"

namespace Fatek {

struct CliStepArgs;

// read ADDR [COUNT] (consecutive elements, 44/46), read ADDR ADDR... (a mixed list, 48). Its
// parser also takes forced's arguments.
class CliReadCommand : public CliCommand
{
    Q_OBJECT

public:
    using CliCommand::CliCommand;

    static QString parse(CliStepArgs &args);

protected:
    void run() override;
};

} // namespace Fatek
