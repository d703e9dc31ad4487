#include "symbolimport.h"

// A comment/symbol list of the ladder project, read into a SymbolTable line by line.

#include "csvreader.h"
#include "watchlisterrors.h"
#include "watchmessages.h"

#include <QFile>
#include <QStringDecoder>
#include <QStringList>

#include <algorithm>
#include <optional>

#ifdef Q_OS_WIN
#include <string>

#include <windows.h>
#endif

namespace Fatek {

using WatchList::Errors::linePlace;

namespace {

struct Decoded
{
    QString text;
    SymbolImport::Encoding encoding = SymbolImport::Encoding::Utf8;
};

#ifdef Q_OS_WIN
// Qt for Windows has no ICU, so no Big5 decoder: Windows' own code page 950 (Traditional
// Chinese) decodes it, line by line so that a line with bytes that are not Big5 gets the U+FFFD
// the caller skips it for, as ICU's decoder does. Empty when the system lacks code page 950.
std::optional<QString> decodeBig5(const QByteArray &data)
{
    if (!IsValidCodePage(950))
        return std::nullopt;
    QStringList lines;
    for (const QByteArray &line : data.split('\n')) {
        const int size = static_cast<int>(line.size());
        const int length = size == 0 ? 0
                                     : MultiByteToWideChar(950, MB_ERR_INVALID_CHARS,
                                                           line.constData(), size, nullptr, 0);
        if (size > 0 && length <= 0) {
            lines.append(QString(QChar(QChar::ReplacementCharacter)));
            continue;
        }
        std::wstring wide(static_cast<std::size_t>(length), L'\0');
        if (length > 0)
            MultiByteToWideChar(950, MB_ERR_INVALID_CHARS, line.constData(), size, wide.data(),
                                length);
        lines.append(QString::fromStdWString(wide));
    }
    return lines.join(QLatin1Char('\n'));
}
#else
std::optional<QString> decodeBig5(const QByteArray &data)
{
    QStringDecoder big5("Big5");
    if (!big5.isValid())
        return std::nullopt;
    return big5.decode(data);
}
#endif

// UTF-8 when the bytes are valid UTF-8, else Big5. Qt's ICU decoder does not report bad Big5
// bytes: it puts U+FFFD in their place, which the lines holding one are skipped for.
std::optional<Decoded> decode(const QByteArray &bytes)
{
    QByteArray data = bytes;
    if (data.startsWith("\xEF\xBB\xBF"))
        data.remove(0, 3);
    QStringDecoder utf8(QStringDecoder::Utf8);
    QString text = utf8.decode(data);
    if (!utf8.hasError())
        return Decoded{text, SymbolImport::Encoding::Utf8};
    const std::optional<QString> big5 = decodeBig5(data);
    if (!big5)
        return std::nullopt;
    return Decoded{*big5, SymbolImport::Encoding::Big5};
}

} // namespace

void SymbolImport::skip(int line, Message reason)
{
    ++m_skipped;
    if (m_problems.size() < maxProblems)
        m_problems.append(msg<MsgId::AtPlace>(linePlace(line), std::move(reason)));
}

Result<SymbolImport> SymbolImport::fromBytes(const QByteArray &bytes)
{
    const std::optional<Decoded> decoded = decode(bytes);
    if (!decoded)
        return makeError(ErrorKind::InvalidRequest, msg<MsgId::SymbolsNoBig5>());

    SymbolImport result;
    result.m_encoding = decoded->encoding;
    // Tabs, commas or semicolons: the first met fixes the separator, so commas in the comments of
    // a tab-separated list stay in them.
    CsvReader reader(decoded->text, u"\t,;", CsvReader::LineEnds::EndRecord);
    bool first = true;
    while (reader.nextRecord()) {
        const int lineNumber = reader.line();
        if (reader.lineText().contains(QChar(QChar::ReplacementCharacter))) {
            result.skip(lineNumber, msg<MsgId::SymbolsNotBig5>());
            first = false;
            continue;
        }
        CsvReader::Problem problem;
        const QStringList fields = reader.fields(&problem);
        if (fields.isEmpty()) {
            result.skip(lineNumber,
                        problem.kind == CsvReader::Problem::Kind::QuoteNotClosed
                            ? msg<MsgId::SymbolsQuoteNotClosed>()
                            : msg<MsgId::SymbolsTextAfterQuote>(problem.field.toStdString()));
            first = false;
            continue;
        }
        if (CsvReader::allEmpty(fields))
            continue; // a row of empty cells (";;;") is a blank line too

        const QString addressText = fields.at(0).trimmed();
        const auto address = Address::parse(addressText.toStdString());
        // A first row whose first cell is no address, and holds no digit either ("Address",
        // "位址"), names the columns; "R99999" there is a bad address, reported.
        const bool header = first && !address
                            && std::none_of(addressText.cbegin(), addressText.cend(),
                                            [](QChar c) { return c.isDigit(); });
        first = false;
        if (header)
            continue;
        if (addressText.isEmpty()) {
            result.skip(lineNumber, msg<MsgId::SymbolsNoAddress>());
            continue;
        }
        if (!address) {
            result.skip(lineNumber, address.error().message);
            continue;
        }
        Symbol symbol;
        symbol.name = fields.size() > 1 ? fields.at(1).trimmed() : QString();
        symbol.comment = fields.size() > 2 ? fields.at(2).trimmed() : QString();
        if (symbol.name.isEmpty() && symbol.comment.isEmpty()) {
            result.skip(lineNumber, msg<MsgId::SymbolsNoName>(address->toString()));
            continue;
        }
        result.m_symbols.insert(*address, symbol);
        ++result.m_imported;
    }
    return result;
}

Result<SymbolImport> SymbolImport::fromFile(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        return makeError(
            ErrorKind::InvalidRequest,
            msg<MsgId::SymbolsCannotRead>(path.toStdString(), file.errorString().toStdString()));
    }
    return fromBytes(file.readAll());
}

Message SymbolImport::summary() const
{
    Message text;
    if (m_problems.isEmpty()) {
        text = msg<MsgId::SymbolsSummary>(m_imported, m_skipped);
    } else {
        Message reasons = m_problems.first();
        for (qsizetype i = 1; i < m_problems.size(); ++i)
            reasons = msg<MsgId::Listed>(reasons, m_problems.at(i));
        if (m_skipped > m_problems.size())
            reasons = msg<MsgId::Listed>(
                reasons, msg<MsgId::SymbolsMoreSkipped>(m_skipped - m_problems.size()));
        text = msg<MsgId::SymbolsSummaryProblems>(m_imported, m_skipped, reasons);
    }
    if (m_encoding == Encoding::Big5)
        text = msg<MsgId::SymbolsReadAsBig5>(text);
    return text;
}

} // namespace Fatek
