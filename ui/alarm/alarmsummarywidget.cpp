#include "alarmsummarywidget.h"

#include "alarmcenter.h"
#include "alarmsummarymodel.h"
#include "alarmsummaryproxy.h"
#include "alarmtext.h"
#include "core/alarm/alarmengine.h"
#include "core/plant/plantconnection.h"
#include "ui/common/messageline.h"
#include "ui/common/uitext.h"

#include <QAction>
#include <QComboBox>
#include <QDateTime>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QSet>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>

namespace Fatek {

namespace {

constexpr qint64 minuteMs = 60 * 1000;

// A shortcut that acts while the focus is anywhere in the summary (the comment line too).
QAction *summaryAction(QWidget *summary, const QString &text, const QKeySequence &key)
{
    auto *action = new QAction(text, summary);
    action->setShortcut(key);
    action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    summary->addAction(action);
    return action;
}

} // namespace

AlarmSummaryWidget::AlarmSummaryWidget(AlarmCenter *center, QWidget *parent)
    : QWidget(parent)
    , m_center(center)
    , m_model(new AlarmSummaryModel(this))
    , m_proxy(new AlarmSummaryProxy(this))
    , m_view(new QTableView(this))
    , m_message(new MessageLine(1, this))
{
    setObjectName(QStringLiteral("alarmSummary"));
    m_proxy->setSourceModel(m_model);
    m_view->setObjectName(QStringLiteral("alarmView"));
    m_view->setModel(m_proxy);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->setSortingEnabled(true);
    m_view->sortByColumn(AlarmSummaryModel::TimeColumn, Qt::DescendingOrder);
    m_view->verticalHeader()->hide();
    m_view->verticalHeader()->setDefaultSectionSize(fontMetrics().lineSpacing() + 6);
    m_view->setWordWrap(false);
    QHeaderView *header = m_view->horizontalHeader();
    header->setSectionResizeMode(QHeaderView::Interactive);
    header->setSectionResizeMode(AlarmSummaryModel::MessageColumn, QHeaderView::Stretch);
    const int em = fontMetrics().horizontalAdvance(QLatin1Char('M'));
    const int widths[] = {0, 6, 7, 7, 8, 0, 6, 6};
    for (int c = 0; c < AlarmSummaryModel::ColumnCount; ++c) {
        // Never narrower than the header's own word, in either language.
        const int word = fontMetrics().horizontalAdvance(
                             m_model->headerData(c, Qt::Horizontal, Qt::DisplayRole).toString())
                         + 2 * em;
        if (widths[c] > 0)
            m_view->setColumnWidth(c, std::max(widths[c] * em, word));
    }
    // The state column fits its longest word (the sort arrow and padding beside it).
    int state = 0;
    for (AlarmState st :
         {AlarmState::Normal, AlarmState::ActiveUnacked, AlarmState::ActiveAcked,
          AlarmState::ReturnedUnacked, AlarmState::Shelved, AlarmState::OutOfService})
        state = std::max(state, fontMetrics().horizontalAdvance(AlarmText::state(st)));
    m_view->setColumnWidth(AlarmSummaryModel::StateColumn, state + 2 * em);
    // Values and states as they are now: the engine's newest, once a second (coalesced rows).
    m_refresh.setInterval(1000);
    connect(&m_refresh, &QTimer::timeout, this, [this] {
        if (!isVisible())
            return;
        for (const QString &connection : m_center->connectionNames())
            resetConnection(connection);
    });
    m_refresh.start();
    m_message->setObjectName(QStringLiteral("alarmMessage"));

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(createFilterBar());
    layout->addWidget(m_view, 1);
    layout->addLayout(createActionBar());
    layout->addWidget(m_message);

    connect(center, &AlarmCenter::alarmEvent, m_model,
            [this](const AlarmEvent &event, const AlarmRecord &) {
                if (AlarmEngine *engine = m_center->engine(event.connection)) {
                    if (const auto status = engine->status(event.alarmId))
                        m_model->updateAlarm(*status);
                }
            });
    connect(center, &AlarmCenter::alarmsReset, this, &AlarmSummaryWidget::resetConnection);
    for (const QString &connection : center->connectionNames())
        resetConnection(connection);
    connect(m_model, &QAbstractItemModel::rowsInserted, this, &AlarmSummaryWidget::refreshGroups);
    connect(m_model, &QAbstractItemModel::rowsRemoved, this, &AlarmSummaryWidget::refreshGroups);
}

QLayout *AlarmSummaryWidget::createFilterBar()
{
    m_priority = new QComboBox(this);
    m_priority->setObjectName(QStringLiteral("priorityFilter"));
    m_priority->addItem(tr("All priorities"));
    for (AlarmPriority p :
         {AlarmPriority::Critical, AlarmPriority::High, AlarmPriority::Medium, AlarmPriority::Low})
        m_priority->addItem(AlarmText::priority(p), static_cast<int>(p));
    m_state = new QComboBox(this);
    m_state->setObjectName(QStringLiteral("stateFilter"));
    m_state->addItem(tr("All states"), static_cast<int>(AlarmSummaryProxy::StateFilter::All));
    m_state->addItem(tr("Unacknowledged"),
                     static_cast<int>(AlarmSummaryProxy::StateFilter::Unacked));
    m_state->addItem(tr("Active"), static_cast<int>(AlarmSummaryProxy::StateFilter::Active));
    m_state->addItem(tr("Shelved"), static_cast<int>(AlarmSummaryProxy::StateFilter::Shelved));
    m_state->addItem(tr("Out of service"),
                     static_cast<int>(AlarmSummaryProxy::StateFilter::OutOfService));
    m_group = new QComboBox(this);
    m_group->setObjectName(QStringLiteral("groupFilter"));
    m_group->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_group->addItem(tr("All groups"));
    m_filter = new QLineEdit(this);
    m_filter->setObjectName(QStringLiteral("alarmFilter"));
    m_filter->setClearButtonEnabled(true);
    m_filter->setPlaceholderText(tr("Filter: item, message, group or connection"));

    connect(m_priority, &QComboBox::currentIndexChanged, this, [this] {
        const QVariant p = m_priority->currentData();
        m_proxy->setPriorityFilter(p.isValid() ? std::optional<int>(p.toInt()) : std::nullopt);
    });
    connect(m_state, &QComboBox::currentIndexChanged, this, [this] {
        m_proxy->setStateFilter(
            static_cast<AlarmSummaryProxy::StateFilter>(m_state->currentData().toInt()));
    });
    connect(m_group, &QComboBox::currentIndexChanged, this, [this](int index) {
        m_proxy->setGroupFilter(index > 0 ? m_group->currentText() : QString());
    });
    connect(m_filter, &QLineEdit::textChanged, m_proxy, &AlarmSummaryProxy::setText);

    auto *bar = new QHBoxLayout;
    bar->addWidget(m_priority);
    bar->addWidget(m_state);
    bar->addWidget(m_group);
    bar->addWidget(m_filter, 1);
    return bar;
}

QLayout *AlarmSummaryWidget::createActionBar()
{
    m_comment = new QLineEdit(this);
    m_comment->setObjectName(QStringLiteral("alarmComment"));
    m_comment->setPlaceholderText(tr("Comment (optional)"));
    m_comment->setToolTip(tr("Kept in the journal with the next acknowledge or shelve"));

    QAction *ack = summaryAction(this, tr("&Acknowledge"), QKeySequence(Qt::CTRL | Qt::Key_K));
    ack->setObjectName(QStringLiteral("acknowledgeAction"));
    connect(ack, &QAction::triggered, this, &AlarmSummaryWidget::acknowledgeSelected);
    QAction *ackAll = summaryAction(this, tr("Acknowledge All &Shown"),
                                    QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_K));
    ackAll->setObjectName(QStringLiteral("acknowledgeAllAction"));
    connect(ackAll, &QAction::triggered, this, &AlarmSummaryWidget::acknowledgeAllShown);

