#pragma once

#include <QObject>
#include <QString>

#include <deque>
#include <functional>
#include <optional>

namespace Fatek {

// Standard input's lines for a command that asks while the event loop keeps running (checkout):
// Ctrl-C, the link's state and the retried release of a forced output are handled while the
// person thinks. A thread of its own reads the lines (a blocking read; also a Windows console,
// which no socket notifier watches) and hands each over, in order, to this object's thread.
class CliLineReader : public QObject
{
    Q_OBJECT

public:
    using Answer = std::function<void(const std::optional<QString> &line)>;

    // The program's one reader, created in the calling thread on first use and never destroyed:
    // its thread may still be blocked in a read when the program ends.
    static CliLineReader *instance();

    // `answer` gets the next line (without its line end), or nullopt at the end of input, from
    // the event loop; it replaces an answer still waiting. Lines typed before are taken first
    // (a script's answers come all at once).
    void nextLine(Answer answer);
    // The waiting answer is dropped: the question is no longer open.
    void cancel() { m_waiting = nullptr; }
    bool isWaiting() const { return static_cast<bool>(m_waiting); }
    // The input ended and every line was taken.
    bool atEnd() const { return m_end && m_lines.empty(); }

private:
    CliLineReader() = default;
    void startReading();
    void received(const std::optional<QString> &line);
    void deliver();

    std::deque<QString> m_lines;
    bool m_end = false;
    bool m_reading = false;
    Answer m_waiting;
};

} // namespace Fatek
