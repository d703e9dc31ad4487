#pragma once

#include <QProcess>
#include <QString>
#include <QStringList>

#include <vector>

namespace TestUtil {

// A fatek-sim child on a free loopback TCP port, in STOP without a ladder unless told otherwise:
// for the tests that stop the simulator (pause(): SIGSTOP, its connections stay open and nothing
// answers, as a PLC that hangs) and that read what it holds through a fatek-cli of their own.
class SimChild
{
public:
    SimChild() = default;
    SimChild(const SimChild &) = delete;
    SimChild &operator=(const SimChild &) = delete;
    // Resumed and stopped as a user would (SIGTERM), then waited for.
    ~SimChild();

    // Starts `simPath --tcp 0 [--stopped] extra` and waits for its port; false (and why in
    // *error) when it did not come up.
    bool start(const QString &simPath, bool stopped = true, const QStringList &extra = {},
               QString *error = nullptr);
    quint16 port() const { return m_port; }
    // fatek-cli's link options for it.
    QStringList link() const;
    // SIGSTOP / SIGCONT (Unix only; false elsewhere).
    bool pause();
    bool resume();

    // `cliPath LINK --json forced START COUNT`: the disable (forced) flags as the simulator holds
    // them; empty (and why in a warning) when fatek-cli failed.
    std::vector<int> forced(const QString &cliPath, const QString &start, int count) const;

private:
    QProcess m_process;
    quint16 m_port = 0;
    bool m_paused = false;
};

} // namespace TestUtil
