#include "mosquittobroker.h"

#include "testutil.h"

#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTcpSocket>
#include <QThread>

#ifdef Q_OS_UNIX
#include <unistd.h>
#endif
#ifdef Q_OS_WIN
#include <QRegularExpression>
#endif

namespace TestUtil {

namespace {

#ifdef Q_OS_WIN
// The broker under Wine is a Linux program: it reads Unix paths (hostPath()).
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
QString hostPaths(const QString &text)
{
    return text;
}
#endif

} // namespace

// Under Wine the broker is a Linux program, which a Windows program can neither signal nor
// kill (QProcess::terminate() and kill() do nothing to it, and its QProcess may say it ended at
// once), and a broker left running holds CTest's output pipe open, so CTest waits for the test
// until its time-out. A Linux shell starts it instead and ends it when the test writes "term" or
// "kill" into the file $3, or when that file's folder (the broker's QTemporaryDir) is gone. Wine
// gives a Linux child no standard input to be told through, and no parent to watch (its parent
// is init).
const char *const wineWrapper
    = "\"$1\" -c \"$2\" & pid=$!; dir=$(dirname \"$3\"); how=; "
      "while kill -0 $pid 2>/dev/null; do "
      "if [ -s \"$3\" ]; then how=$(cat \"$3\"); break; fi; "
      "[ -d \"$dir\" ] || { how=term; break; }; sleep 0.1; done; "
      "case $how in kill) kill -KILL $pid ;; term) kill -TERM $pid ;; esac 2>/dev/null; "
      "wait $pid";

MosquittoBroker::MosquittoBroker() = default;

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

bool MosquittoBroker::startWithTls(QString *error)
{
    const QString openssl = QStandardPaths::findExecutable(QStringLiteral("openssl"));
    if (openssl.isEmpty()) {
        *error = QStringLiteral("openssl is not installed (tools/install-deps.sh installs it)");
        return false;
    }
    const QDir dir(m_dir.path());
    const auto run = [&](const QStringList &args) {
        QProcess p;
        p.setWorkingDirectory(dir.path());
        p.setProcessChannelMode(QProcess::MergedChannels);
        p.start(openssl, args);
        if (p.waitForFinished(30000) && p.exitCode() == 0)
            return true;
        *error = QStringLiteral("openssl %1: %2")
                     .arg(args.join(QLatin1Char(' ')), QString::fromLocal8Bit(p.readAll()));
        return false;
    };
    const QStringList ec{QStringLiteral("-newkey"), QStringLiteral("ec"),
                         QStringLiteral("-pkeyopt"), QStringLiteral("ec_paramgen_curve:prime256v1"),
                         QStringLiteral("-nodes")};
    for (const QString &name : {QStringLiteral("ca"), QStringLiteral("other")}) {
        if (!run(QStringList{QStringLiteral("req"), QStringLiteral("-x509")} + ec
                 + QStringList{QStringLiteral("-keyout"), name + QStringLiteral(".key"),
                               QStringLiteral("-out"), name + QStringLiteral(".crt"),
                               QStringLiteral("-days"), QStringLiteral("2"),
                               QStringLiteral("-subj"), QStringLiteral("/CN=test ") + name}))
            return false;
    }
    QFile ext(dir.filePath(QStringLiteral("ext.cnf")));
    if (!ext.open(QIODevice::WriteOnly)) {
        *error = QStringLiteral("cannot write %1").arg(ext.fileName());
        return false;
    }
    ext.write("subjectAltName=IP:127.0.0.1\n");
    ext.close();
    // The broker's certificate (for 127.0.0.1) and the client's, both signed by ca.
    for (const QString &name : {QStringLiteral("server"), QStringLiteral("client")}) {
        QStringList sign{QStringLiteral("x509"),
                         QStringLiteral("-req"),
                         QStringLiteral("-in"),
                         name + QStringLiteral(".csr"),
                         QStringLiteral("-CA"),
                         QStringLiteral("ca.crt"),
                         QStringLiteral("-CAkey"),
                         QStringLiteral("ca.key"),
                         QStringLiteral("-CAcreateserial"),
                         QStringLiteral("-out"),
                         name + QStringLiteral(".crt"),
                         QStringLiteral("-days"),
                         QStringLiteral("2")};
        if (name == QStringLiteral("server"))
            sign << QStringLiteral("-extfile") << QStringLiteral("ext.cnf");
        if (!run(QStringList{QStringLiteral("req")} + ec
                 + QStringList{QStringLiteral("-keyout"), name + QStringLiteral(".key"),
                               QStringLiteral("-out"), name + QStringLiteral(".csr"),
                               QStringLiteral("-subj"),
                               name == QStringLiteral("server") ? QStringLiteral("/CN=127.0.0.1")
                                                                : QStringLiteral("/CN=studio")})
            || !run(sign))
            return false;
    }
    return start(error, QStringLiteral("cafile %1\ncertfile %2\nkeyfile %3\n"
                                       "require_certificate true\n")
                            .arg(dir.filePath(QStringLiteral("ca.crt")),
                                 dir.filePath(QStringLiteral("server.crt")),
                                 dir.filePath(QStringLiteral("server.key"))));
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
    m_underWine = underWine();
    QFile::remove(stopFile());
    if (m_underWine)
        m_process->start(QStringLiteral("/bin/bash"),
                         {QStringLiteral("-c"), QString::fromLatin1(wineWrapper),
                          QStringLiteral("mosquitto-wrapper"), program, hostPath(configPath),
                          hostPath(stopFile())});
    else
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
    *error = QStringLiteral("mosquitto did not listen on port %1 within 10 s: %2 %3")
                 .arg(m_port)
                 .arg(QString::fromUtf8(m_process->readAll()), log());
    stop();
    return false;
}

QString MosquittoBroker::stopFile() const
{
    return m_dir.filePath(QStringLiteral("mosquitto.stop"));
}

void MosquittoBroker::tellWrapper(const char *how) const
{
    QFile file(stopFile());
    if (file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        file.write(how);
}

void MosquittoBroker::stopUnderWine(const char *how)
{
    tellWrapper(how);
    // Stopped when nothing listens on its port any more.
    const QDeadlineTimer deadline(5000);
    while (!deadline.hasExpired()) {
        QTcpSocket socket;
        socket.connectToHost(QHostAddress::LocalHost, m_port);
        if (!socket.waitForConnected(200))
            break;
        socket.abort();
        QThread::msleep(50);
    }
    m_process.reset();
}

void MosquittoBroker::stop()
{
    if (!m_process)
        return;
    if (m_underWine)
        return stopUnderWine("term");
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
    if (m_underWine)
        return stopUnderWine("kill");
    m_process->kill();
    m_process->waitForFinished(2000);
    m_process.reset();
}

} // namespace TestUtil
