#pragma once

#include <QObject>
#include <QString>

#include <map>

class QKeyEvent;
class QTableView;

namespace Fatek {

class CheckoutRunner;
class ToolDialogFrame;
class CheckoutPlan;

// The keys of the I/O checkout's table, on the point under test: Space passed (an output is
// forced first, then seen), F failed (the forced output not seen), R passed with a remark and D
// deferred (both ask their text), A not applicable, T tested again (the attempt kept, an input
// takes new edges), N the next untested point, V reads an analog point's next check as found and
// Shift+V its last check again as left (after an adjustment), F2 edits the comment. What the
// runner refuses is said in the message line, in words.
class CheckoutKeys : public QObject
{
    Q_OBJECT

public:
    CheckoutKeys(CheckoutRunner *runner, ToolDialogFrame *frame, QTableView *table,
                 QObject *parent = nullptr);

    // A key pressed on the table; true when it was one of the checkout's.
    bool handle(QKeyEvent *key);
    // Every key in a line: the hint under the table and its tooltip.
    static QString hint();
    // "X0 (Start button)", or "X0".
    static QString pointText(const CheckoutPlan &plan, int index);

private:
    void pressSeen(int index);
    void pressFailed(int index);
    // R and D: passed with a remark, or deferred, with its text asked first.
    void pressWithText(int index, bool deferred);
    void pressRetest(int index);
    void readAnalog(int index, bool asLeft);
    void force(int index);
    void editComment();
    // The forced output waits for its answer: nothing else is recorded on it.
    bool refuseWhileForced(int index);
    void analogRecorded(int index, int check);
    void refused(const QString &text);
    QString pointText(int index) const;

    CheckoutRunner *m_runner;
    ToolDialogFrame *m_frame;
    QTableView *m_table;
    std::map<int, int> m_lastRead; // the check an analog point was last read at
};

} // namespace Fatek
