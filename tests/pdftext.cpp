#include "pdftext.h"

#include "testutil.h"

#include <QDeadlineTimer>
#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QThread>
#include <QXmlStreamReader>

namespace PdfText {

namespace {

// Qt's PDF writer names each glyph by the lowest code point the font maps to it, and Noto Sans
// CJK draws the Kangxi radicals (U+2F00..U+2FD5) with the ideographs' glyphs: a reader gets
// "客⼾" (U+2F3E) where the report says "客戶" (U+6236). The same character to a person, and to
// NFKC.
QString withIdeographs(QString text)
{
    for (qsizetype i = 0; i < text.size(); ++i) {
        if (text.at(i).unicode() >= 0x2F00 && text.at(i).unicode() <= 0x2FD5)
            text.replace(i, 1, QString(text.at(i)).normalized(QString::NormalizationForm_KC));
    }
    return text;
}

// pdftotext OPTION pdf -, its standard output.
QString run(const QString &option, const QString &pdf)
{
    if (TestUtil::underWine()) {
        const QString text = pdf + QStringLiteral(".txt");
        QFile::remove(text); // an earlier call's text
        QProcess p;
        p.start(QStringLiteral("/bin/bash"),
                {QStringLiteral("-c"),
                 QStringLiteral("pdftotext \"$3\" \"$1\" \"$2.part\" && mv \"$2.part\" \"$2\" "
                                "|| echo \"<pdftotext failed or is missing>\" > \"$2\""),
                 QStringLiteral("pdftotext-wrapper"), TestUtil::hostPath(pdf),
                 TestUtil::hostPath(text), option});
        QFile file(text);
        const QDeadlineTimer deadline(60000);
        while (!file.exists() && !deadline.hasExpired())
            QThread::msleep(50);
        if (!file.exists())
            return QStringLiteral("<pdftotext did not finish>");
        file.open(QIODevice::ReadOnly);
        return withIdeographs(QString::fromUtf8(file.readAll()));
    }
    const QString tool = QStandardPaths::findExecutable(QStringLiteral("pdftotext"));
    if (tool.isEmpty())
        return QStringLiteral("<pdftotext is missing: install poppler-utils>");
    QProcess p;
    p.start(tool, {option, pdf, QStringLiteral("-")});
    if (!p.waitForFinished(60000))
        return QStringLiteral("<pdftotext did not finish>");
    return withIdeographs(QString::fromUtf8(p.readAllStandardOutput()));
}

} // namespace

QString plain(const QString &pdf)
{
    return run(QStringLiteral("-layout"), pdf);
}

std::vector<Page> pages(const QString &pdf)
{
    std::vector<Page> out;
    QXmlStreamReader xml(run(QStringLiteral("-bbox"), pdf));
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement)
            continue;
        if (xml.name() == QLatin1String("page")) {
            out.emplace_back();
        } else if (xml.name() == QLatin1String("word") && !out.empty()) {
            Word w;
            w.top = xml.attributes().value(QLatin1String("yMin")).toDouble();
            w.bottom = xml.attributes().value(QLatin1String("yMax")).toDouble();
            w.text = xml.readElementText();
            out.back().push_back(std::move(w));
        }
    }
    return out;
}

QString pageText(const Page &page)
{
    QStringList words;
    for (const Word &w : page)
        words << w.text;
    return words.join(QLatin1Char(' '));
}

} // namespace PdfText
