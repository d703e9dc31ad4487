// fatek-cli: what snapshot, diff and restore-values share.
#include "clisnapshotfilecommand.h"

#include "clicommands.h"
#include "clicontext.h"
#include "clitext.h"
#include "core/commission/snapshotfile.h"
#include "core/commission/snapshotreader.h"
#include "core/qtbridge/qtmessage.h"

namespace Fatek {

using namespace CliText;

namespace {

QString jsonValue(const std::optional<std::uint32_t> &v)
{
    return v ? QString::number(*v) : QString();
}

} // namespace

CliSnapshotFileCommand::CliSnapshotFileCommand(CliContext &context)
    : CliCommand(context)
{}

CliSnapshotFileCommand::~CliSnapshotFileCommand() = default;

// RANGES: every further argument, "R0..R99, X0..X255" or "R0..R99 X0..X255".
QString CliSnapshotFileCommand::rangesArg(CliStepArgs &a, qsizetype from)
{
    // An argument given blank (an unset shell variable in quotes) is a mistake, not "every
    // element": restore-values FILE "" would write the whole file.
    for (const QString &arg : a.positional.mid(from)) {
        if (arg.trimmed().isEmpty())
            return QStringLiteral("%1: RANGES is empty; give the ranges (\"R0..R99\") or leave "
                                  "the argument out for every element.")
                .arg(a.cmd());
    }
    const QString text = a.positional.mid(from).join(QLatin1Char(' '));
    const auto ranges = Snapshot::parseRanges(text);
    if (!ranges)
        return QStringLiteral("%1: %2").arg(a.cmd(), CliText::error(ranges.error()));
    a.step.ranges = ranges.value();
    return {};
}

bool CliSnapshotFileCommand::isSnapshotFileName(const QString &path)
{
    return SnapshotFile::formatFor(path).has_value();
}

// A snapshot file name: .json or .csv, or a device (written and read as JSON).
QString CliSnapshotFileCommand::snapshotFileArg(CliStepArgs &a, const QString &path, QString *out)
{
    if (!SnapshotFile::formatFor(path) && !isDevice(path))
        return QStringLiteral("%1: \"%2\" is not a .json or .csv file name.").arg(a.cmd(), path);
    *out = path;
    return {};
}

// snapshot FILE [RANGES], restore-values FILE [RANGES]
QString CliSnapshotFileCommand::parseFileAndRanges(CliStepArgs &a)
{
    if (QString err = snapshotFileArg(a, a.positional.at(0), &a.step.file); !err.isEmpty())
        return err;
    return rangesArg(a, 1);
}

void CliSnapshotFileCommand::rearmWatchdog()
{
    m_context.armWatchdog(m_context.requestBudgetMs());
}

void CliSnapshotFileCommand::readSnapshot(std::vector<AddressRange> ranges, ReadHandler onRead)
{
    SnapshotReader *reader = worker(m_reader);
    connect(reader, &SnapshotReader::finished, this, [this, reader, onRead = std::move(onRead)] {
        if (m_context.isDone())
            return;
        m_context.stopWatchdog();
        if (!reader->ok())
            return m_context.failWithError(reader->error());
        onRead(*reader);
    });
    m_context.armWatchdog(m_context.requestBudgetMs());
    reader->start(m_context.station(), std::move(ranges));
}

std::optional<MemorySnapshot> CliSnapshotFileCommand::loadSnapshot(const QString &path)
{
    const SnapshotFile::Loaded loaded = SnapshotFile::loadFromFile(path);
    if (!loaded.ok()) {
        QJsonObject extra;
        extra.insert(QStringLiteral("kind"), QStringLiteral("SnapshotFile"));
        if (loaded.error.line > 0)
            extra.insert(QStringLiteral("line"), loaded.error.line);
        if (loaded.error.valueIndex > 0)
            extra.insert(QStringLiteral("value"), loaded.error.valueIndex);
        out().error(englishText(loaded.error.message), ExitCode::Usage, extra);
        m_context.finish(ExitCode::Usage);
        return std::nullopt;
    }
    return *loaded.snapshot;
}

void CliSnapshotFileCommand::printDifferences(const std::vector<SnapshotDifference> &differences,
                                              bool readBack)
{
    const QString before = readBack ? QStringLiteral("written") : QStringLiteral("before");
    const QString after = readBack ? QStringLiteral("read") : QStringLiteral("after");
    OutputBlock block;
    block.columns = {QStringLiteral("address"), before, after};
    block.tableHeader = false;
    for (const SnapshotDifference &d : differences) {
        const QString address = addressText(d.address);
        if (options().format == OutputFormat::Table) {
            // "R0: 12 -> 15": the address first, as grep and diff readers expect.
            block.rows << QStringList{englishText(SnapshotDiff::line(d))};
        } else {
            block.rows << QStringList{address, jsonValue(d.before), jsonValue(d.after)};
        }
        QJsonObject json = m_context.itemJson(d.address);
        json.insert(before, d.before ? QJsonValue(static_cast<qint64>(*d.before)) : QJsonValue());
        json.insert(after, d.after ? QJsonValue(static_cast<qint64>(*d.after)) : QJsonValue());
        json.insert(before + QStringLiteral("Text"), SnapshotDiff::valueText(d.address, d.before));
        json.insert(after + QStringLiteral("Text"), SnapshotDiff::valueText(d.address, d.after));
        block.json << json;
    }
    if (options().format == OutputFormat::Table)
        block.columns = {QStringLiteral("difference")};
    if (!differences.empty() || options().format == OutputFormat::Csv)
        out().print(block);
}

void CliSnapshotFileCommand::abandon()
{
    if (m_reader)
        m_reader->cancel();
}

} // namespace Fatek
