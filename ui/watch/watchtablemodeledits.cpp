// WatchTableModel, the edits a person makes to the rows: each is a step on the model's undo stack
// (QUndoStack), made of the model's own changes (applyInsert, applyRemove, applySpec, applyOrder).
// Rows are named by their position: every change of positions goes through the stack, and a
// loaded list (setItems) starts a new history.
#include "watchtablemodel.h"

#include <QCoreApplication>

#include <algorithm>
#include <utility>

namespace Fatek {

// One step: rows inserted, removed, edited or reordered.
class WatchRowsCommand : public QUndoCommand
{
public:
    enum class Kind { Insert, Remove, Edit, Order };
    struct Edit
    {
        int row = 0;
        WatchItemSpec before;
        WatchItemSpec after;
    };

    WatchRowsCommand(WatchTableModel *model, Kind kind, const QString &text)
        : QUndoCommand(text)
        , m_model(model)
        , m_kind(kind)
    {}

    // Insert: `items` at `row`. Remove: the rows `rows` (ascending) that held `items`.
    int row = 0;
    QList<int> rows;
    QList<WatchItemSpec> items;
    QList<Edit> edits;
    QList<int> order; // row i becomes the row that was order[i]

    void redo() override
    {
        switch (m_kind) {
        case Kind::Insert: m_model->applyInsert(row, items); break;
        case Kind::Remove:
            // From the bottom up: the positions above stay valid.
            for (qsizetype i = rows.size() - 1; i >= 0; --i)
                m_model->applyRemove(rows.at(i), 1);
            break;
        case Kind::Edit:
            for (const Edit &e : std::as_const(edits))
                m_model->applySpec(e.row, e.after);
            break;
        case Kind::Order: m_model->applyOrder(order); break;
        }
    }
    void undo() override
    {
        switch (m_kind) {
        case Kind::Insert: m_model->applyRemove(row, static_cast<int>(items.size())); break;
        case Kind::Remove:
            for (qsizetype i = 0; i < rows.size(); ++i)
                m_model->applyInsert(rows.at(i), {items.at(i)});
            break;
        case Kind::Edit:
            for (const Edit &e : std::as_const(edits))
                m_model->applySpec(e.row, e.before);
            break;
        case Kind::Order: {
            QList<int> inverse(order.size());
            for (int i = 0; i < order.size(); ++i)
                inverse[order.at(i)] = i;
            m_model->applyOrder(inverse);
            break;
        }
        }
    }

private:
    WatchTableModel *m_model;
    Kind m_kind;
};

namespace {

QList<int> validRows(QList<int> rows, int count)
{
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    rows.removeIf([count](int r) { return r < 0 || r >= count; });
    return rows;
}

} // namespace

void WatchTableModel::addItems(const QList<WatchItemSpec> &items)
{
    insertItems(static_cast<int>(m_rows.size()), items);
}

void WatchTableModel::insertItems(int row, const QList<WatchItemSpec> &items)
{
    if (items.isEmpty())
        return;
    auto *step
        = new WatchRowsCommand(this, WatchRowsCommand::Kind::Insert,
                               tr("Add %n item(s)", nullptr, static_cast<int>(items.size())));
    step->row = std::clamp(row, 0, static_cast<int>(m_rows.size()));
    step->items = items;
    m_undo.push(step);
}

void WatchTableModel::removeItems(QList<int> rows)
{
    rows = validRows(std::move(rows), static_cast<int>(m_rows.size()));
    if (rows.isEmpty())
        return;
    auto *step
        = new WatchRowsCommand(this, WatchRowsCommand::Kind::Remove,
                               tr("Remove %n item(s)", nullptr, static_cast<int>(rows.size())));
    step->rows = rows;
    for (int r : std::as_const(rows))
        step->items.append(m_rows.at(r).spec());
    m_undo.push(step);
}

bool WatchTableModel::moveItems(const QList<int> &rows, int delta)
{
    const int count = static_cast<int>(m_rows.size());
    const QList<int> moving = validRows(rows, count);
    if (moving.isEmpty() || (delta != -1 && delta != 1))
        return false;
    std::vector<bool> selected(static_cast<std::size_t>(count), false);
    for (int r : moving)
        selected[static_cast<std::size_t>(r)] = true;
    QList<int> order(count);
    for (int i = 0; i < count; ++i)
        order[i] = i;
    // Each run of moving rows swaps with the one row beside it; a run at the edge stays.
    const auto isMoving = [&](int i) {
        return selected[static_cast<std::size_t>(order.at(i))];
    };
    if (delta < 0) {
        for (int i = 1; i < count; ++i) {
            if (isMoving(i) && !isMoving(i - 1))
                std::swap(order[i - 1], order[i]);
        }
    } else {
        for (int i = count - 2; i >= 0; --i) {
            if (isMoving(i) && !isMoving(i + 1))
                std::swap(order[i], order[i + 1]);
        }
    }
    bool changed = false;
    for (int i = 0; i < count && !changed; ++i)
        changed = order.at(i) != i;
    if (!changed)
        return false;
    auto *step = new WatchRowsCommand(this, WatchRowsCommand::Kind::Order,
                                      delta < 0 ? tr("Move Up") : tr("Move Down"));
    step->order = order;
    m_undo.push(step);
    return true;
}

bool WatchTableModel::moveItemsTo(const QList<int> &rows, int destination)
{
    const int count = static_cast<int>(m_rows.size());
    const QList<int> moving = validRows(rows, count);
    if (moving.isEmpty())
        return false;
    destination = std::clamp(destination, 0, count);
    QList<int> order;
    order.reserve(count);
    for (int i = 0; i < destination; ++i) {
        if (!moving.contains(i))
            order.append(i);
    }
    order += moving;
    for (int i = destination; i < count; ++i) {
        if (!moving.contains(i))
            order.append(i);
    }
    bool changed = false;
    for (int i = 0; i < count && !changed; ++i)
        changed = order.at(i) != i;
    if (!changed)
        return false;
    auto *step
        = new WatchRowsCommand(this, WatchRowsCommand::Kind::Order,
                               tr("Move %n item(s)", nullptr, static_cast<int>(moving.size())));
    step->order = order;
    m_undo.push(step);
    return true;
}

Status WatchTableModel::editItem(int row, const WatchItemSpec &spec)
{
    if (row < 0 || row >= m_rows.size())
        return makeError(ErrorKind::InvalidRequest, "no such row");
    if (Status s = WatchList::validateEntry(spec); !s)
        return s;
    const WatchItemSpec before = m_rows.at(row).spec();
    if (before == spec)
        return Ok{};
    auto *step = new WatchRowsCommand(
        this, WatchRowsCommand::Kind::Edit,
        tr("Edit %1").arg(QString::fromStdString(before.address.toString())));
    step->edits.append({row, before, spec});
    m_undo.push(step);
    return Ok{};
}

Status WatchTableModel::setFormat(int row, DisplayFormat format, bool swapWords)
{
    WatchItemSpec spec = m_rows.at(row).spec();
    spec.format = format;
    spec.swapWords = swapWords;
    return editItem(row, spec);
}

Status WatchTableModel::setFormats(const QList<int> &rows, DisplayFormat format)
{
    Status result = Ok{};
    auto *step = new WatchRowsCommand(this, WatchRowsCommand::Kind::Edit, tr("Set Format"));
    for (int r : validRows(rows, static_cast<int>(m_rows.size()))) {
        WatchItemSpec spec = m_rows.at(r).spec();
        const WatchItemSpec before = spec;
        spec.format = format;
        if (Status s = WatchList::validateEntry(spec); !s) {
            if (result)
                result = s;
            continue;
        }
        if (spec != before)
            step->edits.append({r, before, spec});
    }
    if (step->edits.isEmpty())
        delete step;
    else
        m_undo.push(step);
    return result;
}

void WatchTableModel::applyInsert(int row, const QList<WatchItemSpec> &items)
{
    beginInsertRows({}, row, row + static_cast<int>(items.size()) - 1);
    QList<Row> made;
    made.reserve(items.size());
    for (const WatchItemSpec &spec : items) {
        Row r;
        r.values = ItemValues(withSymbols(spec));
        r.key = newRowKey();
        resetValue(r);
        made.append(std::move(r));
    }
    m_rows.insert(row, made.size(), Row());
    std::move(made.begin(), made.end(), m_rows.begin() + row);
    rebuildIndex();
    endInsertRows();
    Q_EMIT pollListChanged();
    Q_EMIT itemsEdited();
}

void WatchTableModel::applyRemove(int row, int count)
{
    beginRemoveRows({}, row, row + count - 1);
    m_rows.remove(row, count);
    rebuildIndex();
    endRemoveRows();
    Q_EMIT pollListChanged();
    Q_EMIT itemsEdited();
}

void WatchTableModel::applySpec(int row, const WatchItemSpec &spec)
{
    Row &r = m_rows[row];
    const bool stationChanged = r.spec().station != spec.station;
    const bool spanChanged = r.values.setItem(spec);
    if (spanChanged) {
        resetValue(r);
        rebuildIndex();
    }
    Q_EMIT dataChanged(index(row, 0), index(row, ColumnCount - 1));
    if (spanChanged || stationChanged)
        Q_EMIT pollListChanged();
    Q_EMIT itemsEdited();
}

void WatchTableModel::applyOrder(const QList<int> &order)
{
    Q_EMIT layoutAboutToBeChanged({}, QAbstractItemModel::VerticalSortHint);
    QList<Row> rows;
    rows.reserve(m_rows.size());
    QList<int> newRowOf(order.size());
    for (int i = 0; i < order.size(); ++i) {
        rows.append(std::move(m_rows[order.at(i)]));
        newRowOf[order.at(i)] = i;
    }
    m_rows = std::move(rows);
    rebuildIndex();
    const QModelIndexList before = persistentIndexList();
    QModelIndexList after;
    after.reserve(before.size());
    for (const QModelIndex &i : before)
        after.append(index(newRowOf.at(i.row()), i.column()));
    changePersistentIndexList(before, after);
    Q_EMIT layoutChanged({}, QAbstractItemModel::VerticalSortHint);
    Q_EMIT itemsEdited();
}

} // namespace Fatek
