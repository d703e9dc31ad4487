#include "forcingpanel.h"

#include "ui/common/messageline.h"

#include "core/session/requesttracker.h"
#include "discretecontrolbatch.h"
#include "discretetablemodel.h"
#include "forcedpointsview.h"
#include "ui/common/toolpalette.h"
#include "ui/common/uitext.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableView>
#include <QVBoxLayout>

#include <algorithm>

namespace Fatek {

ForcingPanel::ForcingPanel(QWidget *parent)
    : QWidget(parent)
    , m_requests(new RequestTracker(this))
    , m_model(new DiscreteTableModel(this))
{
    auto *outer = new QVBoxLayout(this);
    m_targetLabel = new QLabel(this);
    m_targetLabel->setObjectName(QStringLiteral("targetLabel"));
    outer->addWidget(m_targetLabel);
    auto *tabs = new QTabWidget(this);
    outer->addWidget(tabs, 1);

    auto *table = new QWidget(tabs);
    auto *layout = new QVBoxLayout(table);
    auto *row = new QHBoxLayout;
    m_type = new QComboBox(table);
    m_type->setObjectName(QStringLiteral("typeCombo"));
    for (ElementType t : {ElementType::X, ElementType::Y, ElementType::M, ElementType::S,
                          ElementType::T, ElementType::C}) {
        const ElementInfo &info = elementInfo(t);
        m_type->addItem(tr("%1 \u2013 %2")
                            .arg(QString::fromUtf8(info.symbol.data(),
                                                   static_cast<qsizetype>(info.symbol.size())),
                                 UiText::elementName(t)),
                        static_cast<int>(t));
    }
    m_type->setCurrentIndex(1); // Y: outputs are what gets forced most
    m_start = new QSpinBox(table);
    m_start->setObjectName(QStringLiteral("startSpin"));
    m_start->setRange(0, static_cast<int>(elementInfo(ElementType::X).maxNumber));
    m_count = new QSpinBox(table);
    m_count->setObjectName(QStringLiteral("countSpin"));
    m_count->setRange(1, static_cast<int>(Limits::maxDiscretes));
    m_count->setValue(16);
    m_readButton = new QPushButton(tr("Show"), table);
    m_readButton->setObjectName(QStringLiteral("readButton"));
    m_autoRefresh = new QCheckBox(tr("Refresh every second"), table);
    m_autoRefresh->setObjectName(QStringLiteral("autoRefresh"));
    m_autoRefresh->setChecked(true);
    // Two rows: in one the dock would need more than a laptop's side of the screen.
    row->addWidget(new QLabel(tr("Type:"), table));
    row->addWidget(m_type);
    row->addStretch(1);
    row->addWidget(m_autoRefresh);
    layout->addLayout(row);
    auto *rangeRow = new QHBoxLayout;
    rangeRow->addWidget(new QLabel(tr("From:"), table));
    rangeRow->addWidget(m_start);
    rangeRow->addWidget(new QLabel(tr("Points:"), table));
    rangeRow->addWidget(m_count);
    rangeRow->addWidget(m_readButton);
    rangeRow->addStretch(1);
    layout->addLayout(rangeRow);

    m_model->setPalette(palette());
    m_view = new QTableView(table);
    m_view->setObjectName(QStringLiteral("discreteTable"));
    m_view->setModel(m_model);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->verticalHeader()->hide();
    m_view->horizontalHeader()->setStretchLastSection(true);
    m_view->verticalHeader()->setDefaultSectionSize(m_view->fontMetrics().height() + 6);
    layout->addWidget(m_view, 1);

    auto *actions = new QHBoxLayout;
    struct Action
    {
        DiscreteOp op;
        QString text;
        const char *name;
    };
    const Action list[] = {{DiscreteOp::Disable, tr("Disable (force)"), "disableButton"},
                           {DiscreteOp::Enable, tr("Enable"), "enableButton"},
                           {DiscreteOp::Set, tr("Set ON"), "setButton"},
                           {DiscreteOp::Reset, tr("Reset OFF"), "resetButton"}};
    for (const Action &a : list) {
        auto *button = new QPushButton(a.text, table);
        button->setObjectName(QLatin1String(a.name));
        const DiscreteOp op = a.op;
        connect(button, &QPushButton::clicked, this, [this, op] { applyToSelection(op); });
        m_actionButtons << button;
        actions->addWidget(button);
    }
    actions->addStretch(1);
    layout->addLayout(actions);
    // Two lines reserved: an outcome that comes and goes never moves the buttons and rows.
    m_message = new MessageLine(2, table);
    m_message->setObjectName(QStringLiteral("forcingMessage"));
    layout->addWidget(m_message);
    tabs->addTab(table, tr("Discretes"));

    m_forced = new ForcedPointsView(tabs);
    tabs->addTab(m_forced, tr("Forced points"));

    connect(m_readButton, &QPushButton::clicked, this, &ForcingPanel::applyRangeFromControls);
    connect(m_autoRefresh, &QCheckBox::toggled, this, &ForcingPanel::setAutoRefresh);
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &ForcingPanel::updateEnabled);
    connect(m_forced, &ForcedPointsView::pointsChanged, this, &ForcingPanel::refresh);
    m_timer.setInterval(1000);
    connect(&m_timer, &QTimer::timeout, this, [this] {
        // A hidden panel (closed dock) must not keep loading a slow bus.
        if (isVisible())
            refresh();
    });

    // A deleted session leaves the tool in "no connection".
    connect(m_requests, &RequestTracker::sessionDestroyed, this,
            [this] { setTarget(PlcTarget(nullptr, m_target.station(), {})); });
    setTarget(PlcTarget());
}

