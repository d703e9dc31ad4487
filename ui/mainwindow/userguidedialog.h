#pragma once

#include <QDialog>
#include <QTextBrowser>

class QLabel;
class QToolButton;

namespace Fatek {

// Help > User Guide: the Markdown pages of docs/ (built into the program as resources under
// :/docs, so the guide is there offline and matches this version) shown in a browser with Back,
// Forward and Contents; links between the pages and their screenshots work, web links open in
// the system's browser.
class UserGuideDialog : public QDialog
{
    Q_OBJECT

public:
    explicit UserGuideDialog(QWidget *parent = nullptr);

    // "README.md" (the contents), "gui.md", "guide/forcing.md#..."; relative to docs/.
    void showPage(const QString &page);
    QTextBrowser *browser() const { return m_browser; }
    // The page shown, relative to docs/ ("gui.md").
    QString page() const;

    // Where the pages are: "qrc:/docs/".
    static QUrl root();

private:
    // Screenshots are scaled down to the page's width: a 1366 px picture in a narrower dialog
    // would need a sideways scroll.
    class Browser : public QTextBrowser
    {
    public:
        using QTextBrowser::QTextBrowser;
        QVariant loadResource(int type, const QUrl &name) override;
    };

    Browser *m_browser;
    QLabel *m_missing;
};

} // namespace Fatek
