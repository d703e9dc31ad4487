#include "symbolimport.h"

// A comment/symbol list of the ladder project, read into a SymbolTable line by line.

#include "csvfield.h"
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

bool isSeparator(QChar c)
{
    return c == QLatin1Char('\t') || c == QLatin1Char(',') || c == QLatin1Char(';');
}

// The first tab, comma or semicolon outside quotes.
QChar findSeparator(QStringView line)
{
    bool quoted = false;
    for (const QChar c : line) {
        if (c == QLatin1Char('"'))
            quoted = !quoted;
        else if (!quoted && isSeparator(c))
            return c;
    }
    return {};
}

// The fields of one line, or why it cannot be split.
Result<QStringList> splitLine(QStringView line, QChar separator)
{
    QStringList fields;
    const qsizetype n = line.size();
    qsizetype i = 0;
    const auto isBlank = [separator](QChar c) {
        return c != separator && (c == QLatin1Char(' ') || c == QLatin1Char('\t'));
    };
    while (true) {
        while (i < n && isBlank(line[i]))
            ++i;
        QString field;
        if (i < n && line[i] == QLatin1Char('"')) {
            if (!CsvField::readQuoted(line, i, field))
                return makeError(ErrorKind::InvalidRequest, msg<MsgId::SymbolsQuoteNotClosed>());
            while (i < n && isBlank(line[i]))
                ++i;
            if (i < n && line[i] != separator) {
                return makeError(ErrorKind::InvalidRequest,
                                 msg<MsgId::SymbolsTextAfterQuote>(field.toStdString()));
            }
        } else {
            const qsizetype start = i;
            while (i < n && line[i] != separator)
                ++i;
            field = line.mid(start, i - start).trimmed().toString();
        }
        fields.append(field);
        if (i >= n)
            return fields;
        ++i; // the separator
    }
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
    const QStringList lines = decoded->text.split(QLatin1Char('\n'));
    QChar separator;
    bool first = true;
    for (qsizetype l = 0; l < lines.size(); ++l) {
        const int lineNumber = static_cast<int>(l + 1);
        QStringView line(lines.at(l));
        if (line.endsWith(QLatin1Char('\r')))
            line.chop(1);
        const QStringView trimmed = line.trimmed();
        if (trimmed.isEmpty() || trimmed.startsWith(QLatin1Char('#')))
            continue;
        if (line.contains(QChar(QChar::ReplacementCharacter))) {
            result.skip(lineNumber, msg<MsgId::SymbolsNotBig5>());
            first = false;
            continue;
        }
        if (separator.isNull())
            separator = findSeparator(line);
        // A line without any separator is an address alone (or a header word).
        auto fields = separator.isNull() ? Result<QStringList>(QStringList{trimmed.toString()})
                                         : splitLine(line, separator);
        if (!fields) {
            result.skip(lineNumber, fields.error().message);
            first = false;
            continue;
        }
        bool allEmpty = true;
        for (const QString &field : std::as_const(*fields))
            allEmpty = allEmpty && field.trimmed().isEmpty();
        if (allEmpty)
            continue; // a row of empty cells (";;;") is a blank line too

        const QString addressText = fields->at(0).trimmed();
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
        symbol.name = fields->size() > 1 ? fields->at(1).trimmed() : QString();
        symbol.comment = fields->size() > 2 ? fields->at(2).trimmed() : QString();
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
