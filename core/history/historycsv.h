#pragma once

#include "historytypes.h"

#include <QByteArray>
#include <QString>

#include <vector>

namespace Fatek {

// The history's samples as text: one writer for the studio's "Export Range to CSV" and
// fatek-cli history (--csv, and the words of its lines), so both say a value the same way.
namespace HistoryCsv {

// "time,series,value,raw,quality\n".
QByteArray header();
// One row per sample: time (local, ISO 8601 with the UTC offset in force then), the series' key,
// the value (valueText; empty without one), raw (0x and 16 hex digits: the words as read) and the
// quality's word.
QByteArray rows(const HistorySeries &series, const std::vector<HistorySample> &samples);

// "2026-12-07T17:23:31.253+08:00": the time in this computer's zone, with its offset then.
QString localTime(qint64 ms);
// The shortest text that reads back as the value: a float item's as a float ("0.1", not
// "0.10000000149011612"), others as a double ("812", "-3.25"); empty for NaN.
QString valueText(double value, const QString &format);
// "0x0000000000000314".
QString rawText(std::uint64_t raw);

} // namespace HistoryCsv

} // namespace Fatek
