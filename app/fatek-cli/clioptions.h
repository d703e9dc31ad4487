#pragma once

#include "core/protocol/address.h"
#include "core/protocol/addressrange.h"
#include "core/transport/linksettings.h"
#include "core/watch/watchlist.h"

#include <QByteArray>
#include <QList>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <optional>
#include <utility>

namespace Fatek {

// Exit codes of fatek-cli (documented in docs/cli.md).
namespace ExitCode {
inline constexpr int Ok = 0;
inline constexpr int Internal
    = 1; // the tool itself failed: a file or the output not written, the simulator could not listen
inline constexpr int Usage = 2;    // bad command line, or a request that cannot be valid
inline constexpr int Link = 3;     // timeout, no connection, broken answers
inline constexpr int Plc = 4;      // the PLC answered with an error code
inline constexpr int ReadOnly = 5; // refused by --read-only
inline constexpr int Differ = 6;   // diff found differences; restore-values read back others
// A change was sent and not answered, and reading it back could not tell whether the PLC carried
// it out (the link stayed silent or closed): check the PLC.
inline constexpr int Unknown = 7;
inline constexpr int Interrupted
    = 130; // Ctrl-C / SIGTERM before the command finished (128 + SIGINT)
inline constexpr int ClosedPipe
    = 141; // stdout's reader is gone ("| head"): ended quietly, as SIGPIPE would (128 + 13)
} // namespace ExitCode

enum class CliCommandKind {
    ShowStatus,
    Run,
    Stop,
    Read,
    Write,
    Control,
    Forced,
    Loopback,
    Monitor,
    Raw,
    Scan,
    Backup,
    Restore,
    Snapshot,
    Diff,
    RestoreValues,
    Checkout
};
enum class OutputFormat { Table, Json, Csv };

// One command of the command line (several may be chained with --then).
struct CliStep
{
    CliCommandKind command = CliCommandKind::ShowStatus;
    QString name;

    // read / write / forced / control / monitor
    QList<Address> addresses; // read of a mixed list, monitor items, else one start address
    std::uint32_t count = 1;
    bool mixed = false; // read: several addresses -> 48
    std::vector<std::uint32_t> values;
    int controlOp = 0;              // DiscreteOp value for set/reset/enable/disable
    std::uint32_t itemElements = 1; // write: the elements of one typed value (R0:float: 2)

    QByteArray loopbackData;
    QByteArray rawBytes;
    bool rawFrame = false;
    bool rawHex = false; // typed as hex: binary bytes (--frame under auto: binary framing)

    // backup / restore: the program backup file; snapshot / diff / restore-values: the files
    // (.json or .csv) and the element ranges
    QString file;
    QString file2; // diff: the second file; empty = the live PLC
    std::vector<AddressRange> ranges;

    int scanFirst = 1;
    int scanLast = 254;

    // monitor: the format asked for each address ("R0:hex"), then (after parsing) the items to
    // poll with their resolved formats (per item, else --format, else the element's default).
    QList<std::optional<DisplayFormat>> formats;
    QList<WatchItemSpec> items;
};

// Everything the command line asked for, parsed and checked (no I/O yet).
struct CliOptions
{
    bool help = false;
    bool version = false;

    bool sim = false;
    LinkSettings link; // for --sim only the protocol and timing policy count
    bool protocolGiven = false;
    bool timeoutGiven = false;
    std::uint8_t station = 1;
    bool readOnly = false;
    bool assumeYes = false;  // --yes: the confirmation of restore / restore-values is given
    bool otherModel = false; // --other-model: restore-values writes a snapshot of another model
    bool offline = false;    // diff FILE FILE2 alone: no link needed, none opened
    OutputFormat format = OutputFormat::Table;

    QList<CliStep> steps; // run in order; the first failure ends the program

    int loopbackCount = 1;
    int intervalMs = 1000;
    int cycles = 0;     // monitor: 0 = until interrupted
    QString outputPath; // monitor --output: CSV data log, appended
    QString namesPath;  // monitor --names: the ladder project's comment/symbol list
    std::optional<DisplayFormat> valueFormat; // monitor --format
    QString completion; // --completion bash|zsh: print that shell's completion script

    // checkout: the report (.pdf or .csv) and its language, the checkout file saved as it goes
    // (default: PLAN when it is a .json), the report's header
    QString checkoutReport;
    QString checkoutLanguage = QStringLiteral("en");
    QString checkoutSave;
    QString checkoutProject;
    QString checkoutCustomer;
    QString checkoutEngineer;
    // The document's identity and the signatories (the report's every page and signature block)
    QString checkoutDocument;
    QString checkoutRevision;
    QString checkoutCompany; // the engineer's
    QString checkoutWitness;
    QString checkoutWitnessCompany;
    QString checkoutSignatory; // the customer's
    QString checkoutPunch;     // the punch list as CSV
    // --crlf: every CSV file written (monitor --output, snapshot FILE.csv, checkout --report and
    // --punch) with CRLF line ends (Excel on Windows); CSV on stdout keeps LF
    bool crlf = false;
};

struct CliParseResult
{
    std::optional<CliOptions> options;
    QString error; // usage error, when options is empty
};

// Parses argv (without the program name). Options may come before or after the command; a
// leading single '-' is not an option so negative values ("write R0 -5") pass.
CliParseResult parseCommandLine(const QStringList &arguments);

QString usageText();
// The exit codes and what each means, in --help's order (the man page's EXIT STATUS is checked
// against them by packaging/check-man-commands.py).
QList<std::pair<int, QString>> exitCodeUsage();
// Whether `path` names a device or a pipe (also through a link): written directly whatever its
// name (snapshot /dev/stdout, --report /dev/full).
bool isDevice(const QString &path);
// The options that take a value and those that do not (without "--"), for the completions.
QStringList valuedOptionNames();
QStringList flagOptionNames();

} // namespace Fatek
