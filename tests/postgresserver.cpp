#include "postgresserver.h"

#include <libpq-fe.h>

#include <QCollator>
#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTcpServer>
#include <QThread>

#include <grp.h>
#include <pwd.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <optional>

namespace TestUtil {

namespace {

const char *const SuperuserPassword = "postgres-test-pw";

struct Account
{
    uid_t uid;
    gid_t gid;
};

// Whom PostgreSQL runs as: ourselves, or nobody when we are root (initdb and postgres refuse
// root).
std::optional<Account> unprivileged()
{
    if (::geteuid() != 0)
        return std::nullopt;
    const passwd *pw = ::getpwnam("nobody");
    if (!pw)
        return std::nullopt;
    return Account{pw->pw_uid, pw->pw_gid};
}

// Whether every folder from `path` up is open to others (nobody must reach the data).
bool traversable(const QString &path)
{
    for (QString dir = QFileInfo(path).absoluteFilePath(); !dir.isEmpty() && dir != u'/';
         dir = QFileInfo(dir).path()) {
        struct stat st = {};
        if (::stat(QFile::encodeName(dir).constData(), &st) != 0 || !(st.st_mode & S_IXOTH))
            return false;
    }
    return true;
}

bool chownTo(const QString &path, const Account &account)
{
    return ::chown(QFile::encodeName(path).constData(), account.uid, account.gid) == 0;
}

// The process ids whose parent is `parent` (the server's backends), from /proc.
QList<pid_t> childrenOf(pid_t parent)
{
    QList<pid_t> children;
    const QStringList entries = QDir(QStringLiteral("/proc")).entryList(QDir::Dirs);
    for (const QString &entry : entries) {
        bool number = false;
        const pid_t pid = entry.toInt(&number);
        if (!number)
            continue;
        QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
        if (!stat.open(QIODevice::ReadOnly))
            continue;
        const QByteArray text = stat.readAll();
        // "pid (name) state ppid ...": the name may hold spaces and parentheses.
        const QList<QByteArray> fields = text.mid(text.lastIndexOf(')') + 2).split(' ');
        if (fields.size() > 1 && fields[1].toInt() == parent)
            children.append(pid);
    }
    return children;
}

// Gone, or a zombie: it no longer holds the server's shared memory.
bool ended(pid_t pid)
{
    QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!stat.open(QIODevice::ReadOnly))
        return true;
    const QByteArray text = stat.readAll();
    const qsizetype close = text.lastIndexOf(')');
    return close < 0 || text.mid(close + 2, 1) == "Z";
}

// A superuser's connection; its notices ("database ... does not exist, skipping") unprinted.
PGconn *connect(quint16 port, const QString &database);

QString conninfo(quint16 port, const QString &database)
{
    return QStringLiteral("host=127.0.0.1 port=%1 user=postgres password=%2 dbname=%3 "
                          "connect_timeout=5")
        .arg(port)
        .arg(QLatin1String(SuperuserPassword), database);
}

PGconn *connect(quint16 port, const QString &database)
{
    PGconn *conn = PQconnectdb(conninfo(port, database).toUtf8().constData());
    if (conn)
        PQsetNoticeProcessor(
            conn, [](void *, const char *) {}, nullptr);
    return conn;
}

} // namespace

PostgresServer::PostgresServer() = default;

PostgresServer::~PostgresServer()
{
    stop();
}

QString PostgresServer::binDirectory()
{
    const QDir root(QStringLiteral("/usr/lib/postgresql"));
    QStringList versions = root.entryList(QDir::Dirs | QDir::NoDotAndDotDot);
    QCollator numeric;
    numeric.setNumericMode(true);
    std::sort(versions.begin(), versions.end(),
              [&](const QString &a, const QString &b) { return numeric.compare(a, b) > 0; });
    for (const QString &version : versions) {
        const QString bin = root.filePath(version + QStringLiteral("/bin"));
        if (QFileInfo::exists(bin + QStringLiteral("/postgres"))
            && QFileInfo::exists(bin + QStringLiteral("/initdb")))
            return bin;
    }
    return {};
}

QString PostgresServer::dataDirectory() const
{
    return m_dir->filePath(QStringLiteral("data"));
}

QString PostgresServer::url(const QString &database, const QString &password) const
{
    return QStringLiteral("postgresql://%1:%2@127.0.0.1:%3/%4")
        .arg(user(), password)
        .arg(m_port)
        .arg(database);
}

QString PostgresServer::log() const
{
    if (!m_dir)
        return {};
    QFile file(m_dir->filePath(QStringLiteral("postgres.log")));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(file.readAll().right(4000));
}

