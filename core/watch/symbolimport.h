#pragma once

#include "core/protocol/result.h"
#include "symboltable.h"

#include <QByteArray>
#include <QList>
#include <QString>

namespace Fatek {

// A comment/symbol list exported from the ladder project (FATEK WinProladder), read into a
// SymbolTable. One line per address, columns address, name, comment:
//
//   Address,Name,Comment          (optional header: a first row whose first cell is no address
//                                  and holds no digit)
//   R00012,Tank level,"Level in %, 0..1000"
//   X0<TAB>Start button<TAB>NO contact, panel door
//
// - The separator is the first tab, comma or semicolon outside quotes on the first line that is
//   not blank; fields may be quoted ("a, b", "say ""hi"""), one line per record. Further columns
//   are ignored; blank lines and lines starting with # are skipped silently.
// - Addresses go through Address::parse: "R00012", "r12" and "R12" are one key. A later line for
//   the same address replaces an earlier one.
// - Bytes that are valid UTF-8 (with or without BOM) are read as UTF-8, anything else as Big5
//   (Traditional Chinese Windows, code page 950) through QStringDecoder (ICU; see
//   docs/guide/names.md).
// - A bad line (no valid address, neither name nor comment, an unclosed quote, a character that
//   is not Big5) is skipped and reported with its line number; the good lines are kept.
class SymbolImport
{
public:
    enum class Encoding { Utf8, Big5 };
    // Reported skipped lines: the first maxProblems of them.
    static constexpr int maxProblems = 5;

    // Reads the bytes of a list. Fails only when the text cannot be decoded at all (not UTF-8
    // and this Qt has no Big5 decoder); bad lines are skipped, see skipped().
    static Result<SymbolImport> fromBytes(const QByteArray &bytes);
    // fromBytes() of a file; also fails when the file cannot be read.
    static Result<SymbolImport> fromFile(const QString &path);

    const SymbolTable &symbols() const { return m_symbols; }
    // Lines that gave an address its name and comment.
    int imported() const { return m_imported; }
    // Lines skipped as bad (not blank lines, comments or the header).
    int skipped() const { return m_skipped; }
    // Why the first maxProblems bad lines were skipped: "line 7: invalid address ...".
    const QList<Message> &problems() const { return m_problems; }
    Encoding encoding() const { return m_encoding; }

    // One sentence for a person: "Names imported: 12, lines skipped: 2 (line 3: ...; line 9:
    // ...)", with "read as Big5" when it was.
    Message summary() const;

private:
    void skip(int line, Message reason);

    SymbolTable m_symbols;
    int m_imported = 0;
    int m_skipped = 0;
    QList<Message> m_problems;
    Encoding m_encoding = Encoding::Utf8;
};

} // namespace Fatek
