#pragma once

#include "core/plant/plantsubscription.h"
#include "core/watch/watchlist.h"
#include "ui/connection/connection.h"
#include "watchtableactions.h"
#include "watchtablewriter.h"

#include <QHash>
#include <QPointer>
#include <QWidget>

#include <functional>

class QAction;
class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QLayout;
class QModelIndex;
class QSpinBox;
class QTableView;
class QToolButton;

namespace Fatek {

class Connection;
class ConnectionManager;
class ForcedMarks;
class SessionResult;
class WatchTableModel;
class WatchTableProxy;
class WatchTableView;

// One watch table: an entry line to add items, the table, its poll settings (interval, pause,
// confirmation) and the connection it polls through. It turns edits into writes on that
// connection's link and shows their outcome; it does no I/O itself. The view shows the model
// through a WatchTableProxy (sorted by a header click, filtered by the filter line); rows are
// named by the model's numbers everywhere else (selectedRows, viewIndex). Edits of the rows
// (not writes) are steps on the model's undo stack: Ctrl+Z, Ctrl+Y / Ctrl+Shift+Z.
class WatchTableWidget : public QWidget
{
    Q_OBJECT

public:
    WatchTableWidget(ConnectionManager *manager, QWidget *parent = nullptr);
    ~WatchTableWidget() override;

    WatchTableModel *model() const { return m_model; }
    QTableView *view() const;
    WatchTableProxy *proxy() const { return m_proxy; }
    QLineEdit *addressEdit() const { return m_addEdit; }
    QLineEdit *filterEdit() const { return m_filterEdit; }
    // The view's index of a model index (invalid when filtered out), and the reverse.
    QModelIndex viewIndex(const QModelIndex &modelIndex) const;
    int modelRow(const QModelIndex &viewIndex) const;
    // The model rows selected in the view, ascending; the current row when none is selected.
    QList<int> selectedRows() const;
    // The selected rows as tab-separated text, a header line first (address, name, value,
    // format, quality, comment), in the order shown.
    QString selectedRowsText() const;

    Connection *connection() const { return m_connection; }
    void setConnection(Connection *connection);

    WatchTableSpec spec() const;
    void setSpec(const WatchTableSpec &spec);
    QString name() const { return m_name; }
    void setName(const QString &name);

    int intervalMs() const;
    void setIntervalMs(int ms);
    bool isPaused() const;
    void setPaused(bool paused);
    bool confirmWrites() const;
    void setConfirmWrites(bool confirm);
    void setConfirmHandler(ConfirmHandler handler)
    {
        m_writer->setConfirmHandler(std::move(handler));
    }

    // Operator mode has ended: a write it refused ("Read-only mode") is no longer the state of
    // things; the message says what it means now.
    void operatorModeEnded()
    {
        if (!m_failedWrite.isEmpty())
            showMessage(tr("Operator mode is off; %1 was not written.").arg(m_failedWrite), false);
    }

    // Adds items from typed text (addresses, ranges); false with message() set on bad input.
    bool addFromText(const QString &text);
    // Adds items from pasted text (CSV rows or addresses).
    bool addFromPaste(const QString &text);
    // The last error or outcome shown under the entry line.
    QString message() const;

    // Starts a write of `raw` to `row` (after confirmation); the outcome comes in statusMessage().
    void write(int row, quint64 raw) { m_writer->write(row, raw); }

Q_SIGNALS:
    void statusMessage(const QString &text);
    void nameChanged(const QString &name);
    // The table polls through another connection (nullptr: none).
    void connectionChanged(Fatek::Connection *connection);
    // "Add to Trend" on the selected rows (ascending row numbers).
    void addToTrendRequested(const QList<int> &rows);
    // What a saved list holds of this table changed (rows, name, interval, confirmation).
    void edited();

private:
    // The constructor's parts: the entry line and poll settings, the message line and filter,
    // the view, and what the actions, the model and the connection manager trigger.
    QLayout *createEntryBar();
    QLayout *createMessageBar();
    void setUpView();
    void connectActions();
    void connectModel();
    void connectManager();
    void showMessage(const QString &text, bool error);
    void pushPollList();
    void refreshConnections();
    void removeSelected();
    void copySelected();
    void moveSelected(int delta);
    void setSelectedFormat(DisplayFormat format);
    void fillFormatMenu();
    void writeDialog();
    void toggleSwapWords();
    quint8 defaultStation() const;

    ConnectionManager *m_manager;
    QPointer<Connection> m_connection;
    QString m_name;
    // The write whose failure the message line shows in red ("" when it shows something else).
    QString m_failedWrite;
    WatchTableModel *m_model;
    WatchTableProxy *m_proxy;
    WatchTableView *m_view;
    QLineEdit *m_addEdit;
    QLineEdit *m_filterEdit;
    WatchTableActions m_actions;
    QComboBox *m_connectionCombo;
    QSpinBox *m_interval;
    QToolButton *m_pause;
    QCheckBox *m_confirmBox;
    class MessageLine *m_message;
    WatchTableWriter *m_writer;
    ForcedMarks *m_forcedMarks;
    // This table as a consumer of its connection's plant connection.
    PlantSubscription *m_subscription;
    // The table's writes; an outcome counts only while the table uses the connection written to.
};

} // namespace Fatek
