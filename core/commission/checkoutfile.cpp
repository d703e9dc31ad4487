#include "checkoutfile.h"

#include "commissionmessages.h"
#include "core/watch/jsonkeys.h"
#include "core/watch/jsonobjectreader.h"
#include "core/watch/safefile.h"
#include "core/watch/watchmessages.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace Fatek::CheckoutFile {

namespace {

using Problem = std::optional<Message>;

QString timeText(const QDateTime &t)
{
    return t.isValid() ? t.toUTC().toString(Qt::ISODateWithMs) : QString();
}

QString addressText(const Address &a)
{
    return QString::fromStdString(a.toString());
}

QJsonArray addressArray(const std::vector<Address> &addresses)
{
    QJsonArray out;
    for (const Address &a : addresses)
        out.append(addressText(a));
    return out;
}

// Writing.

void insertText(QJsonObject &o, const char *key, const QString &value)
{
    if (!value.isEmpty())
        o.insert(QLatin1String(key), value);
}

QJsonObject attemptJson(const CheckoutAttempt &a)
{
    QJsonObject o;
    o.insert(QStringLiteral("result"), QLatin1String(checkoutResultKey(a.result)));
    insertText(o, "comment", a.comment);
    insertText(o, "time", timeText(a.time));
    insertText(o, "engineer", a.engineer);
    insertText(o, "rose", timeText(a.rose));
    insertText(o, "fell", timeText(a.fell));
    if (!a.changedWith.empty())
        o.insert(QStringLiteral("changedWith"), addressArray(a.changedWith));
    if (a.seen)
        o.insert(QStringLiteral("seen"), *a.seen);
    if (!a.readings.empty()) {
        QJsonArray readings;
        for (const AnalogReading &r : a.readings) {
            QJsonObject ro;
            ro.insert(QStringLiteral("percent"), r.percent);
            if (r.asFound)
                ro.insert(QStringLiteral("asFound"), static_cast<qint64>(*r.asFound));
            if (r.asLeft)
                ro.insert(QStringLiteral("asLeft"), static_cast<qint64>(*r.asLeft));
            readings.append(ro);
        }
        o.insert(QStringLiteral("readings"), readings);
    }
    return o;
}

QJsonObject pointJson(const CheckoutPoint &p)
{
    QJsonObject o = attemptJson(p.attempt());
    o.insert(QStringLiteral("address"), addressText(p.address));
    o.insert(QStringLiteral("kind"), QLatin1String(checkoutKindKey(p.kind)));
    insertText(o, "name", p.name);
    insertText(o, "description", p.description);
    insertText(o, "group", p.group);
    if (p.kind == CheckoutKind::Analog) {
        const AnalogScale &a = p.analog;
        QJsonObject scale;
        scale.insert(QStringLiteral("signed"), a.isSigned);
        scale.insert(QStringLiteral("rawLow"), a.rawLow);
        scale.insert(QStringLiteral("rawHigh"), a.rawHigh);
        scale.insert(QStringLiteral("engLow"), a.engLow);
        scale.insert(QStringLiteral("engHigh"), a.engHigh);
        insertText(scale, "unit", a.unit);
        scale.insert(QStringLiteral("tolerance"), a.tolerance);
        scale.insert(QStringLiteral("tolerancePercent"), a.tolerancePercent);
        QJsonArray checks;
        for (double c : a.checks)
            checks.append(c);
        scale.insert(QStringLiteral("checks"), checks);
        o.insert(QStringLiteral("scale"), scale);
    }
    if (!p.earlier.empty()) {
        QJsonArray earlier;
        for (const CheckoutAttempt &a : p.earlier)
            earlier.append(attemptJson(a));
        o.insert(QStringLiteral("earlier"), earlier);
    }
    if (p.punch != CheckoutPunch{}) {
        QJsonObject punch;
        insertText(punch, "owner", p.punch.owner);
        insertText(punch, "closed", timeText(p.punch.closed));
        insertText(punch, "closedBy", p.punch.closedBy);
        o.insert(QStringLiteral("punch"), punch);
    }
    return o;
}

// Reading: every object through JsonObjectReader, so a key it does not know is refused by name
// (a misspelt "reslt" must not read as untested).

Message badValue(const QString &key, const QString &value)
{
    return msg<MsgId::CheckoutFileBadValue>(key.toStdString(), value.toStdString());
}

Problem readTime(JsonObjectReader &r, const QString &key, QDateTime *target)
{
    const QString s = r.string(key);
    if (r.problem || s.isEmpty())
        return r.problem;
    const QDateTime t = QDateTime::fromString(s, Qt::ISODateWithMs);
    if (!t.isValid())
        return badValue(key, s);
    *target = t.toUTC();
    return std::nullopt;
}

Problem readAddresses(JsonObjectReader &r, const QString &key, std::vector<Address> *target)
{
    const QJsonArray array = r.array(key);
    if (r.problem)
        return r.problem;
    for (const auto &v : array) {
        const auto address = Address::parse(v.toString().toStdString());
        if (!v.isString() || !address)
            return badValue(key, v.toVariant().toString());
        target->push_back(*address);
    }
    return std::nullopt;
}

// The attempt's keys of `r`; `version` 1 also knew "skipped". A missing result is told apart
// (`missingResult`), for the caller to say once it has refused unknown keys.
Problem readAttempt(JsonObjectReader &r, CheckoutAttempt *a, int version, bool *missingResult)
{
    const QString result = r.string(QStringLiteral("result"));
    if (r.problem)
        return r.problem;
    if (version == 1 && result == QLatin1String("skipped")) {
        a->result = CheckoutResult::Deferred;
    } else if (const auto parsed = parseCheckoutResult(result)) {
        a->result = *parsed;
    } else if (!r.has(QStringLiteral("result"))) {
        // Said after the unknown keys: a misspelt "reslt" is the better message.
        *missingResult = true;
    } else {
        return badValue(QStringLiteral("result"), result);
    }
    a->comment = r.string(QStringLiteral("comment"));
    a->engineer = r.string(QStringLiteral("engineer"));
    for (auto [key, target] :
         {std::pair{"time", &a->time}, std::pair{"rose", &a->rose}, std::pair{"fell", &a->fell}}) {
        if (Problem p = readTime(r, QLatin1String(key), target))
            return p;
    }
    if (Problem p = readAddresses(r, QStringLiteral("changedWith"), &a->changedWith))
        return p;
    if (r.has(QStringLiteral("seen")))
        a->seen = r.boolean(QStringLiteral("seen"), false);
    const QJsonArray readings = r.array(QStringLiteral("readings"));
    for (qsizetype i = 0; i < readings.size() && !r.problem; ++i) {
        JsonObjectReader rr(readings.at(i).toObject());
        AnalogReading reading;
        if (const auto v = rr.number(QStringLiteral("percent"), 0, 100))
            reading.percent = *v;
        else if (!rr.problem)
            rr.problem = msg<MsgId::JsonKeyMissing>("percent");
        reading.asFound = rr.integer(QStringLiteral("asFound"), -0x80000000LL, 0xFFFFFFFFLL);
        reading.asLeft = rr.integer(QStringLiteral("asLeft"), -0x80000000LL, 0xFFFFFFFFLL);
        rr.rejectUnknown();
        if (!readings.at(i).isObject())
            rr.problem = msg<MsgId::JsonWrongType>("readings", msg<MsgId::JsonTypeObject>());
        if (rr.problem)
            return msg<MsgId::AtPlace>(msg<MsgId::CheckoutPlaceReading>(i + 1), *rr.problem);
        a->readings.push_back(reading);
    }
    return r.problem;
}

// Version 1 kept an analog point's two ends as raw values: a scale whose engineering units are
// the raw values, checked at 0 and 100 %.
Problem readVersion1Analog(JsonObjectReader &r, CheckoutPoint *p)
{
    AnalogScale &a = p->analog;
    const auto low = r.integer(QStringLiteral("expectedLow"), 0, 0xFFFFFFFFLL);
    const auto high = r.integer(QStringLiteral("expectedHigh"), 0, 0xFFFFFFFFLL);
    const auto tolerance = r.integer(QStringLiteral("tolerance"), 0, 0xFFFFFFFFLL);
    const auto lowValue = r.integer(QStringLiteral("lowValue"), 0, 0xFFFFFFFFLL);
    const auto highValue = r.integer(QStringLiteral("highValue"), 0, 0xFFFFFFFFLL);
    if (r.problem)
        return r.problem;
    a.rawLow = a.engLow = double(low.value_or(0));
    a.rawHigh = a.engHigh = double(high.value_or(0));
    a.tolerance = double(tolerance.value_or(0));
    a.checks = {0, 100};
    if (lowValue)
        p->readings.push_back(AnalogReading{0, *lowValue, {}});
    if (highValue)
        p->readings.push_back(AnalogReading{100, *highValue, {}});
    return std::nullopt;
}

Problem readScale(JsonObjectReader &r, AnalogScale *a)
{
    const QJsonObject o = r.object(QStringLiteral("scale"), false);
    if (r.problem || o.isEmpty())
        return r.problem;
    JsonObjectReader s(o);
    a->isSigned = s.boolean(QStringLiteral("signed"), false);
    const double big = 1e12;
    double *numbers[] = {&a->rawLow, &a->rawHigh, &a->engLow, &a->engHigh, &a->tolerance};
    const char *keys[] = {"rawLow", "rawHigh", "engLow", "engHigh", "tolerance"};
    for (int i = 0; i < 5; ++i) {
        if (const auto v = s.number(QLatin1String(keys[i]), i == 4 ? 0 : -big, big))
            *numbers[i] = *v;
    }
    a->unit = s.string(QStringLiteral("unit"));
    a->tolerancePercent = s.boolean(QStringLiteral("tolerancePercent"), false);
    if (s.has(QStringLiteral("checks"))) {
        a->checks.clear();
        const QJsonArray checks = s.array(QStringLiteral("checks"));
        for (const auto &v : checks) {
            if (!v.isDouble() || v.toDouble() < 0 || v.toDouble() > 100) {
                s.problem = badValue(QStringLiteral("checks"), v.toVariant().toString());
                break;
            }
            a->checks.push_back(v.toDouble());
        }
    }
    s.rejectUnknown();
    if (s.problem)
        return msg<MsgId::AtPlace>(msg<MsgId::CheckoutPlaceScale>(), *s.problem);
    return std::nullopt;
}

Problem readPunch(JsonObjectReader &r, CheckoutPunch *punch)
{
    const QJsonObject o = r.object(QStringLiteral("punch"), false);
    if (r.problem || o.isEmpty())
        return r.problem;
    JsonObjectReader s(o);
    punch->owner = s.string(QStringLiteral("owner"));
    punch->closedBy = s.string(QStringLiteral("closedBy"));
    Problem p = readTime(s, QStringLiteral("closed"), &punch->closed);
    s.rejectUnknown();
    if (p || s.problem)
        return msg<MsgId::AtPlace>(msg<MsgId::CheckoutPlacePunch>(), p ? *p : *s.problem);
    return std::nullopt;
}

// The point of `o`, or what is wrong with it, placed ("point 3 (X2): ...").
Result<CheckoutPoint> readPoint(const QJsonValue &value, int index, int version)
{
    const QJsonObject o = value.toObject();
    const QString addressText = o.value(QStringLiteral("address")).toString();
    const auto placed = [index, &addressText](Message why) {
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::AtPlace>(
                             msg<MsgId::CheckoutPlacePoint>(index + 1, addressText.toStdString()),
                             std::move(why)));
    };
    if (!value.isObject())
        return placed(msg<MsgId::JsonWrongType>("points", msg<MsgId::JsonTypeObject>()));
    JsonObjectReader r(o);
    CheckoutPoint p;
    const QString address = r.string(QStringLiteral("address"));
    const auto parsed = Address::parse(address.toStdString());
    if (!parsed)
        return placed(address.isEmpty() ? msg<MsgId::JsonKeyMissing>("address")
                                        : parsed.error().message);
    p.address = *parsed;
    const QString kind = r.string(QStringLiteral("kind"));
    const auto k = parseCheckoutKind(kind);
    if (!k)
        return placed(kind.isEmpty() ? msg<MsgId::JsonKeyMissing>("kind")
                                     : badValue(QStringLiteral("kind"), kind));
    p.kind = *k;
    p.name = r.string(QStringLiteral("name"));
    p.description = r.string(QStringLiteral("description"));
    p.group = r.string(QStringLiteral("group"));
    bool missingResult = false;
    if (Problem problem = readAttempt(r, &p.attempt(), version, &missingResult))
        return placed(*problem);
    if (p.kind == CheckoutKind::Analog) {
        if (Problem problem = version == 1 ? readVersion1Analog(r, &p) : readScale(r, &p.analog))
            return placed(*problem);
    }
    if (version >= 2) {
        const QJsonArray earlier = r.array(QStringLiteral("earlier"));
        for (qsizetype i = 0; i < earlier.size() && !r.problem; ++i) {
            JsonObjectReader er(earlier.at(i).toObject());
            CheckoutAttempt a;
            bool missing = false;
            Problem problem = readAttempt(er, &a, version, &missing);
            er.rejectUnknown();
            if (!problem && !er.problem && missing)
                problem = msg<MsgId::JsonKeyMissing>("result");
            if (problem || er.problem)
                return placed(msg<MsgId::AtPlace>(msg<MsgId::CheckoutPlaceEarlier>(i + 1),
                                                  problem ? *problem : *er.problem));
            p.earlier.push_back(std::move(a));
        }
        if (Problem problem = readPunch(r, &p.punch))
            return placed(*problem);
    }
    r.rejectUnknown();
    if (r.problem)
        return placed(*r.problem);
    if (missingResult)
        return placed(msg<MsgId::JsonKeyMissing>("result"));
    return p;
}

} // namespace

