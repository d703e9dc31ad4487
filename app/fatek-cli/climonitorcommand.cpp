// fatek-cli monitor: planned polling, one line per cycle, optional CSV log.
#include "climonitorcommand.h"

#include "clicommands.h"
#include "clicontext.h"
#include "clitext.h"
#include "core/watch/watchlist.h"

#include <QDateTime>
#include <QJsonArray>

namespace Fatek {

using namespace CliText;

// monitor ADDR[:FORMAT]...
QString CliMonitorCommand::parse(CliStepArgs &a)
{
    CliStep &s = a.step;
    for (const QString &text : std::as_const(a.positional)) {
        // "R0..R3:hex": a format after the colon applies to every element of the argument.
        const qsizetype colon = text.indexOf(QLatin1Char(':'));
        std::optional<DisplayFormat> format;
        if (colon >= 0) {
            format = ValueFormat::fromName(text.mid(colon + 1).trimmed());
            if (!format)
                return QStringLiteral("Unknown format \"%1\" in %2 (%3).")
                    .arg(text.mid(colon + 1), text, CliText::formatNames());
        }
        auto more = WatchList::expandRange(colon >= 0 ? text.left(colon) : text);
        if (!more)
            return CliText::error(more.error());
        s.addresses += more.value();
        for (qsizetype n = 0; n < more.value().size(); ++n)
            s.formats << format;
    }
    if (s.addresses.size() > WatchList::MaxRangeItems)
        return QStringLiteral("monitor watches at most %1 elements.").arg(WatchList::MaxRangeItems);
    return {};
}

QString CliMonitorCommand::resolveItems(CliStep &step, const CliOptions &o)
{
    for (qsizetype i = 0; i < step.addresses.size(); ++i) {
        WatchItemSpec item;
        item.address = step.addresses.at(i);
        item.station = o.station;
        item.format = step.formats.value(i).value_or(
            o.valueFormat.value_or(ValueFormat::defaultFormat(item.address)));
        // A global --format that does not fit an element (bit for R0) falls back to the
        // element's default; a format asked for that element alone must fit.
        if (!step.formats.value(i) && ValueFormat::valueWidth(item.address, item.format) == 0)
            item.format = ValueFormat::defaultFormat(item.address);
        // Station 0 is refused before for monitor; validate with a real one.
        WatchItemSpec check = item;
        check.station = 1;
        if (const Status valid = WatchList::validateEntry(check); !valid)
            return CliText::error(valid.error());
        step.items << item;
    }
    return {};
}

CliMonitorCommand::CliMonitorCommand(CliContext &context)
    : CliCommand(context)
{
    connect(m_context.session(), &Session::values, this, &CliMonitorCommand::onValues);
}

void CliMonitorCommand::run()
{
    m_cycle = 0;
    m_staleCycles = 0;
    m_errors = false;
    m_context.setPolling(true);
    QStringList columns{QStringLiteral("cycle"), QStringLiteral("time")};
    QList<int> widths{5, 12};
    const QList<WatchItemSpec> &items = step().items;
    // The assembler's keys are the indexes into items (a float over R100 polls R100 and R101).
    QList<WatchedItem> watched;
    for (qsizetype i = 0; i < items.size(); ++i) {
        const WatchItemSpec &item = items.at(i);
        watched.append({static_cast<std::uint64_t>(i), item, options().intervalMs});
        columns << (item.name.isEmpty() ? addressText(item.address) : DataLogger::columnName(item));
        const int width = ItemValues(item).width();
        widths << (width == 1 ? 1 : width <= 16 ? 6 : 12);
    }
    m_items.setItems({}); // fresh poll ids: nothing of an earlier monitor step applies
    m_items.setItems(watched);
    const QList<WatchEntry> entries = m_items.pollEntries();
    if (!options().outputPath.isEmpty() && !m_logger.isOpen()) {
        // Every row reaches the disk at once: an interrupted monitor loses nothing.
        m_logger.setFlushIntervalMs(0);
        if (const Status s
            = m_logger.open(options().outputPath, items,
                            options().crlf ? CsvFile::LineEnd::CrLf : CsvFile::LineEnd::Lf);
            !s) {
            // A file that cannot be written (no such folder, a read-only medium, a full disk) is
            // exit 1, like every file not written; another log's columns is a usage error.
            const int code = m_logger.writeFailed() || m_logger.fileProblem() ? ExitCode::Internal
                                                                              : ExitCode::Usage;
            out().error(QString::fromStdString(s.error().text()), code);
            return m_context.finish(code);
        }
    }
    if (options().format == OutputFormat::Csv)
        out().line(DataLogger::headerLine(items));
    else
        out().beginStream(columns, widths);
    armForNextCycle(entries.size());
    m_context.session()->setWatchList(entries);
}

void CliMonitorCommand::onValues(const QList<WatchValue> &values)
{
    if (m_context.isDone() || !m_context.isPolling())
        return;
    ++m_cycle;
    const QList<WatchItemSpec> &items = step().items;
    // An item the cycle brought nothing of has no value this cycle.
    QList<DataLogger::Cell> cells(items.size());
    QList<Message> cellErrors(items.size());
    for (DataLogger::Cell &c : cells) {
        c.quality = DataLogger::Quality::Missing;
        c.reason = QStringLiteral("no value this cycle");
    }
    for (const WatchItemValue &v : m_items.assemble(values)) {
        const auto item = static_cast<qsizetype>(v.key);
        if (item >= items.size())
            continue;
        DataLogger::Cell &cell = cells[item];
        cell.raw = v.raw;
        cell.quality = DataLogger::qualityOf(v.quality);
        cell.reason = v.quality == ValueQuality::Good ? QString() : englishText(v.error);
        cellErrors[item] = v.error;
    }
    const QDateTime now = QDateTime::currentDateTime();
    QStringList tableCells{QString::number(m_cycle), now.toString(QStringLiteral("HH:mm:ss.zzz"))};
    QJsonArray jsonValues, jsonTexts, jsonAddresses, jsonQualities;
    bool anyGood = false;
    QString staleReason;
    bool stationSilent = false; // the stale reason is the poller's "polled again at ..."
    QStringList late;           // the elements shown late this cycle, said in one line
    QString lateReason;
    for (qsizetype i = 0; i < items.size(); ++i) {
        DataLogger::Cell &cell = cells[i];
        const WatchItemSpec &item = items.at(i);
        const QString name = addressText(item.address);
        jsonAddresses.append(name);
        jsonQualities.append(DataLogger::qualityName(cell.quality));
        if (cell.quality == DataLogger::Quality::Good) {
            anyGood = true;
            const QString text = DataLogger::valueText(item, cell.raw);
            tableCells << text;
            jsonValues.append(static_cast<qint64>(cell.raw));
            jsonTexts.append(text);
            continue;
        }
        if (cell.quality == DataLogger::Quality::Late) {
            // The last value read, said to be old: the line is behind (issue 31).
            const QString text = DataLogger::valueText(item, cell.raw);
            tableCells << QStringLiteral("%1 (late)").arg(text);
            jsonValues.append(static_cast<qint64>(cell.raw));
            jsonTexts.append(text);
            late << name;
            lateReason = cell.reason;
            continue;
        }
        tableCells << QStringLiteral("?");
        jsonValues.append(QJsonValue::Null);
        jsonTexts.append(QJsonValue::Null);
        if (cell.quality == DataLogger::Quality::Error)
            m_errors = true;
        else {
            staleReason = cell.reason;
            stationSilent = cellErrors.value(i).id == MsgId::SessionStationDemoted;
        }
        if (!m_reported.contains(name + cell.reason)) {
            m_reported.insert(name + cell.reason);
            out().note(QStringLiteral("%1: %2").arg(name, cell.reason));
        }
    }
    // Late elements: one line naming them, not one line each, and again only when other
    // elements fall behind (the table marks every late value anyway).
    if (!late.isEmpty() && late != m_lastLate)
        out().note(QStringLiteral("%1: %2").arg(late.join(QStringLiteral(", ")), lateReason));
    m_lastLate = late;
    if (m_logger.isOpen()) {
        // A log that cannot be written (full disk) is said at once; the values go on on stdout,
        // and the program ends with exit 1 (file not written) when the monitor ends.
        if (const Status s = m_logger.writeRow(now, cells); !s)
            out().error(QString::fromStdString(s.error().text()), ExitCode::Internal);
    }
    QJsonObject json;
    json.insert(QStringLiteral("cycle"), m_cycle);
    json.insert(QStringLiteral("time"), DataLogger::timestampText(now)); // as the CSV log
    json.insert(QStringLiteral("station"), m_context.station());
    json.insert(QStringLiteral("addresses"), jsonAddresses);
    json.insert(QStringLiteral("values"), jsonValues);
    json.insert(QStringLiteral("text"), jsonTexts);
    json.insert(QStringLiteral("quality"), jsonQualities);
    if (options().format == OutputFormat::Csv)
        out().line(DataLogger::rowLine(now, items, cells));
    else
        out().streamRow(tableCells, json);

    // Nothing read for three cycles in a row: the link is gone for practical purposes. A station
    // the poller has put to rest left 3 requests in a row unanswered already, and its next
    // values come only with its next probe: that is the end too.
    m_staleCycles = (!anyGood && !staleReason.isEmpty()) ? m_staleCycles + 1 : 0;
    if (m_staleCycles >= 3 || (!anyGood && stationSilent)) {
        // The program ends here: the poller's "polled again at ..." would not happen.
        const QString why = stationSilent ? QStringLiteral("station %1 does not answer on %2.")
                                                .arg(m_context.stationText(), m_context.linkName())
                                          : staleReason;
        out().error(QStringLiteral("Nothing read for 3 cycles: %1").arg(why), ExitCode::Link);
        return m_context.finish(ExitCode::Link);
    }
    if (options().cycles > 0 && m_cycle >= options().cycles) {
        if (m_errors)
            out().note(QStringLiteral("Some elements were refused by the PLC (see above)."));
        if (m_errors)
            return m_context.finish(ExitCode::Plc);
        m_context.session()->setWatchList({});
        m_context.setPolling(false);
        if (closeLog())
            succeed();
        return;
    }
    armForNextCycle(step().addresses.size());
}

void CliMonitorCommand::armForNextCycle(qsizetype elements)
{
    m_context.armWatchdog(options().intervalMs
                          + m_context.requestBudgetMs() * (1 + static_cast<int>(elements) / 16));
}

bool CliMonitorCommand::closeLog()
{
    const bool saidBefore = m_logger.writeFailed();
    if (const Status s = m_logger.close(); !s) {
        if (!saidBefore)
            out().error(QString::fromStdString(s.error().text()), ExitCode::Internal);
        m_context.finish(ExitCode::Internal);
        return false;
    }
    return true;
}

void CliMonitorCommand::interrupt()
{
    if (!m_context.isPolling())
        return CliCommand::interrupt();
    m_context.setPolling(false);
    if (m_errors)
        out().note(QStringLiteral("Some elements were refused by the PLC (see above)."));
    if (closeLog())
        m_context.finish(m_errors ? ExitCode::Plc : ExitCode::Ok);
}

void CliMonitorCommand::abandon()
{
    m_logger.close(); // a monitor ended by an error keeps the rows it logged
}

} // namespace Fatek