    auto *ackButton = new QPushButton(tr("Acknowledge (Ctrl+K)"), this);
    ackButton->setObjectName(QStringLiteral("acknowledgeButton"));
    ackButton->setToolTip(tr("Acknowledge the selected alarms"));
    connect(ackButton, &QPushButton::clicked, ack, &QAction::trigger);
    auto *ackAllButton = new QPushButton(tr("Acknowledge All Shown"), this);
    ackAllButton->setObjectName(QStringLiteral("acknowledgeAllButton"));
    ackAllButton->setToolTip(tr("Acknowledge every alarm the filters show (Ctrl+Shift+K)"));
    connect(ackAllButton, &QPushButton::clicked, ackAll, &QAction::trigger);

    m_shelve = new QToolButton(this);
    m_shelve->setObjectName(QStringLiteral("shelveButton"));
    m_shelve->setText(tr("Shelve"));
    m_shelve->setToolTip(tr("Hide the selected alarms for a while; they come back by themselves"));
    m_shelve->setPopupMode(QToolButton::InstantPopup);
    auto *shelveMenu = new QMenu(m_shelve);
    shelveMenu->setObjectName(QStringLiteral("shelveMenu"));
    for (const auto &[text, minutes] :
         {std::pair{tr("For 15 min"), 15}, std::pair{tr("For 1 h"), 60},
          std::pair{tr("For 8 h"), 480}}) {
        const qint64 ms = minutes * minuteMs;
        shelveMenu->addAction(text, this, [this, ms] { shelveSelected(ms); });
    }
    shelveMenu->addAction(tr("For a Time…"), this, &AlarmSummaryWidget::shelveCustom);
    m_shelve->setMenu(shelveMenu);
    auto *unshelve = new QPushButton(tr("Unshelve"), this);
    unshelve->setObjectName(QStringLiteral("unshelveButton"));
    connect(unshelve, &QPushButton::clicked, this, &AlarmSummaryWidget::unshelveSelected);
    auto *journal = new QPushButton(tr("Journal…"), this);
    journal->setObjectName(QStringLiteral("journalButton"));
    journal->setToolTip(tr("Every raise, acknowledge, return and shelve, by time; export to CSV"));
    connect(journal, &QPushButton::clicked, this, &AlarmSummaryWidget::journalRequested);

