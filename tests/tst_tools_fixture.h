// Shared by the tst_tools_* tests: an in-process simulator on a free TCP port and a Session to it.
#pragma once

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
    std::unique_ptr<Fatek::Session> session;
    QStringList questions; // every confirmation question asked
    bool answer = true;    // what the automatic confirmer answers

    // Starts the simulator (RUN) and opens a session in `protocol`; false if it did not connect.
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
        session = std::make_unique<Fatek::Session>(settings);
        session->open();
        QDeadlineTimer deadline(10000);
        while (session->linkState() != Fatek::LinkState::Connected && !deadline.hasExpired())
            QTest::qWait(5);
        return session->linkState() == Fatek::LinkState::Connected;
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
