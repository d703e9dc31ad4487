#pragma once

#include "clicommand.h"

#include <functional>
#include <memory>
#include <vector>

namespace Fatek {

class CheckoutRunner;
class CliCheckoutInputs;
struct CliStepArgs;

// checkout PLAN: an I/O checkout through CheckoutRunner (core/commission). PLAN is a checkout file
// (.json: resumed and saved as it goes), a plan CSV or ranges ("X0..X15, Y0..Y7"). Inputs are
// asked one at a time (CliCheckoutInputs); outputs are forced one at a time and the technician's
// answer is asked (CliCheckoutAnswer's keys) on the terminal (or read from standard input with
// --yes); analog points are read at each check of their scale, again as left after an adjustment
// when a reading is outside the tolerance. Then the report (--report) and the punch list
// (--punch). Points the PLC refuses end it before anything is forced (exit 2).
// The questions never block the event loop (CliLineReader): Ctrl-C at any of them releases the
// output under test at once and records nothing for it. The program does not end while an output
// it forced is not confirmed released (the runner retries), unless the person says to leave it.
class CliCheckoutCommand : public CliCommand
{
    Q_OBJECT

public:
    explicit CliCheckoutCommand(CliContext &context);
    ~CliCheckoutCommand() override;

    static QString parse(CliStepArgs &args);
    void interrupt() override;
    void abandon() override;
    bool holdsInterrupts() const override;

protected:
    void run() override;
    bool changesPlc() const override { return true; }

private:
    void nextOutput();
    void nextAnalog();
    // Asks for check `check` of an analog point, reads it, then the next check.
    void askAnalog(int index, int check);
    // Reads the check (as found, or as left after an adjustment); sayReading() once it is in.
    void readAnalog(int index, int check, bool asLeft);
    // Says the reading; outside the tolerance, offers to read it again as left.
    void sayReading(int index, int check);
    // "Seen in the field?" for the output forced.
    void askSeen(int index);
    // Stops, releases what is forced, then writeReport() and the end.
    void finishCheckout(int exitCode);
    // A release keeps failing: asks whether to leave the output forced and end.
    void askLeaveForced();
    void leaveForced();
    void writeReport();
    // Asks on stderr; `answer` gets the line (trimmed), `noAnswer` runs at the end of input. The
    // lines come from a terminal or, with --yes, from standard input.
    void ask(const QString &question, std::function<void(const QString &)> answer,
             std::function<void()> noAnswer);
    bool canAsk() const;
    QString forcedText() const; // "Y1, Y4"

    std::unique_ptr<CheckoutRunner> m_runner;
    std::unique_ptr<CliCheckoutInputs> m_inputs;
    std::vector<int> m_outputs;
    std::vector<int> m_analogs;
    std::size_t m_nextOutput = 0;
    std::size_t m_nextAnalog = 0;
    bool m_finishing = false;
    bool m_reported = false;
    bool m_leftForced = false; // the person chose to leave an output forced
    int m_exitCode = 0;
};

} // namespace Fatek
