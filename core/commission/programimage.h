#pragma once

#include "core/protocol/message.h"
#include "core/protocol/programheader.h"
#include "core/protocol/request.h"

#include <QByteArray>
#include <QDateTime>
#include <QString>

#include <array>
#include <cstdint>
#include <optional>
#include <variant>
#include <vector>

namespace Fatek {

// One page of program memory as 4F reads it and 50 writes it.
using ProgramPage = std::array<std::uint16_t, Limits::programPageWords>;

// Why a program backup file could not be read or written: what is wrong, and the sentence.
struct ProgramFileError
{
    enum class Kind {
        Unreadable,  // the file cannot be opened or read
        Unwritable,  // the file cannot be written
        NotJson,     // not JSON, or truncated JSON
        WrongFormat, // JSON, but not a program backup
        Version,     // a newer format version
        Field,       // a field missing or of the wrong type
        PageCount,   // fewer or more pages than the header needs (truncated)
        BadPage,     // a page that is not 64 words of 4 hex digits
        Checksum,    // the words do not give the stored CRC-32
        BadHeader,   // page 0 is not a program header
    };
    Kind kind = Kind::Unreadable;
    Message message;

    std::string text() const { return english(message); }
};

class ProgramLoadResult;

// A PLC program as typed data: the decoded header, the pages (page 0 = the header), and what
// was known when it was read (the model from 53, the station, the date).
//
// File format (JSON; docs/cli.md#program-backup-and-restore):
//   {"format": "fatek-program", "version": 1, "model": "FBs-28MC, OS V3.1, ...",
//    "family": "B", "digits": "13", "programWords": 13184, "pageCount": 207, "station": 1,
//    "date": "2026-11-25T20:00:00Z", "crc32": "1A2B3C4D",
//    "pages": ["464231333380FFFF...", ...]}: one string of 64 x 4 hex digits per page
// The CRC-32 (IEEE) is over every word of every page, high byte first.
class ProgramImage
{
public:
    static constexpr const char *formatName = "fatek-program";
    static constexpr int formatVersion = 1;

    using LoadResult = ProgramLoadResult;

    ProgramImage() = default;
    // The image of pages read from a PLC, page 0 first; nothing when page 0 is not a header or
    // the number of pages is not what the header needs.
    static std::optional<ProgramImage> fromPages(std::vector<ProgramPage> pages);
    // The same from the flat program memory (pages x 64 words), as the simulator keeps it.
    static std::optional<ProgramImage> fromWords(const std::vector<std::uint16_t> &words);

    const ProgramHeader &header() const { return m_header; }
    const std::vector<ProgramPage> &pages() const { return m_pages; }
    int pageCount() const { return static_cast<int>(m_pages.size()); }
    // Every page's words in order (pageCount() x 64).
    std::vector<std::uint16_t> words() const;
    // The page as 4F answers it / 50 sends it.
    std::vector<std::uint32_t> pageValues(int page) const;

    // The model as 53 described it ("FBs-28MC, OS V3.1, program 13184 words"); may be empty.
    QString modelText() const { return m_modelText; }
    void setModelText(const QString &text) { m_modelText = text; }
    int station() const { return m_station; }
    void setStation(int station) { m_station = station; }
    QDateTime date() const { return m_date; }
    void setDate(const QDateTime &date) { m_date = date; }

    // CRC-32 (IEEE) over the words, high byte first.
    std::uint32_t checksum() const;

    // Pages whose words differ; a page only one of the two has counts as differing.
    std::vector<std::uint16_t> differingPages(const ProgramImage &other) const;

    QByteArray toJson() const;
    static LoadResult fromJson(const QByteArray &json);
    // Writes through QSaveFile: on failure the old file stays as it was.
    std::optional<ProgramFileError> save(const QString &path) const;
    static LoadResult load(const QString &path);

private:
    ProgramHeader m_header;
    std::vector<ProgramPage> m_pages;
    QString m_modelText;
    int m_station = 1;
    QDateTime m_date;
};

// A loaded image or the reason the file was refused.
class ProgramLoadResult
{
public:
    ProgramLoadResult(ProgramImage image)
        : m_data(std::move(image))
    {}
    ProgramLoadResult(ProgramFileError error)
        : m_data(std::move(error))
    {}
    bool ok() const { return m_data.index() == 0; }
    const ProgramImage &image() const { return std::get<0>(m_data); }
    const ProgramFileError &error() const { return std::get<1>(m_data); }

private:
    std::variant<ProgramImage, ProgramFileError> m_data;
};

// CRC-32 (IEEE 802.3, reflected, as zlib computes it) of `bytes`.
std::uint32_t crc32(const QByteArray &bytes);

} // namespace Fatek
