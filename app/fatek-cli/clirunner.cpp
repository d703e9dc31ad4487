// fatek-cli: the step sequence. The link is CliContext's, the commands are cli*command.cpp.
#include "clirunner.h"

#include "clicommand.h"
#include "clicommands.h"

namespace Fatek {

CliRunner::CliRunner(const CliOptions &options, QObject *parent)
    : QObject(parent)
    , m_context(options)
{
    connect(&m_context, &CliContext::ready, this, &CliRunner::runStep);
    connect(&m_context, &CliContext::finished, this, &CliRunner::onFinished);
}

CliRunner::~CliRunner()
{
    // The scanner, program transfer, reader and restorer cancel through the session: the
    // commands go first.
    m_current = nullptr;
    m_commands.clear();
}

void CliRunner::start()
{
    m_context.open();
}

void CliRunner::interrupt()
{
    if (m_context.isDone())
        return;
    if (m_current)
        m_current->interrupt();
    else
        m_context.endInterrupted();
}

bool CliRunner::holdsInterrupts() const
{
    return !m_context.isDone() && m_current && m_current->holdsInterrupts();
}

void CliRunner::runStep()
{
    const CliStep &step = m_context.options().steps.at(m_stepIndex);
    std::unique_ptr<CliCommand> &command = m_commands[step.command];
    if (!command) {
        command = createCommand(step.command, m_context);
        connect(command.get(), &CliCommand::succeeded, this, &CliRunner::stepDone);
    }
    m_current = command.get();
    command->start(step);
}

void CliRunner::stepDone()
{
    if (m_context.isDone())
        return;
    if (m_stepIndex + 1 >= m_context.options().steps.size())
        return m_context.finish(ExitCode::Ok);
    ++m_stepIndex;
    runStep();
}

void CliRunner::onFinished(int exitCode)
{
    for (const auto &[kind, command] : m_commands)
        command->abandon();
    Q_EMIT done(exitCode);
}

} // namespace Fatek
