// fatek-cli restore-values.
#include "clirestorevaluescommand.h"

#include "clicontext.h"
#include "clitext.h"
#include "core/commission/commissionmessages.h"
#include "core/commission/valuesrestorer.h"
#include "core/qtbridge/qtmessage.h"

namespace Fatek {

using namespace CliText;

namespace {

QString rangesText(const std::vector<SnapshotValue> &values)
{
    std::vector<Address> addresses;
    addresses.reserve(values.size());
    for (const SnapshotValue &v : values)
        addresses.push_back(v.address);
    return QString::fromStdString(Snapshot::rangesText(addresses));
}

} // namespace

CliRestoreValuesCommand::CliRestoreValuesCommand(CliContext &context)
    : CliSnapshotFileCommand(context)
{}

CliRestoreValuesCommand::~CliRestoreValuesCommand() = default;

void CliRestoreValuesCommand::run()
{
    m_interrupted = false;
    const std::optional<MemorySnapshot> file = loadSnapshot(step().file);
    if (!file)
        return;
    std::vector<SnapshotValue> values = file->toRestore(step().ranges);
    if (values.empty()) {
        m_context.failWithError(makeError(ErrorKind::InvalidRequest, msg<MsgId::RestoreNothing>()));
        return;
    }
    ValuesRestorer *restorer = worker(m_restorer);
    connect(restorer, &ValuesRestorer::finished, this, [this, restorer] {
        if (m_context.isDone())
            return;
        m_context.stopWatchdog();
        if (m_interrupted) {
            out().error(englishText(restorer->outcome()), ExitCode::Interrupted);
            return m_context.finish(ExitCode::Interrupted);
        }
        if (restorer->refusedForModel()) {
            out().error(englishText(restorer->outcome())
                            + QStringLiteral(" Give --other-model to write it all the same."),
                        ExitCode::Usage);
            return m_context.finish(ExitCode::Usage);
        }
        if (restorer->error())
            return m_context.failWithError(*restorer->error());
        printDifferences(restorer->mismatches(), true);
        out().note(englishText(restorer->outcome()));
        if (!restorer->ok())
            return m_context.finish(ExitCode::Differ);
        succeed();
    });
    if (!options().readOnly) {
        // What will be written, then the one confirmation of dangerous commands.
        const auto frames = ValuesRestorer::writeRequests(m_context.station(), values).size();
        // Counts with their nouns (1 value, 1 write request) and the date only when the file
        // has one.
        const QString taken
            = file->info.taken.isValid()
                  ? QStringLiteral(" (%1)").arg(file->info.taken.toString(Qt::ISODate))
                  : QString();
        out().note(QStringLiteral("restore-values: %1 of %2%3 to station %4 in %5: %6")
                       .arg(values.size() == 1 ? QStringLiteral("1 value")
                                               : QStringLiteral("%1 values").arg(values.size()),
                            step().file, taken)
                       .arg(m_context.station())
                       .arg(frames == 1 ? QStringLiteral("1 write request")
                                        : QStringLiteral("%1 write requests").arg(frames))
                       .arg(rangesText(values)));
        m_context.stopWatchdog(); // a person may take their time
        switch (confirm(QStringLiteral("Write these values to the PLC?"), options().assumeYes)) {
        case Confirmation::Yes: break;
        case Confirmation::No:
            out().error(QStringLiteral("Not confirmed: nothing was written."), ExitCode::Usage);
            return m_context.finish(ExitCode::Usage);
        case Confirmation::NoTerminal:
            out().error(QStringLiteral("restore-values writes to the PLC: give --yes to confirm "
                                       "(standard input is not a terminal). Nothing was written."),
                        ExitCode::Usage);
            return m_context.finish(ExitCode::Usage);
        }
    }
    // In operator mode the restorer refuses at once (ErrorKind::ReadOnly, exit 5), nothing sent.
    m_context.armWatchdog(m_context.requestBudgetMs());
    restorer->setAllowOtherModel(options().otherModel);
    restorer->start(m_context.station(), std::move(values), file->info.model);
}

void CliRestoreValuesCommand::interrupt()
{
    if (m_restorer && m_restorer->isRunning()) {
        m_interrupted = true;
        m_restorer->cancel(); // finished() at once: the handler above reports it
        return;
    }
    CliSnapshotFileCommand::interrupt();
}

void CliRestoreValuesCommand::abandon()
{
    CliSnapshotFileCommand::abandon();
    if (m_restorer)
        m_restorer->cancel();
}

} // namespace Fatek
