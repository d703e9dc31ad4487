#include "watchtablemodel.h"

#include "ui/common/uitext.h"

#include <QFont>
#include <QGuiApplication>
#include <QIcon>
#include <QLocale>
#include <QPalette>

#include <algorithm>
#include <atomic>
#include <utility>

namespace Fatek {

namespace {

std::atomic<quint64> nextRowKey{1};

// "0.4 s", "12 s", "3 min", "2 h": precise while it matters, short always.
QString ageText(qint64 ms)
{
    if (ms < 10000)
        return WatchTableModel::tr("%1 s").arg(QLocale().toString(double(ms) / 1000.0, 'f', 1));
    if (ms < 60000)
        return WatchTableModel::tr("%1 s").arg(ms / 1000);
    if (ms < 3600000)
        return WatchTableModel::tr("%1 min").arg(ms / 60000);
    return WatchTableModel::tr("%1 h").arg(ms / 3600000);
}

QString qualityName(ValueQuality quality)
{
    switch (quality) {
    case ValueQuality::Good: return WatchTableModel::tr("good");
    case ValueQuality::Late: return WatchTableModel::tr("late");
    case ValueQuality::Stale: return WatchTableModel::tr("stale");
    case ValueQuality::Error: return WatchTableModel::tr("error");
    }
    return {};
}

} // namespace

WatchTableModel::WatchTableModel(QObject *parent)
    : QAbstractTableModel(parent)
    , m_valueState([this](int row) -> const WatchItemSpec & { return m_rows.at(row).spec(); })
    , m_edits(this)
    , m_goodIcon(QStringLiteral(":/icons/good.svg"))
    , m_staleIcon(QStringLiteral(":/icons/stale.svg"))
    , m_errorIcon(QStringLiteral(":/icons/error.svg"))
    , m_forcedIcon(QStringLiteral(":/icons/forced.svg"))
    , m_alarmIcon(QStringLiteral(":/icons/alarm.svg"))
    , m_historyIcon(QStringLiteral(":/icons/history.svg"))
{
    connect(&m_valueState, &WatchValueState::cellsChanged, this,
            &WatchTableModel::emitCellsChanged);
}

quint64 WatchTableModel::newRowKey()
{
    return nextRowKey++;
}

int WatchTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}

int WatchTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

void WatchTableModel::setItems(const QList<WatchItemSpec> &items)
{
    beginResetModel();
    m_valueState.clear();
    m_rows.clear();
    endResetModel();
    // Another list: the steps taken on the old one mean nothing here.
    undoStack()->clear();
    if (!items.isEmpty())
        applyInsert(0, items);
    else
        Q_EMIT pollListChanged();
}

QList<WatchItemSpec> WatchTableModel::items() const
{
    QList<WatchItemSpec> list;
    list.reserve(m_rows.size());
    for (const Row &row : m_rows)
        list.append(row.spec());
    return list;
}

QList<WatchedItem> WatchTableModel::watchItems(int intervalMs) const
{
    QList<WatchedItem> items;
    items.reserve(m_rows.size());
    for (int r = 0; r < m_rows.size(); ++r)
        items.append({m_valueState.at(r).itemKey, m_rows.at(r).spec(), intervalMs});
    return items;
}

