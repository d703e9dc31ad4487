#pragma once

#include <QProcess>
#include <QString>
#include <QTemporaryDir>

#include <memory>

namespace TestUtil {

// A real Mosquitto broker for one test, on 127.0.0.1 and a free port, with a configuration the
// test writes (anonymous access unless `extraConfig` says otherwise, no persistence: a restart
// forgets every retained message, as a broker that lost its disk would). Stopped with the object.
class MosquittoBroker
{
public:
    MosquittoBroker();
    ~MosquittoBroker();

    // Starts the broker (the first start picks the port; later starts reuse it) and waits until it
    // accepts connections. `extraConfig` is appended to the listener's configuration
    // ("password_file ...", "allow_anonymous false", TLS lines). False with `error` set when the
    // broker is not installed or does not come up.
    bool start(QString *error, const QString &extraConfig = {});
    // Starts the broker with TLS and a client certificate required (mosquitto's
    // require_certificate), after writing test certificates with openssl into directory():
    // ca.crt (signed the broker's and client.crt/client.key), other.crt (a CA that signed
    // nothing here). The broker's certificate names 127.0.0.1. False with `error` set when
    // openssl is missing or a step fails.
    bool startWithTls(QString *error);
    // SIGTERM and wait: the broker closes its clients' connections.
    void stop();
    // SIGKILL: as if the broker's machine lost power.
    void kill();
    bool isRunning() const;
    // The broker's process id (0 when not running), for CPU and memory figures.
    qint64 processId() const;

    quint16 port() const { return m_port; }
    QString url() const;
    // A folder for the test's broker files (password file, certificates); removed with the object.
    QString directory() const { return m_dir.path(); }
    // What the broker wrote (for failure messages).
    QString log() const;

    // /usr/sbin/mosquitto or the first mosquitto in PATH; empty when not installed.
    static QString executable();

private:
    QString stopFile() const;
    void tellWrapper(const char *how) const;
    void stopUnderWine(const char *how);

    QTemporaryDir m_dir;
    std::unique_ptr<QProcess> m_process;
    quint16 m_port = 0;
    bool m_underWine = false; // the broker runs under tests/mosquittobroker.cpp's wineWrapper
};

} // namespace TestUtil
