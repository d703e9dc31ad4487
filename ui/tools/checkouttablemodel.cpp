#include "checkouttablemodel.h"

#include "core/commission/checkoutreport.h"
#include "core/commission/checkoutrunner.h"
#include "core/commission/commissionmessages.h"
#include "core/commission/memorysnapshot.h"
#include "ui/common/toolpalette.h"
#include "ui/common/uitext.h"

#include <QApplication>
#include <QFont>
#include <QPalette>

#include <algorithm>

namespace Fatek {

CheckoutTableModel::CheckoutTableModel(CheckoutRunner *runner, QObject *parent)
    : QAbstractTableModel(parent)
    , m_runner(runner)
{
    connect(runner, &CheckoutRunner::pointChanged, this, &CheckoutTableModel::refreshRow);
    connect(runner, &CheckoutRunner::liveValue, this, [this](int index, quint32 value) {
        const auto it = m_live.find(index);
        if (it != m_live.end() && it->second == value)
            return;
        m_live[index] = value;
        const QModelIndex cell = this->index(index, MeasuredColumn);
        if (cell.isValid())
            Q_EMIT dataChanged(cell, cell, {Qt::DisplayRole});
    });
    // Shown as forced once the PLC has it forced (not while the request is on its way).
    connect(runner, &CheckoutRunner::outputForced, this, [this](int index) {
        m_forced = index;
        refreshRow(index);
    });
    connect(runner, &CheckoutRunner::outputReleased, this, [this](const Address &address) {
        if (m_runner && m_runner->plan().indexOf(address) == m_forced) {
            const int old = m_forced;
            m_forced = -1;
            refreshRow(old);
        }
    });
    connect(runner, &CheckoutRunner::currentPointChanged, this, [this](int index) {
        const int old = m_current;
        m_current = index;
        refreshRow(old);
        refreshRow(index);
    });
}

void CheckoutTableModel::planReset()
{
    beginResetModel();
    m_live.clear();
    m_forced = -1;
    m_current = m_runner ? m_runner->currentPoint() : -1;
    endResetModel();
}

void CheckoutTableModel::refreshRow(int row)
{
    if (row < 0 || row >= rowCount())
        return;
    Q_EMIT dataChanged(index(row, 0), index(row, ColumnCount - 1));
}

int CheckoutTableModel::rowCount(const QModelIndex &parent) const
{
    if (parent.isValid() || !m_runner)
        return 0;
    return static_cast<int>(m_runner->plan().points.size());
}

int CheckoutTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

int CheckoutTableModel::nextCheck(const CheckoutPoint &point)
{
    const std::vector<double> &checks = point.analog.checks;
    for (std::size_t i = 0; i < checks.size(); ++i) {
        const auto read = std::find_if(
            point.readings.begin(), point.readings.end(),
            [&](const AnalogReading &r) { return r.percent == checks[i] && r.asFound; });
        if (read == point.readings.end())
            return static_cast<int>(i);
    }
    return -1;
}

QString CheckoutTableModel::checkText(const CheckoutPoint &point, int check)
{
    const AnalogScale &scale = point.analog;
    if (check < 0 || check >= static_cast<int>(scale.checks.size()))
        return {};
    const double percent = scale.checks[static_cast<std::size_t>(check)];
    const QString value = QString::fromStdString(scale.text(scale.expected(percent)));
    //: An analog check: %1 per cent of the span, %2 the value expected there ("8.00 mA").
    return tr("%1 %: %2 expected").arg(QString::number(percent, 'g', 4), value);
}

QString CheckoutTableModel::history(const CheckoutPoint &point)
{
    QStringList lines;
    int n = 0;
    for (const CheckoutAttempt &a : point.earlier) {
        ++n;
        QString line = tr("Attempt %1: %2, %3 by %4")
                           .arg(n)
                           .arg(translated(checkoutResultMessage(a.result)),
                                CheckoutReport::timeText(a.time),
                                a.engineer.isEmpty() ? tr("(no name)") : a.engineer);
        const Message measured = point.measured(a);
        if (!measured.empty())
            line += QStringLiteral("; ") + translated(measured);
        if (!a.comment.isEmpty())
            line += QStringLiteral("; ") + a.comment;
        lines << line;
    }
    return lines.join(QLatin1Char('\n'));
}

QString CheckoutTableModel::stateText(int row) const
{
    const CheckoutPoint &p = m_runner->plan().points[static_cast<std::size_t>(row)];
    const QString state
        = isForced(row) ? tr("forced: seen?") : translated(checkoutResultMessage(p.result));
    if (p.earlier.empty())
        return state;
    //: The state of a point tested again: %1 its result, %2 the attempt (2 for the second).
    return tr("%1 (attempt %2)").arg(state).arg(p.earlier.size() + 1);
}

QString CheckoutTableModel::measuredText(int row) const
{
    const CheckoutPoint &p = m_runner->plan().points[static_cast<std::size_t>(row)];
    const Message measured = p.measured();
    QString text = measured.empty() ? QString() : translated(measured);
    if (p.kind == CheckoutKind::Analog && p.result == CheckoutResult::Untested) {
        // What to read next, and what it should be: the person sets the signal and presses V.
        const QString next = !p.analog.isDefined() ? tr("no scale: import a plan CSV with it")
                                                   : checkText(p, nextCheck(p));
        if (!next.isEmpty())
            text = text.isEmpty() ? next : tr("%1; next %2").arg(text, next);
    }
    const auto live = m_live.find(row);
    if (p.result == CheckoutResult::Untested && live != m_live.end())
        text = text.isEmpty() ? tr("now %1").arg(live->second)
                              : tr("%1; now %2").arg(text).arg(live->second);
    return text;
}

QVariant CheckoutTableModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const auto &points = m_runner->plan().points;
    const auto row = static_cast<std::size_t>(index.row());
    const CheckoutPoint &p = points[row];
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case GroupColumn:
            // Named once, on the group's first row: the rows below belong to it.
            return row == 0 || points[row - 1].group != p.group ? p.group : QString();
        case PointColumn: return QString::fromStdString(p.address.toString());
        case NameColumn: return p.name;
        case KindColumn: return translated(checkoutKindMessage(p.kind));
        case StateColumn: return stateText(index.row());
        case MeasuredColumn: return measuredText(index.row());
        case CommentColumn: return p.comment;
        }
        return {};
    case Qt::EditRole: return index.column() == CommentColumn ? QVariant(p.comment) : QVariant();
    case Qt::ToolTipRole: {
        // The point's comment, what crossed it, and every earlier attempt.
        QStringList tip;
        if (!p.description.isEmpty())
            tip << p.description;
        if (!p.changedWith.empty()) {
            std::vector<Address> crossed = p.changedWith;
            std::sort(crossed.begin(), crossed.end());
            tip << translated(msg<MsgId::CheckoutChangedWith>(Snapshot::rangesText(crossed)));
        }
        if (const QString h = history(p); !h.isEmpty())
            tip << h;
        return tip.isEmpty() ? QVariant() : QVariant(tip.join(QLatin1Char('\n')));
    }
    case Qt::FontRole:
        if (index.row() == m_current || index.column() == StateColumn) {
            QFont font = QApplication::font();
            font.setBold(true);
            return font;
        }
        return {};
    case Qt::BackgroundRole: {
        const QPalette palette = QApplication::palette();
        if (isForced(index.row()))
            return ToolPalette::blend(palette.color(QPalette::Base),
                                      ToolPalette::activeIndicator(palette), 0.25);
        switch (p.result) {
        case CheckoutResult::Passed: return ToolPalette::passBackground(palette);
        case CheckoutResult::PassedWithRemark:
            return ToolPalette::blend(palette.color(QPalette::Base),
                                      ToolPalette::passBackground(palette), 0.6);
        case CheckoutResult::Failed: return ToolPalette::errorBackground(palette);
        case CheckoutResult::Deferred:
            // Amber, between failed and passed: still to do, not wrong.
            return ToolPalette::blend(palette.color(QPalette::Base),
                                      ToolPalette::blend(ToolPalette::errorText(palette),
                                                         ToolPalette::passText(palette), 0.5),
                                      0.25);
        case CheckoutResult::NotApplicable:
            return ToolPalette::blend(palette.color(QPalette::Base),
                                      ToolPalette::inactiveIndicator(palette), 0.3);
        case CheckoutResult::Untested: return {};
        }
        return {};
    }
    case Qt::ForegroundRole:
        if (index.column() != StateColumn)
            return {};
        switch (p.result) {
        case CheckoutResult::Passed:
        case CheckoutResult::PassedWithRemark:
            return ToolPalette::passText(QApplication::palette());
        case CheckoutResult::Failed: return ToolPalette::errorText(QApplication::palette());
        case CheckoutResult::NotApplicable:
            return QApplication::palette().color(QPalette::Disabled, QPalette::Text);
        default: return {};
        }
    default: return {};
    }
}

Qt::ItemFlags CheckoutTableModel::flags(const QModelIndex &index) const
{
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (index.isValid() && index.column() == CommentColumn)
        f |= Qt::ItemIsEditable;
    return f;
}

bool CheckoutTableModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (!index.isValid() || index.column() != CommentColumn || role != Qt::EditRole
        || index.row() >= rowCount())
        return false;
    m_runner->setComment(index.row(), value.toString()); // pointChanged refreshes the row
    return true;
}

bool CheckoutTableModel::isForced(int row) const
{
    return row == m_forced && m_runner->outputUnderTest() == row;
}

QVariant CheckoutTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case GroupColumn: return tr("Group");
    case PointColumn: return tr("Point");
    case NameColumn: return tr("Name");
    case KindColumn: return tr("Kind");
    case StateColumn: return tr("State");
    case MeasuredColumn: return tr("Times / values");
    case CommentColumn: return tr("Comment");
    }
    return {};
}

} // namespace Fatek
