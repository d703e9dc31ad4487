#pragma once

#include "alarmjournal.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QTimer>

#include <memory>

namespace Fatek {

class AlarmJournalWriter;

// The part of AlarmJournalWriter that lives on its thread: the journal and the batch not written
// yet. Only alarmjournalwriter.cpp uses it; every call reaches it through a queued call.
class AlarmJournalWorker : public QObject
{
public:
    AlarmJournalWorker(const QString &path, AlarmJournalWriter *writer);

    // The file opened if it is not yet (failed() said otherwise).
    bool ensureOpen();
    void record(const AlarmEvent &event, const AlarmRecord &record);
    void load(quint64 ticket, const QString &connection);
    void query(quint64 ticket, qint64 fromMs, qint64 toMs, const QString &connection);
    // Writes the batch now.
    void flush();
    // Writes the batch and closes the file (the writer's destructor, before the thread ends).
    void finish();

private:
    void schedule();
    void report(const Message &reason);

    QString m_path;
    AlarmJournalWriter *m_writer; // outlives this object: its destructor joins the thread
    std::unique_ptr<AlarmJournal> m_journal;
    QList<AlarmEvent> m_events;
    QList<AlarmRecord> m_records;
    QHash<QString, qsizetype> m_recordIndex; // connection + '\n' + alarm id -> m_records
    QTimer *m_timer;
    QElapsedTimer m_sinceWrite;
    Message m_lastReport;
};

} // namespace Fatek
