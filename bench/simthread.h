#pragma once

#include "core/sim/faultconfig.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"

#include <QThread>

#include <memory>

namespace Fatek::Bench {

// The simulator on a thread of its own (as fatek-sim would be, in another process): the
// session's or the UI's thread never does the PLC's work.
class SimThread
{
public:
    explicit SimThread(const FaultConfig &faults = {})
    {
        m_thread.start();
        m_context.moveToThread(&m_thread);
        QMetaObject::invokeMethod(
            &m_context,
            [this, faults] {
                m_server = std::make_unique<SimServer>(&m_plc);
                m_server->setFaults(faults);
                m_server->listenTcp(0, &m_error);
                m_port = m_server->tcpPort();
            },
            Qt::BlockingQueuedConnection);
    }
    ~SimThread()
    {
        QMetaObject::invokeMethod(
            &m_context, [this] { m_server.reset(); }, Qt::BlockingQueuedConnection);
        m_thread.quit();
        m_thread.wait();
    }
    SimThread(const SimThread &) = delete;
    SimThread &operator=(const SimThread &) = delete;

    quint16 port() const { return m_port; }
    QString error() const { return m_error; }
    SimulatedPlc &plc() { return m_plc; }
    QObject *context() { return &m_context; }

private:
    SimulatedPlc m_plc;
    QThread m_thread;
    QObject m_context;
    std::unique_ptr<SimServer> m_server;
    QString m_error;
    quint16 m_port = 0;
};

} // namespace Fatek::Bench

#include "core/session/session.h"

#include <QEventLoop>
#include <QTimer>

namespace Fatek::Bench {

// Opens `session` and waits (running the event loop) until it is connected.
inline bool openAndWait(Session &session, int timeoutMs = 5000)
{
    QEventLoop loop;
    QObject::connect(&session, &Session::linkStateChanged, &loop, [&loop](LinkState state) {
        if (state == LinkState::Connected)
            loop.quit();
    });
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    session.open();
    if (session.linkState() != LinkState::Connected)
        loop.exec();
    return session.linkState() == LinkState::Connected;
}

inline LinkSettings::ProtocolChoice choiceOf(Protocol protocol)
{
    return protocol == Protocol::Facon ? LinkSettings::ProtocolChoice::Facon
                                       : LinkSettings::ProtocolChoice::Binary;
}

} // namespace Fatek::Bench
