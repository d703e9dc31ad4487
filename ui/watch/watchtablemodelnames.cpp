// WatchTableModel and the window's names (SymbolNames): rows take the ladder project's name and
// comment of their address unless a person gave them their own.
#include "watchtablemodel.h"

#include "ui/common/symbolnames.h"

#include <vector>

namespace Fatek {

void WatchTableModel::setSymbols(const SymbolNames *symbols)
{
    if (m_symbols)
        disconnect(m_symbols, nullptr, this, nullptr);
    m_symbols = symbols;
    if (!symbols)
        return;
    connect(symbols, &SymbolNames::changed, this, &WatchTableModel::applySymbols);
    applySymbols(SymbolTable());
}

WatchItemSpec WatchTableModel::withSymbols(WatchItemSpec spec) const
{
    if (!m_symbols)
        return spec;
    if (const Symbol *symbol = m_symbols->table().find(spec.address)) {
        if (spec.name.isEmpty())
            spec.name = symbol->name;
        if (spec.comment.isEmpty())
            spec.comment = symbol->comment;
    }
    return spec;
}

void WatchTableModel::applySymbols(const SymbolTable &previous)
{
    if (!m_symbols)
        return;
    const SymbolTable &current = m_symbols->table();
    std::vector<int> named;
    std::vector<int> commented;
    for (int r = 0; r < m_rows.size(); ++r) {
        Row &row = m_rows[r];
        WatchItemSpec spec = row.spec();
        // Empty, or the old imported text: the row follows the names. Anything else was typed.
        const auto follow = [](const QString &text, const QString &before, const QString &now) {
            return (text.isEmpty() || text == before) && text != now;
        };
        const QString name = current.name(spec.address);
        const QString comment = current.comment(spec.address);
        bool changed = false;
        if (follow(spec.name, previous.name(spec.address), name)) {
            spec.name = name;
            named.push_back(r);
            changed = true;
        }
        if (follow(spec.comment, previous.comment(spec.address), comment)) {
            spec.comment = comment;
            commented.push_back(r);
            changed = true;
        }
        // Name and comment leave the elements as they are: the poll ids stay.
        if (changed)
            row.values.setItem(spec);
    }
    emitRowsChanged(std::move(named), NameColumn, NameColumn);
    emitRowsChanged(std::move(commented), CommentColumn, CommentColumn);
}

} // namespace Fatek
