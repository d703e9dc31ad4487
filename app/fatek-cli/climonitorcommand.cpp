// fatek-cli monitor: planned polling, one line per cycle, optional CSV log.
#include "clirunner.h"

#include "clitext.h"
#include "core/protocol/plcstatus.h"

#include <QDateTime>
#include <QJsonArray>

#include <array>

namespace Fatek {

using namespace CliText;

void CliRunner::runMonitor()
{
    m_cycle = 0;
    m_staleCycles = 0;
    m_monitorErrors = false;
    m_monitoring = true;
    QList<WatchEntry> entries;
    QStringList columns{QStringLiteral("cycle"), QStringLiteral("time")};
    QList<int> widths{5, 12};
    const QList<WatchItemSpec> &items = step().items;
    m_monitorItems.clear();
    m_monitorIds.clear();
    for (qsizetype i = 0; i < items.size(); ++i) {
        const WatchItemSpec &item = items.at(i);
        // A float over R100 polls R100 and R101: one entry per element.
        const ItemValues &values = m_monitorItems.emplace_back(item);
        for (const std::uint64_t id : values.pollIds())
            m_monitorIds.insert(id, i);
        entries += values.pollEntries(m_options.intervalMs);
        columns << (item.name.isEmpty() ? addressText(item.address) : DataLogger::columnName(item));
        const int width = values.width();
        widths << (width == 1 ? 1 : width <= 16 ? 6 : 12);
    }
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
    // Join the elements of each item back into one value; its quality is the worst part's.
    QList<DataLogger::Cell> cells(items.size());
    QList<int> partsSeen(items.size(), 0);
    std::vector<std::array<std::uint32_t, ItemValues::MaxElements>> words(
        static_cast<std::size_t>(items.size()));
    for (DataLogger::Cell &c : cells)
        c.quality = DataLogger::Quality::Good;
    for (const WatchValue &v : values) {
        const qsizetype item = m_monitorIds.value(v.itemId, -1);
        const int part
            = item < 0 || item >= items.size()
                  ? -1
                  : m_monitorItems.at(static_cast<std::size_t>(item)).elementOf(v.itemId);
        if (part < 0)
            continue;
        DataLogger::Cell &cell = cells[item];
        ++partsSeen[item];
        words[static_cast<std::size_t>(item)][static_cast<std::size_t>(part)] = v.value;
        if (v.quality == ValueQuality::Error) {
            cell.quality = DataLogger::Quality::Error;
            cell.reason = englishText(v.error);
        } else if (v.quality == ValueQuality::Stale && cell.quality == DataLogger::Quality::Good) {
            cell.quality = DataLogger::Quality::Stale;
            cell.reason = englishText(v.error);
        }
    }
    const QDateTime now = QDateTime::currentDateTime();
    QStringList tableCells{QString::number(m_cycle), now.toString(QStringLiteral("HH:mm:ss.zzz"))};
    QJsonArray jsonValues, jsonTexts, jsonAddresses;
    bool anyGood = false;
    QString staleReason;
    for (qsizetype i = 0; i < items.size(); ++i) {
        DataLogger::Cell &cell = cells[i];
        const WatchItemSpec &item = items.at(i);
        const ItemValues &itemValues = m_monitorItems.at(static_cast<std::size_t>(i));
        cell.raw = itemValues.join(words[static_cast<std::size_t>(i)]);
        if (partsSeen.at(i) < itemValues.elementCount()
            && cell.quality == DataLogger::Quality::Good) {
            cell.quality = DataLogger::Quality::Missing;
            cell.reason = QStringLiteral("no value this cycle");
        }
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
