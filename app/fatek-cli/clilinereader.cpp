#include "clilinereader.h"

#include "core/session/crossthreadcall.h"

#include <QMetaObject>

#include <iostream>
#include <string>
#include <thread>
#include <utility>

#ifdef Q_OS_UNIX
#include <csignal>
#include <pthread.h>
#endif
#ifdef Q_OS_WIN
#include <windows.h>
#endif

namespace Fatek {

CliLineReader *CliLineReader::instance()
{
    static CliLineReader *reader = new CliLineReader;
    return reader;
}

void CliLineReader::nextLine(Answer answer)
{
    m_waiting = std::move(answer);
    startReading();
    // From the event loop, never inside the caller: an answer may ask the next question.
    QMetaObject::invokeMethod(this, &CliLineReader::deliver, Qt::QueuedConnection);
}

void CliLineReader::startReading()
{
    if (m_reading)
        return;
    m_reading = true;
    std::thread([this] {
#ifdef Q_OS_UNIX
        // Ctrl-C goes to the main thread's handler; here it would end the read as if the input
        // had ended.
        sigset_t all;
        sigfillset(&all);
        pthread_sigmask(SIG_BLOCK, &all, nullptr);
#endif
#ifdef Q_OS_WIN
        // A console's Ctrl-C ends the read under way as if the input had ended; the console is
        // still there, so it is read on (the end of input is a pipe's or a file's).
        DWORD mode = 0;
        const bool console = GetConsoleMode(GetStdHandle(STD_INPUT_HANDLE), &mode) != 0;
#endif
        std::string line;
        for (;;) {
            while (std::getline(std::cin, line)) {
                if (!line.empty() && line.back() == '\r')
                    line.pop_back();
                const QString text
                    = QString::fromUtf8(line.data(), static_cast<qsizetype>(line.size()));
                // Marked for ThreadSanitizer (Debian's Qt hides its queue's ordering from it).
                CrossThreadCall::invoke(this, [this, text] { received(text); });
            }
#ifdef Q_OS_WIN
            if (console) {
                std::cin.clear();
                Sleep(100); // not a busy loop should the console keep failing
                continue;
            }
#endif
            break;
        }
        CrossThreadCall::invoke(this, [this] { received(std::nullopt); });
    }).detach();
}

void CliLineReader::received(const std::optional<QString> &line)
{
    if (line)
        m_lines.push_back(*line);
    else
        m_end = true;
    deliver();
}

void CliLineReader::deliver()
{
    if (!m_waiting || (m_lines.empty() && !m_end))
        return;
    const Answer answer = std::exchange(m_waiting, nullptr);
    if (m_lines.empty())
        return answer(std::nullopt);
    const QString line = m_lines.front();
    m_lines.pop_front();
    answer(line);
}

} // namespace Fatek
