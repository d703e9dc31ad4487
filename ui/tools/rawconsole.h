#pragma once

#include "ui/common/toolconfirmation.h"

#include <QTimer>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableView;

namespace Fatek {

class RawSendBar;
class TrafficFilterProxy;
class TrafficLogModel;

// Live view of a session's traffic log (time, direction, hex, ASCII, meaning, errors highlighted)
// with filters, pause, clear, copy and save, plus a line to send raw frames.
class RawConsole : public QWidget
{
    Q_OBJECT

public:
    explicit RawConsole(QWidget *parent = nullptr);

    // session may be nullptr: the console shows "no connection" and disables sending.
    void setTarget(const PlcTarget &target);

    // Test hook: answers the confirmation questions instead of a message box.
    void setConfirmer(Confirmer confirmer);

    TrafficLogModel *model() const { return m_model; }
    TrafficFilterProxy *filter() const { return m_filter; }
    QTableView *view() const { return m_view; }
    RawSendBar *sendBar() const { return m_sendBar; }

    void setPaused(bool paused);
    bool isPaused() const;
    // Writes every visible row (after filters) as tab-separated text; returns an error sentence or
    // "".
    QString saveToFile(const QString &path) const;
    // The visible (or only the selected, if any) rows as text, also put on the clipboard.
    QString copyRows() const;

public Q_SLOTS:
    void clear();
    // Whether its dock's tab is the one shown (a docked console behind another tab is visible to
    // Qt but covered); the console reads the log only while it is on screen.
    void setOnScreen(bool onScreen);

protected:
    // Theme changes recolour the table (its colours are derived from the palette).
    void changeEvent(QEvent *event) override;
    // The console reads its link's log only while it is on screen (a docked console behind
    // another tab is not): the log and the table grow only when someone looks.
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;

private:
    void fetch();
    void startShowing();
    void listen(bool on); // connects to or from the log's entriesAdded
    void save();
    void applyFilters();
    QString rowsText(bool selectedOnly) const;

    PlcTarget m_target;
    bool m_attached = false; // a direct link was set (its QPointer also reads null once deleted)
    QMetaObject::Connection m_linkGone;
    QMetaObject::Connection m_logListener; // the log's entriesAdded, while on screen
    quint64 m_lastSequence = 0;
    bool m_followTail = true;
    bool isOnScreen() const { return isVisible() && m_tabShown; }
    bool m_tabShown = true;
    bool m_pausedSinceFetch = false; // a gap in the log is the pause's, not the hidden console's
    QTimer m_fetchTimer;

    TrafficLogModel *m_model;
    TrafficFilterProxy *m_filter;
    QLabel *m_targetLabel;
    QComboBox *m_direction;
    QSpinBox *m_stationFilter;
    QComboBox *m_command;
    QCheckBox *m_errorsOnly;
    QPushButton *m_pause;
    QTableView *m_view;
    QLabel *m_status;
    RawSendBar *m_sendBar;
};

} // namespace Fatek
