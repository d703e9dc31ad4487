#include "programimage.h"

#include "commissionmessages.h"
#include "core/watch/safefile.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace Fatek {

namespace {

ProgramFileError fileError(ProgramFileError::Kind kind, Message message)
{
    return ProgramFileError{kind, std::move(message)};
}

ProgramFileError fieldError(const char *field)
{
    return fileError(ProgramFileError::Kind::Field, msg<MsgId::ProgramFileField>(field));
}

QString hex8(std::uint32_t value)
{
    return QStringLiteral("%1").arg(value, 8, 16, QLatin1Char('0')).toUpper();
}

// "0000FFFF..." -> 64 words; nothing unless exactly 64 x 4 hex digits.
std::optional<ProgramPage> parsePage(const QString &text)
{
    if (text.size() != qsizetype{Limits::programPageWords} * 4)
        return std::nullopt;
    ProgramPage page{};
    for (std::size_t i = 0; i < page.size(); ++i) {
        bool ok = false;
        const uint w = QStringView(text).mid(static_cast<qsizetype>(i) * 4, 4).toUInt(&ok, 16);
        if (!ok)
            return std::nullopt;
        page[i] = static_cast<std::uint16_t>(w);
    }
    return page;
}

QString pageText(const ProgramPage &page)
{
    QString s;
    s.reserve(static_cast<qsizetype>(page.size()) * 4);
    for (const std::uint16_t w : page)
        s += QStringLiteral("%1").arg(w, 4, 16, QLatin1Char('0')).toUpper();
    return s;
}

} // namespace

