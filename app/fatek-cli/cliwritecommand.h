#pragma once

#include "clicommand.h"

namespace Fatek {

struct CliStepArgs;

// write ADDR[:FORMAT] VALUE...: consecutive elements (45/47), typed as in a watch table; up to
// 1,024 of them, in as many requests as it takes (as read).
class CliWriteCommand : public CliCommand
{
    Q_OBJECT

public:
    using CliCommand::CliCommand;

    static QString parse(CliStepArgs &args);

protected:
    void run() override;
    bool changesPlc() const override { return true; }

private:
    // Sends the values from index `done` on, one request's worth at a time.
    void writePart(std::size_t done);
};

} // namespace Fatek
