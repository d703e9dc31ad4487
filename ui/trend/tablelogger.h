#pragma once

#include "core/protocol/result.h"
#include "core/watch/datalogger.h"
#include "ui/watch/watchtablemodel.h" // model() converts the QPointer: the full type

#include <QObject>
#include <QPointer>
#include <QTimer>

#include <vector>

namespace Fatek {

// Logs one watch table to a CSV file (DataLogger) while the GUI polls it: one row per batch of
// values (or change of quality) the table receives, with the columns the table had at start.
// Rows removed from the table later stay as empty cells with status "missing".
class TableLogger : public QObject
{
    Q_OBJECT

public:
    explicit TableLogger(QObject *parent = nullptr);
    ~TableLogger() override;

    Status start(WatchTableModel *model, const QString &path,
                 CsvFile::LineEnd lineEnd = CsvFile::LineEnd::Lf);
    // Flushes and closes; stopped() follows.
    void stop();
    bool isLogging() const { return m_logger.isOpen(); }
    QString path() const { return m_logger.path(); }
    qint64 rowCount() const { return m_logger.rowCount(); }
    const WatchTableModel *model() const { return m_model; }

Q_SIGNALS:
    void rowWritten(qint64 rows);
    // The log ended: error is empty after stop(), else why writing failed (disk full, ...).
    void stopped(const QString &error);

private:
    void writeRow();

    DataLogger m_logger;
    QPointer<WatchTableModel> m_model;
    std::vector<quint64> m_keys;
    QList<WatchItemSpec> m_specs;
    // All dataChanged signals of one batch arrive together: one row after them.
    QTimer m_batch;
};

} // namespace Fatek
