#pragma once

#include "clioptions.h"
#include "clioutput.h"

#include <QObject>

#include <cstdint>
#include <functional>
#include <vector>

namespace Fatek {

class CliContext;

// One command of fatek-cli (or a small family sharing its state, such as backup and restore):
// its parser (a static parse(CliStepArgs &) listed in clicommands.cpp), its run and the printing
// of its result. The runner keeps one object per CliCommandKind and starts it for every step of
// that kind; the link, the output and the exit code are the shared CliContext's.
class CliCommand : public QObject
{
    Q_OBJECT

public:
    explicit CliCommand(CliContext &context);
    ~CliCommand() override;

    // Runs `step` (which lives as long as the runner): succeeded() follows when it succeeds,
    // else the context finishes the program; either may come at once.
    void start(const CliStep &step);
    // Ctrl-C / SIGTERM while this command's step runs: by default the program ends with
    // ExitCode::Interrupted. A command that changes the PLC with a request already sent
    // (changesPlc()) first waits for its answer and prints it: what reached the PLC is said.
    virtual void interrupt();
    // The program ends (a failure, an interrupt, the last step): stop what still runs.
    virtual void abandon() {}
    // Whether a further Ctrl-C must come to interrupt() rather than end the program at once:
    // something the command changed in the PLC is not undone yet (checkout: an output forced).
    virtual bool holdsInterrupts() const { return false; }

Q_SIGNALS:
    // The step succeeded: the next one may run.
    void succeeded();

protected:
    virtual void run() = 0;
    // Whether the command writes to the PLC (write, set/reset/enable/disable, run/stop).
    virtual bool changesPlc() const { return false; }

    const CliStep &step() const { return *m_step; }
    const CliOptions &options() const;
    CliOutput &out();
    // The step succeeded: the next one may run.
    void succeed();
    // Prints the command's result and succeeds.
    void succeedWith(const OutputBlock &block);
    // One row per element from `start` (station, address, `column`: text(value)) and one JSON
    // object with the values under `column`; then succeeds.
    void succeedWithElements(const Address &start, const std::vector<std::uint32_t> &values,
                             const QString &column,
                             const std::function<QString(std::uint32_t)> &text);

    CliContext &m_context;

private:
    const CliStep *m_step = nullptr;
    bool m_interruptAfterAnswer = false;
};

} // namespace Fatek