QString WatchTableModel::rowsText(const QList<int> &rows) const
{
    // A field with the separator of pasted rows (tab, turned into ';' by the paste) or a quote
    // is quoted, as CSV quotes it.
    const auto field = [](QString text) {
        if (text.contains(QLatin1Char(';')) || text.contains(QLatin1Char('"'))
            || text.contains(QLatin1Char('\t')) || text.contains(QLatin1Char('\n'))) {
            text.replace(QLatin1Char('"'), QLatin1String("\"\""));
            text = QLatin1Char('"') + text + QLatin1Char('"');
        }
        return text;
    };
    // The header's words are the watch list file's column names (not translated): a paste reads
    // the columns by them, in any language.
    QStringList lines{QStringLiteral("address\tname\tvalue\tformat\tquality\tcomment")};
    for (int row : rows) {
        const WatchItemSpec &item = m_rows.at(row).spec();
        const QString quality = data(index(row, QualityColumn)).toString();
        lines << QStringList{QString::fromStdString(item.address.toString()),
                             field(item.name),
                             field(valueText(row)),
                             ValueFormat::name(item.format),
                             field(quality),
                             field(item.comment)}
                     .join(QLatin1Char('\t'));
    }
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

bool WatchTableModel::removeRows(int row, int count, const QModelIndex &parent)
{
    if (parent.isValid() || row < 0 || count <= 0 || row + count > m_rows.size())
        return false;
    QList<int> rows;
    for (int r = row; r < row + count; ++r)
        rows.append(r);
    removeItems(rows);
    return true;
}

int WatchTableModel::rowOfKey(quint64 key) const
{
    for (int r = 0; r < m_rows.size(); ++r) {
        if (m_rows.at(r).key == key)
            return r;
    }
    return -1;
}

QList<DisplayFormat> WatchTableModel::availableFormats(int row) const
{
    QList<DisplayFormat> list;
    const Address address = m_rows.at(row).spec().address;
    for (DisplayFormat f : ValueFormat::allFormats()) {
        const int width = ValueFormat::valueWidth(address, f);
        if (width > 0 && ValueFormat::isAvailable(f, width))
            list.append(f);
    }
    return list;
}

int WatchTableModel::valueWidth(int row) const
{
    return m_rows.at(row).values.width();
}

QString WatchTableModel::qualityReason(int row) const
{
    const WatchValueState::RowValue &r = m_valueState.at(row);
    return r.quality != ValueQuality::Good && !r.error.empty() ? translated(r.error) : QString();
}

QString WatchTableModel::valueText(int row) const
{
    const WatchValueState::RowValue &v = m_valueState.at(row);
    if (!v.received)
        return {};
    return m_rows.at(row).values.text(v.raw);
}

void WatchTableModel::emitRowsChanged(std::vector<int> rows, int firstColumn, int lastColumn,
                                      const QList<int> &roles)
{
    // One dataChanged per run of consecutive rows: a 100-row table polled every 100 ms must not
    // cost 100 signals per batch.
    if (!std::is_sorted(rows.cbegin(), rows.cend()))
        std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    std::size_t i = 0;
    while (i < rows.size()) {
        std::size_t j = i;
        while (j + 1 < rows.size() && rows[j + 1] == rows[j] + 1)
            ++j;
        Q_EMIT dataChanged(index(rows[i], firstColumn), index(rows[j], lastColumn), roles);
        i = j + 1;
    }
}

void WatchTableModel::emitCellsChanged(const std::vector<int> &rows, WatchValueState::Cell cell,
                                       const QList<int> &roles)
{
    int column = ValueColumn;
    switch (cell) {
    case WatchValueState::Cell::Name: column = NameColumn; break;
    case WatchValueState::Cell::Value: column = ValueColumn; break;
    case WatchValueState::Cell::Quality: column = QualityColumn; break;
    case WatchValueState::Cell::Updated: column = UpdatedColumn; break;
    }
    emitRowsChanged(rows, column, column, roles);
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
        made.append(std::move(r));
    }
    m_rows.insert(row, made.size(), Row());
    std::move(made.begin(), made.end(), m_rows.begin() + row);
    m_valueState.insertRows(row, static_cast<int>(made.size()));
    endInsertRows();
    Q_EMIT pollListChanged();
    Q_EMIT itemsEdited();
}

void WatchTableModel::applyRemove(int row, int count)
{
    beginRemoveRows({}, row, row + count - 1);
    m_rows.remove(row, count);
    m_valueState.removeRows(row, count);
    endRemoveRows();
    Q_EMIT pollListChanged();
    Q_EMIT itemsEdited();
}

