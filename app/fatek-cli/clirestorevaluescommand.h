#pragma once

#include "clisnapshotfilecommand.h"

#include <memory>

namespace Fatek {

class ValuesRestorer;

// restore-values FILE [RANGES]: writes FILE's values back after a confirmation, then reads them
// back and compares.
class CliRestoreValuesCommand : public CliSnapshotFileCommand
{
    Q_OBJECT

public:
    explicit CliRestoreValuesCommand(CliContext &context);
    ~CliRestoreValuesCommand() override;

    void abandon() override;
    // Ctrl-C while writing: the restore stops and says how many values it wrote.
    void interrupt() override;

protected:
    void run() override;

private:
    std::unique_ptr<ValuesRestorer> m_restorer;
    bool m_interrupted = false;
};

} // namespace Fatek
