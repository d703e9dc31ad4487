#include "checkouttablemodel.h"

#include "core/commission/checkoutrunner.h"
#include "ui/common/toolpalette.h"
#include "ui/common/uitext.h"

#include <QApplication>
#include <QFont>
#include <QPalette>

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
        case StateColumn:
            if (isForced(index.row()))
                return tr("forced: seen?");
            return translated(checkoutResultMessage(p.result));
        case MeasuredColumn: {
            const Message measured = p.measured();
            QString text = measured.empty() ? QString() : translated(measured);
            const auto live = m_live.find(index.row());
            if (p.result == CheckoutResult::Untested && live != m_live.end())
                text = text.isEmpty() ? tr("now %1").arg(live->second)
                                      : tr("%1; now %2").arg(text).arg(live->second);
            return text;
        }
        case CommentColumn: return p.comment;
        }
        return {};
    case Qt::EditRole: return index.column() == CommentColumn ? QVariant(p.comment) : QVariant();
    case Qt::ToolTipRole:
        if (index.column() == NameColumn || index.column() == PointColumn)
            return p.description.isEmpty() ? QVariant() : QVariant(p.description);
        return {};
    case Qt::FontRole:
        if (index.row() == m_current || index.column() == StateColumn) {
            QFont font = QApplication::font();
            font.setBold(true);
            return font;
        }
        return {};
    case Qt::BackgroundRole: {
        const QPalette palette = QApplication::palette();
        if (p.result == CheckoutResult::Passed)
            return ToolPalette::passBackground(palette);
        if (p.result == CheckoutResult::Failed)
            return ToolPalette::errorBackground(palette);
        if (isForced(index.row()))
            return ToolPalette::blend(palette.color(QPalette::Base),
                                      ToolPalette::activeIndicator(palette), 0.25);
        return {};
    }
    case Qt::ForegroundRole:
        if (index.column() != StateColumn)
            return {};
        if (p.result == CheckoutResult::Passed)
            return ToolPalette::passText(QApplication::palette());
        if (p.result == CheckoutResult::Failed)
            return ToolPalette::errorText(QApplication::palette());
        return {};
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
