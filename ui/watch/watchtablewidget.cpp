#include "watchtablewidget.h"

#include "forcedmarks.h"
#include "ui/common/messageline.h"
#include "ui/common/toolconfirmation.h"
#include "ui/common/uitext.h"
#include "ui/connection/connectionmanager.h"
#include "watchdelegate.h"
#include "watchinput.h"
#include "watchtablemodel.h"
#include "watchtableview.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QSpinBox>
#include <QTableView>
#include <QTime>
#include <QToolButton>
#include <QVBoxLayout>

namespace Fatek {

WatchTableWidget::WatchTableWidget(ConnectionManager *manager, QWidget *parent)
    : QWidget(parent)
    , m_manager(manager)
    , m_name(tr("Watch"))
    , m_model(new WatchTableModel(this))
    , m_view(new WatchTableView(this))
    , m_forcedMarks(new ForcedMarks(m_model, this))
{
    m_addEdit = new QLineEdit(this);
    m_addEdit->setObjectName(QStringLiteral("addressEdit"));
    m_addEdit->setPlaceholderText(tr("Add: R100, R100..R163, X0..X15 — Enter"));
    m_addEdit->setClearButtonEnabled(true);
    m_addEdit->setMinimumWidth(m_addEdit->fontMetrics().horizontalAdvance(QLatin1Char('M')) * 10);
    auto *addButton = new QPushButton(tr("Add"), this);

    m_connectionCombo = new QComboBox(this);
    m_connectionCombo->setObjectName(QStringLiteral("connectionCombo"));
    m_connectionCombo->setMinimumContentsLength(8);
    m_connectionCombo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_connectionCombo->setToolTip(tr("Connection this table polls through"));

    m_interval = new QSpinBox(this);
    m_interval->setObjectName(QStringLiteral("intervalSpin"));
    m_interval->setRange(WatchList::MinIntervalMs, WatchList::MaxIntervalMs);
    m_interval->setSingleStep(100);
    m_interval->setValue(500);
    m_interval->setSuffix(tr(" ms"));
    m_interval->setToolTip(tr("Poll interval of this table"));

    m_pause = new QToolButton(this);
    m_pause->setObjectName(QStringLiteral("pauseButton"));
    m_pause->setCheckable(true);
    m_pause->setIcon(QIcon(QStringLiteral(":/icons/pause.svg")));
    m_pause->setText(tr("Pause"));
    m_pause->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_pause->setToolTip(tr("Stop polling this table"));

    m_confirmBox = new QCheckBox(tr("Confirm writes"), this);
    m_confirmBox->setChecked(true);

    auto *bar = new QHBoxLayout;
    bar->addWidget(m_addEdit, 3);
    bar->addWidget(addButton);
    bar->addSpacing(12);
    bar->addWidget(new QLabel(tr("Connection:"), this));
    bar->addWidget(m_connectionCombo, 1);
    bar->addWidget(new QLabel(tr("Every"), this));
    bar->addWidget(m_interval);
    bar->addWidget(m_pause);
    bar->addWidget(m_confirmBox);

    // One line, always there: a message that comes and goes never shifts the rows under the
    // pointer. The whole text is in the tooltip and in the status bar.
    m_message = new MessageLine(1, this);
    m_message->setObjectName(QStringLiteral("messageLabel"));

    m_view->setObjectName(QStringLiteral("watchView"));
    m_view->setModel(m_model);
    m_view->setItemDelegate(new WatchDelegate(m_view));
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                            | QAbstractItemView::AnyKeyPressed);
    m_view->setAlternatingRowColors(true);
    m_view->setWordWrap(false);
    m_view->verticalHeader()->setDefaultSectionSize(m_view->fontMetrics().height() + 8);
    m_view->verticalHeader()->hide();
    QHeaderView *header = m_view->horizontalHeader();
    header->setStretchLastSection(true);
    const int em = m_view->fontMetrics().horizontalAdvance(QLatin1Char('M'));
    const int widths[] = {14, 7, 5, 13, 9, 8, 9, 10};
    for (int c = 0; c < WatchTableModel::ColumnCount; ++c)
        header->resizeSection(c, widths[c] * em);
    m_view->setContextMenuPolicy(Qt::ActionsContextMenu);

