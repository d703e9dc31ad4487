#pragma once

#include "clicommand.h"

namespace Fatek {

struct CliStepArgs;

// set, reset, enable, disable ADDR: discrete control (42).
class CliControlCommand : public CliCommand
{
    Q_OBJECT

public:
    using CliCommand::CliCommand;

    static QString parse(CliStepArgs &args);

protected:
    void run() override;
    bool changesPlc() const override { return true; }
};

} // namespace Fatek
