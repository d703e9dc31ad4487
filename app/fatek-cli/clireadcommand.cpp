// fatek-cli read.
#include "clireadcommand.h"

#include "clicommands.h"
#include "clicontext.h"
#include "clitext.h"
#include "core/watch/watchlist.h"

#include <QJsonArray>

namespace Fatek {

using namespace CliText;

// read ADDR [COUNT], read ADDR ADDR... (48), forced ADDR [COUNT].
QString CliReadCommand::parse(CliStepArgs &a)
{
    CliStep &s = a.step;
    const QStringList &positional = a.positional;
    auto first = WatchList::expandRange(positional.at(0));
    if (!first)
        return CliText::error(first.error());
    s.addresses = first.value();
    const bool range = s.addresses.size() > 1;
    bool secondIsAddress = false;
    if (positional.size() >= 2) {
        bool isNumber = false;
        positional.at(1).toLongLong(&isNumber);
        secondIsAddress = !isNumber && s.command == CliCommandKind::Read;
    }
    if (secondIsAddress) {
        // A mixed list (48): every further argument is an address or a range.
        for (qsizetype i = 1; i < positional.size(); ++i) {
            auto more = WatchList::expandRange(positional.at(i));
            if (!more)
                return CliText::error(more.error());
            s.addresses += more.value();
        }
        s.mixed = true;
        s.count = static_cast<std::uint32_t>(s.addresses.size());
        return {};
    }
    if (positional.size() > 2)
        return QStringLiteral("%1: unexpected argument \"%2\".").arg(a.cmd(), positional.at(2));
    if (s.command == CliCommandKind::Forced && !isDiscrete(s.addresses.first().type))
        return QStringLiteral("forced reads discretes (X Y M S T C), not %1.")
            .arg(QString::fromStdString(s.addresses.first().toString()));
    if (positional.size() == 2) {
        if (range)
            return QStringLiteral("%1: give a range or a COUNT, not both.").arg(a.cmd());
        const std::uint32_t max = isDiscrete(s.addresses.first().type) ? Limits::maxDiscretes
                                                                       : Limits::maxRegisterWords;
        if (QString err = a.countArg(positional.at(1), max, &s.count); !err.isEmpty())
            return err;
    } else {
        s.count = static_cast<std::uint32_t>(s.addresses.size());
    }
    s.addresses = {s.addresses.first()};
    const Status span = validateSpan(s.addresses.first(), s.count);
    return span ? QString() : CliText::error(span.error());
}

void CliReadCommand::run()
{
    const Address start = step().addresses.first();
    Request request;
    if (step().mixed)
        request
            = Request::mixedRead(m_context.station(), std::vector<Address>(step().addresses.begin(),
                                                                           step().addresses.end()));
    else if (isDiscrete(start.type))
        request = Request::readDiscretes(m_context.station(), start, step().count);
    else
        request = Request::readRegisters(m_context.station(), start, step().count);
    m_context.submit(request, [this, start](const SessionResult &r) {
        if (!r.ok())
            return m_context.failWith(r);
        const std::vector<std::uint32_t> &values = r.response().values;
        OutputBlock block;
        // Discretes have no hex view worth a column.
        const bool bitsOnly = !step().mixed && isDiscrete(start.type);
        block.columns = {QStringLiteral("address"), QStringLiteral("value"), QStringLiteral("hex")};
        if (bitsOnly)
            block.columns.removeLast();
        if (options().format == OutputFormat::Csv)
            block.columns
                = {QStringLiteral("station"), QStringLiteral("address"), QStringLiteral("value")};
        QJsonArray all;
        for (std::size_t i = 0; i < values.size(); ++i) {
            const Address a = step().mixed ? step().addresses.at(static_cast<qsizetype>(i))
                                           : start.advanced(static_cast<std::uint32_t>(i));
            const QString v = QString::number(values[i]);
            if (options().format == OutputFormat::Csv)
                block.rows << QStringList{m_context.stationText(), addressText(a), v};
            else
                block.rows << (bitsOnly ? QStringList{addressText(a), v}
                                        : QStringList{addressText(a), v, valueHex(values[i], a)});
            all.append(static_cast<qint64>(values[i]));
            if (step().mixed) {
                QJsonObject json = m_context.itemJson(a);
                json.insert(QStringLiteral("values"), QJsonArray{static_cast<qint64>(values[i])});
                block.json << json;
            }
        }
        if (!step().mixed) {
            QJsonObject json = m_context.itemJson(start);
            json.insert(QStringLiteral("values"), all);
            block.json << json;
        }
        succeedWith(block);
    });
}

} // namespace Fatek
