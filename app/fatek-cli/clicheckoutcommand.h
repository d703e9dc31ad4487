#pragma once

#include "clicommand.h"

#include <memory>

namespace Fatek {

class CheckoutRunner;
struct CliStepArgs;

// checkout PLAN: an I/O checkout through CheckoutRunner (core/commission). PLAN is a checkout file
// (.json: resumed and saved as it goes), a plan CSV or ranges ("X0..X15, Y0..Y7"). Inputs are
// watched in any order until each has gone 0->1 and 1->0; outputs are forced one at a time and
// the technician's answer is asked on the terminal (or read from standard input with --yes);
// analog points are read at both ends when the person says so. Then the report (--report).
class CliCheckoutCommand : public CliCommand
{
    Q_OBJECT

public:
    explicit CliCheckoutCommand(CliContext &context);
    ~CliCheckoutCommand() override;

    static QString parse(CliStepArgs &args);
    void interrupt() override;
    void abandon() override;

protected:
    void run() override;
    bool changesPlc() const override { return true; }

private:
    void inputsDone();
    void nextOutput();
    void nextAnalog();
    void finishCheckout(int exitCode);
    // One line from the person: on a terminal asked on stderr; with --yes from standard input.
    QString ask(const QString &question);
    bool canAsk() const;

    std::unique_ptr<CheckoutRunner> m_runner;
    std::vector<int> m_outputs;
    std::vector<int> m_analogs;
    std::size_t m_nextOutput = 0;
    std::size_t m_nextAnalog = 0;
    bool m_inputsDone = false;
    bool m_finishing = false;
    bool m_reported = false;
    int m_exitCode = 0;
};

} // namespace Fatek
