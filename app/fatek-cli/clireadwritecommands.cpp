// fatek-cli read and write.
#include "clirunner.h"

#include "clitext.h"

#include <QJsonArray>

namespace Fatek {

using namespace CliText;

void CliRunner::runRead()
{
    const Address start = step().addresses.first();
    Request request;
    if (step().mixed)
        request
            = Request::mixedRead(m_options.station, std::vector<Address>(step().addresses.begin(),
                                                                         step().addresses.end()));
    else if (isDiscrete(start.type))
        request = Request::readDiscretes(m_options.station, start, step().count);
    else
        request = Request::readRegisters(m_options.station, start, step().count);
    submit(request, [this, start](const SessionResult &r) {
        if (!r.ok())
            return failWith(r);
        const std::vector<std::uint32_t> &values = r.response().values;
        OutputBlock block;
        // Discretes have no hex view worth a column.
        const bool bitsOnly = !step().mixed && isDiscrete(start.type);
        block.columns = {QStringLiteral("address"), QStringLiteral("value"), QStringLiteral("hex")};
        if (bitsOnly)
            block.columns.removeLast();
        if (m_options.format == OutputFormat::Csv)
            block.columns
                = {QStringLiteral("station"), QStringLiteral("address"), QStringLiteral("value")};
        QJsonArray all;
        for (std::size_t i = 0; i < values.size(); ++i) {
            const Address a = step().mixed ? step().addresses.at(static_cast<qsizetype>(i))
                                           : start.advanced(static_cast<std::uint32_t>(i));
            const QString v = QString::number(values[i]);
            if (m_options.format == OutputFormat::Csv)
                block.rows << QStringList{stationText(), addressText(a), v};
            else
                block.rows << (bitsOnly ? QStringList{addressText(a), v}
                                        : QStringList{addressText(a), v, valueHex(values[i], a)});
            all.append(static_cast<qint64>(values[i]));
            if (step().mixed) {
                QJsonObject json = itemJson(a);
                json.insert(QStringLiteral("values"), QJsonArray{static_cast<qint64>(values[i])});
                block.json << json;
            }
        }
        if (!step().mixed) {
            QJsonObject json = itemJson(start);
            json.insert(QStringLiteral("values"), all);
            block.json << json;
        }
        m_out.print(block);
        stepDone();
    });
}

void CliRunner::runWrite()
{
    const Address start = step().addresses.first();
    const Request request = isDiscrete(start.type)
                                ? Request::writeDiscretes(m_options.station, start, step().values)
                                : Request::writeRegisters(m_options.station, start, step().values);
    submit(request, [this, start](const SessionResult &r) {
        if (!r.ok())
            return failWith(r);
        OutputBlock block;
        block.columns
            = {QStringLiteral("station"), QStringLiteral("address"), QStringLiteral("written")};
        QJsonArray all;
        for (std::size_t i = 0; i < step().values.size(); ++i) {
            const Address a = start.advanced(static_cast<std::uint32_t>(i));
            block.rows << QStringList{stationText(), addressText(a),
                                      QString::number(step().values[i])};
            all.append(static_cast<qint64>(step().values[i]));
        }
        QJsonObject json = itemJson(start);
        json.insert(QStringLiteral("written"), all);
        block.json << json;
        m_out.print(block);
        stepDone();
    });
}

} // namespace Fatek
