#pragma once

#include "core/protocol/address.h"
#include "core/protocol/result.h"

#include <QDateTime>
#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

namespace Fatek {

class SymbolTable;

// What a point of an I/O checkout is: an input the technician actuates in the field, an output
// the engineer forces from the PC, or an analog channel checked at both ends of its range.
enum class CheckoutKind { Input, Output, Analog };
enum class CheckoutResult { Untested, Passed, Failed, Skipped };

// The kind an element is checked as: X input, Y output, R or D analog; nothing for the others.
std::optional<CheckoutKind> checkoutKindOf(const Address &address);
// The words of the checkout files ("input", "passed"); parse*() reads them back.
const char *checkoutKindKey(CheckoutKind kind);
const char *checkoutResultKey(CheckoutResult result);
std::optional<CheckoutKind> parseCheckoutKind(const QString &key);
std::optional<CheckoutResult> parseCheckoutResult(const QString &key);
// The same as messages, translated where shown.
Message checkoutKindMessage(CheckoutKind kind);
Message checkoutResultMessage(CheckoutResult result);

// One point of a checkout: what it is and what was found.
struct CheckoutPoint
{
    Address address;
    CheckoutKind kind = CheckoutKind::Input;
    QString name;        // the ladder project's symbol
    QString description; // its comment
    QString group;       // cabinet or name prefix, for grouping in tables and the report

    // Analog: the raw values expected at the low and high end of the range, and how far a
    // reading may be from them.
    std::uint32_t expectedLow = 0;
    std::uint32_t expectedHigh = 0;
    std::uint32_t tolerance = 0;

    CheckoutResult result = CheckoutResult::Untested;
    QString comment;  // the engineer's
    QDateTime time;   // when the result was recorded (UTC)
    QString engineer; // who recorded it

    // Inputs: when 0->1 and 1->0 were seen (UTC), and the other inputs of the plan that changed
    // while this one was under test (crossed wiring).
    QDateTime rose;
    QDateTime fell;
    std::vector<Address> changedWith;
    // Outputs: the technician's answer.
    std::optional<bool> seen;
    // Analog: the raw values read at the two ends.
    std::optional<std::uint32_t> lowValue;
    std::optional<std::uint32_t> highValue;

    bool operator==(const CheckoutPoint &) const = default;

    // Analog: whether `value` is within tolerance of `expected`.
    bool withinTolerance(std::uint32_t value, std::uint32_t expected) const;
    // What was measured, for tables and reports (empty when nothing yet).
    Message measured() const;
};

// Who and what the checkout is for; the PLC's model and OS version are read from its detail
// status (53) when the checkout runs.
struct CheckoutInfo
{
    QString project;
    QString customer;
    int station = 1;
    QString plcModel;
    QString osVersion;
    QDateTime created; // UTC
    QString engineer;  // the default for recorded results

    bool operator==(const CheckoutInfo &) const = default;
};

// A checkout: its points in order, and the outputs it has forced and not released yet (written
// to the file before each force, so a checkout that died with an output forced is released on the
// next start). Pure data; CheckoutRunner runs it, CheckoutFile saves it.
class CheckoutPlan
{
public:
    CheckoutInfo info;
    std::vector<CheckoutPoint> points;
    std::vector<Address> forced;

    bool operator==(const CheckoutPlan &) const = default;

    // -1 when the address is not a point.
    int indexOf(const Address &address) const;
    int count(CheckoutResult result) const;
    std::vector<int> indexesOf(CheckoutKind kind) const;

    // Points from ranges as users type them: "X0..X47, Y0..Y31". X become inputs, Y outputs; R and
    // D analog points with no expected values yet (0..0). Names and comments from `names` when
    // given; the group is the range's text.
    static Result<CheckoutPlan> fromRanges(const QString &text, const SymbolTable *names = nullptr);
    // The inputs and outputs (and R/D) of imported names starting with `prefix` (all when empty),
    // in address order, grouped by the name's part before its first '_', '.' or '-'.
    static Result<CheckoutPlan> fromSymbols(const SymbolTable &names, const QString &prefix = {});
    // CSV: address,name,comment,group,low,high,tolerance (a header line and lines starting with
    // '#' are skipped; only the address is required, low and high for R and D).
    static Result<CheckoutPlan> fromCsv(const QString &text);
};

} // namespace Fatek