std::uint32_t crc32(const QByteArray &bytes)
{
    std::uint32_t crc = 0xFFFFFFFFu;
    for (const char c : bytes) {
        crc ^= static_cast<std::uint8_t>(c);
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return crc ^ 0xFFFFFFFFu;
}

std::optional<ProgramImage> ProgramImage::fromPages(std::vector<ProgramPage> pages)
{
    if (pages.empty())
        return std::nullopt;
    const auto header = ProgramHeader::decode(std::span<const std::uint16_t>(pages.front()));
    if (!header || header->pageCount() != pages.size())
        return std::nullopt;
    ProgramImage image;
    image.m_header = *header;
    image.m_pages = std::move(pages);
    return image;
}

std::optional<ProgramImage> ProgramImage::fromWords(const std::vector<std::uint16_t> &words)
{
    if (words.empty() || words.size() % Limits::programPageWords != 0)
        return std::nullopt;
    std::vector<ProgramPage> pages(words.size() / Limits::programPageWords);
    for (std::size_t i = 0; i < words.size(); ++i)
        pages[i / Limits::programPageWords][i % Limits::programPageWords] = words[i];
    return fromPages(std::move(pages));
}

std::vector<std::uint16_t> ProgramImage::words() const
{
    std::vector<std::uint16_t> out;
    out.reserve(m_pages.size() * Limits::programPageWords);
    for (const ProgramPage &p : m_pages)
        out.insert(out.end(), p.begin(), p.end());
    return out;
}

std::vector<std::uint32_t> ProgramImage::pageValues(int page) const
{
    if (page < 0 || page >= pageCount())
        return {};
    const ProgramPage &p = m_pages[static_cast<std::size_t>(page)];
    return {p.begin(), p.end()};
}

std::uint32_t ProgramImage::checksum() const
{
    QByteArray bytes;
    bytes.reserve(static_cast<qsizetype>(m_pages.size() * Limits::programPageWords * 2));
    for (const ProgramPage &p : m_pages) {
        for (const std::uint16_t w : p) {
            bytes.append(static_cast<char>(w >> 8));
            bytes.append(static_cast<char>(w & 0xFFu));
        }
    }
    return crc32(bytes);
}

std::vector<std::uint16_t> ProgramImage::differingPages(const ProgramImage &other) const
{
    std::vector<std::uint16_t> out;
    const std::size_t n = std::max(m_pages.size(), other.m_pages.size());
    for (std::size_t i = 0; i < n; ++i) {
        if (i >= m_pages.size() || i >= other.m_pages.size() || m_pages[i] != other.m_pages[i])
            out.push_back(static_cast<std::uint16_t>(i));
    }
    return out;
}

QByteArray ProgramImage::toJson() const
{
    QJsonObject o;
    o.insert(QStringLiteral("format"), QLatin1String(formatName));
    o.insert(QStringLiteral("version"), formatVersion);
    o.insert(QStringLiteral("model"), m_modelText);
    o.insert(QStringLiteral("family"), QString(QLatin1Char(m_header.family)));
    o.insert(QStringLiteral("digits"), QString::fromLatin1(m_header.digits, 2));
    o.insert(QStringLiteral("programWords"), m_header.ladderSize);
    o.insert(QStringLiteral("pageCount"), pageCount());
    o.insert(QStringLiteral("station"), m_station);
    if (m_date.isValid())
        o.insert(QStringLiteral("date"), m_date.toUTC().toString(Qt::ISODate));
    o.insert(QStringLiteral("crc32"), hex8(checksum()));
    QJsonArray pages;
    for (const ProgramPage &p : m_pages)
        pages.append(pageText(p));
    o.insert(QStringLiteral("pages"), pages);
    return QJsonDocument(o).toJson(QJsonDocument::Indented);
}

ProgramImage::LoadResult ProgramImage::fromJson(const QByteArray &json)
{
    using Kind = ProgramFileError::Kind;
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError || !doc.isObject()) {
        const QString why = parseError.error != QJsonParseError::NoError
                                ? QStringLiteral("%1 at offset %2")
                                      .arg(parseError.errorString())
                                      .arg(parseError.offset)
                                : QStringLiteral("not an object");
        return fileError(Kind::NotJson, msg<MsgId::ProgramFileNotJson>(why.toStdString()));
    }
    const QJsonObject o = doc.object();
    const QString format = o.value(QStringLiteral("format")).toString();
    if (format != QLatin1String(formatName))
        return fileError(Kind::WrongFormat,
                         msg<MsgId::ProgramFileWrongFormat>(format.toStdString()));
    const QJsonValue version = o.value(QStringLiteral("version"));
    if (!version.isDouble())
        return fieldError("version");
    if (version.toInt() != formatVersion)
        return fileError(Kind::Version, msg<MsgId::ProgramFileVersion>(version.toInt()));
    const QJsonValue pageCount = o.value(QStringLiteral("pageCount"));
    const QJsonValue words = o.value(QStringLiteral("programWords"));
    const QJsonValue crc = o.value(QStringLiteral("crc32"));
    const QJsonValue pages = o.value(QStringLiteral("pages"));
    if (!pageCount.isDouble())
        return fieldError("pageCount");
    if (!words.isDouble() || words.toInt() <= 0 || words.toInt() > 0xFFFF)
        return fieldError("programWords");
    if (!crc.isString())
        return fieldError("crc32");
    if (!pages.isArray())
        return fieldError("pages");
    const QJsonArray list = pages.toArray();
    ProgramHeader expected;
    expected.ladderSize = static_cast<std::uint16_t>(words.toInt());
    if (list.size() != pageCount.toInt() || list.size() != expected.pageCount()) {
        return fileError(Kind::PageCount,
                         msg<MsgId::ProgramFilePageCount>(list.size(), expected.pageCount()));
    }
    std::vector<ProgramPage> parsed;
    parsed.reserve(static_cast<std::size_t>(list.size()));
    for (qsizetype i = 0; i < list.size(); ++i) {
        const auto page = parsePage(list.at(i).toString());
        if (!page)
            return fileError(Kind::BadPage, msg<MsgId::ProgramFileBadPage>(i));
        parsed.push_back(*page);
    }
    ProgramImage image;
    image.m_pages = std::move(parsed);
    bool crcOk = false;
    const uint stored = crc.toString().toUInt(&crcOk, 16);
    if (!crcOk || stored != image.checksum()) {
        return fileError(Kind::Checksum,
                         msg<MsgId::ProgramFileChecksum>(crc.toString().toStdString(),
                                                         hex8(image.checksum()).toStdString()));
    }
    const auto header
        = ProgramHeader::decode(std::span<const std::uint16_t>(image.m_pages.front()));
    if (!header || header->ladderSize != expected.ladderSize)
        return fileError(Kind::BadHeader, msg<MsgId::ProgramFileBadHeader>());
    image.m_header = *header;
    image.m_modelText = o.value(QStringLiteral("model")).toString();
    image.m_station = o.value(QStringLiteral("station")).toInt(1);
    image.m_date = QDateTime::fromString(o.value(QStringLiteral("date")).toString(), Qt::ISODate);
    return image;
}

std::optional<ProgramFileError> ProgramImage::save(const QString &path) const
{
    if (const QString reason = SafeFile::write(path, toJson()); !reason.isEmpty()) {
        return fileError(
            ProgramFileError::Kind::Unwritable,
            msg<MsgId::ProgramFileUnwritable>(path.toStdString(), reason.toStdString()));
    }
    return std::nullopt;
}

ProgramImage::LoadResult ProgramImage::load(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        return fileError(ProgramFileError::Kind::Unreadable,
                         msg<MsgId::ProgramFileUnreadable>(path.toStdString(),
                                                           file.errorString().toStdString()));
    }
    return fromJson(file.readAll());
}

} // namespace Fatek
