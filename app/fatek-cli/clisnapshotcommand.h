#pragma once

#include "clisnapshotfilecommand.h"

namespace Fatek {

// snapshot FILE [RANGES]: saves element values to FILE (.json or .csv).
class CliSnapshotCommand : public CliSnapshotFileCommand
{
    Q_OBJECT

public:
    using CliSnapshotFileCommand::CliSnapshotFileCommand;

protected:
    void run() override;
};

} // namespace Fatek
