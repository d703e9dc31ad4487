#pragma once

#include "clicommand.h"

namespace Fatek {

struct CliStepArgs;

// write ADDR[:FORMAT] VALUE...: consecutive elements (45/47), typed as in a watch table.
class CliWriteCommand : public CliCommand
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