    auto *writeAction = new QAction(tr("&Write Value…"), m_view);
    writeAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_W));
    writeAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_swapAction = new QAction(tr("&Swap Words"), m_view);
    m_swapAction->setToolTip(
        tr("Low word first for 32- and 64-bit values (some HMIs store floats so)"));
    auto *pasteAction = new QAction(tr("&Paste Items"), m_view);
    pasteAction->setShortcut(QKeySequence::Paste);
    pasteAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    auto *removeAction
        = new QAction(QIcon(QStringLiteral(":/icons/remove.svg")), tr("&Remove"), m_view);
    removeAction->setShortcut(QKeySequence::Delete);
    removeAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_view->addActions({writeAction, m_swapAction, pasteAction, removeAction});
    auto *trendAction = new QAction(tr("Add to &Trend"), m_view);
    trendAction->setToolTip(tr("Plot the selected items over time in the trend view"));
    m_view->addAction(trendAction);
    connect(trendAction, &QAction::triggered, this, [this] {
        QList<int> rows;
        for (const QModelIndex &index : m_view->selectionModel()->selectedIndexes()) {
            if (!rows.contains(index.row()))
                rows.append(index.row());
        }
        if (rows.isEmpty() && m_view->currentIndex().isValid())
            rows.append(m_view->currentIndex().row());
        std::sort(rows.begin(), rows.end());
        if (!rows.isEmpty())
            Q_EMIT addToTrendRequested(rows);
    });

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(bar);
    layout->addWidget(m_message);
    layout->addWidget(m_view, 1);

    connect(m_addEdit, &QLineEdit::returnPressed, this, [this] { addFromText(m_addEdit->text()); });
    connect(addButton, &QPushButton::clicked, this, [this] { addFromText(m_addEdit->text()); });
    connect(writeAction, &QAction::triggered, this, &WatchTableWidget::writeDialog);
    connect(m_swapAction, &QAction::triggered, this, &WatchTableWidget::toggleSwapWords);
    connect(pasteAction, &QAction::triggered, this,
            [this] { addFromPaste(QApplication::clipboard()->text()); });
    connect(removeAction, &QAction::triggered, this, &WatchTableWidget::removeSelected);
    connect(m_model, &WatchTableModel::pollListChanged, this, &WatchTableWidget::pushPollList);
    // Queued: the confirmation dialog must not open inside the editor's commit (a nested event
    // loop while the view is closing its editor). The row is found again by its key.
    connect(m_model, &WatchTableModel::writeRequested, this, [this](int row, quint64 raw) {
        const quint64 key = m_model->rowKey(row);
        QMetaObject::invokeMethod(
            this,
            [this, key, raw] {
                const int current = m_model->rowOfKey(key);
                if (current >= 0)
                    write(current, raw);
            },
            Qt::QueuedConnection);
    });
    connect(m_model, &WatchTableModel::inputRejected, this,
            [this](const QString &text) { showMessage(text, true); });
    connect(m_interval, &QSpinBox::valueChanged, this, &WatchTableWidget::pushPollList);
    connect(m_pause, &QToolButton::toggled, this, [this](bool paused) {
        pushPollList();
        if (paused)
            m_model->markAllStale(tr("polling paused"));
    });
    connect(m_connectionCombo, &QComboBox::activated, this,
            [this](int index) { setConnection(m_manager->connection(index)); });
    connect(manager, &ConnectionManager::connectionAdded, this, [this](Connection *c) {
        refreshConnections();
        if (!m_connection)
            setConnection(c);
    });
    connect(manager, &ConnectionManager::connectionAboutToBeRemoved, this, [this](Connection *c) {
        if (c == m_connection)
            setConnection(nullptr);
    });
    connect(manager, &ConnectionManager::connectionRemoved, this,
            &WatchTableWidget::refreshConnections);

    // Forced marks cost bus time: only for a table someone can see, that polls a live link.
    m_forcedMarks->setActiveCheck([this] {
        return isVisible() && !isPaused() && m_connection
               && m_connection->linkState() == LinkState::Connected;
    });

    refreshConnections();
    if (!manager->connections().isEmpty())
        setConnection(manager->connections().constFirst());
}

WatchTableWidget::~WatchTableWidget()
{
    if (m_connection)
        m_connection->setWatchItems(this, {});
}

void WatchTableWidget::refreshConnections()
{
    m_connectionCombo->clear();
    for (Connection *c : m_manager->connections())
        m_connectionCombo->addItem(c->name());
    m_connectionCombo->setCurrentIndex(m_manager->indexOf(m_connection));
}

