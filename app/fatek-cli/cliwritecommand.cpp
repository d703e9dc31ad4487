// fatek-cli write.
#include "cliwritecommand.h"

#include "clicommands.h"
#include "clicontext.h"
#include "clitext.h"
#include "core/watch/itemvalues.h"
#include "core/watch/watchlist.h"

namespace Fatek {

using namespace CliText;

// write ADDR[:FORMAT] VALUE...
QString CliWriteCommand::parse(CliStepArgs &a)
{
    CliStep &s = a.step;
    const QStringList &positional = a.positional;
    // "R100:float 1.5": the values are typed in FORMAT, each one an item of as many elements as
    // the format spans (R100 and R101 here); without it, in the element's default format.
    const QString &target = positional.at(0);
    const qsizetype colon = target.indexOf(QLatin1Char(':'));
    auto address = Address::parse((colon >= 0 ? target.left(colon) : target).toStdString());
    if (!address)
        return CliText::error(address.error());
    WatchItemSpec item;
    item.address = address.value();
    item.format = ValueFormat::defaultFormat(item.address);
    if (colon >= 0) {
        const auto format = ValueFormat::fromName(target.mid(colon + 1).trimmed());
        if (!format)
            return QStringLiteral("Unknown format \"%1\" in %2 (%3).")
                .arg(target.mid(colon + 1), target, CliText::formatNames());
        item.format = *format;
        if (const Status valid = WatchList::validateEntry(item); !valid)
            return CliText::error(valid.error());
    }
    s.addresses = {item.address};
    // Several values go to consecutive items; validateSpan below checks that they all exist.
    const auto elements = static_cast<std::uint32_t>(ItemValues(item).elementCount());
    for (qsizetype i = 1; i < positional.size(); ++i) {
        const QString &text = positional.at(i);
        item.address = s.addresses.first().advanced(static_cast<std::uint32_t>(i - 1) * elements);
        const ItemValues values(item);
        const auto raw = values.parse(text);
        if (!raw) {
            // Discretes keep the sentence fatek-cli has always given them.
            if (isDiscrete(item.address.type))
                return QStringLiteral("%1 is a discrete: write 0, 1, on or off, not \"%2\".")
                    .arg(QString::fromStdString(item.address.toString()), text.trimmed());
            return QStringLiteral("%1: %2").arg(QString::fromStdString(item.address.toString()),
                                                CliText::error(raw.error()));
        }
        const std::vector<std::uint32_t> words = values.split(*raw);
        s.values.insert(s.values.end(), words.cbegin(), words.cend());
    }
    s.count = static_cast<std::uint32_t>(s.values.size());
    s.itemElements = elements;
    // As many as read takes: sent in as many requests as it takes (run()).
    if (s.count > static_cast<std::uint32_t>(WatchList::MaxRangeItems))
        return QStringLiteral("write takes at most %1 elements, not %2.")
            .arg(WatchList::MaxRangeItems)
            .arg(s.count);
    const Status span = validateSpan(s.addresses.first(), s.count);
    return span ? QString() : CliText::error(span.error());
}

void CliWriteCommand::run()
{
    writePart(0);
}

void CliWriteCommand::writePart(std::size_t done)
{
    const Address start = step().addresses.first();
    const std::vector<std::uint32_t> &all = step().values;
    if (done >= all.size())
        return succeedWithElements(start, all, QStringLiteral("written"),
                                   [](std::uint32_t value) { return QString::number(value); });
    // As large as one request may be (64 registers, 256 discretes), never cutting a typed value
    // (R0:float) in two; each part goes under the one rule of changes, one after the other.
    const std::uint32_t limit
        = isDiscrete(start.type) ? Limits::maxDiscretes : Limits::maxRegisterWords;
    const std::uint32_t unit = std::max<std::uint32_t>(1, step().itemElements);
    const std::size_t size
        = std::min<std::size_t>(all.size() - done, std::max(unit, limit / unit * unit));
    const Address from = start.advanced(static_cast<std::uint32_t>(done));
    const std::vector<std::uint32_t> part(all.begin() + static_cast<std::ptrdiff_t>(done),
                                          all.begin() + static_cast<std::ptrdiff_t>(done + size));
    const Request request = isDiscrete(start.type)
                                ? Request::writeDiscretes(m_context.station(), from, part)
                                : Request::writeRegisters(m_context.station(), from, part);
    m_context.submitChange(request, [this, from, done, size](const SessionResult &) {
        // Split: each part's outcome is said as it comes; a later part that fails ends the
        // program with its reason, and these lines tell what is in the PLC already.
        if (size < step().values.size()) {
            const Address last = from.advanced(static_cast<std::uint32_t>(size - 1));
            out().note(QStringLiteral("%1 written.")
                           .arg(size == 1 ? addressText(from)
                                          : QStringLiteral("%1..%2").arg(addressText(from),
                                                                         addressText(last))));
        }
        writePart(done + size);
    });
}

} // namespace Fatek
