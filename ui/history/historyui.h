#pragma once

#include <QObject>
#include <QPointer>

class QAction;
class QMainWindow;

namespace Fatek {

class ConnectionManager;
class HistoryCenter;
class HistorySettingsDialog;
class WatchTableWidget;

// The history in the main window: the history center (recorders and the store), its failures in
// the status bar, and in every watch table the row actions "Record in History" (checkable, on the
// selected rows) and "History Settings…", edits of the rows as undoable steps, refused in
// operator mode. The trend reads the store through center().
class HistoryUi : public QObject
{
    Q_OBJECT

public:
    // `location` empty: HistoryCenter::defaultLocation().
    HistoryUi(QMainWindow *window, ConnectionManager *manager, const QString &location = {});
    ~HistoryUi() override;

    HistoryCenter *center() const { return m_center; }

    // The table's recorded rows feed the history, and it gets the row actions.
    void addTable(WatchTableWidget *table);
    // Records the table's selected rows (default setting; rows with one keep theirs) or stops
    // recording them; false, with the reason in statusMessage(), when refused.
    bool setRecorded(WatchTableWidget *table, bool recorded);
    // Opens the settings of the table's selected rows (not blocking); nullptr when refused.
    HistorySettingsDialog *editSettings(WatchTableWidget *table);

Q_SIGNALS:
    void statusMessage(const QString &text);

private:
    bool refusedInOperatorMode();

    ConnectionManager *m_manager;
    HistoryCenter *m_center;
};

} // namespace Fatek