void PostgresServer::prepare(QProcess &process) const
{
    process.setWorkingDirectory(m_dir->path());
    if (const std::optional<Account> account = unprivileged()) {
        const Account a = *account;
        // In the child, before exec: only async-signal-safe calls.
        process.setChildProcessModifier([a] {
            if (::setgroups(0, nullptr) != 0 || ::setgid(a.gid) != 0 || ::setuid(a.uid) != 0)
                ::_exit(126);
        });
    }
}

bool PostgresServer::run(const QString &program, const QStringList &arguments, QString *error) const
{
    QProcess process;
    prepare(process);
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(binDirectory() + u'/' + program, arguments);
    if (process.waitForFinished(120000) && process.exitStatus() == QProcess::NormalExit
        && process.exitCode() == 0)
        return true;
    *error = QStringLiteral("%1 failed (exit %2, %3): %4")
                 .arg(program)
                 .arg(process.exitCode())
                 .arg(process.errorString(), QString::fromLocal8Bit(process.readAll()));
    return false;
}

bool PostgresServer::initialize(QString *error)
{
    if (binDirectory().isEmpty()) {
        *error
            = QStringLiteral("PostgreSQL is not installed (no /usr/lib/postgresql/*/bin/postgres; "
                             "tools/install-deps.sh installs it)");
        return false;
    }
    const std::optional<Account> account = unprivileged();
    if (::geteuid() == 0 && !account) {
        *error = QStringLiteral("running as root and there is no user nobody to run PostgreSQL as");
        return false;
    }
    // As root, the folder must be reachable by nobody: the system's temporary folder if every
    // folder above it is open to others, else /tmp.
    QString base = QDir::tempPath();
    if (account && !traversable(base))
        base = QStringLiteral("/tmp");
    m_dir = std::make_unique<QTemporaryDir>(base + QStringLiteral("/fatek-pg-XXXXXX"));
    if (!m_dir->isValid()) {
        *error = QStringLiteral("cannot make a temporary folder in %1: %2")
                     .arg(base, m_dir->errorString());
        return false;
    }
    const QString pwfile = m_dir->filePath(QStringLiteral("pwfile"));
    QFile file(pwfile);
    if (!file.open(QIODevice::WriteOnly) || file.write(SuperuserPassword) < 0) {
        *error = QStringLiteral("cannot write %1").arg(pwfile);
        return false;
    }
    file.close();
    if (account && (!chownTo(m_dir->path(), *account) || !chownTo(pwfile, *account))) {
        *error = QStringLiteral("cannot give %1 to nobody: %2")
                     .arg(m_dir->path(), QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    }
    // C locale and UTF-8: the same server whatever the machine's locale (a fresh root has none).
    if (!run(QStringLiteral("initdb"),
             {QStringLiteral("-D"), dataDirectory(), QStringLiteral("-U"),
              QStringLiteral("postgres"), QStringLiteral("--pwfile=") + pwfile,
              QStringLiteral("--auth=scram-sha-256"), QStringLiteral("--locale=C"),
              QStringLiteral("-E"), QStringLiteral("UTF8"), QStringLiteral("--no-sync")},
             error))
        return false;
    return true;
}

bool PostgresServer::pickPort(QString *error)
{
    // A port nobody listens on now; the server binds it a moment later.
    QTcpServer probe;
    if (!probe.listen(QHostAddress::LocalHost, 0)) {
        *error = QStringLiteral("no free port: %1").arg(probe.errorString());
        return false;
    }
    m_port = probe.serverPort();
    return true;
}

bool PostgresServer::start(QString *error)
{
    stop();
    const bool first = !m_initialized;
    if (first && (!initialize(error) || !pickPort(error)))
        return false;
    m_initialized = true;
    // Another program may take the free port between the probe and the bind: a new one then,
    // at the first start (later starts keep theirs: the test's URLs name it).
    for (int attempt = 1;; ++attempt) {
        if (!launch(error))
            return false;
        if (waitUntilReady(error))
            break;
        if (!first || attempt == 3 || !log().contains(QLatin1String("could not bind"))
            || !pickPort(error))
            return false;
    }
    if (first
        && !exec(QStringLiteral("postgres"),
                 QStringLiteral("CREATE ROLE %1 LOGIN PASSWORD '%2'").arg(user(), password()),
                 error))
        return false;
    return true;
}

bool PostgresServer::launch(QString *error)
{
    m_process = std::make_unique<QProcess>();
    prepare(*m_process);
    m_process->setProcessChannelMode(QProcess::MergedChannels);
    m_process->setStandardOutputFile(m_dir->filePath(QStringLiteral("postgres.log")),
                                     QIODevice::Append);
    // fsync off: the tests kill the server, never the machine (the page cache survives); small
    // buffers: the machine is shared.
    m_process->start(binDirectory() + QStringLiteral("/postgres"),
                     {QStringLiteral("-D"), dataDirectory(), QStringLiteral("-p"),
                      QString::number(m_port), QStringLiteral("-k"), m_dir->path(),
                      QStringLiteral("-c"), QStringLiteral("listen_addresses=127.0.0.1"),
                      QStringLiteral("-c"), QStringLiteral("fsync=off"), QStringLiteral("-c"),
                      QStringLiteral("shared_buffers=32MB"), QStringLiteral("-c"),
                      QStringLiteral("max_connections=40")});
    if (!m_process->waitForStarted(5000)) {
        *error = QStringLiteral("postgres did not start: %1").arg(m_process->errorString());
        m_process.reset();
        return false;
    }
    return true;
}

bool PostgresServer::waitUntilReady(QString *error)
{
    // Crash recovery after kill() takes a moment; a slow CI machine, more.
    const QByteArray info = conninfo(m_port, QStringLiteral("postgres")).toUtf8();
    const QDeadlineTimer deadline(30000);
    while (PQping(info.constData()) != PQPING_OK) {
        if (m_process->state() != QProcess::Running) {
            *error = QStringLiteral("postgres exited (code %1): %2")
                         .arg(m_process->exitCode())
                         .arg(log());
            m_process.reset();
            return false;
        }
        if (deadline.hasExpired()) {
            *error
                = QStringLiteral("postgres did not accept connections on port %1 within 30 s: %2")
                      .arg(m_port)
                      .arg(log());
            stop();
            return false;
        }
        QThread::msleep(50);
    }
    return true;
}

bool PostgresServer::isRunning() const
{
    return m_process && m_process->state() == QProcess::Running;
}

void PostgresServer::stop()
{
    if (!m_process)
        return;
    if (m_process->state() != QProcess::NotRunning) {
        ::kill(pid_t(m_process->processId()), SIGINT); // pg_ctl stop -m fast
        if (!m_process->waitForFinished(10000))
            return kill();
    }
    m_process.reset();
}

void PostgresServer::kill()
{
    if (!m_process)
        return;
    if (m_process->state() != QProcess::NotRunning) {
        const pid_t server = pid_t(m_process->processId());
        const QList<pid_t> backends = childrenOf(server);
        // The server first, so that it starts no new backend; then each backend, which would
        // otherwise notice its server's death later, holding the shared memory the next start
        // needs free.
        ::kill(server, SIGKILL);
        for (const pid_t pid : backends)
            ::kill(pid, SIGKILL);
        m_process->waitForFinished(5000);
        const QDeadlineTimer deadline(5000);
        for (const pid_t pid : backends) {
            while (!ended(pid) && !deadline.hasExpired())
                QThread::msleep(10);
        }
    }
    m_process.reset();
}

bool PostgresServer::exec(const QString &database, const QString &sql, QString *error) const
{
    PGconn *conn = connect(m_port, database);
    bool ok = PQstatus(conn) == CONNECTION_OK;
    if (ok) {
        PGresult *result = PQexec(conn, sql.toUtf8().constData());
        const ExecStatusType status = PQresultStatus(result);
        ok = status == PGRES_COMMAND_OK || status == PGRES_TUPLES_OK;
        PQclear(result);
    }
    if (!ok)
        *error
            = QStringLiteral("%1: %2").arg(sql, QString::fromUtf8(PQerrorMessage(conn)).trimmed());
    PQfinish(conn);
    return ok;
}

QString PostgresServer::value(const QString &database, const QString &sql) const
{
    PGconn *conn = connect(m_port, database);
    QString answer;
    PGresult *result
        = PQstatus(conn) == CONNECTION_OK ? PQexec(conn, sql.toUtf8().constData()) : nullptr;
    if (PQresultStatus(result) == PGRES_TUPLES_OK && PQntuples(result) > 0)
        answer = QString::fromUtf8(PQgetvalue(result, 0, 0));
    else if (PQresultStatus(result) != PGRES_TUPLES_OK)
        answer = QStringLiteral("ERROR: ") + QString::fromUtf8(PQerrorMessage(conn)).trimmed();
    PQclear(result);
    PQfinish(conn);
    return answer;
}

bool PostgresServer::createDatabase(const QString &name, QString *error) const
{
    // Two statements: neither runs in a transaction block (one PQexec of both would be one).
    return exec(QStringLiteral("postgres"),
                QStringLiteral("DROP DATABASE IF EXISTS %1 WITH (FORCE)").arg(name), error)
           && exec(QStringLiteral("postgres"),
                   QStringLiteral("CREATE DATABASE %1 OWNER %2").arg(name, user()), error);
}

} // namespace TestUtil