void WatchTableModel::applySpec(int row, const WatchItemSpec &spec)
{
    Row &r = m_rows[row];
    const bool stationChanged = r.spec().station != spec.station;
    const bool spanChanged = r.values.setItem(spec);
    // Another station is another PLC: the value read from the old one is not this row's (it
    // showed as "good, 1.3 s" beside a station that never answered). Waiting, under a new key.
    if (spanChanged || stationChanged)
        m_valueState.resetRow(row);
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
    m_valueState.reorder(order);
    const QModelIndexList before = persistentIndexList();
    QModelIndexList after;
    after.reserve(before.size());
    for (const QModelIndex &i : before)
        after.append(index(newRowOf.at(i.row()), i.column()));
    changePersistentIndexList(before, after);
    Q_EMIT layoutChanged({}, QAbstractItemModel::VerticalSortHint);
    Q_EMIT itemsEdited();
}

QVariant WatchTableModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const int r = index.row();
    const Row &row = m_rows.at(r);
    const WatchValueState::RowValue &state = m_valueState.at(r);
    const WatchItemSpec &spec = row.spec();
    const bool have = state.received;
    const ValueQuality q = quality(r);
    const bool discrete = isDiscrete(spec.address.type);

    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        // A row without its own name shows the gateway's; typing one replaces it.
        case NameColumn: return spec.name.isEmpty() ? state.peerName : spec.name;
        case AddressColumn: return QString::fromStdString(spec.address.toString());
        case StationColumn: return spec.station;
        case ValueColumn: {
            if (!have)
                return QStringLiteral("…");
            // ON/OFF in the UI language, as the forcing table says them; what is edited and
            // copied stays in the PLC's words, which the parser reads.
            const QString text = valueText(r);
            if (spec.format == DisplayFormat::Bit && text == QLatin1String("ON"))
                return tr("ON");
            if (spec.format == DisplayFormat::Bit && text == QLatin1String("OFF"))
                return tr("OFF");
            return text;
        }
        case FormatColumn:
            return spec.swapWords ? tr("%1, words swapped").arg(UiText::format(spec.format))
                                  : UiText::format(spec.format);
        case QualityColumn: {
            // Short enough for the column; the station is beside it and in the tooltip.
            QString text = (q == ValueQuality::Stale && m_valueState.isSilent(spec.station))
                               ? tr("no answer")
                           : (!have && q != ValueQuality::Error) ? tr("waiting")
                                                                 : qualityName(q);
            // How old the value is: a good value a minute old is worth knowing about.
            if (const qint64 age = ageMs(r); age >= 0)
                return tr("%1, %2", "quality, age of the value").arg(text, ageText(age));
            return text;
        }
        case UpdatedColumn: {
            const QDateTime &latest = state.updated;
            return latest.isValid() ? latest.toLocalTime().toString(QStringLiteral("HH:mm:ss.zzz"))
                                    : QString();
        }
        case CommentColumn: return spec.comment;
        default: return {};
        }
    case Qt::EditRole:
        switch (index.column()) {
        case NameColumn: return spec.name;
        case StationColumn: return spec.station;
        case ValueColumn: return valueText(r);
        case FormatColumn: return static_cast<int>(spec.format);
        case CommentColumn: return spec.comment;
        default: return data(index, Qt::DisplayRole);
        }
    case SortRole:
        switch (index.column()) {
        case AddressColumn:
            return (qulonglong(spec.address.type) << 32) | qulonglong(spec.address.number);
        case StationColumn: return spec.station;
        case ValueColumn: {
            if (!have)
                return {};
            const std::optional<double> value
                = ValueFormat::number(state.raw, row.values.width(), spec.format, spec.swapWords);
            return value ? QVariant(*value) : QVariant(valueText(r));
        }
        case QualityColumn: return static_cast<int>(q);
        case UpdatedColumn: return state.updated.isValid() ? state.updated.toMSecsSinceEpoch() : 0;
        default: return data(index, Qt::DisplayRole);
        }
    case Qt::CheckStateRole:
        if (index.column() == ValueColumn && discrete && have)
            return (state.raw & 1u) ? Qt::Checked : Qt::Unchecked;
        return {};
    case Qt::ToolTipRole: {
        QStringList lines;
        const QString reason = qualityReason(r);
        if (index.column() == ValueColumn || index.column() == QualityColumn) {
            if (q == ValueQuality::Stale && m_valueState.isSilent(spec.station))
                lines << tr("No answer from station %1: check the station number, the PLC's "
                            "power and the cable.")
                             .arg(spec.station);
            if (q != ValueQuality::Good && !reason.isEmpty())
                lines << tr("%1: %2").arg(qualityName(q), reason);
            else if (!have)
                lines << tr("No value yet");
            if (!state.writeOutcome.isEmpty())
                lines << state.writeOutcome;
            if (index.column() == ValueColumn && state.forced.value_or(false))
                lines << tr("Forced: disabled from the ladder, it keeps the value written to it "
                            "(Tools \u25b8 Forcing lists and enables forced points).");
            if (index.column() == ValueColumn)
                lines << (discrete ? tr("Click the box to toggle")
                                   : tr("Double-click or F2 to write"));
        } else if (index.column() == NameColumn) {
            // The whole name: a narrow column elides it.
            if (!spec.name.isEmpty())
                lines << spec.name;
            if (spec.name.isEmpty() && !state.peerName.isEmpty())
                lines << tr("The gateway's name for this item; type a name to use your own.");
            if (spec.history)
                lines << tr("Recorded in the history (deadband %1, heartbeat %2 s)")
                             .arg(spec.history->deadband)
                             .arg(spec.history->heartbeatS);
        } else if (index.column() == AddressColumn) {
            const int count = row.values.elementCount();
            lines << (count > 1 ? tr("%1 .. %2 (%3 elements)")
                                      .arg(QString::fromStdString(spec.address.toString()),
                                           QString::fromStdString(
                                               spec.address
                                                   .advanced(static_cast<std::uint32_t>(count - 1))
                                                   .toString()))
                                      .arg(count)
                                : UiText::elementName(spec.address.type));
            if (!spec.alarms.isEmpty())
                lines << tr("%n alarm(s) defined (Alarms… in the context menu, Ctrl+Shift+A)",
                            nullptr, static_cast<int>(spec.alarms.size()));
        }
        if (index.column() == CommentColumn && !spec.comment.isEmpty())
            lines << spec.comment; // whole, where the column elides it
        return lines.isEmpty() ? QVariant() : QVariant(lines.join(QLatin1Char('\n')));
    }
    case Qt::DecorationRole:
        if (index.column() == ValueColumn && state.forced.value_or(false))
            return m_forcedIcon;
        if (index.column() == AddressColumn && !spec.alarms.isEmpty())
            return m_alarmIcon;
        if (index.column() == NameColumn && spec.history)
            return m_historyIcon;
        if (index.column() == QualityColumn) {
            if (q == ValueQuality::Error
                || (q == ValueQuality::Stale && m_valueState.isSilent(spec.station)))
                return m_errorIcon;
            if ((q == ValueQuality::Stale || q == ValueQuality::Late) && have)
                return m_staleIcon;
            if (q == ValueQuality::Good && have)
                return m_goodIcon;
        }
        return {};
    case Qt::FontRole:
        if ((index.column() == ValueColumn || index.column() == QualityColumn)
            && q != ValueQuality::Good) {
            QFont font;
            font.setItalic(true);
            return font;
        }
        return {};
    case Qt::ForegroundRole:
        // Stale and failed values are greyed with the palette's own colour (light and dark themes).
        if (index.column() == ValueColumn && q != ValueQuality::Good)
            return QGuiApplication::palette().brush(QPalette::PlaceholderText);
        return {};
    case Qt::BackgroundRole:
        if (index.column() == ValueColumn && m_valueState.isFlashing(r)) {
            QColor flash = QGuiApplication::palette().color(QPalette::Highlight);
            flash.setAlpha(90);
            return flash;
        }
        return {};
    case Qt::TextAlignmentRole:
        if (index.column() == ValueColumn || index.column() == StationColumn)
            return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
        return {};
    default: return {};
    }
}

