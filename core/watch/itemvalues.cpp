#include "itemvalues.h"

#include "watchmessages.h"

#include <algorithm>
#include <atomic>

namespace Fatek {

namespace {

// Process-wide: every table and the CLI draw from one counter, so no two poll entries meet.
std::atomic<std::uint64_t> nextPollId{1};

int elementBits(const Address &address)
{
    if (isDiscrete(address.type))
        return 1;
    return isDoubleWord(address.type) ? 32 : 16;
}

int spannedElements(const WatchItemSpec &item)
{
    return std::clamp(ValueFormat::elementCount(item.address, item.format), 1,
                      ItemValues::MaxElements);
}

} // namespace

ItemValues::ItemValues(const WatchItemSpec &item)
    : m_item(item)
{
    takePollIds();
}

void ItemValues::takePollIds()
{
    const int count = spannedElements(m_item);
    const std::uint64_t first = nextPollId.fetch_add(static_cast<std::uint64_t>(count));
    m_pollIds.clear();
    for (int i = 0; i < count; ++i)
        m_pollIds.push_back(first + static_cast<std::uint64_t>(i));
}

bool ItemValues::setItem(const WatchItemSpec &item)
{
    const bool elementsChanged = m_pollIds.empty() || item.address != m_item.address
                                 || spannedElements(item) != spannedElements(m_item);
    m_item = item;
    if (elementsChanged)
        takePollIds();
    return elementsChanged;
}

int ItemValues::elementCount() const
{
    return spannedElements(m_item);
}

int ItemValues::width() const
{
    const int width = ValueFormat::valueWidth(m_item.address, m_item.format);
    return width > 0 ? width : elementBits(m_item.address);
}

Address ItemValues::elementAddress(int element) const
{
    return m_item.address.advanced(static_cast<std::uint32_t>(element));
}

int ItemValues::elementOf(std::uint64_t pollId) const
{
    // The ids of one item are consecutive (takePollIds).
    if (m_pollIds.empty() || pollId < m_pollIds.front() || pollId > m_pollIds.back())
        return -1;
    return static_cast<int>(pollId - m_pollIds.front());
}

QList<WatchEntry> ItemValues::pollEntries(int intervalMs) const
{
    QList<WatchEntry> entries;
    entries.reserve(static_cast<qsizetype>(m_pollIds.size()));
    for (std::size_t i = 0; i < m_pollIds.size(); ++i) {
        WatchEntry e;
        e.id = m_pollIds[i];
        e.station = m_item.station;
        e.address = elementAddress(static_cast<int>(i));
        e.intervalMs = intervalMs;
        entries.append(e);
    }
    return entries;
}

std::uint64_t ItemValues::join(std::span<const std::uint32_t> words) const
{
    const int bits = elementBits(m_item.address);
    const std::uint64_t mask = (std::uint64_t(1) << bits) - 1;
    const std::size_t count = std::min(words.size(), static_cast<std::size_t>(elementCount()));
    std::uint64_t raw = 0;
    for (std::size_t i = 0; i < count; ++i)
        raw |= (static_cast<std::uint64_t>(words[i]) & mask) << (static_cast<int>(i) * bits);
    return raw;
}

std::vector<std::uint32_t> ItemValues::split(std::uint64_t raw) const
{
    const int bits = elementBits(m_item.address);
    const std::uint64_t mask = (std::uint64_t(1) << bits) - 1;
    std::vector<std::uint32_t> words;
    words.reserve(static_cast<std::size_t>(elementCount()));
    for (int i = 0; i < elementCount(); ++i)
        words.push_back(static_cast<std::uint32_t>((raw >> (i * bits)) & mask));
    return words;
}

QString ItemValues::text(std::uint64_t raw) const
{
    return ValueFormat::format(raw, width(), m_item.format, m_item.swapWords);
}

Result<std::uint64_t> ItemValues::parse(const QString &text) const
{
    const Result<std::uint64_t> raw
        = ValueFormat::parse(text, width(), m_item.format, m_item.swapWords);
    if (!raw)
        return raw;
    return finite(*raw, text.trimmed());
}

Result<std::uint64_t> ItemValues::fromWords(std::span<const std::uint32_t> words) const
{
    const int bits = elementBits(m_item.address);
    const std::uint64_t mask = (std::uint64_t(1) << bits) - 1;
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (words[i] <= mask)
            continue;
        const Message range
            = msg<MsgId::ValueTooLarge>(std::to_string(words[i]),
                                        bits == 1    ? msg<MsgId::ValueWidthBit>()
                                        : bits == 16 ? msg<MsgId::ValueWidthRegister>()
                                                     : msg<MsgId::ValueWidthBits>(bits),
                                        "0.." + std::to_string(mask));
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::AtPlace>(
                             Message::text(elementAddress(static_cast<int>(i)).toString()), range));
    }
    const std::uint64_t raw = join(words);
    return finite(raw, text(raw));
}

Result<std::uint64_t> ItemValues::finite(std::uint64_t raw, const QString &text) const
{
    if (m_item.allowNonFinite
        || ValueFormat::isFinite(raw, width(), m_item.format, m_item.swapWords))
        return raw;
    return makeError(ErrorKind::InvalidRequest,
                     msg<MsgId::ValueNotFinite>(text.toStdString(), "allowNonFinite"));
}

Request ItemValues::writeRequest(std::uint64_t raw) const
{
    if (isDiscrete(m_item.address.type))
        return Request::writeDiscretes(m_item.station, m_item.address, split(raw));
    return Request::writeRegisters(m_item.station, m_item.address, split(raw));
}

} // namespace Fatek
