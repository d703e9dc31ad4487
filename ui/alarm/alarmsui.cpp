#include "alarmsui.h"

#include "alarmannunciator.h"
#include "alarmcenter.h"
#include "alarmdefinitiondialog.h"
#include "alarmjournaldialog.h"
#include "alarmsummarywidget.h"
#include "ui/common/uitext.h"
#include "ui/connection/connectionmanager.h"
#include "ui/watch/watchtablemodel.h"
#include "ui/watch/watchtablewidget.h"

#include <QAction>
#include <QDockWidget>
#include <QMainWindow>
#include <QMenu>
#include <QStatusBar>
#include <QTableView>

namespace Fatek {

AlarmsUi::AlarmsUi(QMainWindow *window, QDockWidget *tabWith, ConnectionManager *manager,
                   QMenu *toolsMenu, QMenu *viewMenu, const QString &journalPath)
    : QObject(window)
    , m_window(window)
    , m_tabWith(tabWith)
    , m_manager(manager)
    , m_center(new AlarmCenter(manager, journalPath, this))
{
    setObjectName(QStringLiteral("alarmsUi"));
    m_summary = new AlarmSummaryWidget(m_center, window);
    m_dock = new QDockWidget(tr("Alarms"), window);
    m_dock->setObjectName(QStringLiteral("alarmDock"));
    m_dock->setWidget(m_summary);
    window->addDockWidget(Qt::BottomDockWidgetArea, m_dock);
    m_dock->hide(); // shown by View > Alarm Summary or the status bar's count
    QAction *toggle = m_dock->toggleViewAction();
    toggle->setText(tr("&Alarm Summary"));
    toggle->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_M));
    toggle->setIcon(QIcon(QStringLiteral(":/icons/alarm.svg")));
    viewMenu->addAction(toggle);
    toolsMenu->addAction(toggle);
    toolsMenu->addAction(tr("Alarm &Journal…"), this, &AlarmsUi::showJournal);

    m_annunciator = new AlarmAnnunciator(m_center, window);
    window->statusBar()->addPermanentWidget(m_annunciator);
    viewMenu->addAction(m_annunciator->muteAction());
    m_summary->addMuteAction(m_annunciator->muteAction());
    connect(m_annunciator, &AlarmAnnunciator::summaryRequested, this, [this] {
        showSummary();
        m_summary->view()->setFocus(Qt::OtherFocusReason);
    });
    connect(m_summary, &AlarmSummaryWidget::journalRequested, this, &AlarmsUi::showJournal);
    connect(m_summary, &AlarmSummaryWidget::statusMessage, this, &AlarmsUi::statusMessage);
    connect(m_center, &AlarmCenter::journalFailed, this, &AlarmsUi::statusMessage);
}

AlarmsUi::~AlarmsUi() = default;

void AlarmsUi::addTable(WatchTableWidget *table)
{
    m_center->addTable(table);
    auto *action
        = new QAction(QIcon(QStringLiteral(":/icons/alarm.svg")), tr("&Alarms…"), table->view());
    action->setObjectName(QStringLiteral("alarmDefinitionsAction"));
    action->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_A));
    action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    action->setToolTip(tr("Limits, bit and quality alarms of the row (not in operator mode)"));
    table->view()->addAction(action);
    connect(action, &QAction::triggered, this, [this, table] { editAlarms(table); });
}

QWidget *AlarmsUi::showSummary()
{
    const bool wasHidden = m_dock->isHidden();
    m_dock->show();
    m_dock->raise();
    // First shown: a tab of the bottom area beside the connections, with room for the rows.
    QDockWidget *connections = m_tabWith.data();
    if (wasHidden && connections && !connections->isHidden() && !m_dock->isFloating()
        && m_window->dockWidgetArea(m_dock) == Qt::BottomDockWidgetArea
        && m_window->dockWidgetArea(connections) == Qt::BottomDockWidgetArea
        && m_window->tabifiedDockWidgets(m_dock).isEmpty()) {
        m_window->tabifyDockWidget(connections, m_dock);
        m_dock->raise();
        m_window->resizeDocks({m_dock}, {m_window->height() * 2 / 5}, Qt::Vertical);
    }
    return m_summary;
}

AlarmJournalDialog *AlarmsUi::showJournal()
{
    if (!m_journal) {
        m_journal
            = new AlarmJournalDialog(m_center->journal(), m_center->connectionNames(), m_window);
        m_journal->setAttribute(Qt::WA_DeleteOnClose);
    }
    m_journal->show();
    m_journal->raise();
    m_journal->query();
    return m_journal;
}

AlarmDefinitionDialog *AlarmsUi::editAlarms(WatchTableWidget *table)
{
    // Definitions are the engineer's: an operator acknowledges and shelves, never edits them.
    if (m_manager->isReadOnly()) {
        Q_EMIT statusMessage(tr("Operator mode: alarm definitions cannot be changed."));
        return nullptr;
    }
    const QList<int> rows = table->selectedRows();
    if (rows.isEmpty()) {
        Q_EMIT statusMessage(tr("Select the row whose alarms to edit."));
        return nullptr;
    }
    WatchTableModel *model = table->model();
    const quint64 key = model->rowKey(rows.first());
    auto *dialog = new AlarmDefinitionDialog(model->item(rows.first()), table);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog, model, key] {
        const int row = model->rowOfKey(key);
        if (row < 0)
            return; // removed meanwhile
        if (m_manager->isReadOnly()) {
            Q_EMIT statusMessage(tr("Operator mode: alarm definitions cannot be changed."));
            return;
        }
        if (const Status s = model->setAlarms(row, dialog->alarms()); !s)
            Q_EMIT statusMessage(translated(s.error().message));
    });
    dialog->open();
    return dialog;
}

} // namespace Fatek
