#include "symbolnames.h"

namespace Fatek {

QString SymbolNames::label(const Address &address) const
{
    const QString text = QString::fromStdString(address.toString());
    const QString symbol = m_table.name(address);
    return symbol.isEmpty() ? text : text + QLatin1Char(' ') + symbol;
}

void SymbolNames::setTable(const SymbolTable &table)
{
    if (table == m_table)
        return;
    const SymbolTable previous = m_table;
    m_table = table;
    Q_EMIT changed(previous);
}

void SymbolNames::merge(const SymbolTable &imported)
{
    SymbolTable merged = m_table;
    merged.merge(imported);
    setTable(merged);
}

} // namespace Fatek
