#include "clicommand.h"

#include "clicontext.h"

namespace Fatek {

CliCommand::CliCommand(CliContext &context)
    : m_context(context)
{}

CliCommand::~CliCommand() = default;

void CliCommand::start(const CliStep &step)
{
    m_step = &step;
    run();
}

void CliCommand::interrupt()
{
    m_context.endInterrupted();
}

const CliOptions &CliCommand::options() const
{
    return m_context.options();
}

CliOutput &CliCommand::out()
{
    return m_context.out();
}

void CliCommand::succeed()
{
    Q_EMIT succeeded();
}

void CliCommand::succeedWith(const OutputBlock &block)
{
    out().print(block);
    succeed();
}

} // namespace Fatek
