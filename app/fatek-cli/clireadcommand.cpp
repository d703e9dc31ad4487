// fatek-cli read.
#include "clireadcommand.h"

#include "clicommands.h"
#include "clicontext.h"
#include "clitext.h"
#include "core/watch/watchlist.h"

#include "core/watch/itemvalues.h"

#include <QJsonArray>

#include <algorithm>
#include <map>

namespace Fatek {

using namespace CliText;

namespace {

std::uint32_t requestLimit(const Address &start)
{
    return isDiscrete(start.type) ? Limits::maxDiscretes : Limits::maxRegisterWords;
}

// "R200:float" -> R200 and float; no colon: no format.
QString splitFormat(const QString &text, QString *address, std::optional<DisplayFormat> *format)
{
    const qsizetype colon = text.indexOf(QLatin1Char(':'));
    *address = colon >= 0 ? text.left(colon) : text;
    if (colon < 0)
        return {};
    *format = ValueFormat::fromName(text.mid(colon + 1).trimmed());
    if (!*format)
        return QStringLiteral("Unknown format \"%1\" in %2 (%3).")
            .arg(text.mid(colon + 1), text, CliText::formatNames());
    return {};
}

} // namespace

// read ADDR[:FORMAT] [COUNT], read ADDR[:FORMAT]... (a mixed list: 48 without formats), forced
// ADDR [COUNT]. A range or COUNT larger than one request carries is read in several.
QString CliReadCommand::parse(CliStepArgs &a)
{
    CliStep &s = a.step;
    const QStringList &positional = a.positional;
    QString firstText;
    std::optional<DisplayFormat> firstFormat;
    if (QString err = splitFormat(positional.at(0), &firstText, &firstFormat); !err.isEmpty())
        return err;
    if (firstFormat && s.command == CliCommandKind::Forced)
        return QStringLiteral("forced reads discretes: no format after %1.").arg(firstText);
    auto first = WatchList::expandRange(firstText);
    if (!first)
        return CliText::error(first.error());
    s.addresses = first.value();
    const bool range = s.addresses.size() > 1;
    bool secondIsCount = false;
    if (positional.size() >= 2) {
        positional.at(1).toLongLong(&secondIsCount);
        if (!secondIsCount && s.command != CliCommandKind::Read)
            return QStringLiteral("%1: COUNT must be a number, not \"%2\".")
                .arg(a.cmd(), positional.at(1));
    }
    // Items in a format (R200:float): each token its consecutive items, read as element runs.
    bool anyFormat = firstFormat.has_value();
    for (qsizetype i = 1; i < positional.size() && !secondIsCount; ++i)
        anyFormat = anyFormat || positional.at(i).contains(QLatin1Char(':'));
    if (anyFormat) {
        if (positional.size() > 2 && secondIsCount)
            return QStringLiteral("%1: unexpected argument \"%2\".").arg(a.cmd(), positional.at(2));
        for (qsizetype i = 0; i < positional.size(); ++i) {
            if (secondIsCount && i == 1)
                break;
            QString text;
            std::optional<DisplayFormat> format;
            if (QString err = splitFormat(positional.at(i), &text, &format); !err.isEmpty())
                return err;
            auto addresses = WatchList::expandRange(text);
            if (!addresses)
                return CliText::error(addresses.error());
            WatchItemSpec item;
            item.address = addresses.value().first();
            item.station = 1; // checked with a real station; the link's is used when reading
            item.format = format.value_or(ValueFormat::defaultFormat(item.address));
            if (const Status valid = WatchList::validateEntry(item); !valid)
                return CliText::error(valid.error());
            const auto width = static_cast<std::uint32_t>(ItemValues(item).elementCount());
            std::uint32_t items = 1;
            if (secondIsCount) {
                if (QString err
                    = a.countArg(positional.at(1),
                                 static_cast<std::uint32_t>(WatchList::MaxRangeItems), &items);
                    !err.isEmpty())
                    return err;
            } else {
                // A range in a format: as many items as fit in it (R0..R7:float is 4 floats).
                items = std::max<std::uint32_t>(
                    1, static_cast<std::uint32_t>(addresses.value().size()) / width);
            }
            const Status span = validateSpan(item.address, items * width);
            if (!span)
                return CliText::error(span.error());
            s.ranges.push_back({item.address, items * width});
            for (std::uint32_t n = 0; n < items; ++n) {
                s.items << item;
                item.address = item.address.advanced(width);
            }
        }
        if (s.items.size() > WatchList::MaxRangeItems)
            return QStringLiteral("read takes at most %1 items.").arg(WatchList::MaxRangeItems);
        return {};
    }
    if (positional.size() >= 2 && !secondIsCount) {
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
        if (QString err = a.countArg(
                positional.at(1), static_cast<std::uint32_t>(WatchList::MaxRangeItems), &s.count);
            !err.isEmpty())
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
    if (!step().items.isEmpty())
        return readRuns(step().ranges, 0, {},
                        [this](const ReadWords &words) { printItems(words); });
    const Address start = step().addresses.first();
    if (step().mixed)
        return m_context.submit(
            Request::mixedRead(m_context.station(), std::vector<Address>(step().addresses.begin(),
                                                                         step().addresses.end())),
            [this](const SessionResult &r) {
                if (!r.ok())
                    return m_context.failWith(r);
                printElements(r.response().values);
            });
    readRuns({{start, step().count}}, 0, {}, [this, start](const ReadWords &words) {
        std::vector<std::uint32_t> values;
        values.reserve(step().count);
        for (std::uint32_t i = 0; i < step().count; ++i)
            values.push_back(words.at(start.advanced(i)));
        printElements(values);
    });
}

void CliReadCommand::readRuns(std::vector<AddressRange> runs, std::size_t done, ReadWords words,
                              std::function<void(const ReadWords &)> finished)
{
    // One request at a time, each as large as the protocol allows; the first failure ends it.
    while (!runs.empty() && done >= runs.front().count) {
        runs.erase(runs.begin());
        done = 0;
    }
    if (runs.empty())
        return finished(words);
    const AddressRange run = runs.front();
    const Address from = run.start.advanced(static_cast<std::uint32_t>(done));
    const std::uint32_t count
        = std::min<std::uint32_t>(requestLimit(from), run.count - static_cast<std::uint32_t>(done));
    const Request request = isDiscrete(from.type)
                                ? Request::readDiscretes(m_context.station(), from, count)
                                : Request::readRegisters(m_context.station(), from, count);
    m_context.submit(request, [this, runs = std::move(runs), done, words = std::move(words), from,
                               count,
                               finished = std::move(finished)](const SessionResult &r) mutable {
        if (!r.ok())
            return m_context.failWith(r);
        const std::vector<std::uint32_t> &values = r.response().values;
        for (std::uint32_t i = 0; i < count && i < values.size(); ++i)
            words[from.advanced(i)] = values[i];
        readRuns(std::move(runs), done + count, std::move(words), std::move(finished));
    });
}

void CliReadCommand::printElements(const std::vector<std::uint32_t> &values)
{
    const Address start = step().addresses.first();
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
}

void CliReadCommand::printItems(const ReadWords &words)
{
    // One row per item, its value in its format (R200:float 1.5), with the words it spans.
    OutputBlock block;
    block.columns = {QStringLiteral("address"), QStringLiteral("format"), QStringLiteral("value"),
                     QStringLiteral("words")};
    if (options().format == OutputFormat::Csv)
        block.columns.prepend(QStringLiteral("station"));
    for (const WatchItemSpec &item : step().items) {
        const ItemValues values(item);
        std::vector<std::uint32_t> itemWords;
        QStringList hex;
        for (int e = 0; e < values.elementCount(); ++e) {
            const Address element = values.elementAddress(e);
            itemWords.push_back(words.at(element));
            hex << valueHex(itemWords.back(), element);
        }
        const QString text = values.text(values.join(itemWords));
        const QString format = ValueFormat::name(item.format);
        QStringList row{addressText(item.address), format, text, hex.join(QLatin1Char(' '))};
        if (options().format == OutputFormat::Csv)
            row.prepend(m_context.stationText());
        block.rows << row;
        QJsonObject json = m_context.itemJson(item.address);
        json.insert(QStringLiteral("format"), format);
        json.insert(QStringLiteral("value"), text);
        QJsonArray raw;
        for (std::uint32_t w : itemWords)
            raw.append(static_cast<qint64>(w));
        json.insert(QStringLiteral("words"), raw);
        block.json << json;
    }
    succeedWith(block);
}

} // namespace Fatek
