#include "demosimulator.h"

#include "core/session/crossthreadcall.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"

namespace Fatek {

namespace {

// Lives in the server thread and owns the server; runs the calls posted to that thread.
class DemoAnchor : public QObject
{
public:
    explicit DemoAnchor(const DemoSimulator *owner)
        : m_owner(owner)
    {}
    // Deleted last on the server thread, when it ends.
    ~DemoAnchor() override
    {
        const QObjectList servers = children(); // the server goes before the mark
        qDeleteAll(servers);
        CrossThreadCall::threadEnds(m_owner);
    }
    bool event(QEvent *event) override
    {
        return CrossThreadCall::deliver(this, event) || QObject::event(event);
    }

private:
    const DemoSimulator *m_owner;
};

} // namespace

DemoSimulator::DemoSimulator(QObject *parent)
    : QObject(parent)
    , m_plc(std::make_unique<SimulatedPlc>(ModelProfile::fbs()))
    , m_anchor(new DemoAnchor(this))
{
    m_thread.setObjectName(QStringLiteral("demo-plc"));
    m_anchor->moveToThread(&m_thread);
    // The server is a child of the anchor: both are deleted in their own thread when it ends.
    connect(&m_thread, &QThread::finished, m_anchor, &QObject::deleteLater);
}

DemoSimulator::~DemoSimulator()
{
    m_thread.quit();
    m_thread.wait();
    CrossThreadCall::threadEnded(this); // before the PLC the server thread used goes
}

bool DemoSimulator::event(QEvent *event)
{
    return CrossThreadCall::deliver(this, event) || QObject::event(event);
}

void DemoSimulator::start()
{
    m_plc->setRunning(true);
    m_thread.start();
    SimulatedPlc *plc = m_plc.get();
    QObject *anchor = m_anchor;
    CrossThreadCall::post(m_anchor, [this, plc, anchor] {
        auto *server = new SimServer(plc, anchor);
        QString error;
        if (!server->listenTcp(0, &error)) {
            CrossThreadCall::post(this, [this, error] { Q_EMIT failed(error); });
            return;
        }
        server->setDemoLadder(true);
        const quint16 port = server->tcpPort();
        CrossThreadCall::post(this, [this, port] { Q_EMIT ready(port); });
    });
}

WatchTableSpec DemoSimulator::demoTable(quint8 station)
{
    WatchTableSpec spec;
    spec.name = tr("Demo");
    spec.intervalMs = 200;
    spec.confirmWrites = true;
    auto add = [&](const char *address, DisplayFormat format, const QString &name,
                   const QString &comment) {
        WatchItemSpec item;
        item.address = *Address::parse(address);
        item.station = station;
        item.format = format;
        item.name = name;
        item.comment = comment;
        spec.items.append(item);
    };
    add("R0", DisplayFormat::Unsigned, tr("Scan counter"), tr("counts ladder scans"));
    add("R1", DisplayFormat::Signed, tr("Sine"), tr("±1000, 10 s period"));
    add("Y0", DisplayFormat::Bit, tr("Blink"), tr("1 Hz"));
    for (int i = 0; i < 8; ++i) {
        add(QStringLiteral("X%1").arg(i).toLatin1().constData(), DisplayFormat::Bit,
            tr("Walking bit %1").arg(i), i == 0 ? tr("one step per 250 ms") : QString());
    }
    add("DR10", DisplayFormat::Unsigned, tr("Ramp"), tr("0..99999, one step per 10 ms"));
    return spec;
}

} // namespace Fatek
