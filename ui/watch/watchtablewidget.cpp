#include "watchtablewidget.h"

#include "forcedmarks.h"
#include "ui/common/messageline.h"
#include "ui/common/uitext.h"
#include "ui/connection/connectionmanager.h"
#include "watchdelegate.h"
#include "watchinput.h"
#include "watchtablemodel.h"
#include "watchtableproxy.h"
#include "watchtableview.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <vector>

namespace Fatek {

WatchTableWidget::WatchTableWidget(ConnectionManager *manager, QWidget *parent)
    : QWidget(parent)
    , m_manager(manager)
    , m_name(tr("Watch"))
    , m_model(new WatchTableModel(this))
    , m_proxy(new WatchTableProxy(this))
    , m_view(new WatchTableView(this))
    , m_actions(this, m_view, m_model->undoStack())
    , m_writer(new WatchTableWriter(m_model, this))
    , m_forcedMarks(new ForcedMarks(m_model, this))
    , m_subscription(new PlantSubscription(this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(createEntryBar());
    layout->addLayout(createMessageBar());
    setUpView();
    layout->addWidget(m_view, 1);
    connectActions();
    connectModel();
    connectManager();
    connect(m_writer, &WatchTableWriter::message, this, &WatchTableWidget::showMessage);
    connect(m_writer, &WatchTableWriter::refused, this,
            [this](const QString &what) { m_failedWrite = what; });

    // Forced marks cost bus time: only for a table someone can see, that polls a live link.
    m_forcedMarks->setActiveCheck([this] {
        return isVisible() && !isPaused() && m_connection
               && m_connection->linkState() == LinkState::Connected;
    });

    refreshConnections();
    if (!manager->connections().isEmpty())
        setConnection(manager->connections().constFirst());
}

QLayout *WatchTableWidget::createEntryBar()
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

    connect(m_addEdit, &QLineEdit::returnPressed, this, [this] { addFromText(m_addEdit->text()); });
    connect(addButton, &QPushButton::clicked, this, [this] { addFromText(m_addEdit->text()); });
    connect(m_interval, &QSpinBox::valueChanged, this, &WatchTableWidget::edited);
    connect(m_confirmBox, &QCheckBox::toggled, this, &WatchTableWidget::edited);
    connect(this, &WatchTableWidget::nameChanged, this, &WatchTableWidget::edited);
    connect(m_interval, &QSpinBox::valueChanged, this, &WatchTableWidget::pushPollList);
    connect(m_pause, &QToolButton::toggled, this, [this](bool paused) {
        m_pause->setText(paused ? tr("Resume") : tr("Pause")); // what a click does
        m_pause->setToolTip(paused ? tr("Poll this table again") : tr("Stop polling this table"));
        pushPollList();
        if (paused)
            m_model->markAllStale(tr("polling paused"));
    });
    connect(m_connectionCombo, &QComboBox::activated, this,
            [this](int index) { setConnection(m_manager->connection(index)); });
    return bar;
}

QLayout *WatchTableWidget::createMessageBar()
{
    // One line, always there (a message never shifts the rows); whole in its tooltip and status.
    m_message = new MessageLine(1, this);
    m_message->setObjectName(QStringLiteral("messageLabel"));

    // Beside the message line: it takes no height of its own from the rows.
    m_filterEdit = new QLineEdit(this);
    m_filterEdit->setObjectName(QStringLiteral("filterEdit"));
    m_filterEdit->setPlaceholderText(tr("Filter: address, name or comment"));
    m_filterEdit->setClearButtonEnabled(true);
    m_filterEdit->setToolTip(tr("Show only the rows whose address, name or comment contains this "
                                "text (Ctrl+F)"));
    // Wide enough for its placeholder, which says what it searches.
    m_filterEdit->setMinimumWidth(
        m_filterEdit->fontMetrics().horizontalAdvance(m_filterEdit->placeholderText()) + 40);
    auto *findAction = new QAction(this);
    findAction->setShortcut(QKeySequence::Find);
    findAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    addAction(findAction);
    connect(findAction, &QAction::triggered, m_filterEdit, [this] {
        m_filterEdit->setFocus(Qt::ShortcutFocusReason);
        m_filterEdit->selectAll();
    });
    connect(m_filterEdit, &QLineEdit::textChanged, m_proxy, &WatchTableProxy::setFilterText);

    auto *messageBar = new QHBoxLayout;
    messageBar->addWidget(m_message, 1);
    messageBar->addWidget(m_filterEdit);
    return messageBar;
}

void WatchTableWidget::setUpView()
{
    m_proxy->setSourceModel(m_model);
    m_view->setObjectName(QStringLiteral("watchView"));
    m_view->setModel(m_proxy);
    // Ages are repainted where they can be seen: a hidden table or a row scrolled away paints
    // its age afresh when it comes back.
    m_model->setAgeRows([this] {
        std::vector<int> rows;
        if (!m_view->isVisible() || m_proxy->rowCount() == 0)
            return rows;
        const int first = std::max(0, m_view->rowAt(0));
        int last = m_view->rowAt(m_view->viewport()->height() - 1);
        if (last < 0)
            last = m_proxy->rowCount() - 1;
        for (int r = first; r <= last; ++r)
            rows.push_back(modelRow(m_proxy->index(r, 0)));
        return rows;
    });
    auto *delegate = new WatchDelegate(m_view);
    // A format picked in one row's combo goes to every selected row with it.
    delegate->setFormatHandler([this](const QModelIndex &index, DisplayFormat format) {
        QList<int> rows = selectedRows();
        const int row = modelRow(index);
        if (!rows.contains(row))
            rows = {row};
        if (const Status s = m_model->setFormats(rows, format); !s)
            showMessage(translated(s.error().message), true);
    });
    m_view->setItemDelegate(delegate);
    m_view->setUpColumns();

    // Rows are moved in the model's order: not while the view shows another (Ctrl+Up says so).
    connect(m_proxy, &WatchTableProxy::rearrangedChanged, this, [this](bool rearranged) {
        m_view->setRowsMovable(!rearranged);
        m_actions.setRowsMovable(!rearranged);
    });
    connect(m_view, &WatchTableView::rowsDropped, this,
            [this](const QList<int> &rows, int destination) {
                QList<int> moved;
                for (int r : rows)
                    moved.append(modelRow(m_proxy->index(r, 0)));
                // Not rearranged (else no drag): the view's rows are the model's.
                m_model->moveItemsTo(moved, destination);
            });
}

void WatchTableWidget::connectActions()
{
    connect(m_actions.trend, &QAction::triggered, this, [this] {
        const QList<int> rows = selectedRows();
        if (!rows.isEmpty())
            Q_EMIT addToTrendRequested(rows);
    });
    connect(m_actions.copy, &QAction::triggered, this, &WatchTableWidget::copySelected);
    connect(m_actions.moveUp, &QAction::triggered, this, [this] { moveSelected(-1); });
    connect(m_actions.moveDown, &QAction::triggered, this, [this] { moveSelected(1); });
    connect(m_actions.moveRefused, &QAction::triggered, this, [this] {
        showMessage(tr("Rows move only in own order: clear the filter, choose Own Order."), false);
    });
    connect(m_actions.ownOrder, &QAction::triggered, this,
            [this] { m_view->horizontalHeader()->setSortIndicator(-1, Qt::AscendingOrder); });
    connect(m_actions.formatMenu, &QMenu::aboutToShow, this, &WatchTableWidget::fillFormatMenu);
    connect(m_actions.write, &QAction::triggered, this, &WatchTableWidget::writeDialog);
    connect(m_actions.swapWords, &QAction::triggered, this, &WatchTableWidget::toggleSwapWords);
    connect(m_actions.paste, &QAction::triggered, this,
            [this] { addFromPaste(QApplication::clipboard()->text()); });
    connect(m_actions.remove, &QAction::triggered, this, &WatchTableWidget::removeSelected);
}

void WatchTableWidget::connectModel()
{
    connect(m_model, &WatchTableModel::itemsEdited, this, &WatchTableWidget::edited);
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
}

void WatchTableWidget::connectManager()
{
    connect(m_manager, &ConnectionManager::connectionAdded, this, [this](Connection *c) {
        refreshConnections();
        if (!m_connection)
            setConnection(c);
    });
    connect(m_manager, &ConnectionManager::connectionAboutToBeRemoved, this, [this](Connection *c) {
        if (c == m_connection)
            setConnection(nullptr);
    });
    connect(m_manager, &ConnectionManager::connectionRemoved, this,
            &WatchTableWidget::refreshConnections);
}

WatchTableWidget::~WatchTableWidget()
{
    m_subscription->setConnection(nullptr);
}

QTableView *WatchTableWidget::view() const
{
    return m_view;
}

QModelIndex WatchTableWidget::viewIndex(const QModelIndex &modelIndex) const
{
    return m_proxy->mapFromSource(modelIndex);
}

int WatchTableWidget::modelRow(const QModelIndex &viewIndex) const
{
    const QModelIndex source
        = viewIndex.model() == m_model ? viewIndex : m_proxy->mapToSource(viewIndex);
    return source.isValid() ? source.row() : -1;
}

QList<int> WatchTableWidget::selectedRows() const
{
    QList<int> rows;
    for (const QModelIndex &index : m_view->selectionModel()->selectedIndexes()) {
        const int row = modelRow(index);
        if (row >= 0 && !rows.contains(row))
            rows.append(row);
    }
    if (rows.isEmpty() && m_view->currentIndex().isValid())
        rows.append(modelRow(m_view->currentIndex()));
    std::sort(rows.begin(), rows.end());
    return rows;
}

QString WatchTableWidget::selectedRowsText() const
{
    // The rows as the view shows them (sorted, filtered).
    QList<int> viewRows;
    for (const QModelIndex &index : m_view->selectionModel()->selectedIndexes()) {
        if (!viewRows.contains(index.row()))
            viewRows.append(index.row());
    }
    if (viewRows.isEmpty() && m_view->currentIndex().isValid())
        viewRows.append(m_view->currentIndex().row());
    std::sort(viewRows.begin(), viewRows.end());
    QList<int> rows;
    for (int viewRow : std::as_const(viewRows)) {
        if (const int row = modelRow(m_proxy->index(viewRow, 0)); row >= 0)
            rows.append(row);
    }
    return m_model->rowsText(rows);
}

void WatchTableWidget::copySelected()
{
    if (selectedRows().isEmpty())
        return;
    QApplication::clipboard()->setText(selectedRowsText());
    showMessage(tr("Copied %n row(s).", nullptr, static_cast<int>(selectedRows().size())), false);
}

void WatchTableWidget::moveSelected(int delta)
{
    if (m_proxy->isRearranged())
        return;
    m_model->moveItems(selectedRows(), delta);
    // The current row goes along (the selection does, as persistent indexes).
    m_view->scrollTo(m_view->currentIndex());
}

void WatchTableWidget::setSelectedFormat(DisplayFormat format)
{
    if (const Status s = m_model->setFormats(selectedRows(), format); !s)
        showMessage(translated(s.error().message), true);
}

void WatchTableWidget::fillFormatMenu()
{
    m_actions.formatMenu->clear();
    const QList<int> rows = selectedRows();
    if (rows.isEmpty())
        return;
    // The formats every selected row can show.
    QList<DisplayFormat> formats = m_model->availableFormats(rows.first());
    for (int r : rows) {
        const QList<DisplayFormat> own = m_model->availableFormats(r);
        formats.removeIf([&own](DisplayFormat f) { return !own.contains(f); });
    }
    for (DisplayFormat f : std::as_const(formats)) {
        QAction *a = m_actions.formatMenu->addAction(UiText::format(f));
        a->setObjectName(QStringLiteral("format_") + ValueFormat::name(f));
        connect(a, &QAction::triggered, this, [this, f] { setSelectedFormat(f); });
    }
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
        disconnect(m_connection, nullptr, m_model, nullptr);
        disconnect(m_subscription, nullptr, m_model, nullptr);
    }
    m_connection = connection;
    m_subscription->setItems({}); // pushPollList() subscribes them to the new connection
    m_subscription->setConnection(connection ? connection->plant() : nullptr);
    if (connection) {
        // A paused table is frozen: a cycle already under way when it paused must not update it.
        // Batches are applied in time slices, coalesced per frame (WatchTableModel::queueValues).
        connect(m_subscription, &PlantSubscription::itemValues, m_model,
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
    m_forcedMarks->setTarget(
        connection ? PlcTarget(connection->link(), connection->station(), connection->name())
                   : PlcTarget());
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
    m_subscription->setItems(isPaused() ? QList<WatchedItem>() : m_model->watchItems(intervalMs()));
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
    m_view->showInsertedRow(m_proxy->mapFromSource(m_model->index(m_model->rowCount() - 1, 0)));
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
    // Rows only, as new rows: a paste never writes a value to the PLC.
    m_model->addItems(*items);
    m_view->showInsertedRow(m_proxy->mapFromSource(m_model->index(m_model->rowCount() - 1, 0)));
    showMessage(tr("Pasted %n item(s).", nullptr, static_cast<int>(items->size())), false);
    return true;
}

void WatchTableWidget::removeSelected()
{
    m_model->removeItems(selectedRows());
}

void WatchTableWidget::writeDialog()
{
    if (const int row = modelRow(m_view->currentIndex()); row >= 0)
        m_writer->askAndWrite(row);
}

void WatchTableWidget::toggleSwapWords()
{
    // One step to undo for all the rows.
    m_model->undoStack()->beginMacro(m_actions.swapWords->text().remove(QLatin1Char('&')));
    for (int row : selectedRows()) {
        const WatchItemSpec item = m_model->item(row);
        const Status s = m_model->setFormat(row, item.format, !item.swapWords);
        if (!s)
            showMessage(translated(s.error().message), true);
    }
    m_model->undoStack()->endMacro();
}

} // namespace Fatek