void WatchTableWidget::setConnection(Connection *connection)
{
    if (connection == m_connection)
        return;
    if (m_connection) {
        m_connection->setWatchItems(this, {});
        disconnect(m_connection, nullptr, m_model, nullptr);
    }
    m_connection = connection;
    if (connection) {
        // A paused table is frozen: a cycle already under way when it paused must not update it.
        // Batches are applied in time slices, coalesced per frame (WatchTableModel::queueValues).
        connect(connection, &Connection::itemValues, m_model,
                [this](const QList<WatchItemValue> &values) {
                    if (!isPaused())
                        m_model->queueValues(values);
                });
        // A link stops reporting while it is down (no batches come): mark the rows here.
        connect(connection, &Connection::linkStateChanged, m_model,
                [this](LinkState state, const Message &reason) {
                    // The link is back: a red "write failed" would say the link is still down.
                    // It becomes a plain note that the value was not written (not repeated:
                    // the person decides whether it is still wanted).
                    if (state == LinkState::Connected && !m_failedWrite.isEmpty())
                        showMessage(tr("%1 is connected again; %2 was not written.")
                                        .arg(m_connection->name(), m_failedWrite),
                                    false);
                    if (state == LinkState::Connected || state == LinkState::Connecting)
                        return;
                    m_model->markAllStale(
                        reason.empty()
                            ? tr("link %1").arg(UiText::linkState(state))
                            : tr("link %1: %2").arg(UiText::linkState(state), translated(reason)));
                });
        connect(connection, &Connection::changed, m_model,
                [this] { m_model->setSilentStations(m_connection->silentStations()); });
        m_model->setSilentStations(connection->silentStations());
    } else {
        m_model->setSilentStations({});
        m_model->markAllStale(tr("no connection"));
    }
    m_forcedMarks->setSession(connection ? connection->session() : nullptr);
    // A link whose far end sets the intervals (its own configuration): the spin box would change
    // nothing.
    const bool fixed = connection && !connection->link()->takesIntervals();
    m_interval->setEnabled(!fixed);
    m_interval->setToolTip(
        fixed ? tr("Polled at the intervals %1 is configured with").arg(connection->linkText())
              : tr("Poll interval of this table"));
    m_connectionCombo->setCurrentIndex(m_manager->indexOf(connection));
    pushPollList();
    Q_EMIT connectionChanged(connection);
}

void WatchTableWidget::pushPollList()
{
    if (!m_connection)
        return;
    m_connection->setWatchItems(this, isPaused() ? QList<WatchedItem>()
                                                 : m_model->watchItems(intervalMs()));
}

WatchTableSpec WatchTableWidget::spec() const
{
    WatchTableSpec spec;
    spec.name = m_name;
    spec.intervalMs = intervalMs();
    spec.confirmWrites = confirmWrites();
    spec.items = m_model->items();
    return spec;
}

void WatchTableWidget::setSpec(const WatchTableSpec &spec)
{
    setName(spec.name);
    const QSignalBlocker blocker(m_interval);
    m_interval->setValue(spec.intervalMs);
    setConfirmWrites(spec.confirmWrites);
    m_model->setItems(spec.items);
}

void WatchTableWidget::setName(const QString &name)
{
    if (name == m_name)
        return;
    m_name = name;
    Q_EMIT nameChanged(name);
}

int WatchTableWidget::intervalMs() const
{
    return m_interval->value();
}

void WatchTableWidget::setIntervalMs(int ms)
{
    m_interval->setValue(ms);
}

bool WatchTableWidget::isPaused() const
{
    return m_pause->isChecked();
}

void WatchTableWidget::setPaused(bool paused)
{
    m_pause->setChecked(paused);
}

bool WatchTableWidget::confirmWrites() const
{
    return m_confirmBox->isChecked();
}

void WatchTableWidget::setConfirmWrites(bool confirm)
{
    m_confirmBox->setChecked(confirm);
}

quint8 WatchTableWidget::defaultStation() const
{
    return m_connection ? std::max<quint8>(1, m_connection->station()) : quint8(1);
}

QString WatchTableWidget::message() const
{
    return m_message->text();
}

void WatchTableWidget::showMessage(const QString &text, bool error)
{
    m_failedWrite.clear();
    m_message->setMessage(text, error);
    Q_EMIT statusMessage(text);
}

bool WatchTableWidget::addFromText(const QString &text)
{
    const auto addresses = WatchInput::parseAddresses(text);
    if (!addresses) {
        showMessage(translated(addresses.error().message), true);
        return false;
    }
    QList<Address> wanted = *addresses;
    QList<Address> present;
    for (const WatchItemSpec &item : m_model->items())
        present << item.address;
    QList<WatchItemSpec> items;
    int companions = 0;
    auto append = [&](const Address &address) {
        WatchItemSpec item;
        item.address = address;
        item.station = defaultStation();
        item.format = ValueFormat::defaultFormat(address);
        items.append(item);
    };
    for (const Address &address : std::as_const(wanted)) {
        append(address);
        // A timer's or counter's contact alone says little: its current value goes beside it
        // (RT0 with T0; RC with 16-bit counters C0-C199), unless the table or the input has it.
        std::optional<Address> value;
        if (address.type == ElementType::T)
            value = Address{ElementType::RT, address.number};
        else if (address.type == ElementType::C && address.number < 200)
            value = Address{ElementType::RC, address.number};
        if (value && !present.contains(*value) && !wanted.contains(*value)) {
            append(*value);
            present << *value;
            ++companions;
        }
    }
    m_model->addItems(items);
    m_addEdit->clear();
    const int typed = static_cast<int>(items.size()) - companions;
    showMessage(companions == 0
                    ? tr("Added %n item(s).", nullptr, typed)
                    : tr("Added %n item(s), each timer and counter contact with its current "
                         "value (RT/RC) beside it.",
                         nullptr, typed),
                false);
    return true;
}

