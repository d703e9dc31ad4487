#pragma once

#include "checkoutplan.h"
#include "core/protocol/result.h"

#include <QByteArray>
#include <QString>

namespace Fatek {

// Checkout files (JSON): the plan, every result so far (each point's latest attempt, its earlier
// ones and its punch-list entry) and the outputs forced and not released, so a checkout resumes
// after a crash or on another day and a later start releases what a dead one left forced.
//   {"format": "fatek-checkout", "version": 2,
//    "info": {"project": ..., "customer": ..., "documentId": ..., "revision": ..., "station": 1,
//             "plcModel": ..., "osVersion": ..., "created": "2026-11-25T19:55:00Z",
//             "engineer": ..., "engineerCompany": ..., "witness": ..., "witnessCompany": ...,
//             "customerSignatory": ...},
//    "forced": ["Y3"],
//    "points": [{"address": "X0", "kind": "input", "name": ..., "result": "passed",
//                "rose": ..., "fell": ..., "earlier": [{"result": "failed", ...}],
//                "punch": {"owner": ..., "closed": ..., "closedBy": ...}},
//               {"address": "R100", "kind": "analog", "scale": {"rawLow": 0, "rawHigh": 32000,
//                "engLow": 4, "engHigh": 20, "unit": "mA", "tolerance": 0.1,
//                "tolerancePercent": false, "signed": false, "checks": [0, 25, 50, 75, 100]},
//                "readings": [{"percent": 0, "asFound": 12, "asLeft": 0}, ...]}, ...]}
// Version 1 files (two raw ends per analog point, "skipped") are read too and saved as version 2.
// A key that no reader knows, or one given twice, is refused with its place.
namespace CheckoutFile {

inline constexpr const char *FormatMarker = "fatek-checkout";
inline constexpr int CurrentVersion = 2;

QByteArray save(const CheckoutPlan &plan);
// `name` names the file in messages.
Result<CheckoutPlan> load(const QByteArray &data, const QString &name);

// Through SafeFile: written completely (synced, renamed over the old one) or an error, never a
// half-written file that passes as saved (a full disk is an error).
Status saveToFile(const CheckoutPlan &plan, const QString &path);
Result<CheckoutPlan> loadFromFile(const QString &path);

} // namespace CheckoutFile

} // namespace Fatek
