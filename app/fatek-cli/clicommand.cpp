#include "clicommand.h"

#include "clicontext.h"
#include "clitext.h"

#include <QJsonArray>

namespace Fatek {

CliCommand::CliCommand(CliContext &context)
    : m_context(context)
{}

CliCommand::~CliCommand() = default;

void CliCommand::start(const CliStep &step)
{
    m_step = &step;
    m_interruptAfterAnswer = false;
    run();
}

void CliCommand::interrupt()
{
    // A write on its way may already have reached the PLC: its answer says whether it did, and
    // comes within the request's timeout. A second Ctrl-C does not wait.
    if (changesPlc() && !m_interruptAfterAnswer && m_context.requests().pendingCount() > 0) {
        m_interruptAfterAnswer = true;
        return;
    }
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
    if (m_interruptAfterAnswer)
        return m_context.endInterrupted(); // the result is printed; no further step runs
    Q_EMIT succeeded();
}

void CliCommand::succeedWith(const OutputBlock &block)
{
    out().print(block);
    succeed();
}

void CliCommand::succeedWithElements(const Address &start, const std::vector<std::uint32_t> &values,
                                     const QString &column,
                                     const std::function<QString(std::uint32_t)> &text)
{
    OutputBlock block;
    block.columns = {QStringLiteral("station"), QStringLiteral("address"), column};
    QJsonArray all;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const Address a = start.advanced(static_cast<std::uint32_t>(i));
        block.rows << QStringList{m_context.stationText(), CliText::addressText(a),
                                  text(values[i])};
        all.append(static_cast<qint64>(values[i]));
    }
    QJsonObject json = m_context.itemJson(start);
    json.insert(column, all);
    block.json << json;
    succeedWith(block);
}

} // namespace Fatek
