#include "checkoutplan.h"

#include "commissionmessages.h"
#include "core/protocol/addressrange.h"
#include "core/watch/csvreader.h"
#include "core/watch/symboltable.h"

#include <QRegularExpression>
#include <QStringList>

#include <algorithm>
#include <set>

namespace Fatek {

std::optional<CheckoutKind> checkoutKindOf(const Address &address)
{
    switch (address.type) {
    case ElementType::X: return CheckoutKind::Input;
    case ElementType::Y: return CheckoutKind::Output;
    case ElementType::R:
    case ElementType::D: return CheckoutKind::Analog;
    default: return std::nullopt;
    }
}

const char *checkoutKindKey(CheckoutKind kind)
{
    switch (kind) {
    case CheckoutKind::Input: return "input";
    case CheckoutKind::Output: return "output";
    case CheckoutKind::Analog: return "analog";
    }
    return "input";
}

const char *checkoutResultKey(CheckoutResult result)
{
    switch (result) {
    case CheckoutResult::Untested: return "untested";
    case CheckoutResult::Passed: return "passed";
    case CheckoutResult::Failed: return "failed";
    case CheckoutResult::Skipped: return "skipped";
    }
    return "untested";
}

std::optional<CheckoutKind> parseCheckoutKind(const QString &key)
{
    for (CheckoutKind k : {CheckoutKind::Input, CheckoutKind::Output, CheckoutKind::Analog}) {
        if (key == QLatin1String(checkoutKindKey(k)))
            return k;
    }
    return std::nullopt;
}

std::optional<CheckoutResult> parseCheckoutResult(const QString &key)
{
    for (CheckoutResult r : {CheckoutResult::Untested, CheckoutResult::Passed,
                             CheckoutResult::Failed, CheckoutResult::Skipped}) {
        if (key == QLatin1String(checkoutResultKey(r)))
            return r;
    }
    return std::nullopt;
}

Message checkoutKindMessage(CheckoutKind kind)
{
    switch (kind) {
    case CheckoutKind::Input: return msg<MsgId::CheckoutKindInput>();
    case CheckoutKind::Output: return msg<MsgId::CheckoutKindOutput>();
    case CheckoutKind::Analog: return msg<MsgId::CheckoutKindAnalog>();
    }
    return {};
}

Message checkoutResultMessage(CheckoutResult result)
{
    switch (result) {
    case CheckoutResult::Untested: return msg<MsgId::CheckoutUntested>();
    case CheckoutResult::Passed: return msg<MsgId::CheckoutPassed>();
    case CheckoutResult::Failed: return msg<MsgId::CheckoutFailed>();
    case CheckoutResult::Skipped: return msg<MsgId::CheckoutSkipped>();
    }
    return {};
}

bool CheckoutPoint::withinTolerance(std::uint32_t value, std::uint32_t expected) const
{
    const std::uint32_t d = value > expected ? value - expected : expected - value;
    return d <= tolerance;
}

namespace {

std::string timeText(const QDateTime &t)
{
    return t.isValid() ? t.toLocalTime().toString(QStringLiteral("HH:mm:ss")).toStdString()
                       : std::string("-");
}

std::string valueText(const std::optional<std::uint32_t> &v)
{
    return v ? std::to_string(*v) : std::string("-");
}

std::string addressList(const std::vector<Address> &addresses)
{
    std::string out;
    for (const Address &a : addresses) {
        if (!out.empty())
            out += ", ";
        out += a.toString();
    }
    return out;
}

} // namespace

Message CheckoutPoint::measured() const
{
    switch (kind) {
    case CheckoutKind::Input: {
        if (!rose.isValid() && !fell.isValid() && changedWith.empty())
            return {};
        Message m = msg<MsgId::CheckoutInputTimes>(timeText(rose), timeText(fell));
        if (!changedWith.empty()) {
            return msg<MsgId::AtPlace>(std::move(m),
                                       msg<MsgId::CheckoutChangedWith>(addressList(changedWith)));
        }
        return m;
    }
    case CheckoutKind::Output:
        if (!seen)
            return {};
        return *seen ? msg<MsgId::CheckoutOutputSeen>() : msg<MsgId::CheckoutOutputNotSeen>();
    case CheckoutKind::Analog:
        if (!lowValue && !highValue)
            return {};
        return msg<MsgId::CheckoutAnalogEnds>(valueText(lowValue), expectedLow,
                                              valueText(highValue), expectedHigh, tolerance);
    }
    return {};
}

int CheckoutPlan::indexOf(const Address &address) const
{
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (points[i].address == address)
            return static_cast<int>(i);
    }
    return -1;
}

int CheckoutPlan::count(CheckoutResult result) const
{
    return static_cast<int>(
        std::count_if(points.begin(), points.end(),
                      [result](const CheckoutPoint &p) { return p.result == result; }));
}

std::vector<int> CheckoutPlan::indexesOf(CheckoutKind kind) const
{
    std::vector<int> out;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (points[i].kind == kind)
            out.push_back(static_cast<int>(i));
    }
    return out;
}

