#include "tablelogger.h"

#include "ui/common/uitext.h"
#include "ui/watch/watchtablemodel.h"

#include <QDateTime>

namespace Fatek {

TableLogger::TableLogger(QObject *parent)
    : QObject(parent)
{
    m_batch.setSingleShot(true);
    m_batch.setInterval(0);
    connect(&m_batch, &QTimer::timeout, this, &TableLogger::writeRow);
}

TableLogger::~TableLogger()
{
    m_batch.stop();
    m_logger.close();
}

Status TableLogger::start(WatchTableModel *model, const QString &path, CsvFile::LineEnd lineEnd)
{
    if (isLogging())
        stop();
    if (!model)
        return makeError(ErrorKind::InvalidRequest, tr("No watch table to log.").toStdString());
    const QList<WatchItemSpec> items = model->items();
    if (const Status s = m_logger.open(path, items, lineEnd); !s)
        return s;
    m_model = model;
    m_specs = items;
    m_keys.clear();
    for (int r = 0; r < model->rowCount(); ++r)
        m_keys.push_back(model->rowKey(r));
    connect(model, &QAbstractItemModel::dataChanged, this,
            [this](const QModelIndex &topLeft, const QModelIndex &bottomRight) {
                // Values and quality reach the Updated column; a fading highlight does not, nor
                // does a new name or comment.
                if (bottomRight.column() >= WatchTableModel::QualityColumn
                    && topLeft.column() <= WatchTableModel::UpdatedColumn)
                    m_batch.start();
            });
    connect(model, &QObject::destroyed, this, [this] {
        if (isLogging())
            stop();
    });
    return Ok{};
}

void TableLogger::stop()
{
    if (!isLogging())
        return;
    m_batch.stop();
    if (m_model)
        disconnect(m_model, nullptr, this, nullptr);
    m_model = nullptr;
    const Status s = m_logger.close();
    Q_EMIT stopped(s ? QString() : translated(s.error().message));
}

void TableLogger::writeRow()
{
    if (!isLogging() || !m_model)
        return;
    QList<DataLogger::Cell> cells;
    for (std::size_t i = 0; i < m_keys.size(); ++i) {
        DataLogger::Cell cell;
        const int row = m_model->rowOfKey(m_keys[i]);
        const WatchItemSpec &spec = m_specs.at(static_cast<qsizetype>(i));
        if (row < 0) {
            cell.reason = tr("removed from the table");
        } else if (const WatchItemSpec now = m_model->item(row);
                   now.address != spec.address || now.format != spec.format
                   || now.swapWords != spec.swapWords) {
            cell.reason = tr("format changed");
        } else if (!m_model->hasValue(row)) {
            cell.quality = m_model->quality(row) == ValueQuality::Error
                               ? DataLogger::Quality::Error
                               : DataLogger::Quality::Missing;
            cell.reason = m_model->qualityReason(row);
        } else {
            cell.quality = DataLogger::qualityOf(m_model->quality(row));
            cell.raw = m_model->rawValue(row);
            cell.reason = m_model->qualityReason(row);
        }
        cells.append(cell);
    }
    if (const Status s = m_logger.writeRow(QDateTime::currentDateTime(), cells); !s) {
        m_batch.stop();
        if (m_model)
            disconnect(m_model, nullptr, this, nullptr);
        m_model = nullptr;
        m_logger.close();
        Q_EMIT stopped(translated(s.error().message));
        return;
    }
    Q_EMIT rowWritten(m_logger.rowCount());
}

} // namespace Fatek
