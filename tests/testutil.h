#pragma once

#include "core/protocol/request.h"

#include <QByteArray>
#include <QJsonObject>
#include <QList>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

class QProcess;

#include <cstring>
#include <memory>
#include <span>

namespace TestUtil {

struct Vector
{
    QString what;
    Fatek::Bytes query;
    Fatek::Bytes response;
};

// "R100" -> the address (the text must parse: a test's own constant).
inline Fatek::Address addr(const char *text)
{
    return *Fatek::Address::parse(text);
}

// The IEEE-754 bits of a float, as a float over R(n) holds them (low word in R(n)).
inline std::uint32_t floatBits(float value)
{
    std::uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

// Frames of tests/data/vectors.json for "binary" or "facon".
QList<Vector> loadVectors(const QString &protocol);

// "51 10 00 02" -> bytes.
Fatek::Bytes fromHex(const QString &hex);
// "<STX>0140C7<ETX>" -> bytes (only <STX> and <ETX> are recognised).
Fatek::Bytes fromFacon(const QString &text);
// Bytes -> "51 10 00 02" for failure messages.
QString toHex(std::span<const std::uint8_t> bytes);
// Bytes -> "<STX>0140C7<ETX>".
QString toFacon(std::span<const std::uint8_t> bytes);

// Points QSettings at INI files in `directory` under the test's own application name, so the
// developer's own settings never leak into a test (nor a test's into them).
void useTestSettings(const QString &directory, const QString &applicationName);

// True when a Windows test program runs under Wine (tools/windows/test.sh).
bool underWine();
// Under Wine, the Unix path of a Windows path, for a Linux program the test starts (Wine starts
// those too); elsewhere the path as it is.
QString hostPath(const QString &path);

// Starts a console program (fatek-gateway, fatek-sim) so that stopConsoleProgram() can ask it to
// stop as a user would. On Windows it gets a process group of its own, the target of a Ctrl-Break.
void startConsoleProgram(QProcess *process, const QString &program, const QStringList &arguments);
// Starts `socat` with a pty pair linked at `a` and `b` (stopped when the last copy goes); null
// when socat is missing or fails.
std::shared_ptr<QProcess> startPtyPair(const QString &a, const QString &b);

// SIGTERM on Unix; on Windows a Ctrl-Break (QProcess::terminate() sends WM_CLOSE there, which a
// console program, having no window, never gets). The program's stop path is the same as for a
// user's Ctrl-C.
void stopConsoleProgram(QProcess *process);

// One run of a command-line program: exit code (-1: did not start or end in time, -2: crashed),
// standard output and error.
struct ProgramRun
{
    int code = -1;
    QString out;
    QString err;

    QStringList lines() const;
    // The first line of standard output as a JSON object.
    QJsonObject json() const;
};

// Runs `program` with the event loop turning (an in-process simulator keeps answering); standard
// input is a pipe, not a terminal. Killed after `timeoutMs`.
ProgramRun runProgram(const QString &program, const QStringList &arguments, int timeoutMs = 30000);
// Runs `program` with `input` on its standard input (then closed) in the environment `env`,
// waiting for it (no event loop: for programs that need nothing of the test). Killed after
// `timeoutMs`.
ProgramRun runProgramWith(const QString &program, const QStringList &arguments,
                          const QByteArray &input,
                          const QProcessEnvironment &env = QProcessEnvironment::systemEnvironment(),
                          int timeoutMs = 60000);

// A small tmpfs mounted for a test (a full or read-only disk for real; needs root and the right
// to mount), unmounted when it goes.
class TmpfsMount
{
public:
    TmpfsMount() = default;
    TmpfsMount(const TmpfsMount &) = delete;
    TmpfsMount &operator=(const TmpfsMount &) = delete;
    ~TmpfsMount();
    // Mounts `kilobytes` at `dir` (created); an empty text when mounted, else why not.
    QString mount(const QString &dir, int kilobytes);
    // Makes it read-only (what was written stays readable); an empty text when done.
    QString makeReadOnly();

private:
    QString m_dir;
};

} // namespace TestUtil
