#pragma once

#include "core/protocol/message.h"
#include "core/watch/csvfile.h"
#include "memorysnapshot.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace Fatek {

// Snapshot files, one of two formats chosen by the file name's extension.
//
// JSON (self-describing):
//   {"format": "fatek-studio-snapshot", "version": 1,
//    "taken": "2026-11-25T19:55:00Z", "link": "tcp 127.0.0.1:500", "station": 1,
//    "protocol": "FACON", "model": "FBs-28MC, OS V3.1, ...",
//    "values": [{"address": "R0", "value": 12}, {"address": "X0", "value": 1}, ...]}
// CSV: metadata as comment lines, then a header and one row per element:
//   # fatek-studio-snapshot 1
//   # taken: 2026-11-25T19:55:00Z
//   # link: tcp 127.0.0.1:500
//   # station: 1
//   # protocol: FACON
//   # model: FBs-28MC, OS V3.1, ...
//   address,value,hex
//   R0,12,0x000C
//   X0,1,
// The hex column is written for registers and optional when reading (when given it must agree
// with the value). Values are unsigned raw values: 0/1, 0..65535, 0..4294967295.
namespace SnapshotFile {

inline constexpr const char *FormatMarker = "fatek-studio-snapshot";
inline constexpr int CurrentVersion = 1;

enum class Format { Json, Csv };
// By extension (.json, .csv, any case); JSON for a device or a pipe; nothing for other names.
std::optional<Format> formatFor(const QString &path);

// Why a file was refused. `line` (1-based, 0 when the place is not a line) and `valueIndex`
// (1-based index in the JSON "values", 0 when none) say where; `message` is the whole sentence
// with its place ("line 7: \"R0x\" ...").
struct Error
{
    enum class Kind {
        Io,          // cannot open, read or write the file; unknown extension
        Syntax,      // not JSON / not CSV rows of address,value[,hex]
        NotSnapshot, // JSON of something else
        Version,     // a newer format version
        Content,     // a bad address, value, duplicate, missing key
    };
    Kind kind = Kind::Content;
    int line = 0;
    int valueIndex = 0;
    Message message;
};

struct Loaded
{
    std::optional<MemorySnapshot> snapshot;
    Error error; // when !snapshot

    bool ok() const { return snapshot.has_value(); }
};

// CSV as a file Excel on Windows opens right: UTF-8 with the byte order mark, the line ends asked
// (CsvFile); JSON is plain UTF-8 with LF.
QByteArray save(const MemorySnapshot &snapshot, Format format,
                CsvFile::LineEnd lineEnd = CsvFile::LineEnd::Lf);
Loaded load(const QByteArray &data, Format format);

// Through QSaveFile: on any error an existing file stays as it was.
std::optional<Error> saveToFile(const MemorySnapshot &snapshot, const QString &path,
                                CsvFile::LineEnd lineEnd = CsvFile::LineEnd::Lf);
Loaded loadFromFile(const QString &path);

} // namespace SnapshotFile

} // namespace Fatek
