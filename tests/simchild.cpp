#include "simchild.h"

#include "testutil.h"

#include <QDeadlineTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>

#ifdef Q_OS_UNIX
#include <csignal>
#endif

namespace TestUtil {

SimChild::~SimChild()
{
    if (m_process.state() == QProcess::NotRunning)
        return;
    resume();
    stopConsoleProgram(&m_process);
    if (!m_process.waitForFinished(10000))
        m_process.kill();
    m_process.waitForFinished();
}

bool SimChild::start(const QString &simPath, bool stopped, const QStringList &extra, QString *error)
{
    QStringList arguments{QStringLiteral("--tcp"), QStringLiteral("0")};
    if (stopped)
        arguments << QStringLiteral("--stopped");
    startConsoleProgram(&m_process, simPath, arguments + extra);
    if (!m_process.waitForStarted(10000)) {
        if (error)
            *error = QStringLiteral("fatek-sim did not start: %1").arg(m_process.errorString());
        return false;
    }
    // "listening on tcp 127.0.0.1:41735"
    static const QRegularExpression listening(QStringLiteral("listening on tcp [^:]+:(\\d+)"));
    QByteArray out;
    const QDeadlineTimer deadline(20000);
    while (m_port == 0 && !deadline.hasExpired() && m_process.state() != QProcess::NotRunning) {
        m_process.waitForReadyRead(200);
        out += m_process.readAllStandardOutput();
        const auto match = listening.match(QString::fromUtf8(out));
        if (match.hasMatch())
            m_port = static_cast<quint16>(match.captured(1).toUInt());
    }
    if (m_port == 0 && error)
        *error
            = QStringLiteral("fatek-sim gave no port: %1 %2")
                  .arg(QString::fromUtf8(out), QString::fromUtf8(m_process.readAllStandardError()));
    return m_port != 0;
}

QStringList SimChild::link() const
{
    return {QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:%1").arg(m_port)};
}

bool SimChild::pause()
{
#ifdef Q_OS_UNIX
    m_paused = ::kill(static_cast<pid_t>(m_process.processId()), SIGSTOP) == 0;
    return m_paused;
#else
    return false;
#endif
}

bool SimChild::resume()
{
#ifdef Q_OS_UNIX
    if (!m_paused)
        return true;
    m_paused = false;
    return ::kill(static_cast<pid_t>(m_process.processId()), SIGCONT) == 0;
#else
    return false;
#endif
}

std::vector<int> SimChild::forced(const QString &cliPath, const QString &start, int count) const
{
    const ProgramRun run
        = runProgram(cliPath, link()
                                  + QStringList{QStringLiteral("--json"), QStringLiteral("forced"),
                                                start, QString::number(count)});
    const QJsonArray flags = run.json().value(QStringLiteral("forced")).toArray();
    if (run.code != 0 || flags.size() != count) {
        qWarning("fatek-cli forced: exit %d: %s %s", run.code, qPrintable(run.out),
                 qPrintable(run.err));
        return {};
    }
    std::vector<int> result;
    for (const QJsonValue &v : flags)
        result.push_back(v.toInt());
    return result;
}

} // namespace TestUtil
