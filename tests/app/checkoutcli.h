#pragma once

// fatek-cli checkout as a test runs it: the built program, its answers written to its standard
// input (--yes), its standard error collected as it comes; and the checkout file it saved.
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStringList>
#include <QTest>

#ifdef Q_OS_UNIX
#include <csignal>
#endif

namespace TestUtil {

struct CheckoutCli
{
    static constexpr int longWait = 30000;

    QProcess process;
    QString err;

    void start(const QStringList &arguments)
    {
        process.start(QStringLiteral(FATEK_CLI_PATH), arguments);
    }
    // Waits until standard error has said `text` `times` times (false when the program ended
    // first or it took too long).
    bool said(const QString &text, int times = 1)
    {
        return QTest::qWaitFor(
                   [&] {
                       err += QString::fromUtf8(process.readAllStandardError());
                       return err.count(text) >= times || process.state() == QProcess::NotRunning;
                   },
                   longWait)
               && err.count(text) >= times;
    }
    void answer(const char *line) { process.write(line); }
    // The exit code, or -1 when it did not end in time.
    int exitCode()
    {
        const bool ended
            = QTest::qWaitFor([&] { return process.state() == QProcess::NotRunning; }, longWait);
        err += QString::fromUtf8(process.readAllStandardError());
        if (!ended || process.exitStatus() != QProcess::NormalExit)
            return -1;
        return process.exitCode();
    }
    void interrupt()
    {
#ifdef Q_OS_UNIX
        ::kill(static_cast<pid_t>(process.processId()), SIGINT);
#endif
    }
};

// The checkout file's "forced" list and each point's result ("untested", "passed"...), and the
// whole file.
struct SavedCheckout
{
    QStringList forced;
    QStringList results;
    QJsonObject file;

    QJsonObject point(int index) const
    {
        return file.value(QStringLiteral("points")).toArray().at(index).toObject();
    }
};

inline SavedCheckout savedCheckout(const QString &path)
{
    QFile f(path);
    SavedCheckout saved;
    if (!f.open(QIODevice::ReadOnly))
        return saved;
    saved.file = QJsonDocument::fromJson(f.readAll()).object();
    for (const QJsonValue &v : saved.file.value(QStringLiteral("forced")).toArray())
        saved.forced << v.toString();
    for (const QJsonValue &v : saved.file.value(QStringLiteral("points")).toArray())
        saved.results << v.toObject().value(QStringLiteral("result")).toString();
    return saved;
}

} // namespace TestUtil
