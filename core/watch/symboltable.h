#pragma once

#include "core/protocol/address.h"

#include <QString>

#include <map>

namespace Fatek {

// What the ladder project calls one address: its symbol (name) and comment.
struct Symbol
{
    QString name;
    QString comment;

    bool operator==(const Symbol &) const = default;
};

// The names of a ladder project: address -> (name, comment). Keys are parsed addresses, so
// "R00012" and "R12" are one key; station-independent (a ladder project is one PLC's program).
// Filled by SymbolImport (a WinProladder comment/symbol list) or a watch list file's "symbols".
class SymbolTable
{
public:
    bool isEmpty() const { return m_entries.empty(); }
    qsizetype size() const { return static_cast<qsizetype>(m_entries.size()); }

    // nullptr when the address has no entry.
    const Symbol *find(const Address &address) const;
    // Empty when the address has none.
    QString name(const Address &address) const;
    QString comment(const Address &address) const;

    // Adds or replaces the entry of `address`; a symbol with neither name nor comment removes it.
    void insert(const Address &address, const Symbol &symbol);
    // Every entry of `other` replaces the one of this table for the same address.
    void merge(const SymbolTable &other);
    void clear() { m_entries.clear(); }

    // In address order (type, then number).
    const std::map<Address, Symbol> &entries() const { return m_entries; }

    bool operator==(const SymbolTable &) const = default;

private:
    std::map<Address, Symbol> m_entries;
};

} // namespace Fatek
