// The steps of a watch table's edits, made of the model's own changes (applyInsert, applyRemove,
// applySpec, applyOrder).
#include "watchtableedits.h"

#include "watchtablemodel.h"

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

WatchTableEdits::WatchTableEdits(WatchTableModel *model)
    : m_model(model)
{}

void WatchTableEdits::insertItems(int row, const QList<WatchItemSpec> &items)
{
    if (items.isEmpty())
        return;
    auto *step
        = new WatchRowsCommand(m_model, WatchRowsCommand::Kind::Insert,
                               tr("Add %n item(s)", nullptr, static_cast<int>(items.size())));
    step->row = std::clamp(row, 0, m_model->rowCount());
    step->items = items;
    m_undo.push(step);
}

void WatchTableEdits::removeItems(QList<int> rows)
{
    rows = validRows(std::move(rows), m_model->rowCount());
    if (rows.isEmpty())
        return;
    auto *step
        = new WatchRowsCommand(m_model, WatchRowsCommand::Kind::Remove,
                               tr("Remove %n item(s)", nullptr, static_cast<int>(rows.size())));
    step->rows = rows;
    for (int r : std::as_const(rows))
        step->items.append(m_model->item(r));
    m_undo.push(step);
}

bool WatchTableEdits::moveItems(const QList<int> &rows, int delta)
{
    const int count = m_model->rowCount();
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
    auto *step = new WatchRowsCommand(m_model, WatchRowsCommand::Kind::Order,
                                      delta < 0 ? tr("Move Up") : tr("Move Down"));
    step->order = order;
    m_undo.push(step);
    return true;
}

bool WatchTableEdits::moveItemsTo(const QList<int> &rows, int destination)
{
    const int count = m_model->rowCount();
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
        = new WatchRowsCommand(m_model, WatchRowsCommand::Kind::Order,
                               tr("Move %n item(s)", nullptr, static_cast<int>(moving.size())));
    step->order = order;
    m_undo.push(step);
    return true;
}

Status WatchTableEdits::editItem(int row, const WatchItemSpec &spec)
{
    if (row < 0 || row >= m_model->rowCount())
        return makeError(ErrorKind::InvalidRequest, "no such row");
    if (Status s = WatchList::validateEntry(spec); !s)
        return s;
    const WatchItemSpec before = m_model->item(row);
    if (before == spec)
        return Ok{};
    auto *step = new WatchRowsCommand(
        m_model, WatchRowsCommand::Kind::Edit,
        tr("Edit %1").arg(QString::fromStdString(before.address.toString())));
    step->edits.append({row, before, spec});
    m_undo.push(step);
    return Ok{};
}

Status WatchTableEdits::setFormat(int row, DisplayFormat format, bool swapWords)
{
    WatchItemSpec spec = m_model->item(row);
    spec.format = format;
    spec.swapWords = swapWords;
    return editItem(row, spec);
}

Status WatchTableEdits::setFormats(const QList<int> &rows, DisplayFormat format)
{
    Status result = Ok{};
    auto *step = new WatchRowsCommand(m_model, WatchRowsCommand::Kind::Edit, tr("Set Format"));
    for (int r : validRows(rows, m_model->rowCount())) {
        WatchItemSpec spec = m_model->item(r);
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

Status WatchTableEdits::setAlarms(int row, const QList<AlarmDefinition> &alarms)
{
    if (row < 0 || row >= m_model->rowCount())
        return makeError(ErrorKind::InvalidRequest, "no such row");
    const WatchItemSpec before = m_model->item(row);
    WatchItemSpec spec = before;
    spec.alarms = alarms;
    if (Status s = Alarms::validate(spec); !s)
        return s;
    if (spec == before)
        return Ok{};
    auto *step = new WatchRowsCommand(
        m_model, WatchRowsCommand::Kind::Edit,
        tr("Alarms of %1").arg(QString::fromStdString(before.address.toString())));
    step->edits.append({row, before, spec});
    m_undo.push(step);
    return Ok{};
}

Status WatchTableEdits::setHistory(const QList<int> &rows,
                                   const std::optional<HistorySetting> &setting)
{
    Status result = Ok{};
    auto *step = new WatchRowsCommand(m_model, WatchRowsCommand::Kind::Edit,
                                      setting ? tr("Record in History") : tr("Stop Recording"));
    for (int r : validRows(rows, m_model->rowCount())) {
        const WatchItemSpec before = m_model->item(r);
        WatchItemSpec spec = before;
        spec.history = setting;
        // Bits and ASCII take no deadband: among other rows they are recorded at every change.
        if (spec.history && !HistorySettings::validate(spec))
            spec.history->deadband = 0;
        if (Status s = HistorySettings::validate(spec); !s) {
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

} // namespace Fatek
