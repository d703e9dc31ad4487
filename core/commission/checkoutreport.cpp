#include "checkoutreport.h"

#include "commissionmessages.h"
#include "core/qtbridge/qtmessage.h"
#include "core/watch/csvfield.h"

#include <QStringList>

#include <algorithm>
#include <cstdlib>
#include <utility>

namespace Fatek {

namespace {

Message textOrNotReported(const QString &value)
{
    return value.isEmpty() ? msg<MsgId::ReportNotReported>() : Message::text(value.toStdString());
}

} // namespace

QString CheckoutReport::timeText(const QDateTime &time)
{
    const QDateTime local = time.toLocalTime();
    const int offset = local.offsetFromUtc();
    const int minutes = std::abs(offset) / 60;
    return local.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss "))
           + QLatin1Char(offset < 0 ? '-' : '+')
           + QStringLiteral("%1:%2")
                 .arg(minutes / 60, 2, 10, QLatin1Char('0'))
                 .arg(minutes % 60, 2, 10, QLatin1Char('0'));
}

CheckoutReport CheckoutReport::of(const CheckoutPlan &plan, const QDateTime &date)
{
    CheckoutReport r;
    const QDateTime when = date.isValid() ? date : QDateTime::currentDateTime();
    const auto text = [](const QString &s) {
        return Message::text(s.toStdString());
    };
    r.project = plan.info.project;
    r.customer = plan.info.customer;
    r.made = timeText(when);
    QDateTime first;
    QDateTime last;
    // Who recorded how many results, in order of first appearance.
    std::vector<std::pair<QString, int>> engineers;
    for (const CheckoutPoint &p : plan.points) {
        if (!p.time.isValid())
            continue;
        if (!first.isValid() || p.time < first)
            first = p.time;
        if (!last.isValid() || p.time > last)
            last = p.time;
        const auto it = std::find_if(engineers.begin(), engineers.end(),
                                     [&p](const auto &e) { return e.first == p.engineer; });
        if (it == engineers.end())
            engineers.emplace_back(p.engineer, 1);
        else
            ++it->second;
    }
    std::stable_sort(engineers.begin(), engineers.end(),
                     [](const auto &a, const auto &b) { return a.second > b.second; });
    Message engineerField = text(plan.info.engineer);
    r.engineer = plan.info.engineer;
    if (!engineers.empty()) {
        engineerField = {};
        for (const auto &[who, count] : engineers) {
            Message part = msg<MsgId::ReportEngineerPoints>(
                who.isEmpty() ? msg<MsgId::ReportUnnamed>() : text(who), count);
            engineerField = engineerField.empty()
                                ? std::move(part)
                                : msg<MsgId::Listed>(std::move(engineerField), std::move(part));
        }
        if (!engineers.front().first.isEmpty())
            r.engineer = engineers.front().first;
    }
    r.fields.push_back({msg<MsgId::ReportProject>(), text(plan.info.project)});
    r.fields.push_back({msg<MsgId::ReportCustomer>(), text(plan.info.customer)});
    r.fields.push_back({msg<MsgId::ReportPlcModel>(), textOrNotReported(plan.info.plcModel)});
    r.fields.push_back({msg<MsgId::ReportOsVersion>(), textOrNotReported(plan.info.osVersion)});
    r.fields.push_back({msg<MsgId::ReportStation>(), text(QString::number(plan.info.station))});
    r.fields.push_back({msg<MsgId::ReportTestDates>(),
                        first.isValid() ? msg<MsgId::ReportTestRange>(timeText(first).toStdString(),
                                                                      timeText(last).toStdString())
                                        : msg<MsgId::ReportNotYet>()});
    r.fields.push_back({msg<MsgId::ReportMade>(), text(r.made)});
    r.fields.push_back({msg<MsgId::ReportEngineer>(), engineerField});
    for (const CheckoutPoint &p : plan.points) {
        Row row;
        row.address = QString::fromStdString(p.address.toString());
        row.name = p.name;
        if (!p.description.isEmpty())
            row.name = row.name.isEmpty() ? p.description
                                          : row.name + QStringLiteral(" - ") + p.description;
        row.group = p.group;
        row.kind = p.kind;
        row.result = p.result;
        row.measured = p.measured();
        row.comment = p.comment;
        if (p.time.isValid())
            row.time = timeText(p.time);
        row.engineer = p.engineer;
        r.rows.push_back(std::move(row));
    }
    r.summary = msg<MsgId::ReportSummary>(
        plan.points.size(), plan.count(CheckoutResult::Passed), plan.count(CheckoutResult::Failed),
        plan.count(CheckoutResult::Skipped), plan.count(CheckoutResult::Untested));
    return r;
}

std::vector<Message> CheckoutReport::columns()
{
    return {msg<MsgId::ReportPoint>(),   msg<MsgId::ReportName>(),   msg<MsgId::ReportGroup>(),
            msg<MsgId::ReportKind>(),    msg<MsgId::ReportResult>(), msg<MsgId::ReportMeasured>(),
            msg<MsgId::ReportComment>(), msg<MsgId::ReportTested>(), msg<MsgId::ReportEngineer>()};
}

QByteArray CheckoutReport::toCsv(const TextFunction &textFunction) const
{
    const TextFunction text = textFunction ? textFunction : TextFunction(englishText);
    QString out;
    out += QStringLiteral("# ") + text(msg<MsgId::ReportTitle>()) + QLatin1Char('\n');
    for (const Field &f : fields)
        out += QStringLiteral("# %1: %2\n").arg(text(f.label), text(f.value));
    QStringList header;
    for (const Message &c : columns())
        header << CsvField::quoted(text(c));
    out += header.join(QLatin1Char(',')) + QLatin1Char('\n');
    for (const Row &r : rows) {
        const QStringList cells{r.address,
                                r.name,
                                r.group,
                                text(checkoutKindMessage(r.kind)),
                                text(checkoutResultMessage(r.result)),
                                text(r.measured),
                                r.comment,
                                r.time,
                                r.engineer};
        QStringList fieldsOut;
        for (const QString &c : cells)
            fieldsOut << CsvField::quoted(c);
        out += fieldsOut.join(QLatin1Char(',')) + QLatin1Char('\n');
    }
    out += QStringLiteral("# %1: %2\n").arg(text(msg<MsgId::ReportSummaryTitle>()), text(summary));
    return out.toUtf8();
}

} // namespace Fatek
