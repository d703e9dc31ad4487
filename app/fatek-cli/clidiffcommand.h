#pragma once

#include "clisnapshotfilecommand.h"

namespace Fatek {

struct CliStepArgs;

// diff FILE [FILE2]: differences, one line per element: FILE against the PLC, or against FILE2
// (no link needed). Differences end with exit 6.
class CliDiffCommand : public CliSnapshotFileCommand
{
    Q_OBJECT

public:
    using CliSnapshotFileCommand::CliSnapshotFileCommand;

    static QString parse(CliStepArgs &args);

protected:
    void run() override;
};

} // namespace Fatek
