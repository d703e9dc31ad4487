#pragma once

#include <QProcess>
#include <QString>
#include <QTemporaryDir>

#include <memory>

namespace TestUtil {

// A real PostgreSQL server for one test: initdb into a temporary folder, postgres on 127.0.0.1
// and a free port, password (SCRAM) logins only. Its superuser is "postgres"; the tests log in
// as "fatek", an ordinary role owning the databases createDatabase() makes, as a gateway's role
// would. PostgreSQL refuses to run as root: as root (CI's fresh Debian root) the server and
// initdb run as the user nobody, which owns the folder. Stopped with the object.
class PostgresServer
{
public:
    PostgresServer();
    ~PostgresServer();

    // Starts the server (the first start runs initdb and picks the port; later starts reuse
    // both, so data survives kill() and start()) and waits until it accepts logins. False with
    // `error` set when PostgreSQL is not installed or does not come up.
    bool start(QString *error);
    // A fast shutdown (SIGINT: clients are disconnected), SIGKILL after 10 s.
    void stop();
    // SIGKILL to the server and every process of it: as if its machine lost power.
    void kill();
    bool isRunning() const;

    quint16 port() const { return m_port; }
    static QString user() { return QStringLiteral("fatek"); }
    static QString password() { return QStringLiteral("fatek-test-pw"); }
    // postgresql://fatek:<password>@127.0.0.1:<port>/<database>
    QString url(const QString &database,
                const QString &password = PostgresServer::password()) const;
    // Runs SQL as the superuser in `database`; false with `error` set when it fails.
    bool exec(const QString &database, const QString &sql, QString *error) const;
    // The first value `sql` returns ("" for NULL), run as the superuser; "ERROR: <reason>" when
    // it fails, so that a comparison shows why.
    QString value(const QString &database, const QString &sql) const;
    // A new, empty database owned by user(), dropped first if it exists.
    bool createDatabase(const QString &name, QString *error) const;
    // What the server wrote (for failure messages).
    QString log() const;

    // /usr/lib/postgresql/<newest version>/bin; empty when PostgreSQL is not installed.
    static QString binDirectory();

private:
    bool initialize(QString *error);
    bool pickPort(QString *error);
    // Starts postgres; waits until it accepts connections (false: it exited or did not in 30 s).
    bool launch(QString *error);
    bool waitUntilReady(QString *error);
    // Runs one of PostgreSQL's programs to its end (as nobody when we are root).
    bool run(const QString &program, const QStringList &arguments, QString *error) const;
    void prepare(QProcess &process) const;
    QString dataDirectory() const;

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<QProcess> m_process;
    quint16 m_port = 0;
    bool m_initialized = false;
};

} // namespace TestUtil
