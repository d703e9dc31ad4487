// Shared by the tst_tools_* tests: an in-process simulator on a free TCP port and a direct link
// (a SessionLink) to it.
#pragma once

#include "core/link/sessionlink.h"
#include "core/plant/plctarget.h"
#include "core/session/session.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"

#include <QStringList>
#include <QTest>

#include <memory>

namespace ToolsTest {

struct Rig
{
    std::unique_ptr<Fatek::SimulatedPlc> plc;
    std::unique_ptr<Fatek::SimServer> server;
    std::unique_ptr<Fatek::SessionLink> link; // reset(): the connection is closed
    QStringList questions;                    // every confirmation question asked
    bool answer = true;                       // what the automatic confirmer answers

    // Starts the simulator (RUN) and opens a link in `protocol`; false if it did not connect.
    bool start(Fatek::LinkSettings::ProtocolChoice protocol
               = Fatek::LinkSettings::ProtocolChoice::Facon,
               int timeoutMs = 1000, int retries = 1,
               const Fatek::ModelProfile &profile = Fatek::ModelProfile::fbs())
    {
        Fatek::registerSessionMetaTypes();
        plc = std::make_unique<Fatek::SimulatedPlc>(profile);
        plc->setRunning(true);
        server = std::make_unique<Fatek::SimServer>(plc.get());
        QString error;
        if (!server->listenTcp(0, &error)) {
            qWarning() << error;
            return false;
        }
        auto settings
            = Fatek::LinkSettings::tcp(QStringLiteral("127.0.0.1"), server->tcpPort(), protocol);
        settings.timeoutMs = timeoutMs;
        settings.retries = retries;
        link = std::make_unique<Fatek::SessionLink>(settings);
        link->open();
        QDeadlineTimer deadline(10000);
        while (link->linkState() != Fatek::LinkState::Connected && !deadline.hasExpired())
            QTest::qWait(5);
        return link->linkState() == Fatek::LinkState::Connected;
    }

    // The link's session (what core's engines run on); nullptr once the link is closed.
    Fatek::Session *session() const { return link ? link->session() : nullptr; }
    // What a tool acts on: `station` behind the link.
    Fatek::PlcTarget target(quint8 station = 1) const
    {
        return Fatek::PlcTarget(link.get(), station, connectionName());
    }

    std::function<bool(const QString &)> confirmer()
    {
        return [this](const QString &question) {
            questions << question;
            return answer;
        };
    }

    static QString connectionName() { return QStringLiteral("Test line"); }
};

// The simulator's whole program memory, page by page.
inline std::vector<std::vector<std::uint32_t>> plcPages(const Fatek::SimulatedPlc &plc)
{
    std::vector<std::vector<std::uint32_t>> pages;
    for (std::uint16_t p = 0; p < plc.profile().programPages(); ++p)
        pages.push_back(plc.programPage(p));
    return pages;
}

inline Fatek::Address addr(const char *text)
{
    return Fatek::Address::parse(text).value();
}

} // namespace ToolsTest
