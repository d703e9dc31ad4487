#pragma once

#include <QObject>
#include <QString>

#include <functional>
#include <set>
#include <vector>

namespace Fatek {

class CheckoutRunner;
class CliOutput;

// fatek-cli checkout's inputs, one at a time as in the GUI: the input under test is named (the
// runner's current point, moved on by its edges), an edge on another input is crossed wiring on
// it, and the person may skip (it stays untested), fail, defer, pass with a remark or take out
// (not applicable) the input under test, or test it again. A dead input does not hold up the
// rest. done() once every input untested at start() has a result or was skipped.
class CliCheckoutInputs : public QObject
{
    Q_OBJECT

public:
    // Asks `question` on stderr: the line (trimmed), or noAnswer at the end of input.
    using Ask
        = std::function<void(const QString &question, std::function<void(const QString &)> answer,
                             std::function<void()> noAnswer)>;

    // `canAsk`: false when no question can be answered (no terminal, no --yes): the inputs are
    // named and their edges alone move on.
    CliCheckoutInputs(CheckoutRunner &runner, CliOutput &out, Ask ask, bool canAsk,
                      QObject *parent = nullptr);

    void start();
    // The checkout ends: nothing more is asked.
    void stop() { m_stopped = true; }

Q_SIGNALS:
    void done();
    // The end of input at an input's question.
    void noAnswer();

private:
    void next(int after);
    void askInput(int index);
    void answer(int index, const QString &line);
    void finish();

    CheckoutRunner &m_runner;
    CliOutput &m_out;
    Ask m_ask;
    bool m_canAsk = false;
    bool m_stopped = false;
    bool m_done = false;
    std::vector<int> m_inputs; // untested at start, in plan order
    std::set<int> m_skipped;   // skipped in this run: not asked again
    int m_underTest = -1;
};

} // namespace Fatek
