#pragma once

#include "clicommand.h"
#include "core/protocol/request.h"
#include "core/session/session.h"

namespace Fatek {

// status: STATUS1 bits (40) and the detail status (53), which some PLCs refuse.
class CliStatusCommand : public CliCommand
{
    Q_OBJECT

public:
    using CliCommand::CliCommand;

protected:
    void run() override;

private:
    // The brief status (40), and the detail status (53) or why there is none.
    void report(const Bytes &briefBytes, const SessionResult &detail);
};

} // namespace Fatek
