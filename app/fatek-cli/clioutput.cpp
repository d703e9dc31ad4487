#include "clioutput.h"

#include "clioptions.h"
#include "core/qtbridge/qtmessage.h"
#include "core/watch/csvfield.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

#include <cerrno>
#include <cstdio>
#include <cstring>

#ifdef Q_OS_UNIX
#include <unistd.h>
#endif

namespace Fatek {

CliOutput::CliOutput(OutputFormat format)
    : m_format(format)
    , m_err(stderr)
{}

QString CliOutput::csvCell(const QString &text)
{
    return CsvField::quoted(text);
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
            write(jsonLine(object) + QLatin1Char('\n'));
        break;
    case OutputFormat::Csv: {
        QStringList header;
        for (const QString &c : block.columns)
            header << csvCell(c);
        QString text = header.join(QLatin1Char(',')) + QLatin1Char('\n');
        for (const QStringList &row : block.rows) {
            QStringList cells;
            for (const QString &c : row)
                cells << csvCell(c);
            text += cells.join(QLatin1Char(',')) + QLatin1Char('\n');
        }
        write(text);
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
        QString out;
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
            out += text + QLatin1Char('\n');
        };
        if (block.tableHeader)
            line(block.columns, true);
        for (const QStringList &row : block.rows)
            line(row, false);
        write(out);
        break;
    }
    }
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
    write(header.join(m_format == OutputFormat::Csv ? QStringLiteral(",") : QStringLiteral("  "))
          + QLatin1Char('\n'));
}

void CliOutput::streamRow(const QStringList &cells, const QJsonObject &json)
{
    if (m_format == OutputFormat::Json) {
        write(jsonLine(json) + QLatin1Char('\n'));
    } else if (m_format == OutputFormat::Csv) {
        QStringList out;
        for (const QString &c : cells)
            out << csvCell(c);
        write(out.join(QLatin1Char(',')) + QLatin1Char('\n'));
    } else {
        QStringList out;
        for (qsizetype i = 0; i < cells.size(); ++i) {
            const int w = i < m_streamWidths.size() ? m_streamWidths.at(i) : 0;
            out << (i == 0 ? cells.at(i).leftJustified(w) : cells.at(i).rightJustified(w));
        }
        write(out.join(QLatin1String("  ")) + QLatin1Char('\n'));
    }
}

void CliOutput::line(const QString &text)
{
    write(text + QLatin1Char('\n'));
}

void CliOutput::error(const QString &message, int exitCode, const QJsonObject &extra)
{
    m_err << "fatek-cli: " << message << '\n';
    m_err.flush();
    if (m_format == OutputFormat::Json) {
        QJsonObject object = extra;
        object.insert(QStringLiteral("error"), message);
        object.insert(QStringLiteral("code"), exitCode);
        write(jsonLine(object) + QLatin1Char('\n'));
    }
}

QString CliOutput::writeStdout(const QByteArray &bytes, bool *closedPipe)
{
    if (closedPipe)
        *closedPipe = false;
#ifdef Q_OS_UNIX
    // Straight to the descriptor: no stdio buffer that would fail later, unseen.
    qint64 done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(STDOUT_FILENO, bytes.constData() + done,
                                  static_cast<size_t>(bytes.size() - done));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            const int error = n < 0 ? errno : ENOSPC;
            // Qt ignores SIGPIPE (for its sockets): a closed pipe shows up as EPIPE here.
            if (closedPipe)
                *closedPipe = error == EPIPE;
            return QString::fromLocal8Bit(std::strerror(error));
        }
        done += n;
    }
    return {};
#else
    QFile out;
    if (!out.open(stdout, QIODevice::WriteOnly, QFileDevice::DontCloseHandle))
        return out.errorString();
    if (out.write(bytes) != bytes.size() || !out.flush())
        return out.errorString();
    return {};
#endif
}

int CliOutput::printStdout(const QString &text)
{
    bool closedPipe = false;
    const QString reason = writeStdout(text.toUtf8(), &closedPipe);
    if (reason.isEmpty())
        return ExitCode::Ok;
    if (closedPipe)
        return ExitCode::ClosedPipe;
    QTextStream(stderr) << "fatek-cli: Cannot write the output: " << reason << '\n';
    return ExitCode::Internal;
}

void CliOutput::write(const QString &text)
{
    if (m_failure != Failure::None || text.isEmpty())
        return;
    bool closedPipe = false;
    const QString reason = writeStdout(text.toUtf8(), &closedPipe);
    if (reason.isEmpty())
        return;
    m_failure = closedPipe ? Failure::ClosedPipe : Failure::WriteError;
    // A closed pipe ends the program quietly, as other Unix tools do.
    if (!closedPipe)
        note(QStringLiteral("Cannot write the output: %1").arg(reason));
    if (m_onFailure)
        m_onFailure();
}

int CliOutput::failureExitCode() const
{
    switch (m_failure) {
    case Failure::None: return ExitCode::Ok;
    case Failure::ClosedPipe: return ExitCode::ClosedPipe;
    case Failure::WriteError: return ExitCode::Internal;
    }
    return ExitCode::Internal;
}

void CliOutput::note(const QString &message)
{
    m_err << "fatek-cli: " << message << '\n';
    m_err.flush();
}

namespace {

void printJsonError(const QString &text, int code)
{
    const QJsonObject object{{QStringLiteral("error"), text}, {QStringLiteral("code"), code}};
    CliOutput::printStdout(QString::fromUtf8(QJsonDocument(object).toJson(QJsonDocument::Compact))
                           + '\n');
}

} // namespace

int CliOutput::usageError(const QString &error, bool json)
{
    QTextStream(stderr) << "fatek-cli: " << error << "\nTry 'fatek-cli --help'.\n";
    if (json)
        printJsonError(error, ExitCode::Usage);
    return ExitCode::Usage;
}

int CliOutput::failure(const Fatek::Message &reason, int code, bool json)
{
    const QString text = Fatek::englishText(reason);
    QTextStream(stderr) << "fatek-cli: " << text << '\n';
    if (json)
        printJsonError(text, code);
    return code;
}

} // namespace Fatek
