#pragma once

#include "alarmdefinition.h"
#include "core/protocol/address.h"
#include "core/protocol/result.h"
#include "historysetting.h"
#include "symboltable.h"
#include "valueformat.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <optional>

namespace Fatek {

// One row of a watch table. (Named apart from the session's WatchEntry, the poll entry: both live
// in namespace Fatek and the GUI links and includes both.)
struct WatchItemSpec
{
    QString name;
    QString comment;
    Address address;
    quint8 station = 1;
    DisplayFormat format = DisplayFormat::Signed;
    bool swapWords = false;
    // Writes may put NaN or an infinity into a float or double item (off: refused, as a PLC
    // program's arithmetic rarely expects one; issue 48).
    bool allowNonFinite = false;
    // The item's alarms (issue 50), at most one per kind (Alarms::validate).
    QList<AlarmDefinition> alarms;
    // How the item is recorded in the history (issue 51); nothing: not recorded.
    std::optional<HistorySetting> history;

    bool operator==(const WatchItemSpec &) const = default;
};

// One watch table: its rows and how it is polled.
struct WatchTableSpec
{
    QString name;
    int intervalMs = 500;
    bool confirmWrites = true;
    QList<WatchItemSpec> items;

    bool operator==(const WatchTableSpec &) const = default;
};

// Everything a watch list file holds.
struct WatchListFile
{
    QList<WatchTableSpec> tables;
    // The ladder project's names (File > Import Names and Comments), kept with the list.
    SymbolTable symbols;

    bool operator==(const WatchListFile &) const = default;
};

// The saved watch tables: versioned JSON
//   {"format":"fatek-studio-watchlist","version":1,"tables":[{"name":"Main","intervalMs":500,
//    "confirmWrites":true,"items":[{"address":"R100","station":1,"format":"signed","swapWords":false,
//    "name":"Tank level","comment":"...","allowNonFinite":true,
//    "alarms":[{"type":"high","limit":80,"deadband":2,"onDelayMs":0,"offDelayMs":0,
//               "priority":"high","message":"Tank level high","group":"Tank farm"}],
//    "history":{"deadband":0.5,"heartbeatS":600}}]}],
//   "symbols":[{"address":"R12","name":"Tank level","comment":"..."}]}
// "symbols" (the imported names, SymbolTable) is optional and written only when there are names,
// an item's "allowNonFinite" only when true: readers before issue 55 ignored unknown keys, so the
// version stays 1; a file with alarms or history settings is version 2. Every object of the file
// (root, table, item, symbol, alarm, history setting) refuses a key it does not know, with its line
// and the known key it most likely means (issue 55: a misspelt "staton" polled station 1), so a
// new key needs a new version. A key given twice in one object is an error ("line 4:
// duplicate key ..."), not the last one silently. Errors name the place ("table 2, item 5: ...",
// "line 7: ...").
namespace WatchList {

inline constexpr const char *FormatMarker = "fatek-studio-watchlist";
inline constexpr int CurrentVersion = 1;
// A file whose items have alarms (issue 50) or history settings (issue 51) is version 2: a
// version 1 reader would drop them unseen on its next save. This reader reads both.
inline constexpr int ItemSettingsVersion = 2;
inline constexpr int AlarmsVersion = ItemSettingsVersion;
inline constexpr int MinIntervalMs = 10;
inline constexpr int MaxIntervalMs = 3600000;
inline constexpr int MaxRangeItems = 1024;
// One table (or one CSV import) holds at most this many items: more than every element of the
// largest model, and a bound on what a damaged or hostile file can make the app hold.
inline constexpr int MaxTableItems = 65536;

// How alarm ids and history series name an item within its connection: "1-R100" (station and
// address).
QString itemId(const WatchItemSpec &item);

// Station 1..254 (0 is broadcast: no answer to watch), the address exists, the format applies to it
// and every register it spans exists (R65535 as float would need R65536).
Status validateEntry(const WatchItemSpec &entry);
// Every entry and table setting; errors start with "table N" / "table N, item M".
Status validate(const WatchListFile &file);

// Parses and validates a watch list file. Within version 1, missing optional keys take their
// defaults (station 1, format by element type, swapWords false, intervalMs 500, confirmWrites
// true); an unknown key is an error.
Result<WatchListFile> load(const QByteArray &json);
Result<WatchListFile> loadFromFile(const QString &path);

// Pretty-printed JSON with every key written.
QByteArray save(const WatchListFile &file);
// Validates, then writes through QSaveFile: on any error the existing file stays as it was.
Status saveToFile(const WatchListFile &file, const QString &path);

// Rows from CSV: columns address[,station][,format][,name][,comment]. A first row with a cell
// "address" (and no address in its first cell) is a header naming the columns (any order, any
// subset with address; value and quality columns, as a watch table copies them, are skipped);
// without it the columns are positional. Comma or semicolon separated (the
// first separator outside quotes decides), fields may be quoted ("a, b" and "say ""hi"""), blank
// lines and lines starting with # are skipped, "R100..R103" in the address column gives four rows
// (names get [0], [1], ... suffixes). UTF-8 with or without BOM; text that is not UTF-8 is read as
// Latin-1 (older spreadsheet exports).
Result<QList<WatchItemSpec>> importCsv(const QByteArray &csv);

// An AddressRange as its addresses: "R100..R163" -> R100..R163 (64), "WY0..WY32" -> WY0, WY16,
// WY32, "DR0..DR4" -> DR0, DR2, DR4, "R100..163", "R100-163" and "R100" alone (1). Rejects what
// AddressRange::parse rejects, and more than MaxRangeItems elements.
Result<QList<Address>> expandRange(const QString &text);

} // namespace WatchList

} // namespace Fatek
