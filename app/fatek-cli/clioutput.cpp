#include "clioutput.h"

#include <QJsonDocument>

#include <cstdio>

namespace Fatek {

CliOutput::CliOutput(OutputFormat format)
    : m_format(format)
    , m_out(stdout)
    , m_err(stderr)
{}

QString CliOutput::csvCell(const QString &text)
{
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"'))
        && !text.contains(QLatin1Char('\n')) && !text.contains(QLatin1Char(';')))
        return text;
    QString quoted = text;
    quoted.replace(QLatin1String("\""), QLatin1String("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

namespace {

QString jsonLine(const QJsonObject &object)
{
    return QString::fromUtf8(QJsonDocument(object).toJson(QJsonDocument::Compact));
}

// Numbers right-aligned so columns of values line up; text left-aligned.
bool looksNumeric(const QString &text)
{
    bool ok = false;
    text.toLongLong(&ok);
    return ok;
}

} // namespace

void CliOutput::print(const OutputBlock &block)
{
    switch (m_format) {
    case OutputFormat::Json:
        for (const QJsonObject &object : block.json)
            m_out << jsonLine(object) << '\n';
        break;
    case OutputFormat::Csv: {
        QStringList header;
        for (const QString &c : block.columns)
            header << csvCell(c);
        m_out << header.join(QLatin1Char(',')) << '\n';
        for (const QStringList &row : block.rows) {
            QStringList cells;
            for (const QString &c : row)
                cells << csvCell(c);
            m_out << cells.join(QLatin1Char(',')) << '\n';
        }
        break;
    }
    case OutputFormat::Table: {
        QList<int> widths;
        for (const QString &c : block.columns)
            widths << (block.tableHeader ? static_cast<int>(c.size()) : 0);
        for (const QStringList &row : block.rows) {
            for (qsizetype i = 0; i < row.size() && i < widths.size(); ++i)
                widths[i] = std::max(widths[i], static_cast<int>(row.at(i).size()));
        }
        auto line = [&](const QStringList &cells, bool header) {
            QString text;
            for (qsizetype i = 0; i < cells.size(); ++i) {
                const int w = i < widths.size() ? widths.at(i) : 0;
                const bool last = i + 1 == cells.size();
                if (i > 0)
                    text += QLatin1String("  ");
                if (!header && block.tableHeader && looksNumeric(cells.at(i)) && i > 0)
                    text += cells.at(i).rightJustified(w);
                else
                    text += last ? cells.at(i) : cells.at(i).leftJustified(w);
            }
            m_out << text << '\n';
        };
        if (block.tableHeader)
            line(block.columns, true);
        for (const QStringList &row : block.rows)
            line(row, false);
        break;
    }
    }
    m_out.flush();
}

void CliOutput::beginStream(const QStringList &columns, const QList<int> &minWidths)
{
    m_streamColumns = columns;
    m_streamWidths.clear();
    for (qsizetype i = 0; i < columns.size(); ++i)
        m_streamWidths << std::max(static_cast<int>(columns.at(i).size()),
                                   i < minWidths.size() ? minWidths.at(i) : 0);
    if (m_format == OutputFormat::Json)
        return;
    QStringList header;
    for (qsizetype i = 0; i < columns.size(); ++i) {
        if (m_format == OutputFormat::Csv)
            header << csvCell(columns.at(i));
        else
            header << (i == 0 ? columns.at(i).leftJustified(m_streamWidths.at(i))
                              : columns.at(i).rightJustified(m_streamWidths.at(i)));
    }
    m_out << header.join(m_format == OutputFormat::Csv ? QStringLiteral(",") : QStringLiteral("  "))
          << '\n';
    m_out.flush();
}

void CliOutput::streamRow(const QStringList &cells, const QJsonObject &json)
{
    if (m_format == OutputFormat::Json) {
        m_out << jsonLine(json) << '\n';
    } else if (m_format == OutputFormat::Csv) {
        QStringList out;
        for (const QString &c : cells)
            out << csvCell(c);
        m_out << out.join(QLatin1Char(',')) << '\n';
    } else {
        QStringList out;
        for (qsizetype i = 0; i < cells.size(); ++i) {
            const int w = i < m_streamWidths.size() ? m_streamWidths.at(i) : 0;
            out << (i == 0 ? cells.at(i).leftJustified(w) : cells.at(i).rightJustified(w));
        }
        m_out << out.join(QLatin1String("  ")) << '\n';
    }
    m_out.flush();
}

void CliOutput::line(const QString &text)
{
    m_out << text << '\n';
    m_out.flush();
}

void CliOutput::error(const QString &message, int exitCode, const QJsonObject &extra)
{
    m_err << "fatek-cli: " << message << '\n';
    m_err.flush();
    if (m_format == OutputFormat::Json) {
        QJsonObject object = extra;
        object.insert(QStringLiteral("error"), message);
        object.insert(QStringLiteral("code"), exitCode);
        m_out << jsonLine(object) << '\n';
        m_out.flush();
    }
}

void CliOutput::note(const QString &message)
{
    m_err << "fatek-cli: " << message << '\n';
    m_err.flush();
}

} // namespace Fatek