void ForcingPanel::setTarget(const PlcTarget &target)
{
    m_target = target;
    target.aim(m_requests);
    m_requests->forgetPending(); // answers meant for the previous target are ignored
    m_forced->setTarget(target);
    ++m_generation;
    m_pendingReads = 0;
    m_reads = 0;
    m_acting = false;
    m_message->setMessage({}, false);
    if (!target.isDirect()) {
        m_targetLabel->setText(tr("No connection: choose a connection and a station."));
        m_timer.stop();
        m_model->setRange(m_model->range()); // forget the values of the previous PLC
    } else {
        m_targetLabel->setText(
            tr("Station %1 on \u201c%2\u201d").arg(target.station()).arg(target.connectionName()));
        applyRangeFromControls();
        setAutoRefresh(m_autoRefresh->isChecked());
    }
    updateEnabled();
}

void ForcingPanel::setSymbols(const SymbolNames *symbols)
{
    m_model->setSymbols(symbols);
    m_forced->setSymbols(symbols);
}

void ForcingPanel::setConfirmer(Confirmer confirmer)
{
    m_confirmer = confirmer;
    m_forced->setConfirmer(std::move(confirmer));
}

void ForcingPanel::showRange(ElementType type, quint32 start, quint32 count)
{
    const int index = m_type->findData(static_cast<int>(type));
    if (index < 0) {
        m_message->setMessage(tr("Only X, Y, M, S, T and C points can be forced."), true);
        return;
    }
    m_type->setCurrentIndex(index);
    m_start->setValue(static_cast<int>(start));
    m_count->setValue(static_cast<int>(count));
    applyRangeFromControls();
}

void ForcingPanel::setAutoRefresh(bool on)
{
    if (m_autoRefresh->isChecked() != on)
        m_autoRefresh->setChecked(on);
    if (on && m_target.isDirect())
        m_timer.start();
    else
        m_timer.stop();
}

QString ForcingPanel::messageText() const
{
    return m_message->text();
}

void ForcingPanel::applyRangeFromControls()
{
    AddressRange range;
    range.start = Address{static_cast<ElementType>(m_type->currentData().toInt()),
                          static_cast<quint32>(m_start->value())};
    range.count = static_cast<quint32>(m_count->value());
    if (const Status s = validateSpan(range.start, range.count); !s) {
        m_message->setMessage(translated(s.error().message), true);
        return;
    }
    ++m_generation;
    m_pendingReads = 0;
    m_reads = 0;
    m_model->setRange(range);
    m_message->setMessage({}, false);
    refresh();
}

void ForcingPanel::refresh()
{
    // Both reads of the previous refresh must be back first: a slow link must not pile up requests.
    if (!m_target.isDirect() || m_pendingReads > 0 || m_model->range().count == 0)
        return;
    const AddressRange range = m_model->range();
    const quint64 generation = m_generation;
    auto handle = [this, generation](bool states) {
        return [this, generation, states](const SessionResult &r) {
            if (generation != m_generation)
                return;
            std::optional<std::vector<std::uint32_t>> values;
            if (r.ok())
                values = r.response().values;
            else
                m_message->setMessage(tr("Could not read: %1").arg(translated(r.errorMessage())),
                                      true);
            if (states)
                m_model->setStates(values);
            else
                m_model->setDisabled(values);
            if (--m_pendingReads == 0) {
                ++m_reads;
                updateEnabled(); // follows a change of operator mode
            }
        };
    };
    m_pendingReads = 2;
    m_requests->submit(Request::readDiscretes(m_target.station(), range.start, range.count),
                       handle(true));
    m_requests->submit(Request::readEnableFlags(m_target.station(), range.start, range.count),
                       handle(false));
}

void ForcingPanel::applyToSelection(DiscreteOp op)
{
    if (!m_target.isDirect() || m_acting)
        return;
    QList<int> rows;
    for (const QModelIndex &index : m_view->selectionModel()->selectedRows())
        rows << index.row();
    std::sort(rows.begin(), rows.end());
    if (rows.isEmpty()) {
        m_message->setMessage(tr("Select the points first (Ctrl/Shift-click for several)."), false);
        return;
    }
    QList<Address> points;
    for (int row : rows)
        points << m_model->addressAt(row);
    const QString action = DiscreteControlBatch::describe(op, points);
    const QString question = tr("%1 on %2?").arg(action, ToolConfirmation::target(m_target));
    if (!ToolConfirmation::ask(this, tr("Forcing"), question, m_confirmer)) {
        m_message->setMessage(tr("Cancelled: nothing sent."), false);
        return;
    }
    m_acting = true;
    updateEnabled();
    m_message->setMessage(tr("%1 \u2026").arg(action), false);
    DiscreteControlBatch::run(
        m_requests, m_target, op, points, [this, op](const DiscreteControlBatch::Outcome &outcome) {
            m_acting = false;
            m_message->setMessage(DiscreteControlBatch::outcomeText(op, outcome),
                                  !outcome.errors.isEmpty());
            updateEnabled();
            refresh();
        });
}

void ForcingPanel::updateEnabled()
{
    const bool connected = m_target.isDirect();
    const bool selected = m_view->selectionModel() && m_view->selectionModel()->hasSelection();
    // Operator mode: the session would refuse every 42; say so on the buttons.
    const bool writable = connected && !m_target.isReadOnly();
    const QString tip = connected && !writable
                            ? tr("Read-only (operator) mode: forcing is disabled.")
                            : QString();
    for (QPushButton *b : std::as_const(m_actionButtons)) {
        b->setEnabled(writable && selected && !m_acting);
        b->setToolTip(tip);
    }
    m_readButton->setEnabled(connected);
}

void ForcingPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::PaletteChange) {
        m_model->setPalette(palette());
        m_view->viewport()->update();
    }
    QWidget::changeEvent(event);
}

} // namespace Fatek
