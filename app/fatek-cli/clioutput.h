#pragma once

#include "clioptions.h"

#include <QJsonObject>
#include <QList>
#include <QString>
#include <QStringList>
#include <QTextStream>
#include <QVariant>

namespace Fatek {

// One result of a command in the three output shapes: table rows and CSV rows share the columns;
// JSON has its own objects (one per line) because a read is one object with a values array.
struct OutputBlock
{
    QStringList columns;
    QList<QStringList> rows;
    QList<QJsonObject> json;
    bool tableHeader = true; // false: "key  value" lines without a header row
};

// Writes results to stdout and reasons to stderr in the chosen format.
class CliOutput
{
public:
    explicit CliOutput(OutputFormat format);

    OutputFormat format() const { return m_format; }

    void print(const OutputBlock &block);

    // Streaming rows (monitor): the header once, then one line per row, flushed at once.
    void beginStream(const QStringList &columns, const QList<int> &minWidths = {});
    void streamRow(const QStringList &cells, const QJsonObject &json);
    // One finished line on stdout (monitor --csv: DataLogger's rows), flushed at once.
    void line(const QString &text);

    // The reason on stderr in technician words; with --json also {"error":...,"code":...} on
    // stdout.
    void error(const QString &message, int exitCode, const QJsonObject &extra = {});
    // A remark on stderr that does not change the exit code.
    void note(const QString &message);

    static QString csvCell(const QString &text);

private:
    OutputFormat m_format;
    QTextStream m_out;
    QTextStream m_err;
    QStringList m_streamColumns;
    QList<int> m_streamWidths;
};

} // namespace Fatek
