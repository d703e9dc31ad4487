#pragma once

#include "core/watch/watchlist.h"

#include <QString>

namespace Fatek {

// What a technician types or pastes into a watch table, turned into rows.
namespace WatchInput {

// Addresses and ranges separated by spaces, commas, semicolons or new lines: "R100", "R100..R163",
// "X0..X15 Y0". All or nothing: the first bad token gives an error naming it.
Result<QList<Address>> parseAddresses(const QString &text);

// Pasted text: CSV rows (address[,station][,format][,name][,comment], see WatchList::importCsv)
// when a line holds a separator after an address, else a plain list of addresses. Rows without a
// station column get `station`.
Result<QList<WatchItemSpec>> parsePasted(const QString &text, quint8 station);

} // namespace WatchInput

} // namespace Fatek
