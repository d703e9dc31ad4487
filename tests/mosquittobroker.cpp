#include "mosquittobroker.h"

#include <QDeadlineTimer>
#include <QFile>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTcpSocket>
#include <QThread>

#ifdef Q_OS_UNIX
#include <unistd.h>
#endif
#ifdef Q_OS_WIN
#include <QDir>
#include <QRegularExpression>

#include <windows.h>
#endif

namespace TestUtil {

namespace {

#ifdef Q_OS_WIN
// The Windows build's tests run under Wine (tools/windows/test.sh), where the broker is the host's
// Linux mosquitto (Wine starts Unix programs too). It reads Unix paths: Wine's kernel32 converts
// the Windows paths of its configuration. On Windows itself the function is absent and paths stay.
QString hostPath(const QString &path)
{
    using ToUnix = char *(*)(const wchar_t *);
    static const auto toUnix = reinterpret_cast<ToUnix>(reinterpret_cast<void (*)()>(
        GetProcAddress(GetModuleHandleW(L"kernel32.dll"), "wine_get_unix_file_name")));
    if (!toUnix)
        return path;
    const std::wstring native = QDir::toNativeSeparators(path).toStdWString();
    char *unixPath = toUnix(native.c_str());
    if (!unixPath)
        return path;
    const QString result = QString::fromUtf8(unixPath);
    HeapFree(GetProcessHeap(), 0, unixPath);
    return result;
}

bool underWine()
{
    return GetProcAddress(GetModuleHandleW(L"kernel32.dll"), "wine_get_unix_file_name") != nullptr;
}

QString hostPaths(const QString &text)
{
    static const QRegularExpression drivePath(QStringLiteral("[A-Za-z]:[/\\\\][^\\s]*"));
    QString result;
    qsizetype last = 0;
    for (const QRegularExpressionMatch &m : drivePath.globalMatch(text)) {
        result += text.mid(last, m.capturedStart() - last) + hostPath(m.captured());
        last = m.capturedEnd();
    }
    return result + text.mid(last);
}
#else
QString hostPath(const QString &path)
{
    return path;
}
QString hostPaths(const QString &text)
{
    return text;
}
#endif

} // namespace

MosquittoBroker::MosquittoBroker() = default;

bool MosquittoBroker::canStop()
{
#ifdef Q_OS_WIN
    return !underWine();
#else
    return true;
#endif
}

MosquittoBroker::~MosquittoBroker()
{
    stop();
}

QString MosquittoBroker::executable()
{
    if (QFile::exists(QStringLiteral("/usr/sbin/mosquitto")))
        return QStringLiteral("/usr/sbin/mosquitto");
    return QStandardPaths::findExecutable(QStringLiteral("mosquitto"));
}

QString MosquittoBroker::url() const
{
    return QStringLiteral("mqtt://127.0.0.1:%1").arg(m_port);
}

bool MosquittoBroker::isRunning() const
{
    return m_process && m_process->state() == QProcess::Running;
}

qint64 MosquittoBroker::processId() const
{
    return isRunning() ? m_process->processId() : 0;
}

QString MosquittoBroker::log() const
{
    QFile file(m_dir.filePath(QStringLiteral("mosquitto.log")));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(file.readAll());
}

bool MosquittoBroker::start(QString *error, const QString &extraConfig)
{
    stop();
    const QString program = executable();
    if (program.isEmpty()) {
        *error = QStringLiteral("mosquitto is not installed (tools/install-deps.sh installs it)");
        return false;
    }
    if (m_port == 0) {
        // A port nobody listens on now; the broker binds it a moment later.
        QTcpServer probe;
        if (!probe.listen(QHostAddress::LocalHost, 0)) {
            *error = QStringLiteral("no free port: %1").arg(probe.errorString());
            return false;
        }
        m_port = probe.serverPort();
    }
    const QString configPath = m_dir.filePath(QStringLiteral("mosquitto.conf"));
    QFile config(configPath);
    if (!config.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        *error = QStringLiteral("cannot write %1").arg(configPath);
        return false;
    }
    QString text = QStringLiteral("listener %1 127.0.0.1\n"
                                  "persistence false\n"
                                  "log_dest file %2\n"
                                  "log_type error\nlog_type warning\nlog_type notice\n"
                                  "log_type information\n"
                                  "max_queued_messages 100000\n")
                       .arg(m_port)
                       .arg(m_dir.filePath(QStringLiteral("mosquitto.log")));
    // Started as root, mosquitto switches to the user "mosquitto", which cannot write the log in
    // our private directory; it then resets every connection (seen in a fresh Debian root).
#ifdef Q_OS_UNIX
    if (::geteuid() == 0)
        text += QStringLiteral("user root\n");
#else
    // Under Wine the broker is a Linux program, possibly started as root (a Windows mosquitto
    // ignores the option; a Linux one not started as root too).
    text += QStringLiteral("user root\n");
#endif
    if (!extraConfig.contains(QStringLiteral("allow_anonymous")))
        text += QStringLiteral("allow_anonymous true\n");
    text += extraConfig + u'\n';
    config.write(hostPaths(text).toUtf8());
    config.close();

    m_process = std::make_unique<QProcess>();
    m_process->setProcessChannelMode(QProcess::MergedChannels);
    m_process->start(program, {QStringLiteral("-c"), hostPath(configPath)});
    if (!m_process->waitForStarted(5000)) {
        *error = QStringLiteral("mosquitto did not start: %1").arg(m_process->errorString());
        m_process.reset();
        return false;
    }
    const QDeadlineTimer deadline(10000);
    while (!deadline.hasExpired()) {
        if (m_process->state() != QProcess::Running) {
            *error = QStringLiteral("mosquitto exited: %1 %2")
                         .arg(QString::fromUtf8(m_process->readAll()), log());
            m_process.reset();
            return false;
        }
        QTcpSocket socket;
        socket.connectToHost(QHostAddress::LocalHost, m_port);
        if (socket.waitForConnected(200)) {
            socket.abort();
            return true;
        }
        QThread::msleep(20);
    }
    *error = QStringLiteral("mosquitto did not listen on port %1 within 10 s: %2")
                 .arg(m_port)
                 .arg(log());
    stop();
    return false;
}

void MosquittoBroker::stop()
{
    if (!m_process)
        return;
    if (m_process->state() != QProcess::NotRunning) {
        m_process->terminate();
        if (!m_process->waitForFinished(5000)) {
            m_process->kill();
            m_process->waitForFinished(2000);
        }
    }
    m_process.reset();
}

void MosquittoBroker::kill()
{
    if (!m_process)
        return;
    m_process->kill();
    m_process->waitForFinished(2000);
    m_process.reset();
}

} // namespace TestUtil
