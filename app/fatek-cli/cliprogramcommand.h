#pragma once

#include "clicommand.h"
#include "core/commission/programtransfer.h"

#include <memory>

namespace Fatek {

struct CliStepArgs;

// backup FILE, restore FILE: the PLC's program (core's ProgramTransfer over 4F/50; the file is
// core's ProgramImage). Restore compares first, asks, then writes and verifies.
class CliProgramCommand : public CliCommand
{
    Q_OBJECT

public:
    using CliCommand::CliCommand;

    static QString parse(CliStepArgs &args);
    // Stopped between pages: the transfer says how far it got, then the program ends.
    void interrupt() override;

protected:
    void run() override;

private:
    void runBackup();
    void runRestore();
    // Restore, once the PLC's program is compared with the file: ask, then write.
    void confirmRestore(const ProgramImage &image, const ProgramTransferResult &check);
    void startTransfer();
    void showTransferProgress(int done, int total);
    // A backup, check or restore that did not succeed: its message and exit code.
    void failTransfer(const ProgramTransferResult &result);

    std::unique_ptr<ProgramTransfer> m_program;
    bool m_progressShown = false;
    bool m_interrupted = false;
    // restore: the pages are being written (before: read and compared, nothing written yet).
    bool m_writing = false;
};

} // namespace Fatek
