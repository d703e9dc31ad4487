#pragma once

#include <QObject>
#include <QPointer>

class QDockWidget;
class QMainWindow;
class QMenu;
class QWidget;

namespace Fatek {

class AlarmAnnunciator;
class AlarmCenter;
class AlarmDefinitionDialog;
class AlarmJournalDialog;
class AlarmSummaryWidget;
class ConnectionManager;
class WatchTableWidget;

// Alarms in the main window: the alarm center (engines and journal), the summary dock
// (View > Alarm Summary, Ctrl+Shift+M), the status bar's count with its sound, the journal viewer,
// and in every watch table the row action "Alarms…" (Ctrl+Shift+A) that edits the row's
// definitions as an undoable step, refused in operator mode.
class AlarmsUi : public QObject
{
    Q_OBJECT

public:
    // The summary opens as a tab beside `tabWith` (the connections dock). `journalPath` empty:
    // AlarmCenter::defaultJournalPath().
    AlarmsUi(QMainWindow *window, QDockWidget *tabWith, ConnectionManager *manager,
             QMenu *toolsMenu, QMenu *viewMenu, const QString &journalPath = {});
    ~AlarmsUi() override;

    AlarmCenter *center() const { return m_center; }
    AlarmSummaryWidget *summary() const { return m_summary; }
    AlarmAnnunciator *annunciator() const { return m_annunciator; }
    QDockWidget *dock() const { return m_dock; }

    // The table's rows feed the alarms, and it gets the "Alarms…" row action.
    void addTable(WatchTableWidget *table);
    // Shows and raises the summary dock; returns the summary.
    QWidget *showSummary();
    // Opens the journal viewer (not blocking) and shows the last day.
    AlarmJournalDialog *showJournal();
    // Opens the definitions of the table's current row (not blocking); nullptr when refused
    // (operator mode, no row), with the reason in statusMessage().
    AlarmDefinitionDialog *editAlarms(WatchTableWidget *table);

Q_SIGNALS:
    void statusMessage(const QString &text);

private:
    QMainWindow *m_window;
    QPointer<QDockWidget> m_tabWith;
    ConnectionManager *m_manager;
    AlarmCenter *m_center;
    AlarmSummaryWidget *m_summary;
    QDockWidget *m_dock;
    AlarmAnnunciator *m_annunciator;
    QPointer<AlarmJournalDialog> m_journal;
};

} // namespace Fatek
