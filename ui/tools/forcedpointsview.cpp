#include "forcedpointsview.h"

#include "ui/common/messageline.h"

#include "core/protocol/element.h"
#include "core/protocol/plcstatus.h"
#include "core/session/requesttracker.h"
#include "discretecontrolbatch.h"
#include "discretescan.h"
#include "ui/common/symbolnames.h"
#include "ui/common/toolpalette.h"
#include "ui/common/uitext.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <memory>

namespace Fatek {

ForcedPointsView::ForcedPointsView(QWidget *parent)
    : QWidget(parent)
    , m_requests(new RequestTracker(this))
{
    auto *layout = new QVBoxLayout(this);
    auto *row = new QHBoxLayout;
    row->addWidget(new QLabel(tr("Ranges:"), this));
    m_ranges = new QLineEdit(this);
    m_ranges->setObjectName(QStringLiteral("forcedRanges"));
    m_ranges->setClearButtonEnabled(true);
    m_ranges->setPlaceholderText(tr("All points of the PLC"));
    m_ranges->setToolTip(tr("Empty: every X Y M S T C point the PLC reports in its status. Or "
                            "type ranges to scan, e.g. X0-255, Y0-255, M0-999"));
    row->addWidget(m_ranges, 1);
    m_scanButton = new QPushButton(tr("Scan"), this);
    m_scanButton->setObjectName(QStringLiteral("scanButton"));
    row->addWidget(m_scanButton);
    layout->addLayout(row);

    m_list = new QListWidget(this);
    m_list->setObjectName(QStringLiteral("forcedList"));
    layout->addWidget(m_list, 1);

    auto *bottom = new QHBoxLayout;
    m_enableAllButton = new QPushButton(tr("Enable all"), this);
    m_enableAllButton->setObjectName(QStringLiteral("enableAllButton"));
    m_enableAllButton->setToolTip(tr("Give every listed point back to the ladder"));
    bottom->addStretch(1);
    bottom->addWidget(m_enableAllButton);
    layout->addLayout(bottom);
    // The whole width and three lines reserved, under the button (beside it, in a narrow dock,
    // the scan's outcome was cut to "enable it befo…"): the list and "Enable all" stay where
    // they are whatever it says.
    m_message = new MessageLine(3, this);
    m_message->setObjectName(QStringLiteral("forcedMessage"));
    layout->addWidget(m_message);

    connect(m_scanButton, &QPushButton::clicked, this, &ForcedPointsView::scan);
    connect(m_ranges, &QLineEdit::returnPressed, this, &ForcedPointsView::scan);
    connect(m_enableAllButton, &QPushButton::clicked, this, &ForcedPointsView::enableAll);
    setTarget(PlcTarget());
}

void ForcedPointsView::setTarget(const PlcTarget &target)
{
    m_target = target;
    target.aim(m_requests);
    m_requests->forgetPending(); // answers meant for the previous target are ignored
    ++m_generation;
    m_scanning = m_enabling = false;
    m_scans = 0;
    m_prefix.clear();
    m_prefixIsError = false;
    m_scanned.clear();
    m_plcRanges.reset();
    m_plcNote.clear();
    m_forced.clear();
    showList();
    m_message->setMessage(target.isDirect() ? tr("Press Scan to list the forced points.")
                                            : tr("No connection."),
                          false);
    updateEnabled();
}

void ForcedPointsView::setRanges(const QString &ranges)
{
    m_ranges->setText(ranges);
}

QString ForcedPointsView::messageText() const
{
    return m_message->text();
}

void ForcedPointsView::updateEnabled()
{
    const bool connected = m_target.isDirect();
    m_scanButton->setEnabled(connected && !m_scanning && !m_enabling);
    const bool writable = connected && !m_target.isReadOnly();
    m_enableAllButton->setEnabled(writable && !m_scanning && !m_enabling && !m_forced.isEmpty());
    m_enableAllButton->setToolTip(connected && !writable
                                      ? tr("Read-only (operator) mode: forcing is disabled.")
                                      : tr("Give every listed point back to the ladder"));
}

void ForcedPointsView::scan()
{
    if (!m_target.isDirect() || m_scanning || m_enabling)
        return;
    if (!m_ranges->text().trimmed().isEmpty()) {
        const Result<QList<AddressRange>> ranges = DiscreteScan::parse(m_ranges->text());
        if (!ranges) {
            m_message->setMessage(translated(ranges.error().message), true);
            return;
        }
        scanRanges(*ranges, {});
        return;
    }
    if (m_plcRanges) {
        scanRanges(*m_plcRanges, m_plcNote);
        return;
    }
    // Every point the PLC has: its detail status (53) says how many of each kind.
    const quint64 generation = ++m_generation;
    m_scanning = true;
    m_message->setMessage(tr("Reading the PLC's sizes \u2026"), false);
    updateEnabled();
    m_requests->submit(
        Request::detailStatus(m_target.station()), [this, generation](const SessionResult &result) {
            if (generation != m_generation)
                return;
            m_scanning = false;
            if (!result.ok()) {
                // Not remembered: the next scan asks again.
                scanRanges(DiscreteScan::defaults(),
                           tr("The PLC did not report its sizes (%1): default ranges scanned.")
                               .arg(translated(result.errorMessage())));
                return;
            }
            QList<ElementType> unreported;
            m_plcRanges
                = DiscreteScan::wholePlc(DetailStatus::decode(result.response().data), &unreported);
            QStringList kinds;
            for (ElementType t : std::as_const(unreported))
                kinds << QString::fromUtf8(elementInfo(t).symbol.data(),
                                           static_cast<qsizetype>(elementInfo(t).symbol.size()));
            m_plcNote = kinds.isEmpty() ? QString()
                                        : tr("The PLC did not report how many %1 it has: default "
                                             "ranges scanned for them.")
                                              .arg(kinds.join(QStringLiteral(", ")));
            scanRanges(*m_plcRanges, m_plcNote);
        });
}

void ForcedPointsView::scanRanges(const QList<AddressRange> &ranges, const QString &note)
{
    // One 43 per 256 points.
    QList<AddressRange> chunks;
    for (const AddressRange &r : ranges) {
        for (quint32 done = 0; done < r.count; done += Limits::maxDiscretes)
            chunks << AddressRange{r.start.advanced(done),
                                   std::min<quint32>(Limits::maxDiscretes, r.count - done)};
    }
    struct ScanState
    {
        qsizetype remaining;
        QList<Address> forced;
        QStringList errors;
    };
    auto state = std::make_shared<ScanState>(ScanState{chunks.size(), {}, {}});
    const quint64 generation = ++m_generation;
    const QString scanned = DiscreteScan::listText(ranges);
    m_scanning = true;
    m_message->setMessage(tr("Scanning %1 \u2026").arg(scanned), false);
    updateEnabled();
    for (const AddressRange &chunk : chunks) {
        m_requests->submit(
            Request::readEnableFlags(m_target.station(), chunk.start, chunk.count),
            [this, state, chunk, generation, scanned, note](const SessionResult &result) {
                if (generation != m_generation)
                    return;
                if (!result.ok()) {
                    state->errors << tr("%1: %2").arg(QString::fromStdString(chunk.toString()),
                                                      translated(result.errorMessage()));
                } else {
                    const auto &flags = result.response().values;
                    for (std::size_t i = 0; i < flags.size(); ++i) {
                        if (flags[i] != 0)
                            state->forced << chunk.start.advanced(static_cast<quint32>(i));
                    }
                }
                if (--state->remaining > 0)
                    return;
                m_scanning = false;
                ++m_scans;
                m_scanned = scanned;
                m_forced = state->forced;
                std::sort(m_forced.begin(), m_forced.end());
                showList();
                QString text
                    = !state->errors.isEmpty() ? tr("Scan incomplete \u2014 %1")
                                                     .arg(state->errors.join(QStringLiteral("; ")))
                      : m_forced.isEmpty() ? tr("Scanned %1: no forced points.").arg(scanned)
                      : m_forced.size() == 1
                          ? tr("Scanned %1: 1 forced point; enable it before leaving the site.")
                                .arg(scanned)
                          : tr("Scanned %1: %2 forced points; enable them before leaving the "
                               "site.")
                                .arg(scanned)
                                .arg(m_forced.size());
                if (!note.isEmpty())
                    text += QLatin1Char(' ') + note;
                // Keep the outcome of an Enable all visible in front of the new list.
                m_message->setMessage((m_prefix + QLatin1Char(' ') + text).trimmed(),
                                      m_prefixIsError || !state->errors.isEmpty());
                m_prefix.clear();
                m_prefixIsError = false;
                updateEnabled();
            });
    }
}

void ForcedPointsView::enableAll()
{
    if (!m_target.isDirect() || m_forced.isEmpty() || m_enabling)
        return;
    const QString question = tr("%1 on %2?")
                                 .arg(DiscreteControlBatch::describe(DiscreteOp::Enable, m_forced),
                                      ToolConfirmation::target(m_target));
    if (!ToolConfirmation::ask(this, tr("Enable all forced points"), question, m_confirmer)) {
        m_message->setMessage(tr("Enable all cancelled; the points stay forced."), false);
        return;
    }
    m_enabling = true;
    updateEnabled();
    DiscreteControlBatch::run(m_requests, m_target, DiscreteOp::Enable, m_forced,
                              [this](const DiscreteControlBatch::Outcome &outcome) {
                                  m_enabling = false;
                                  m_prefix = DiscreteControlBatch::outcomeText(DiscreteOp::Enable,
                                                                               outcome);
                                  m_prefixIsError = !outcome.errors.isEmpty();
                                  Q_EMIT pointsChanged();
                                  scan(); // show what is really left
                              });
}

void ForcedPointsView::setSymbols(const SymbolNames *symbols)
{
    if (m_symbols)
        disconnect(m_symbols, nullptr, this, nullptr);
    m_symbols = symbols;
    if (symbols)
        connect(symbols, &SymbolNames::changed, this, &ForcedPointsView::showList);
    showList();
}

QStringList ForcedPointsView::listedTexts() const
{
    QStringList texts;
    for (int i = 0; i < m_list->count(); ++i)
        texts << m_list->item(i)->text();
    return texts;
}

void ForcedPointsView::showList()
{
    m_list->clear();
    for (const Address &a : std::as_const(m_forced)) {
        auto *item = new QListWidgetItem(
            m_symbols ? m_symbols->label(a) : QString::fromStdString(a.toString()), m_list);
        if (m_symbols)
            item->setToolTip(m_symbols->table().comment(a));
    }
}

} // namespace Fatek