QByteArray save(const CheckoutPlan &plan)
{
    QJsonObject info;
    info.insert(QStringLiteral("project"), plan.info.project);
    info.insert(QStringLiteral("customer"), plan.info.customer);
    insertText(info, "documentId", plan.info.documentId);
    insertText(info, "revision", plan.info.revision);
    info.insert(QStringLiteral("station"), plan.info.station);
    info.insert(QStringLiteral("plcModel"), plan.info.plcModel);
    info.insert(QStringLiteral("osVersion"), plan.info.osVersion);
    info.insert(QStringLiteral("created"), timeText(plan.info.created));
    info.insert(QStringLiteral("engineer"), plan.info.engineer);
    insertText(info, "engineerCompany", plan.info.engineerCompany);
    insertText(info, "witness", plan.info.witness);
    insertText(info, "witnessCompany", plan.info.witnessCompany);
    insertText(info, "customerSignatory", plan.info.customerSignatory);
    QJsonArray points;
    for (const CheckoutPoint &p : plan.points)
        points.append(pointJson(p));
    QJsonObject root;
    root.insert(QStringLiteral("format"), QLatin1String(FormatMarker));
    root.insert(QStringLiteral("version"), CurrentVersion);
    root.insert(QStringLiteral("info"), info);
    root.insert(QStringLiteral("forced"), addressArray(plan.forced));
    root.insert(QStringLiteral("points"), points);
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

Result<CheckoutPlan> load(const QByteArray &data, const QString &name)
{
    const auto damaged = [&name](Message why) {
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::CheckoutFileDamaged>(name.toStdString(), std::move(why)));
    };
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(data, &parseError);
    if (doc.isNull())
        return damaged(msg<MsgId::SnapshotJsonSyntax>(parseError.errorString().toStdString()));
    // A key given twice would silently mean the second.
    if (std::optional<Message> twice = JsonKeys::firstDuplicate(data))
        return damaged(std::move(*twice));
    const QJsonObject root = doc.object();
    if (root.value(QStringLiteral("format")).toString() != QLatin1String(FormatMarker))
        return damaged(msg<MsgId::CheckoutFileNotCheckout>(FormatMarker));
    const int version = root.value(QStringLiteral("version")).toInt(-1);
    if (version < 1 || version > CurrentVersion)
        return damaged(msg<MsgId::CheckoutFileVersion>(version, CurrentVersion));
    JsonObjectReader r(root);
    r.known({QStringLiteral("format"), QStringLiteral("version")});
    CheckoutPlan plan;
    JsonObjectReader info(r.object(QStringLiteral("info"), false));
    CheckoutInfo &i = plan.info;
    i.project = info.string(QStringLiteral("project"));
    i.customer = info.string(QStringLiteral("customer"));
    info.integerInto(QStringLiteral("station"), 0, 255, &i.station);
    i.plcModel = info.string(QStringLiteral("plcModel"));
    i.osVersion = info.string(QStringLiteral("osVersion"));
    i.engineer = info.string(QStringLiteral("engineer"));
    Problem infoProblem = readTime(info, QStringLiteral("created"), &i.created);
    if (version >= 2) {
        i.documentId = info.string(QStringLiteral("documentId"));
        i.revision = info.string(QStringLiteral("revision"));
        i.engineerCompany = info.string(QStringLiteral("engineerCompany"));
        i.witness = info.string(QStringLiteral("witness"));
        i.witnessCompany = info.string(QStringLiteral("witnessCompany"));
        i.customerSignatory = info.string(QStringLiteral("customerSignatory"));
    }
    info.rejectUnknown();
    if (infoProblem || info.problem)
        return damaged(msg<MsgId::AtPlace>(msg<MsgId::CheckoutPlaceInfo>(),
                                           infoProblem ? *infoProblem : *info.problem));
    if (Problem p = readAddresses(r, QStringLiteral("forced"), &plan.forced))
        return damaged(std::move(*p));
    const QJsonArray points = r.array(QStringLiteral("points"));
    r.rejectUnknown();
    if (r.problem)
        return damaged(std::move(*r.problem));
    for (qsizetype n = 0; n < points.size(); ++n) {
        auto p = readPoint(points.at(n), static_cast<int>(n), version);
        if (!p)
            return damaged(p.error().message);
        plan.points.push_back(std::move(p).value());
    }
    if (plan.points.empty())
        return damaged(msg<MsgId::CheckoutPlanEmpty>());
    return plan;
}

Status saveToFile(const CheckoutPlan &plan, const QString &path)
{
    const QString reason = SafeFile::write(path, save(plan));
    if (!reason.isEmpty())
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::CheckoutFileCannotWrite>(path.toStdString(),
                                                             Message::text(reason.toStdString())));
    return Ok{};
}

Result<CheckoutPlan> loadFromFile(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::CheckoutFileCannotRead>(
                             path.toStdString(), Message::text(file.errorString().toStdString())));
    return load(file.readAll(), path);
}

} // namespace Fatek::CheckoutFile