namespace {

// A point for `address`, or the reason it cannot be one.
Result<CheckoutPoint> pointFor(const Address &address, const SymbolTable *names)
{
    const std::optional<CheckoutKind> kind = checkoutKindOf(address);
    if (!kind)
        return makeError(ErrorKind::InvalidAddress,
                         msg<MsgId::CheckoutPlanBadKind>(address.toString()));
    CheckoutPoint p;
    p.address = address;
    p.kind = *kind;
    if (names) {
        if (const Symbol *s = names->find(address)) {
            p.name = s->name;
            p.description = s->comment;
        }
    }
    return p;
}

Status checkPlan(const CheckoutPlan &plan)
{
    if (plan.points.empty())
        return makeError(ErrorKind::InvalidRequest, msg<MsgId::CheckoutPlanEmpty>());
    std::set<Address> seen;
    for (const CheckoutPoint &p : plan.points) {
        if (!seen.insert(p.address).second)
            return makeError(ErrorKind::InvalidRequest,
                             msg<MsgId::CheckoutPlanDuplicate>(p.address.toString()));
    }
    return Ok{};
}

QString groupOf(const QString &name)
{
    const qsizetype cut = name.indexOf(QRegularExpression(QStringLiteral("[_.\\-]")));
    return cut > 0 ? name.left(cut) : QString();
}

std::optional<std::uint32_t> number(const QString &text)
{
    bool ok = false;
    const uint v = text.toUInt(&ok);
    if (!ok || v > 0xFFFF)
        return std::nullopt;
    return v;
}

} // namespace

Result<CheckoutPlan> CheckoutPlan::fromRanges(const QString &text, const SymbolTable *names)
{
    const auto ranges = AddressRange::parseList(text.toStdString());
    if (!ranges)
        return ranges.error();
    CheckoutPlan plan;
    for (const AddressRange &r : *ranges) {
        for (const Address &a : r.addresses()) {
            auto p = pointFor(a, names);
            if (!p)
                return p.error();
            p.value().group = QString::fromStdString(r.toString());
            plan.points.push_back(std::move(p).value());
        }
    }
    if (auto s = checkPlan(plan); !s)
        return s.error();
    return plan;
}

Result<CheckoutPlan> CheckoutPlan::fromSymbols(const SymbolTable &names, const QString &prefix)
{
    CheckoutPlan plan;
    for (const auto &[address, symbol] : names.entries()) {
        if (!checkoutKindOf(address) || !symbol.name.startsWith(prefix, Qt::CaseInsensitive))
            continue;
        CheckoutPoint p = pointFor(address, &names).value();
        p.group = groupOf(symbol.name);
        plan.points.push_back(std::move(p));
    }
    if (plan.points.empty())
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::CheckoutPlanNoSymbols>(prefix.toStdString()));
    return plan;
}

Result<CheckoutPlan> CheckoutPlan::fromCsv(const QString &text)
{
    CheckoutPlan plan;
    // ',' or ';' separated, quoted fields as the watch-list CSV reads them.
    CsvReader reader(text, u",;", CsvReader::LineEnds::EndRecord);
    while (reader.nextRecord()) {
        const int lineNo = reader.line();
        const auto lineError = [lineNo](Message why) {
            return makeError(ErrorKind::InvalidRequest,
                             msg<MsgId::CheckoutCsvLine>(lineNo, std::move(why)));
        };
        CsvReader::Problem problem;
        const QStringList fields = reader.fields(&problem);
        if (fields.isEmpty() || fields.size() > 7)
            return lineError(
                msg<MsgId::CheckoutCsvColumns>("address,name,comment,group,low,high,tolerance"));
        const auto address = Address::parse(fields.at(0).toStdString());
        if (!address) {
            // The header line names its columns.
            if (plan.points.empty()
                && fields.at(0).compare(QLatin1String("address"), Qt::CaseInsensitive) == 0)
                continue;
            return lineError(address.error().message);
        }
        auto point = pointFor(*address, nullptr);
        if (!point)
            return lineError(point.error().message);
        CheckoutPoint p = std::move(point).value();
        const auto field = [&fields](int i) {
            return i < fields.size() ? fields.at(i) : QString();
        };
        p.name = field(1);
        p.description = field(2);
        p.group = field(3);
        if (p.kind == CheckoutKind::Analog) {
            if (field(4).isEmpty() || field(5).isEmpty())
                return lineError(msg<MsgId::CheckoutAnalogNeedsRange>(address->toString()));
            std::uint32_t *targets[] = {&p.expectedLow, &p.expectedHigh, &p.tolerance};
            for (int i = 0; i < 3; ++i) {
                if (field(4 + i).isEmpty())
                    continue;
                const auto v = number(field(4 + i));
                if (!v)
                    return lineError(msg<MsgId::CheckoutCsvNumber>(field(4 + i).toStdString()));
                *targets[i] = *v;
            }
        }
        plan.points.push_back(std::move(p));
    }
    if (auto s = checkPlan(plan); !s)
        return s.error();
    return plan;
}

} // namespace Fatek
