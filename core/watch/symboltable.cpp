#include "symboltable.h"

namespace Fatek {

const Symbol *SymbolTable::find(const Address &address) const
{
    const auto it = m_entries.find(address);
    return it == m_entries.end() ? nullptr : &it->second;
}

QString SymbolTable::name(const Address &address) const
{
    const Symbol *symbol = find(address);
    return symbol ? symbol->name : QString();
}

QString SymbolTable::comment(const Address &address) const
{
    const Symbol *symbol = find(address);
    return symbol ? symbol->comment : QString();
}

void SymbolTable::insert(const Address &address, const Symbol &symbol)
{
    if (symbol.name.isEmpty() && symbol.comment.isEmpty())
        m_entries.erase(address);
    else
        m_entries[address] = symbol;
}

void SymbolTable::merge(const SymbolTable &other)
{
    for (const auto &[address, symbol] : other.m_entries)
        m_entries[address] = symbol;
}

} // namespace Fatek
