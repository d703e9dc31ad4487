#pragma once

#include "core/protocol/result.h"

#include <QTimer>
#include <QWidget>

#include <functional>

class QAction;
class QComboBox;
class QHBoxLayout;
class QLayout;
class QLineEdit;
class QPushButton;
class QTableView;
class QToolButton;

namespace Fatek {

class AlarmCenter;
class AlarmSummaryModel;
class AlarmSummaryProxy;
class MessageLine;

// The alarm summary (a dock of the main window): the listed alarms of every connection, sorted
// and filtered, with the operator's actions on them: acknowledge the selected alarms (Ctrl+K) or
// every one shown (Ctrl+Shift+K) with the optional comment of the comment line, shelve the
// selected ones for 15 min, 1 h, 8 h or a time typed in, unshelve, and open the journal.
// Operator mode allows all of them: they change no PLC and no definition.
class AlarmSummaryWidget : public QWidget
{
    Q_OBJECT

public:
    AlarmSummaryWidget(AlarmCenter *center, QWidget *parent = nullptr);

    AlarmSummaryModel *model() const { return m_model; }
    AlarmSummaryProxy *proxy() const { return m_proxy; }
    QTableView *view() const { return m_view; }
    QLineEdit *commentEdit() const { return m_comment; }
    // Beside the actions: the status bar's mute toggle (AlarmAnnunciator).
    void addMuteAction(QAction *mute);

    // Acts on the alarms selected in the view (the current one when none is); false with the
    // reason in the message line when none could.
    bool acknowledgeSelected();
    bool acknowledgeAllShown();
    bool shelveSelected(qint64 durationMs);
    bool unshelveSelected();

Q_SIGNALS:
    void journalRequested();
    void statusMessage(const QString &text);

private:
    QLayout *createFilterBar();
    QLayout *createActionBar();
    // (connection, alarm id) of the rows chosen, in the order shown.
    QList<QPair<QString, QString>> chosen(bool allShown) const;
    // Applies `action` to each chosen alarm; says how many it did and the first refusal.
    bool apply(const QList<QPair<QString, QString>> &alarms, const QString &done,
               const std::function<Status(const QString &, const QString &)> &action);
    void resetConnection(const QString &connection);
    void refreshGroups();
    void shelveCustom();

    AlarmCenter *m_center;
    AlarmSummaryModel *m_model;
    AlarmSummaryProxy *m_proxy;
    QTableView *m_view;
    QComboBox *m_priority;
    QComboBox *m_state;
    QComboBox *m_group;
    QLineEdit *m_filter;
    QLineEdit *m_comment;
    QToolButton *m_shelve;
    QHBoxLayout *m_actionBar = nullptr;
    QTimer m_refresh;
    MessageLine *m_message;
};

} // namespace Fatek
