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
    r.documentId = plan.info.documentId;
    r.revision = plan.info.revision;
    r.info = plan.info;
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
    if (!plan.info.documentId.isEmpty())
        r.fields.push_back({msg<MsgId::ReportDocument>(), text(plan.info.documentId)});
    if (!plan.info.revision.isEmpty())
        r.fields.push_back({msg<MsgId::ReportRevision>(), text(plan.info.revision)});
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
        row.attempts = p.attempts();
        r.rows.push_back(std::move(row));
    }
    for (int index : plan.punchList()) {
        const CheckoutPoint &p = plan.points[static_cast<std::size_t>(index)];
        PunchRow row;
        row.address = QString::fromStdString(p.address.toString());
        row.name = p.name;
        row.result = p.result;
        // The remark of the latest failure or deferral: what is to be mended.
        const auto punched = [](const CheckoutAttempt &a) {
            return a.result == CheckoutResult::Failed || a.result == CheckoutResult::Deferred;
        };
        if (punched(p.attempt())) {
            row.remark = p.comment;
        } else {
            for (auto it = p.earlier.rbegin(); it != p.earlier.rend(); ++it) {
                if (punched(*it)) {
                    row.remark = it->comment;
                    break;
                }
            }
        }
        row.owner = p.punch.owner;
        row.closed = p.punch.closed.isValid();
        row.state = row.closed ? msg<MsgId::ReportPunchClosed>(
                        timeText(p.punch.closed).toStdString(), p.punch.closedBy.toStdString())
                               : msg<MsgId::ReportPunchOpen>();
        r.punch.push_back(std::move(row));
    }
    r.summary = msg<MsgId::ReportSummary>(
        plan.points.size(), plan.count(CheckoutResult::Passed),
        plan.count(CheckoutResult::PassedWithRemark), plan.count(CheckoutResult::Failed),
        plan.count(CheckoutResult::Deferred), plan.count(CheckoutResult::NotApplicable),
        plan.count(CheckoutResult::Untested));
    return r;
}

std::vector<Message> CheckoutReport::columns()
{
    return {msg<MsgId::ReportPoint>(),   msg<MsgId::ReportName>(),   msg<MsgId::ReportGroup>(),
            msg<MsgId::ReportKind>(),    msg<MsgId::ReportResult>(), msg<MsgId::ReportMeasured>(),
            msg<MsgId::ReportComment>(), msg<MsgId::ReportTested>(), msg<MsgId::ReportEngineer>(),
            msg<MsgId::ReportAttempts>()};
}

std::vector<Message> CheckoutReport::punchColumns()
{
    return {msg<MsgId::ReportPoint>(),   msg<MsgId::ReportName>(),  msg<MsgId::ReportResult>(),
            msg<MsgId::ReportComment>(), msg<MsgId::ReportOwner>(), msg<MsgId::ReportPunchState>()};
}

namespace {

QString csvLine(const QStringList &cells)
{
    QStringList out;
    for (const QString &c : cells)
        out << CsvField::quoted(c);
    return out.join(QLatin1Char(',')) + QLatin1Char('\n');
}

} // namespace

QByteArray CheckoutReport::toCsv(const TextFunction &textFunction, LineEnds ends) const
{
    const TextFunction text = textFunction ? textFunction : TextFunction(englishText);
    QString out;
    out += QStringLiteral("# ") + text(msg<MsgId::ReportTitle>()) + QLatin1Char('\n');
    for (const Field &f : fields)
        out += QStringLiteral("# %1: %2\n").arg(text(f.label), text(f.value));
    QStringList header;
    for (const Message &c : columns())
        header << text(c);
    out += csvLine(header);
    for (const Row &r : rows) {
        out += csvLine({r.address, r.name, r.group, text(checkoutKindMessage(r.kind)),
                        text(checkoutResultMessage(r.result)), text(r.measured), r.comment, r.time,
                        r.engineer, QString::number(r.attempts)});
    }
    out += QStringLiteral("# %1: %2\n").arg(text(msg<MsgId::ReportSummaryTitle>()), text(summary));
    return CsvFile::bytes(out, ends);
}

QByteArray CheckoutReport::punchCsv(const TextFunction &textFunction, LineEnds ends) const
{
    const TextFunction text = textFunction ? textFunction : TextFunction(englishText);
    QString out;
    out += QStringLiteral("# ") + text(msg<MsgId::ReportPunchList>()) + QLatin1Char('\n');
    for (const Field &f : fields)
        out += QStringLiteral("# %1: %2\n").arg(text(f.label), text(f.value));
    QStringList header;
    for (const Message &c : punchColumns())
        header << text(c);
    out += csvLine(header);
    for (const PunchRow &p : punch) {
        out += csvLine({p.address, p.name, text(checkoutResultMessage(p.result)), p.remark, p.owner,
                        text(p.state)});
    }
    return CsvFile::bytes(out, ends);
}

} // namespace Fatek