QVariant WatchTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case NameColumn: return tr("Name");
    case AddressColumn: return tr("Address");
    case StationColumn: return tr("Station");
    case ValueColumn: return tr("Value");
    case FormatColumn: return tr("Format");
    case QualityColumn: return tr("Quality");
    case UpdatedColumn: return tr("Last update");
    case CommentColumn: return tr("Comment");
    default: return {};
    }
}

Qt::ItemFlags WatchTableModel::flags(const QModelIndex &index) const
{
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (!index.isValid())
        return f;

    const bool discrete = isDiscrete(m_rows.at(index.row()).spec().address.type);
    // Every cell drags its row (WatchTableView; the table moves the rows with moveItemsTo).
    f |= Qt::ItemIsDragEnabled;
    switch (index.column()) {
    case NameColumn:
    case AddressColumn:
    case StationColumn:
    case FormatColumn:
    case CommentColumn: return f | Qt::ItemIsEditable;
    case ValueColumn: return discrete ? (f | Qt::ItemIsUserCheckable) : (f | Qt::ItemIsEditable);
    default: return f;
    }
}

bool WatchTableModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (!index.isValid())
        return false;
    const int r = index.row();
    Row &row = m_rows[r];
    if (index.column() == ValueColumn) {
        if (role == Qt::CheckStateRole && isDiscrete(row.spec().address.type)) {
            const bool on = value.toInt() == Qt::Checked;
            Q_EMIT writeRequested(r, on ? 1u : 0u);
            return false; // shown when the PLC reports it
        }
        if (role != Qt::EditRole)
            return false;
        const QString text = value.toString().trimmed();
        if (text.isEmpty() || text == valueText(r))
            return false;
        const auto raw = row.values.parse(text);
        if (!raw) {
            Q_EMIT inputRejected(
                tr("%1: %2").arg(QString::fromStdString(row.spec().address.toString()),
                                 translated(raw.error().message)));
            return false;
        }
        Q_EMIT writeRequested(r, *raw);
        return false;
    }
    if (role != Qt::EditRole)
        return false;
    // One step on the undo stack per edit; name, comment and station leave the elements as they
    // are (the poll ids stay).
    WatchItemSpec spec = row.spec();
    switch (index.column()) {
    case NameColumn: spec.name = value.toString(); break;
    case CommentColumn: spec.comment = value.toString(); break;
    case AddressColumn: {
        const auto address = Address::parse(value.toString().trimmed().toUpper().toStdString());
        if (!address) {
            Q_EMIT inputRejected(
                tr("%1: %2").arg(value.toString(), translated(address.error().message)));
            return false;
        }
        spec.address = *address;
        // A format the new element cannot show gives way to the element's usual one.
        if (!WatchList::validateEntry(spec))
            spec.format = ValueFormat::defaultFormat(*address);
        break;
    }
    case StationColumn: {
        bool ok = false;
        const int station = value.toInt(&ok);
        if (!ok || station < 1 || station > 254) {
            Q_EMIT inputRejected(tr("Station must be a number from 1 to 254."));
            return false;
        }
        spec.station = static_cast<quint8>(station);
        break;
    }
    case FormatColumn: {
        std::optional<DisplayFormat> format;
        bool isInt = false;
        const int asInt = value.toInt(&isInt);
        if (isInt && value.typeId() != QMetaType::QString)
            format = static_cast<DisplayFormat>(asInt);
        else
            format = UiText::formatFromName(value.toString());
        if (!format) {
            Q_EMIT inputRejected(tr("Unknown format \"%1\".").arg(value.toString()));
            return false;
        }
        spec.format = *format;
        break;
    }
    default: return false;
    }
    if (const Status s = editItem(r, spec); !s) {
        Q_EMIT inputRejected(translated(s.error().message));
        return false;
    }
    return true;
}

} // namespace Fatek
