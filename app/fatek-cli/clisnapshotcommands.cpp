// fatek-cli commands on memory snapshots: snapshot, diff, restore-values (core/commission).
#include "clirunner.h"
#include "core/commission/commissionmessages.h"

#include "clitext.h"
#include "core/commission/snapshotreader.h"
#include "core/commission/valuesrestorer.h"
#include "core/qtbridge/qtmessage.h"

#include <QJsonArray>

namespace Fatek {

using namespace CliText;

namespace {

QString jsonValue(const std::optional<std::uint32_t> &v)
{
    return v ? QString::number(*v) : QString();
}

QString rangesText(const std::vector<SnapshotValue> &values)
{
    std::vector<Address> addresses;
    addresses.reserve(values.size());
    for (const SnapshotValue &v : values)
        addresses.push_back(v.address);
    QStringList parts;
    for (const AddressRange &r : Snapshot::rangesOf(addresses))
        parts << QString::fromStdString(r.toString());
    return parts.join(QStringLiteral(", "));
}

} // namespace

SnapshotReader *CliRunner::snapshotReader()
{
    if (!m_snapshotReader) {
        m_snapshotReader = std::make_unique<SnapshotReader>();
        m_snapshotReader->setSession(m_session.get());
        connect(m_snapshotReader.get(), &SnapshotReader::progress, this,
                [this] { armWatchdog(requestBudgetMs()); });
    }
    disconnect(m_snapshotReader.get(), &SnapshotReader::finished, this, nullptr);
    return m_snapshotReader.get();
}

void CliRunner::failWithError(const ProtocolError &error)
{
    failWith(SessionResult::fromError(error));
}

std::optional<MemorySnapshot> CliRunner::loadSnapshot(const QString &path)
{
    const SnapshotFile::Loaded loaded = SnapshotFile::loadFromFile(path);
    if (!loaded.ok()) {
        QJsonObject extra;
        extra.insert(QStringLiteral("kind"), QStringLiteral("SnapshotFile"));
        if (loaded.error.line > 0)
            extra.insert(QStringLiteral("line"), loaded.error.line);
        if (loaded.error.valueIndex > 0)
            extra.insert(QStringLiteral("value"), loaded.error.valueIndex);
        m_out.error(englishText(loaded.error.message), ExitCode::Usage, extra);
        finish(ExitCode::Usage);
        return std::nullopt;
    }
    return *loaded.snapshot;
}

void CliRunner::printDifferences(const std::vector<SnapshotDifference> &differences, bool readBack)
{
    const QString before = readBack ? QStringLiteral("written") : QStringLiteral("before");
    const QString after = readBack ? QStringLiteral("read") : QStringLiteral("after");
    OutputBlock block;
    block.columns = {QStringLiteral("address"), before, after};
    block.tableHeader = false;
    for (const SnapshotDifference &d : differences) {
        const QString address = addressText(d.address);
        if (m_options.format == OutputFormat::Table) {
            // "R0: 12 -> 15": the address first, as grep and diff readers expect.
            block.rows << QStringList{englishText(SnapshotDiff::line(d))};
        } else {
            block.rows << QStringList{address, jsonValue(d.before), jsonValue(d.after)};
        }
        QJsonObject json = itemJson(d.address);
        json.insert(before, d.before ? QJsonValue(static_cast<qint64>(*d.before)) : QJsonValue());
        json.insert(after, d.after ? QJsonValue(static_cast<qint64>(*d.after)) : QJsonValue());
        json.insert(before + QStringLiteral("Text"), SnapshotDiff::valueText(d.address, d.before));
        json.insert(after + QStringLiteral("Text"), SnapshotDiff::valueText(d.address, d.after));
        block.json << json;
    }
    if (m_options.format == OutputFormat::Table)
        block.columns = {QStringLiteral("difference")};
    if (!differences.empty() || m_options.format == OutputFormat::Csv)
        m_out.print(block);
}

// --- snapshot ------------------------------------------------------------------------------------

void CliRunner::runSnapshot()
{
    SnapshotReader *reader = snapshotReader();
    connect(reader, &SnapshotReader::finished, this, [this, reader] {
        if (m_done)
            return;
        m_watchdog.stop();
        if (!reader->ok())
            return failWithError(reader->error());
        const MemorySnapshot &s = reader->snapshot();
        if (const auto problem = SnapshotFile::saveToFile(s, step().file)) {
            m_out.error(englishText(problem->message), ExitCode::Internal);
            return finish(ExitCode::Internal);
        }
        OutputBlock block;
        block.columns = {QStringLiteral("field"), QStringLiteral("value")};
        block.tableHeader = false;
        block.rows << QStringList{QStringLiteral("file"), step().file}
                   << QStringList{QStringLiteral("values"), QString::number(s.values.size())}
                   << QStringList{QStringLiteral("requests"),
                                  QString::number(reader->requestsTotal())}
                   << QStringList{QStringLiteral("model"), s.info.model};
        QJsonObject json;
        json.insert(QStringLiteral("file"), step().file);
        json.insert(QStringLiteral("station"), m_options.station);
        json.insert(QStringLiteral("values"), static_cast<qint64>(s.values.size()));
        json.insert(QStringLiteral("requests"), reader->requestsTotal());
        json.insert(QStringLiteral("model"), s.info.model);
        block.json << json;
        m_out.print(block);
        stepDone();
    });
    armWatchdog(requestBudgetMs());
    reader->start(m_options.station, step().ranges);
}

// --- diff ----------------------------------------------------------------------------------------

void CliRunner::runDiff()
{
    const std::optional<MemorySnapshot> before = loadSnapshot(step().file);
    if (!before)
        return;
    // Differences end with exit 6 (like diff(1) ends with 1): scripts test for equality.
    auto report = [this](const MemorySnapshot &a, const MemorySnapshot &b) {
        std::size_t compared = 0;
        const auto differences = SnapshotDiff::compare(a, b, &compared);
        printDifferences(differences, false);
        m_out.note(englishText(SnapshotDiff::summary(differences.size(), compared)));
        if (!differences.empty())
            return finish(ExitCode::Differ);
        stepDone();
    };
    if (!step().file2.isEmpty()) {
        const std::optional<MemorySnapshot> after = loadSnapshot(step().file2);
        if (after)
            report(*before, *after);
        return;
    }
    std::vector<Address> addresses;
    addresses.reserve(before->values.size());
    for (const SnapshotValue &v : before->values)
        addresses.push_back(v.address);
    SnapshotReader *reader = snapshotReader();
    connect(reader, &SnapshotReader::finished, this, [this, reader, report, file = *before] {
        if (m_done)
            return;
        m_watchdog.stop();
        if (!reader->ok())
            return failWithError(reader->error());
        report(file, reader->snapshot());
    });
    armWatchdog(requestBudgetMs());
    reader->start(m_options.station, Snapshot::rangesOf(addresses));
}

// --- restore-values ------------------------------------------------------------------------------

void CliRunner::runRestoreValues()
{
    const std::optional<MemorySnapshot> file = loadSnapshot(step().file);
    if (!file)
        return;
    std::vector<SnapshotValue> values = file->toRestore(step().ranges);
    if (values.empty()) {
        failWithError(makeError(ErrorKind::InvalidRequest, msg<MsgId::RestoreNothing>()));
        return;
    }
    if (!m_restorer) {
        m_restorer = std::make_unique<ValuesRestorer>();
        m_restorer->setSession(m_session.get());
        connect(m_restorer.get(), &ValuesRestorer::progress, this,
                [this] { armWatchdog(requestBudgetMs()); });
    }
    disconnect(m_restorer.get(), &ValuesRestorer::finished, this, nullptr);
    ValuesRestorer *restorer = m_restorer.get();
    connect(restorer, &ValuesRestorer::finished, this, [this, restorer] {
        if (m_done)
            return;
        m_watchdog.stop();
        if (restorer->error())
            return failWithError(*restorer->error());
        printDifferences(restorer->mismatches(), true);
        m_out.note(englishText(restorer->outcome()));
        if (!restorer->ok())
            return finish(ExitCode::Differ);
        stepDone();
    });
    if (!m_options.readOnly) {
        // What will be written, then the one confirmation of dangerous commands.
        const auto frames = ValuesRestorer::writeRequests(m_options.station, values).size();
        m_out.note(QStringLiteral("restore-values: %1 values of %2 (%3) to station %4 in %5 write "
                                  "requests: %6")
                       .arg(values.size())
                       .arg(step().file, file->info.taken.toString(Qt::ISODate))
                       .arg(m_options.station)
                       .arg(frames)
                       .arg(rangesText(values)));
        m_watchdog.stop(); // a person may take their time
        switch (confirm(QStringLiteral("Write these values to the PLC?"), m_options.assumeYes)) {
        case Confirmation::Yes: break;
        case Confirmation::No:
            m_out.error(QStringLiteral("Not confirmed: nothing was written."), ExitCode::Usage);
            return finish(ExitCode::Usage);
        case Confirmation::NoTerminal:
            m_out.error(QStringLiteral("restore-values writes to the PLC: give --yes to confirm "
                                       "(standard input is not a terminal). Nothing was written."),
                        ExitCode::Usage);
            return finish(ExitCode::Usage);
        }
    }
    // In operator mode the restorer refuses at once (ErrorKind::ReadOnly, exit 5), nothing sent.
    armWatchdog(requestBudgetMs());
    restorer->start(m_options.station, std::move(values));
}

} // namespace Fatek
