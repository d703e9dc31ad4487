// fatek-cli monitor: planned polling, one line per cycle, optional CSV log.
#include "clirunner.h"

#include "clitext.h"
#include "core/protocol/plcstatus.h"

#include <QDateTime>
#include <QJsonArray>

namespace Fatek {

using namespace CliText;

void CliRunner::runMonitor()
{
    m_cycle = 0;
    m_staleCycles = 0;
    m_monitorErrors = false;
    m_monitoring = true;
    QStringList columns{QStringLiteral("cycle"), QStringLiteral("time")};
    QList<int> widths{5, 12};
    const QList<WatchItemSpec> &items = step().items;
    // The assembler's keys are the indexes into items (a float over R100 polls R100 and R101).
    QList<WatchedItem> watched;
    for (qsizetype i = 0; i < items.size(); ++i) {
        const WatchItemSpec &item = items.at(i);
        watched.append({static_cast<std::uint64_t>(i), item, m_options.intervalMs});
        columns << (item.name.isEmpty() ? addressText(item.address) : DataLogger::columnName(item));
        const int width = ItemValues(item).width();
        widths << (width == 1 ? 1 : width <= 16 ? 6 : 12);
    }
    m_monitorItems.setItems({}); // fresh poll ids: nothing of an earlier monitor step applies
    m_monitorItems.setItems(watched);
    const QList<WatchEntry> entries = m_monitorItems.pollEntries();
    if (!m_options.outputPath.isEmpty() && !m_logger.isOpen()) {
        // Every row reaches the disk at once: an interrupted monitor loses nothing.
        m_logger.setFlushIntervalMs(0);
        if (const Status s = m_logger.open(m_options.outputPath, items); !s) {
            m_out.error(QString::fromStdString(s.error().text()), ExitCode::Usage);
            return finish(ExitCode::Usage);
        }
    }
    if (m_options.format == OutputFormat::Csv)
        m_out.line(DataLogger::headerLine(items));
    else
        m_out.beginStream(columns, widths);
    armWatchdog(m_options.intervalMs
                + requestBudgetMs() * (1 + static_cast<int>(entries.size()) / 16));
    m_session->setWatchList(entries);
}

void CliRunner::onValues(const QList<WatchValue> &values)
{
    if (m_done || !m_monitoring || step().command != CliCommand::Monitor)
        return;
    ++m_cycle;
    const QList<WatchItemSpec> &items = step().items;
    // An item the cycle brought nothing of has no value this cycle.
    QList<DataLogger::Cell> cells(items.size());
    for (DataLogger::Cell &c : cells) {
        c.quality = DataLogger::Quality::Missing;
        c.reason = QStringLiteral("no value this cycle");
    }
    for (const WatchItemValue &v : m_monitorItems.assemble(values)) {
        const auto item = static_cast<qsizetype>(v.key);
        if (item >= items.size())
            continue;
        DataLogger::Cell &cell = cells[item];
        cell.raw = v.raw;
        cell.quality = DataLogger::qualityOf(v.quality);
        cell.reason = v.quality == ValueQuality::Good ? QString() : englishText(v.error);
    }
    const QDateTime now = QDateTime::currentDateTime();
    QStringList tableCells{QString::number(m_cycle), now.toString(QStringLiteral("HH:mm:ss.zzz"))};
    QJsonArray jsonValues, jsonTexts, jsonAddresses;
    bool anyGood = false;
    QString staleReason;
    for (qsizetype i = 0; i < items.size(); ++i) {
        DataLogger::Cell &cell = cells[i];
        const WatchItemSpec &item = items.at(i);
        const QString name = addressText(item.address);
        jsonAddresses.append(name);
        if (cell.quality == DataLogger::Quality::Good) {
            anyGood = true;
            const QString text = DataLogger::valueText(item, cell.raw);
            tableCells << text;
            jsonValues.append(static_cast<qint64>(cell.raw));
            jsonTexts.append(text);
            continue;
        }
        tableCells << QStringLiteral("?");
        jsonValues.append(QJsonValue::Null);
        jsonTexts.append(QJsonValue::Null);
        if (cell.quality == DataLogger::Quality::Error)
            m_monitorErrors = true;
        else
            staleReason = cell.reason;
        if (!m_reported.contains(name + cell.reason)) {
            m_reported.insert(name + cell.reason);
            m_out.note(QStringLiteral("%1: %2").arg(name, cell.reason));
        }
    }
    if (m_logger.isOpen()) {
        if (const Status s = m_logger.writeRow(now, cells); !s) {
            m_out.error(QString::fromStdString(s.error().text()), ExitCode::Internal);
            return finish(ExitCode::Internal);
        }
    }
    QJsonObject json;
    json.insert(QStringLiteral("cycle"), m_cycle);
    json.insert(QStringLiteral("time"), now.toString(Qt::ISODateWithMs));
    json.insert(QStringLiteral("station"), m_options.station);
    json.insert(QStringLiteral("addresses"), jsonAddresses);
    json.insert(QStringLiteral("values"), jsonValues);
    json.insert(QStringLiteral("text"), jsonTexts);
    if (m_options.format == OutputFormat::Csv)
        m_out.line(DataLogger::rowLine(now, items, cells));
    else
        m_out.streamRow(tableCells, json);

    // Nothing read for three cycles in a row: the link is gone for practical purposes.
    m_staleCycles = (!anyGood && !staleReason.isEmpty()) ? m_staleCycles + 1 : 0;
    if (m_staleCycles >= 3) {
        m_out.error(QStringLiteral("Nothing read for 3 cycles: %1").arg(staleReason),
                    ExitCode::Link);
        return finish(ExitCode::Link);
    }
    if (m_options.cycles > 0 && m_cycle >= m_options.cycles) {
        if (m_monitorErrors)
            m_out.note(QStringLiteral("Some elements were refused by the PLC (see above)."));
        if (m_monitorErrors)
            return finish(ExitCode::Plc);
        m_session->setWatchList({});
        m_monitoring = false;
        if (const Status s = m_logger.close(); !s) {
            m_out.error(QString::fromStdString(s.error().text()), ExitCode::Internal);
            return finish(ExitCode::Internal);
        }
        return stepDone();
    }
    armWatchdog(m_options.intervalMs
                + requestBudgetMs() * (1 + static_cast<int>(step().addresses.size()) / 16));
}

// --- raw
// ------------------------------------------------------------------------------------------------

} // namespace Fatek
