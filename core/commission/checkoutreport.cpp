#include "checkoutreport.h"

#include "commissionmessages.h"
#include "core/qtbridge/qtmessage.h"
#include "core/watch/csvfield.h"

#include <QStringList>

namespace Fatek {

namespace {

Message textOrNotReported(const QString &value)
{
    return value.isEmpty() ? msg<MsgId::ReportNotReported>() : Message::text(value.toStdString());
}

} // namespace

CheckoutReport CheckoutReport::of(const CheckoutPlan &plan, const QDateTime &date)
{
    CheckoutReport r;
    const QDateTime when = date.isValid() ? date : QDateTime::currentDateTime();
    const auto text = [](const QString &s) {
        return Message::text(s.toStdString());
    };
    r.fields.push_back({msg<MsgId::ReportProject>(), text(plan.info.project)});
    r.fields.push_back({msg<MsgId::ReportCustomer>(), text(plan.info.customer)});
    r.fields.push_back({msg<MsgId::ReportPlcModel>(), textOrNotReported(plan.info.plcModel)});
    r.fields.push_back({msg<MsgId::ReportOsVersion>(), textOrNotReported(plan.info.osVersion)});
    r.fields.push_back({msg<MsgId::ReportStation>(), text(QString::number(plan.info.station))});
    r.fields.push_back({msg<MsgId::ReportDate>(),
                        text(when.toLocalTime().toString(QStringLiteral("yyyy-MM-dd")))});
    r.fields.push_back({msg<MsgId::ReportEngineer>(), text(plan.info.engineer)});
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
            row.time = p.time.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"));
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
