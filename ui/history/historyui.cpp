#include "historyui.h"

#include "historycenter.h"
#include "historysettingsdialog.h"
#include "ui/common/uitext.h"
#include "ui/connection/connectionmanager.h"
#include "ui/watch/watchtablemodel.h"
#include "ui/watch/watchtablewidget.h"

#include <QAction>
#include <QDir>
#include <QEvent>
#include <QMainWindow>
#include <QTableView>

#include <algorithm>

namespace Fatek {

namespace {

bool allRecorded(const WatchTableWidget *table)
{
    const QList<int> rows = table->selectedRows();
    return !rows.isEmpty() && std::all_of(rows.cbegin(), rows.cend(), [table](int r) {
        return table->model()->item(r).history.has_value();
    });
}

// The check mark shows whether every selected row is recorded, set as the context menu opens
// (by the mouse on the rows or by the keyboard's menu key on the table).
class RecordCheckMark : public QObject
{
public:
    RecordCheckMark(WatchTableWidget *table, QAction *action)
        : QObject(action)
        , m_table(table)
        , m_action(action)
    {
        table->view()->installEventFilter(this);
        table->view()->viewport()->installEventFilter(this);
    }

    bool eventFilter(QObject *watched, QEvent *event) override
    {
        if (event->type() == QEvent::ContextMenu && m_table)
            m_action->setChecked(allRecorded(m_table));
        return QObject::eventFilter(watched, event);
    }

private:
    QPointer<WatchTableWidget> m_table;
    QAction *m_action;
};

} // namespace

HistoryUi::HistoryUi(QMainWindow *window, ConnectionManager *manager, const QString &location)
    : QObject(window)
    , m_manager(manager)
    , m_center(new HistoryCenter(manager, location, this))
{
    setObjectName(QStringLiteral("historyUi"));
    connect(m_center, &HistoryCenter::statusMessage, this, &HistoryUi::statusMessage);
}

HistoryUi::~HistoryUi() = default;

void HistoryUi::addTable(WatchTableWidget *table)
{
    m_center->addTable(table);
    QTableView *view = table->view();
    auto *record
        = new QAction(QIcon(QStringLiteral(":/icons/history.svg")), tr("Record in &History"), view);
    record->setObjectName(QStringLiteral("recordHistoryAction"));
    record->setCheckable(true);
    record->setToolTip(tr("Keep the values of the selected rows in the history, to look back at "
                          "them in the trend (not in operator mode)"));
    auto *settings = new QAction(tr("History &Settings…"), view);
    settings->setObjectName(QStringLiteral("historySettingsAction"));
    settings->setToolTip(tr("Deadband and heartbeat of the selected rows' recording"));
    view->addActions({record, settings});
    new RecordCheckMark(table, record);
    // What the mark showed when the menu opened decides, not the mark's own toggle.
    connect(record, &QAction::triggered, this, [this, table, record] {
        setRecorded(table, !allRecorded(table));
        record->setChecked(allRecorded(table));
    });
    connect(settings, &QAction::triggered, this, [this, table] { editSettings(table); });
}

bool HistoryUi::refusedInOperatorMode()
{
    // What is recorded is the engineer's choice, as alarm definitions are.
    if (!m_manager->isReadOnly())
        return false;
    Q_EMIT statusMessage(tr("Operator mode: what is recorded in the history cannot be changed."));
    return true;
}

bool HistoryUi::setRecorded(WatchTableWidget *table, bool recorded)
{
    if (refusedInOperatorMode())
        return false;
    const QList<int> rows = table->selectedRows();
    if (rows.isEmpty()) {
        Q_EMIT statusMessage(tr("Select the rows to record in the history."));
        return false;
    }
    WatchTableModel *model = table->model();
    Status s = Ok{};
    if (!recorded) {
        s = model->setHistory(rows, std::nullopt);
    } else {
        // Rows already recorded keep their own settings; the others get the default.
        QList<int> fresh;
        for (int r : rows) {
            if (!model->item(r).history)
                fresh.append(r);
        }
        s = model->setHistory(fresh, HistorySetting{});
    }
    if (!s) {
        Q_EMIT statusMessage(translated(s.error().message));
        return false;
    }
    Q_EMIT statusMessage(recorded ? tr("%n row(s) recorded in the history (%1).", nullptr,
                                       static_cast<int>(rows.size()))
                                        .arg(QDir::toNativeSeparators(m_center->location()))
                                  : tr("%n row(s) no longer recorded in the history.", nullptr,
                                       static_cast<int>(rows.size())));
    return true;
}

HistorySettingsDialog *HistoryUi::editSettings(WatchTableWidget *table)
{
    if (refusedInOperatorMode())
        return nullptr;
    const QList<int> rows = table->selectedRows();
    if (rows.isEmpty()) {
        Q_EMIT statusMessage(tr("Select the rows whose recording to set."));
        return nullptr;
    }
    WatchTableModel *model = table->model();
    QList<quint64> keys;
    bool discreteOnly = true;
    for (int r : rows) {
        keys.append(model->rowKey(r));
        discreteOnly = discreteOnly && model->valueWidth(r) == 1;
    }
    const WatchItemSpec first = model->item(rows.first());
    auto *dialog = new HistorySettingsDialog(first.history.value_or(HistorySetting{}),
                                             static_cast<int>(rows.size()), discreteOnly, table);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog, model, keys] {
        if (refusedInOperatorMode())
            return;
        QList<int> now; // rows removed meanwhile are left out
        for (quint64 key : keys) {
            if (const int row = model->rowOfKey(key); row >= 0)
                now.append(row);
        }
        if (const Status s = model->setHistory(now, dialog->setting()); !s)
            Q_EMIT statusMessage(translated(s.error().message));
    });
    dialog->open();
    return dialog;
}

} // namespace Fatek