bool WatchTableWidget::addFromPaste(const QString &text)
{
    const auto items = WatchInput::parsePasted(text, defaultStation());
    if (!items) {
        showMessage(tr("Cannot paste: %1").arg(translated(items.error().message)), true);
        return false;
    }
    m_model->addItems(*items);
    showMessage(tr("Pasted %n item(s).", nullptr, static_cast<int>(items->size())), false);
    return true;
}

void WatchTableWidget::write(int row, quint64 raw)
{
    const WatchItemSpec item = m_model->item(row);
    const QString address = QString::fromStdString(item.address.toString());
    const QString text
        = ValueFormat::format(raw, m_model->valueWidth(row), item.format, item.swapWords);
    const QString what = tr("%1 (station %2) = %3").arg(address).arg(item.station).arg(text);
    if (!m_connection) {
        showMessage(tr("Cannot write %1: the table has no connection.").arg(what), true);
        return;
    }
    // In operator mode the link refuses the write with its own message: no question first.
    if (confirmWrites() && !m_connection->isReadOnly()) {
        const QString question = tr("Write %1 to the PLC on %2?").arg(what, m_connection->name());
        // One rule for every question before the PLC changes: the safe answer is the default,
        // so a second Enter after typing the value does not write.
        const bool go = m_confirm ? m_confirm(this, question)
                                  : ToolConfirmation::ask(this, tr("Write Value"), question, {});
        if (!go) {
            showMessage(tr("Write of %1 cancelled.").arg(what), false);
            return;
        }
    }
    // Answers meant for a connection the table has left since are dropped.
    m_connection->link()->write(
        item, raw, this,
        [this, rowKey = m_model->rowKey(row), what,
         written = QPointer<Connection>(m_connection)](const LinkWriteResult &result) {
            if (written == m_connection)
                onWritten(rowKey, what, result);
        });
    showMessage(tr("Writing %1 …").arg(what), false);
}

void WatchTableWidget::onWritten(quint64 rowKey, const QString &what, const LinkWriteResult &result)
{
    const QString outcome = result.ok
                                ? tr("Wrote %1.").arg(what)
                                : tr("Write of %1 failed: %2").arg(what, translated(result.error));
    const int row = m_model->rowOfKey(rowKey);
    if (row >= 0)
        m_model->setWriteOutcome(
            row,
            tr("%1 %2").arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss")), outcome));
    showMessage(outcome, !result.ok);
    if (!result.ok)
        m_failedWrite = what;
}

void WatchTableWidget::removeSelected()
{
    QList<int> rows;
    for (const QModelIndex &index : m_view->selectionModel()->selectedRows())
        rows.append(index.row());
    std::sort(rows.begin(), rows.end(), std::greater<>());
    for (int row : std::as_const(rows))
        m_model->removeRows(row, 1);
}

void WatchTableWidget::writeDialog()
{
    const QModelIndex current = m_view->currentIndex();
    if (!current.isValid())
        return;
    const int row = current.row();
    const WatchItemSpec item = m_model->item(row);
    // Operator mode: say so at once instead of asking for a value that will be refused.
    if (m_connection && m_connection->isReadOnly()) {
        showMessage(tr("Operator mode (read-only): %1 cannot be written.")
                        .arg(QString::fromStdString(item.address.toString())),
                    true);
        return;
    }
    bool ok = false;
    const QString text = QInputDialog::getText(
        this, tr("Write Value"),
        tr("New value for %1 (%2; hex as 0x1A or 1Ah):")
            .arg(QString::fromStdString(item.address.toString()), UiText::format(item.format)),
        QLineEdit::Normal, m_model->valueText(row), &ok);
    if (ok)
        m_model->setData(m_model->index(row, WatchTableModel::ValueColumn), text);
}

void WatchTableWidget::toggleSwapWords()
{
    for (const QModelIndex &index : m_view->selectionModel()->selectedRows()) {
        const WatchItemSpec item = m_model->item(index.row());
        const Status s = m_model->setFormat(index.row(), item.format, !item.swapWords);
        if (!s)
            showMessage(translated(s.error().message), true);
    }
}

} // namespace Fatek
