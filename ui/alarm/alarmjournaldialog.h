#pragma once

#include "core/alarm/alarmtypes.h"
#include "core/watch/csvfile.h"

#include <QAbstractTableModel>
#include <QDialog>
#include <QList>

class QComboBox;
class QDateTimeEdit;
class QPushButton;
class QTableView;

namespace Fatek {

class AlarmJournalWriter;
class MessageLine;

// The journal's events as a table: time (local, with its UTC offset), connection, alarm, event,
// state, priority, message, value, user, comment.
class AlarmEventsModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    using QAbstractTableModel::QAbstractTableModel;

    void setEvents(const QList<AlarmEvent> &events);
    const QList<AlarmEvent> &events() const { return m_events; }

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    QList<AlarmEvent> m_events;
};

// The alarm journal viewer: the events of a time range (and one connection or all), asked of the
// journal's own thread (the window goes on meanwhile), and their export to CSV.
class AlarmJournalDialog : public QDialog
{
    Q_OBJECT

public:
    AlarmJournalDialog(AlarmJournalWriter *journal, const QStringList &connections,
                       QWidget *parent = nullptr);

    AlarmEventsModel *model() const { return m_model; }
    QDateTimeEdit *fromEdit() const { return m_from; }
    QDateTimeEdit *toEdit() const { return m_to; }
    // Asks the journal for the range; finished() when the events are shown.
    void query();
    // Writes the events shown to `path` as CSV; the reason when it could not.
    // The events as a CSV file (the byte order mark, `lineEnd`); the reason when not written.
    QString exportCsv(const QString &path, CsvFile::LineEnd lineEnd = CsvFile::LineEnd::Lf) const;

Q_SIGNALS:
    void queried();

private:
    void exportDialog();

    AlarmJournalWriter *m_journal;
    AlarmEventsModel *m_model;
    QDateTimeEdit *m_from;
    QDateTimeEdit *m_to;
    QComboBox *m_connection;
    QPushButton *m_query;
    QPushButton *m_export;
    QTableView *m_view;
    MessageLine *m_message;
    int m_pending = 0; // queries asked and not answered
};

} // namespace Fatek
