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
// the engineer forces from the PC, or an analog channel checked at points of its range.
enum class CheckoutKind { Input, Output, Analog };
// The statuses loop-check sheets keep. "Passed with remark" and "deferred" carry the remark or
// the reason in the attempt's comment; "not applicable" takes a point out of the count.
enum class CheckoutResult { Untested, Passed, PassedWithRemark, Failed, Deferred, NotApplicable };
inline constexpr CheckoutResult allCheckoutResults[]
    = {CheckoutResult::Untested, CheckoutResult::Passed,   CheckoutResult::PassedWithRemark,
       CheckoutResult::Failed,   CheckoutResult::Deferred, CheckoutResult::NotApplicable};

// The kind an element is checked as: X input, Y output, R, D, DR or DD analog; nothing for the
// others.
std::optional<CheckoutKind> checkoutKindOf(const Address &address);
// The words of the checkout files ("input", "passed-with-remark"); parse*() reads them back.
const char *checkoutKindKey(CheckoutKind kind);
const char *checkoutResultKey(CheckoutResult result);
std::optional<CheckoutKind> parseCheckoutKind(const QString &key);
std::optional<CheckoutResult> parseCheckoutResult(const QString &key);
// The same as messages, translated where shown.
Message checkoutKindMessage(CheckoutKind kind);
Message checkoutResultMessage(CheckoutResult result);
// Passed, passed with remark and not applicable need nothing more; failed and deferred go on the
// punch list.
bool isCheckoutDone(CheckoutResult result);

// How an analog point's register maps to what the instrument measures, and where it is checked:
// raw low..high is engineering low..high (4..20 mA as 0..32000), checked at `checks` per cent of
// the span, a reading good within `tolerance` (engineering units, or per cent of the span).
struct AnalogScale
{
    bool isSigned = false; // the register holds a two's complement value
    double rawLow = 0;
    double rawHigh = 0;
    double engLow = 0;
    double engHigh = 0;
    QString unit;
    double tolerance = 0;
    bool tolerancePercent = false;
    std::vector<double> checks = {0, 25, 50, 75, 100};

    bool operator==(const AnalogScale &) const = default;

    // The expected values are known: an analog point with none cannot pass.
    bool isDefined() const { return rawHigh != rawLow; }
    double engineering(double raw) const;
    double expected(double percent) const; // engineering units
    double toleranceUnits() const;         // engineering units
    bool within(double raw, double percent) const;
    // A value in engineering units as the report prints it: the digits the tolerance needs.
    std::string text(double engineering) const;
};

// One reading of an analog point at one check: as found, and as left after the person adjusted
// the transmitter (raw register values).
struct AnalogReading
{
    double percent = 0;
    std::optional<std::int64_t> asFound;
    std::optional<std::int64_t> asLeft;

    bool operator==(const AnalogReading &) const = default;
    std::optional<std::int64_t> last() const { return asLeft ? asLeft : asFound; }
};

// One test of a point: its result, who recorded it and when, and what was measured.
struct CheckoutAttempt
{
    CheckoutResult result = CheckoutResult::Untested;
    QString comment;  // the remark, the reason of a deferral, the engineer's note
    QDateTime time;   // when the result was recorded (UTC)
    QString engineer; // who recorded it

    // Inputs: when 0->1 and 1->0 were seen (UTC), and the other inputs of the plan that changed
    // while this one was under test (crossed wiring).
    QDateTime rose;
    QDateTime fell;
    std::vector<Address> changedWith;
    // Outputs: the technician's answer.
    std::optional<bool> seen;
    // Analog: one per check read so far, in the scale's order of checks.
    std::vector<AnalogReading> readings;

    bool operator==(const CheckoutAttempt &) const = default;
    // Nothing measured or recorded: a re-test has nothing to keep.
    bool isEmpty() const { return *this == CheckoutAttempt{}; }
};

// What is to be done about a failed or deferred point: who mends it, and when it was closed out.
struct CheckoutPunch
{
    QString owner;
    QDateTime closed; // UTC; invalid while open
    QString closedBy;

    bool operator==(const CheckoutPunch &) const = default;
};

// One point of a checkout: what it is, its latest attempt (the base), the earlier ones, and its
// punch-list entry.
struct CheckoutPoint : CheckoutAttempt
{
    Address address;
    CheckoutKind kind = CheckoutKind::Input;
    QString name;        // the ladder project's symbol
    QString description; // its comment
    QString group;       // cabinet or name prefix, for grouping in tables and the report
    AnalogScale analog;

    std::vector<CheckoutAttempt> earlier; // oldest first
    CheckoutPunch punch;

    bool operator==(const CheckoutPoint &) const = default;

    CheckoutAttempt &attempt() { return *this; }
    const CheckoutAttempt &attempt() const { return *this; }
    // The tests with a result, the latest included.
    int attempts() const;
    // A failed or deferred result now or in an earlier attempt: the punch list has it.
    bool onPunchList() const;
    // The register value of a reading as the point's type reads it (signed, 16 or 32 bits).
    std::int64_t rawValue(std::uint32_t registerValue) const;
    // What was measured in `attempt`, for tables and reports (empty when nothing yet).
    Message measured(const CheckoutAttempt &attempt) const;
    Message measured() const { return measured(*this); }
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
    // The document's identity on every page of the report, and the signatories' printed names.
    QString documentId;
    QString revision;
    QString engineerCompany;
    QString witness;
    QString witnessCompany;
    QString customerSignatory;

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
    // The points on the punch list, in plan order.
    std::vector<int> punchList() const;
    std::vector<int> indexesOf(CheckoutKind kind) const;

    // Points from ranges as users type them: "X0..X47, Y0..Y31". X become inputs, Y outputs; R, D,
    // DR and DD analog points with no expected values yet (they cannot pass until a scale is
    // given). Names and comments from `names` when given; the group is the range's text.
    static Result<CheckoutPlan> fromRanges(const QString &text, const SymbolTable *names = nullptr);
    // The inputs and outputs (and R/D) of imported names starting with `prefix` (all when empty),
    // in address order, grouped by the name's part before its first '_', '.' or '-'.
    static Result<CheckoutPlan> fromSymbols(const SymbolTable &names, const QString &prefix = {});
    // CSV: address,name,comment,group,low,high,tolerance[,engLow,engHigh,unit,checks,signed] (a
    // header line and lines starting with '#' are skipped; only the address is required, low and
    // high for analog points). low/high are the raw values at 0 and 100 %; engLow/engHigh what
    // they mean (the raw values when empty); tolerance in engineering units, or "2%" of the span;
    // checks "0/25/50/75/100" (the default) or "0/100"; signed "yes" for two's complement.
    static Result<CheckoutPlan> fromCsv(const QString &text);
};

} // namespace Fatek
