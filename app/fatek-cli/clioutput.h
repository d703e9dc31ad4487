#pragma once

#include "core/protocol/message.h"

#include "clioptions.h"

#include <QJsonObject>
#include <QList>
#include <QString>
#include <QStringList>
#include <QTextStream>
#include <QVariant>

#include <functional>

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
//
// Every write to stdout is checked. When stdout cannot take more, nothing more is written to it
// and failed() says how: a closed pipe (the reader is gone, as with "| head") ends the program
// quietly with ExitCode::ClosedPipe; any other failure (a full disk, /dev/full) is said once on
// stderr ("Cannot write the output: No space left on device") and ends it with
// ExitCode::Internal. The owner hears of it through setOnFailure (to end a monitor at once).
class CliOutput
{
public:
    enum class Failure { None, ClosedPipe, WriteError };

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

    Failure failure() const { return m_failure; }
    // The exit code a failed stdout ends the program with (ExitCode::Ok while it works).
    int failureExitCode() const;
    // Called once, at the first failed write to stdout.
    void setOnFailure(std::function<void()> onFailure) { m_onFailure = std::move(onFailure); }

    // Writes all of `bytes` to stdout (unbuffered); an empty text when written, else the reason
    // from the system, and *closedPipe tells whether the reader is gone (EPIPE).
    static QString writeStdout(const QByteArray &bytes, bool *closedPipe = nullptr);
    // --help, --version: stdout without a CliOutput; the exit code (Ok, or the failure's).
    static int printStdout(const QString &text);
    // The refusal of a command line for the programs of their own (alarms, history): on stderr
    // with the hint to --help, and with --json also as {"error","code"} on stdout; ExitCode::Usage.
    static int usageError(const QString &error, bool json);
    // A failure with its reason in English, the same two ways; returns `code`.
    static int failure(const Fatek::Message &reason, int code, bool json);

private:
    void write(const QString &text);

    OutputFormat m_format;
    Failure m_failure = Failure::None;
    std::function<void()> m_onFailure;
    QTextStream m_err;
    QStringList m_streamColumns;
    QList<int> m_streamWidths;
};

} // namespace Fatek
