#pragma once

#include "core/watch/symboltable.h"

#include <QObject>

namespace Fatek {

// The names of the main window's addresses: the ladder project's symbol table (File > Import
// Names and Comments…, or the "symbols" of the watch list opened). One owner, the window's
// WatchListDocument; the watch tables, the trend and the forcing tool read it through a pointer
// and follow changed(). Nothing else keeps a copy of the lookup.
class SymbolNames : public QObject
{
    Q_OBJECT

public:
    explicit SymbolNames(QObject *parent = nullptr)
        : QObject(parent)
    {}

    const SymbolTable &table() const { return m_table; }
    QString name(const Address &address) const { return m_table.name(address); }
    // "X0 Start button", or "X0" when the address has no name.
    QString label(const Address &address) const;

    // Replaces the table (a watch list was opened).
    void setTable(const SymbolTable &table);
    // Adds `imported`: its entries replace those of the same addresses.
    void merge(const SymbolTable &imported);

Q_SIGNALS:
    // The table changed; `previous` is what it was, so a row can tell a name it got from the
    // table (replaced by the new one) from a name a person typed (kept).
    void changed(const Fatek::SymbolTable &previous);

private:
    SymbolTable m_table;
};

} // namespace Fatek
