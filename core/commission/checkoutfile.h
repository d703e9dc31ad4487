#pragma once

#include "checkoutplan.h"
#include "core/protocol/result.h"

#include <QByteArray>
#include <QString>

namespace Fatek {

// Checkout files (JSON): the plan, every result so far and the outputs forced and not released,
// so a checkout resumes after a crash or on another day and a later start releases what a dead
// one left forced.
//   {"format": "fatek-checkout", "version": 1,
//    "info": {"project": ..., "customer": ..., "station": 1, "plcModel": ..., "osVersion": ...,
//             "created": "2026-11-25T19:55:00Z", "engineer": ...},
//    "forced": ["Y3"],
//    "points": [{"address": "X0", "kind": "input", "name": ..., "result": "passed",
//                "rose": ..., "fell": ..., ...}, ...]}
namespace CheckoutFile {

inline constexpr const char *FormatMarker = "fatek-checkout";
inline constexpr int CurrentVersion = 1;

QByteArray save(const CheckoutPlan &plan);
// `name` names the file in messages.
Result<CheckoutPlan> load(const QByteArray &data, const QString &name);

// Through SafeFile: written completely (synced, renamed over the old one) or an error, never a
// half-written file that passes as saved (a full disk is an error).
Status saveToFile(const CheckoutPlan &plan, const QString &path);
Result<CheckoutPlan> loadFromFile(const QString &path);

} // namespace CheckoutFile

} // namespace Fatek
