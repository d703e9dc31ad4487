#pragma once

#include "clicontext.h"
#include "clioptions.h"

#include <QObject>

#include <map>
#include <memory>

namespace Fatek {

class CliCommand;

// Runs the steps of the command line in order: the shared context opens the link (or the
// embedded simulator), then each step goes to the command object of its kind (clicommands.cpp),
// one object per kind for every step of it; done() carries the exit code. Never blocks: the
// context's watchdog ends the program if the session stays silent longer than a request could
// possibly take.
class CliRunner : public QObject
{
    Q_OBJECT

public:
    explicit CliRunner(const CliOptions &options, QObject *parent = nullptr);
    ~CliRunner() override;

    // Call once the event loop runs (done() may follow at once).
    void start();
    // Ctrl-C / SIGTERM: a monitor ends as if its last cycle had come (exit 0, the data log
    // closed); any other command ends with ExitCode::Interrupted. Writes already accepted are
    // still sent when the session closes.
    void interrupt();
    // A further Ctrl-C goes to interrupt() instead of ending the program at once (the current
    // command has not undone a change to the PLC yet: a checkout's forced output).
    bool holdsInterrupts() const;

Q_SIGNALS:
    void done(int exitCode);

private:
    void runStep();
    // The current step succeeded: run the next one or end with 0.
    void stepDone();
    void onFinished(int exitCode);

    CliContext m_context;
    // Declared after the context: destroyed first (they cancel through its session).
    std::map<CliCommandKind, std::unique_ptr<CliCommand>> m_commands;
    CliCommand *m_current = nullptr;
    qsizetype m_stepIndex = 0;
};

} // namespace Fatek