    m_actionBar = new QHBoxLayout;
    m_actionBar->addWidget(m_comment, 1);
    m_actionBar->addWidget(ackButton);
    m_actionBar->addWidget(ackAllButton);
    m_actionBar->addWidget(m_shelve);
    m_actionBar->addWidget(unshelve);
    m_actionBar->addWidget(journal);
    return m_actionBar;
}

void AlarmSummaryWidget::addMuteAction(QAction *mute)
{
    auto *button = new QToolButton(this);
    button->setObjectName(QStringLiteral("muteButton"));
    button->setDefaultAction(mute);
    button->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_actionBar->addWidget(button);
}

QList<QPair<QString, QString>> AlarmSummaryWidget::chosen(bool allShown) const
{
    QList<int> viewRows;
    if (allShown) {
        for (int r = 0; r < m_proxy->rowCount(); ++r)
            viewRows.append(r);
    } else {
        for (const QModelIndex &index : m_view->selectionModel()->selectedRows())
            viewRows.append(index.row());
        if (viewRows.isEmpty() && m_view->currentIndex().isValid())
            viewRows.append(m_view->currentIndex().row());
        std::sort(viewRows.begin(), viewRows.end());
    }
    QList<QPair<QString, QString>> alarms;
    for (int r : std::as_const(viewRows)) {
        const QModelIndex index = m_proxy->index(r, 0);
        alarms.append({index.data(AlarmSummaryModel::ConnectionRole).toString(),
                       index.data(AlarmSummaryModel::AlarmIdRole).toString()});
    }
    return alarms;
}

bool AlarmSummaryWidget::apply(
    const QList<QPair<QString, QString>> &alarms, const QString &done,
    const std::function<Status(const QString &, const QString &)> &action)
{
    if (alarms.isEmpty()) {
        m_message->setMessage(tr("Select the alarms first (click a row, or the arrow keys)."),
                              true);
        return false;
    }
    int count = 0;
    QString refusal;
    for (const auto &[connection, id] : alarms) {
        if (const Status s = action(connection, id); s)
            ++count;
        else if (refusal.isEmpty())
            refusal = tr("%1: %2").arg(id, translated(s.error().message));
    }
    const QString text = done.arg(count);
    m_message->setMessage(refusal.isEmpty() ? text : tr("%1 %2").arg(text, refusal), count == 0);
    if (count > 0)
        m_comment->clear();
    Q_EMIT statusMessage(m_message->text());
    return count > 0;
}

