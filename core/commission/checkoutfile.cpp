#include "checkoutfile.h"

#include "commissionmessages.h"
#include "core/watch/safefile.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace Fatek::CheckoutFile {

namespace {

QString timeText(const QDateTime &t)
{
    return t.isValid() ? t.toUTC().toString(Qt::ISODateWithMs) : QString();
}

QDateTime parseTime(const QJsonValue &v)
{
    const QString s = v.toString();
    return s.isEmpty() ? QDateTime() : QDateTime::fromString(s, Qt::ISODateWithMs).toUTC();
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

std::optional<std::vector<Address>> parseAddresses(const QJsonValue &v)
{
    std::vector<Address> out;
    const QJsonArray array = v.toArray();
    for (const auto &a : array) {
        const auto address = Address::parse(a.toString().toStdString());
        if (!address)
            return std::nullopt;
        out.push_back(*address);
    }
    return out;
}

QJsonObject pointJson(const CheckoutPoint &p)
{
    QJsonObject o;
    o.insert(QStringLiteral("address"), addressText(p.address));
    o.insert(QStringLiteral("kind"), QLatin1String(checkoutKindKey(p.kind)));
    const auto text = [&o](const char *key, const QString &value) {
        if (!value.isEmpty())
            o.insert(QLatin1String(key), value);
    };
    text("name", p.name);
    text("description", p.description);
    text("group", p.group);
    if (p.kind == CheckoutKind::Analog) {
        o.insert(QStringLiteral("expectedLow"), static_cast<qint64>(p.expectedLow));
        o.insert(QStringLiteral("expectedHigh"), static_cast<qint64>(p.expectedHigh));
        o.insert(QStringLiteral("tolerance"), static_cast<qint64>(p.tolerance));
    }
    o.insert(QStringLiteral("result"), QLatin1String(checkoutResultKey(p.result)));
    text("comment", p.comment);
    text("time", timeText(p.time));
    text("engineer", p.engineer);
    text("rose", timeText(p.rose));
    text("fell", timeText(p.fell));
    if (!p.changedWith.empty())
        o.insert(QStringLiteral("changedWith"), addressArray(p.changedWith));
    if (p.seen)
        o.insert(QStringLiteral("seen"), *p.seen);
    if (p.lowValue)
        o.insert(QStringLiteral("lowValue"), static_cast<qint64>(*p.lowValue));
    if (p.highValue)
        o.insert(QStringLiteral("highValue"), static_cast<qint64>(*p.highValue));
    return o;
}

std::optional<std::uint32_t> unsignedOf(const QJsonValue &v)
{
    if (!v.isDouble())
        return std::nullopt;
    const qint64 n = v.toInteger(-1);
    if (n < 0 || n > 0xFFFFFFFFLL)
        return std::nullopt;
    return static_cast<std::uint32_t>(n);
}

// The point of `o`, or what is wrong with it (a message without the file's name).
Result<CheckoutPoint> parsePoint(const QJsonObject &o, int index)
{
    const auto bad = [index](const char *key) {
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::AtPlace>(msg<MsgId::SnapshotPlaceValue>(index + 1),
                                             msg<MsgId::SnapshotMissing>(key)));
    };
    CheckoutPoint p;
    const auto address
        = Address::parse(o.value(QStringLiteral("address")).toString().toStdString());
    if (!address)
        return bad("address");
    p.address = *address;
    const auto kind = parseCheckoutKind(o.value(QStringLiteral("kind")).toString());
    if (!kind)
        return bad("kind");
    p.kind = *kind;
    const auto result = parseCheckoutResult(o.value(QStringLiteral("result")).toString());
    if (!result)
        return bad("result");
    p.result = *result;
    p.name = o.value(QStringLiteral("name")).toString();
    p.description = o.value(QStringLiteral("description")).toString();
    p.group = o.value(QStringLiteral("group")).toString();
    p.comment = o.value(QStringLiteral("comment")).toString();
    p.engineer = o.value(QStringLiteral("engineer")).toString();
    p.time = parseTime(o.value(QStringLiteral("time")));
    p.rose = parseTime(o.value(QStringLiteral("rose")));
    p.fell = parseTime(o.value(QStringLiteral("fell")));
    const auto changed = parseAddresses(o.value(QStringLiteral("changedWith")));
    if (!changed)
        return bad("changedWith");
    p.changedWith = *changed;
    if (o.contains(QStringLiteral("seen")))
        p.seen = o.value(QStringLiteral("seen")).toBool();
    if (p.kind == CheckoutKind::Analog) {
        std::uint32_t *targets[] = {&p.expectedLow, &p.expectedHigh, &p.tolerance};
        const char *keys[] = {"expectedLow", "expectedHigh", "tolerance"};
        for (int i = 0; i < 3; ++i) {
            const auto v = unsignedOf(o.value(QLatin1String(keys[i])));
            if (!v)
                return bad(keys[i]);
            *targets[i] = *v;
        }
    }
    if (o.contains(QStringLiteral("lowValue")))
        p.lowValue = unsignedOf(o.value(QStringLiteral("lowValue")));
    if (o.contains(QStringLiteral("highValue")))
        p.highValue = unsignedOf(o.value(QStringLiteral("highValue")));
    return p;
}

} // namespace

QByteArray save(const CheckoutPlan &plan)
{
    QJsonObject info;
    info.insert(QStringLiteral("project"), plan.info.project);
    info.insert(QStringLiteral("customer"), plan.info.customer);
    info.insert(QStringLiteral("station"), plan.info.station);
    info.insert(QStringLiteral("plcModel"), plan.info.plcModel);
    info.insert(QStringLiteral("osVersion"), plan.info.osVersion);
    info.insert(QStringLiteral("created"), timeText(plan.info.created));
    info.insert(QStringLiteral("engineer"), plan.info.engineer);
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
    const QJsonObject root = doc.object();
    if (root.value(QStringLiteral("format")).toString() != QLatin1String(FormatMarker))
        return damaged(msg<MsgId::CheckoutFileNotCheckout>(FormatMarker));
    const int version = root.value(QStringLiteral("version")).toInt(-1);
    if (version < 1 || version > CurrentVersion)
        return damaged(msg<MsgId::SnapshotVersion>(version, CurrentVersion));
    CheckoutPlan plan;
    const QJsonObject info = root.value(QStringLiteral("info")).toObject();
    plan.info.project = info.value(QStringLiteral("project")).toString();
    plan.info.customer = info.value(QStringLiteral("customer")).toString();
    plan.info.station = info.value(QStringLiteral("station")).toInt(1);
    plan.info.plcModel = info.value(QStringLiteral("plcModel")).toString();
    plan.info.osVersion = info.value(QStringLiteral("osVersion")).toString();
    plan.info.created = parseTime(info.value(QStringLiteral("created")));
    plan.info.engineer = info.value(QStringLiteral("engineer")).toString();
    const auto forced = parseAddresses(root.value(QStringLiteral("forced")));
    if (!forced)
        return damaged(msg<MsgId::SnapshotMissing>("forced"));
    plan.forced = *forced;
    const QJsonArray points = root.value(QStringLiteral("points")).toArray();
    for (qsizetype i = 0; i < points.size(); ++i) {
        auto p = parsePoint(points.at(i).toObject(), static_cast<int>(i));
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
