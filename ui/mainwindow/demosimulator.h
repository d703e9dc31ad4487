#pragma once

#include "core/watch/watchlist.h"

#include <QObject>
#include <QThread>

#include <memory>

namespace Fatek {

class SimServer;
class SimulatedPlc;

// The embedded PLC for --demo: a SimulatedPlc (FBs profile, RUN, demo ladder on) served over TCP on
// a free local port by a SimServer that lives in its own thread, so the UI thread never serves it.
class DemoSimulator : public QObject
{
    Q_OBJECT

public:
    explicit DemoSimulator(QObject *parent = nullptr);
    ~DemoSimulator() override;

    // Starts the server thread; ends in ready(port) or failed(reason).
    void start();
    SimulatedPlc *plc() const { return m_plc.get(); }

    // The table the demo opens: the ladder's moving values, with names.
    static WatchTableSpec demoTable(quint8 station = 1);

    // Runs the calls posted to this object (CrossThreadCall).
    bool event(QEvent *event) override;

Q_SIGNALS:
    void ready(quint16 port);
    void failed(const QString &reason);

private:
    std::unique_ptr<SimulatedPlc> m_plc;
    QThread m_thread;
    QObject *m_anchor; // lives in m_thread; parent of the server
};

} // namespace Fatek