bool AlarmSummaryWidget::acknowledgeSelected()
{
    const QString comment = m_comment->text().trimmed();
    return apply(chosen(false), tr("Acknowledged: %1."),
                 [this, comment](const QString &c, const QString &id) {
                     return m_center->acknowledge(c, id, comment);
                 });
}

bool AlarmSummaryWidget::acknowledgeAllShown()
{
    // Only those that wait for it: "nothing to acknowledge" for the others says nothing new.
    QList<QPair<QString, QString>> alarms;
    for (int r = 0; r < m_proxy->rowCount(); ++r) {
        const QModelIndex index = m_proxy->index(r, 0);
        if (Alarms::isUnacked(
                static_cast<AlarmState>(index.data(AlarmSummaryModel::StateRole).toInt())))
            alarms.append({index.data(AlarmSummaryModel::ConnectionRole).toString(),
                           index.data(AlarmSummaryModel::AlarmIdRole).toString()});
    }
    if (alarms.isEmpty()) {
        m_message->setMessage(tr("No alarm shown waits for an acknowledge."), false);
        return false;
    }
    const QString comment = m_comment->text().trimmed();
    return apply(alarms, tr("Acknowledged: %1."),
                 [this, comment](const QString &c, const QString &id) {
                     return m_center->acknowledge(c, id, comment);
                 });
}

bool AlarmSummaryWidget::shelveSelected(qint64 durationMs)
{
    const qint64 until = QDateTime::currentMSecsSinceEpoch() + durationMs;
    const QString comment = m_comment->text().trimmed();
    return apply(chosen(false),
                 tr("Shelved until %1: %2.").arg(AlarmText::time(until), QStringLiteral("%1")),
                 [this, until, comment](const QString &c, const QString &id) {
                     return m_center->shelve(c, id, until, comment);
                 });
}

void AlarmSummaryWidget::shelveCustom()
{
    bool ok = false;
    const int minutes = QInputDialog::getInt(this, tr("Shelve Alarms"),
                                             tr("Shelve the selected alarms for (minutes):"), 30, 1,
                                             7 * 24 * 60, 5, &ok);
    if (ok)
        shelveSelected(minutes * minuteMs);
}

bool AlarmSummaryWidget::unshelveSelected()
{
    return apply(chosen(false), tr("Unshelved: %1."),
                 [this](const QString &c, const QString &id) { return m_center->unshelve(c, id); });
}

void AlarmSummaryWidget::resetConnection(const QString &connection)
{
    QList<AlarmStatus> listed;
    if (AlarmEngine *engine = m_center->engine(connection)) {
        const QList<AlarmStatus> all = engine->alarms();
        for (const AlarmStatus &a : all) {
            if (Alarms::isListed(a.state))
                listed.append(a);
        }
    }
    m_model->setAlarms(connection, listed);
}

void AlarmSummaryWidget::refreshGroups()
{
    QSet<QString> groups;
    for (int r = 0; r < m_model->rowCount(); ++r) {
        if (!m_model->status(r).definition.group.isEmpty())
            groups.insert(m_model->status(r).definition.group);
    }
    QStringList sorted(groups.cbegin(), groups.cend());
    sorted.sort(Qt::CaseInsensitive);
    const QString current = m_group->currentIndex() > 0 ? m_group->currentText() : QString();
    if (!current.isEmpty() && !sorted.contains(current))
        sorted.append(current); // the chosen filter stays until changed
    QStringList shown;
    for (int i = 1; i < m_group->count(); ++i)
        shown.append(m_group->itemText(i));
    if (shown == sorted)
        return;
    const QSignalBlocker blocker(m_group);
    while (m_group->count() > 1)
        m_group->removeItem(1);
    m_group->addItems(sorted);
    m_group->setCurrentIndex(current.isEmpty() ? 0 : m_group->findText(current));
}

} // namespace Fatek
