#include "checkoutplan.h"

#include "commissionmessages.h"
#include "core/protocol/addressrange.h"
#include "core/watch/csvreader.h"
#include "core/watch/symboltable.h"

#include <QRegularExpression>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <set>

namespace Fatek {

std::optional<CheckoutKind> checkoutKindOf(const Address &address)
{
    switch (address.type) {
    case ElementType::X: return CheckoutKind::Input;
    case ElementType::Y: return CheckoutKind::Output;
    case ElementType::R:
    case ElementType::D:
    case ElementType::DR:
    case ElementType::DD: return CheckoutKind::Analog;
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
    case CheckoutResult::PassedWithRemark: return "passed-with-remark";
    case CheckoutResult::Failed: return "failed";
    case CheckoutResult::Deferred: return "deferred";
    case CheckoutResult::NotApplicable: return "not-applicable";
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
    for (CheckoutResult r : allCheckoutResults) {
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
    case CheckoutResult::PassedWithRemark: return msg<MsgId::CheckoutPassedWithRemark>();
    case CheckoutResult::Failed: return msg<MsgId::CheckoutFailed>();
    case CheckoutResult::Deferred: return msg<MsgId::CheckoutDeferred>();
    case CheckoutResult::NotApplicable: return msg<MsgId::CheckoutNotApplicable>();
    }
    return {};
}

bool isCheckoutDone(CheckoutResult result)
{
    return result == CheckoutResult::Passed || result == CheckoutResult::PassedWithRemark
           || result == CheckoutResult::NotApplicable;
}

double AnalogScale::engineering(double raw) const
{
    if (!isDefined())
        return raw;
    return engLow + (raw - rawLow) * (engHigh - engLow) / (rawHigh - rawLow);
}

double AnalogScale::expected(double percent) const
{
    return engLow + (engHigh - engLow) * percent / 100.0;
}

double AnalogScale::toleranceUnits() const
{
    return tolerancePercent ? std::abs(engHigh - engLow) * tolerance / 100.0 : tolerance;
}

bool AnalogScale::within(double raw, double percent) const
{
    if (!isDefined())
        return false;
    // A hair of slack for the division: a reading exactly at the limit is within.
    const double allowed = toleranceUnits();
    return std::abs(engineering(raw) - expected(percent))
           <= allowed + 1e-9 * std::max(1.0, std::abs(engHigh - engLow));
}

std::string AnalogScale::text(double engineering) const
{
    // The digits that show a difference the size of a tenth of the tolerance (at most 6).
    const double resolution
        = toleranceUnits() > 0 ? toleranceUnits() / 10.0 : std::abs(engHigh - engLow) / 10000.0;
    int digits = 0;
    if (resolution > 0 && std::isfinite(resolution))
        digits = std::clamp(static_cast<int>(std::ceil(-std::log10(resolution))), 0, 6);
    QString number = QString::number(engineering, 'f', digits);
    if (!unit.isEmpty())
        number += QLatin1Char(' ') + unit;
    return number.toStdString();
}

int CheckoutPoint::attempts() const
{
    int n = result == CheckoutResult::Untested ? 0 : 1;
    for (const CheckoutAttempt &a : earlier)
        n += a.result == CheckoutResult::Untested ? 0 : 1;
    return n;
}

bool CheckoutPoint::onPunchList() const
{
    const auto punched = [](CheckoutResult r) {
        return r == CheckoutResult::Failed || r == CheckoutResult::Deferred;
    };
    return punched(result)
           || std::any_of(earlier.begin(), earlier.end(),
                          [&punched](const CheckoutAttempt &a) { return punched(a.result); });
}

std::int64_t CheckoutPoint::rawValue(std::uint32_t registerValue) const
{
    if (!analog.isSigned)
        return isDoubleWord(address.type) ? std::int64_t(registerValue)
                                          : std::int64_t(registerValue & 0xFFFFu);
    if (isDoubleWord(address.type))
        return static_cast<std::int32_t>(registerValue);
    return static_cast<std::int16_t>(static_cast<std::uint16_t>(registerValue & 0xFFFFu));
}

namespace {

std::string timeText(const QDateTime &t)
{
    return t.isValid() ? t.toLocalTime().toString(QStringLiteral("HH:mm:ss")).toStdString()
                       : std::string("-");
}

std::string percentText(double percent)
{
    return QString::number(percent, 'g', 4).toStdString();
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

Message CheckoutPoint::measured(const CheckoutAttempt &a) const
{
    switch (kind) {
    case CheckoutKind::Input: {
        if (!a.rose.isValid() && !a.fell.isValid() && a.changedWith.empty())
            return {};
        Message m = msg<MsgId::CheckoutInputTimes>(timeText(a.rose), timeText(a.fell));
        if (!a.changedWith.empty()) {
            return msg<MsgId::AtPlace>(std::move(m),
                                       msg<MsgId::CheckoutChangedWith>(addressList(a.changedWith)));
        }
        return m;
    }
    case CheckoutKind::Output:
        if (!a.seen)
            return {};
        return *a.seen ? msg<MsgId::CheckoutOutputSeen>() : msg<MsgId::CheckoutOutputNotSeen>();
    case CheckoutKind::Analog: {
        Message list;
        for (const AnalogReading &r : a.readings) {
            if (!r.asFound)
                continue;
            const std::string found = analog.text(analog.engineering(double(*r.asFound)));
            Message one;
            if (r.asLeft)
                one = msg<MsgId::CheckoutAnalogFoundLeft>(
                    percentText(r.percent), found,
                    analog.text(analog.engineering(double(*r.asLeft))));
            else
                one = msg<MsgId::CheckoutAnalogFound>(percentText(r.percent), found);
            if (analog.isDefined() && !analog.within(double(*r.last()), r.percent))
                one = msg<MsgId::CheckoutAnalogOff>(
                    percentText(r.percent), analog.text(analog.engineering(double(*r.last()))),
                    analog.text(analog.expected(r.percent)));
            list = list.empty() ? std::move(one)
                                : msg<MsgId::Listed>(std::move(list), std::move(one));
        }
        if (list.empty())
            return {};
        return msg<MsgId::CheckoutAnalogReadings>(std::move(list),
                                                  "\u00B1" + analog.text(analog.toleranceUnits()));
    }
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

std::vector<int> CheckoutPlan::punchList() const
{
    std::vector<int> out;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (points[i].onPunchList())
            out.push_back(static_cast<int>(i));
    }
    return out;
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

constexpr const char *csvColumns
    = "address,name,comment,group,low,high,tolerance,engLow,engHigh,unit,checks,signed";

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

std::optional<double> number(const QString &text)
{
    bool ok = false;
    const double v = text.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v))
        return std::nullopt;
    return v;
}

// "0/25/50/75/100": per cents, each in 0..100, in the order the person checks them.
std::optional<std::vector<double>> checksOf(const QString &text)
{
    std::vector<double> out;
    for (const QString &part : text.split(QLatin1Char('/'))) {
        const auto v = number(part);
        if (!v || *v < 0 || *v > 100)
            return std::nullopt;
        out.push_back(*v);
    }
    return out;
}

// The analog columns of a plan line: low,high,tolerance,engLow,engHigh,unit,checks,signed from
// column 4 on. The reason when one is wrong.
std::optional<Message> readScale(CheckoutPoint &p, const QStringList &fields)
{
    const auto field = [&fields](int i) {
        return i < fields.size() ? fields.at(i).trimmed() : QString();
    };
    if (field(4).isEmpty() || field(5).isEmpty())
        return msg<MsgId::CheckoutAnalogNeedsRange>(p.address.toString());
    AnalogScale &a = p.analog;
    double *targets[] = {&a.rawLow, &a.rawHigh, nullptr, &a.engLow, &a.engHigh};
    for (int i : {0, 1, 3, 4}) {
        if (field(4 + i).isEmpty())
            continue;
        const auto v = number(field(4 + i));
        if (!v)
            return msg<MsgId::CheckoutCsvNumber>(field(4 + i).toStdString());
        *targets[i] = *v;
    }
    if (field(7).isEmpty())
        a.engLow = a.rawLow;
    if (field(8).isEmpty())
        a.engHigh = a.rawHigh;
    if (QString t = field(6); !t.isEmpty()) {
        a.tolerancePercent = t.endsWith(QLatin1Char('%'));
        if (a.tolerancePercent)
            t.chop(1);
        const auto v = number(t);
        if (!v || *v < 0)
            return msg<MsgId::CheckoutCsvNumber>(field(6).toStdString());
        a.tolerance = *v;
    }
    a.unit = field(9);
    if (!field(10).isEmpty()) {
        const auto checks = checksOf(field(10));
        if (!checks)
            return msg<MsgId::CheckoutCsvChecks>(field(10).toStdString());
        a.checks = *checks;
    }
    const QString sign = field(11).toLower();
    if (sign == QLatin1String("yes") || sign == QLatin1String("signed"))
        a.isSigned = true;
    else if (!sign.isEmpty() && sign != QLatin1String("no") && sign != QLatin1String("unsigned"))
        return msg<MsgId::CheckoutCsvColumns>(csvColumns);
    if (!a.isDefined())
        return msg<MsgId::CheckoutAnalogNeedsRange>(p.address.toString());
    return std::nullopt;
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
        if (fields.isEmpty() || fields.size() > 12)
            return lineError(msg<MsgId::CheckoutCsvColumns>(csvColumns));
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
            if (auto why = readScale(p, fields))
                return lineError(std::move(*why));
        }
        plan.points.push_back(std::move(p));
    }
    if (auto s = checkPlan(plan); !s)
        return s.error();
    return plan;
}

} // namespace Fatek
