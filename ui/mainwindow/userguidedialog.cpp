#include "userguidedialog.h"

#include <QFile>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QScrollBar>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

// Q_INIT_RESOURCE must be called from the global namespace.
static void initUserGuideResources()
{
    Q_INIT_RESOURCE(userguide);
}

namespace Fatek {

namespace {
const QString contentsPage = QStringLiteral("README.md");
} // namespace

QUrl UserGuideDialog::root()
{
    return QUrl(QStringLiteral("qrc:/docs/"));
}

QVariant UserGuideDialog::Browser::loadResource(int type, const QUrl &name)
{
    QVariant resource = QTextBrowser::loadResource(type, name);
    if (type != QTextDocument::ImageResource)
        return resource;
    QImage image;
    if (resource.typeId() == QMetaType::QImage)
        image = resource.value<QImage>();
    else if (resource.typeId() == QMetaType::QByteArray)
        image.loadFromData(resource.toByteArray());
    const int room = viewport()->width() - 2 * int(document()->documentMargin())
                     - verticalScrollBar()->sizeHint().width();
    if (image.isNull() || room <= 0 || image.width() <= room)
        return resource;
    return image.scaledToWidth(room, Qt::SmoothTransformation);
}

UserGuideDialog::UserGuideDialog(QWidget *parent)
    : QDialog(parent)
{
    initUserGuideResources();
    setWindowTitle(tr("FATEK Studio User Guide"));
    auto *layout = new QVBoxLayout(this);
    auto *bar = new QHBoxLayout;
    auto addButton
        = [this, bar](QStyle::StandardPixmap icon, const QString &text, const QString &name) {
              auto *b = new QToolButton(this);
              b->setIcon(style()->standardIcon(icon));
              b->setText(text);
              b->setToolTip(text);
              b->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
              b->setObjectName(name);
              bar->addWidget(b);
              return b;
          };
    QToolButton *back = addButton(QStyle::SP_ArrowBack, tr("Back"), QStringLiteral("backButton"));
    QToolButton *forward
        = addButton(QStyle::SP_ArrowForward, tr("Forward"), QStringLiteral("forwardButton"));
    QToolButton *contents
        = addButton(QStyle::SP_DirHomeIcon, tr("Contents"), QStringLiteral("contentsButton"));
    bar->addStretch(1);
    layout->addLayout(bar);

    m_browser = new Browser(this);
    m_browser->setObjectName(QStringLiteral("guideBrowser"));
    m_browser->setOpenExternalLinks(true);
    m_browser->setSearchPaths({QStringLiteral(":/docs")});
    layout->addWidget(m_browser, 1);
    m_missing = new QLabel(this);
    m_missing->setObjectName(QStringLiteral("missingLabel"));
    m_missing->setWordWrap(true);
    m_missing->hide();
    layout->addWidget(m_missing);

    back->setEnabled(false);
    forward->setEnabled(false);
    connect(back, &QToolButton::clicked, m_browser, &QTextBrowser::backward);
    connect(forward, &QToolButton::clicked, m_browser, &QTextBrowser::forward);
    connect(contents, &QToolButton::clicked, this, [this] { showPage(contentsPage); });
    connect(m_browser, &QTextBrowser::backwardAvailable, back, &QToolButton::setEnabled);
    connect(m_browser, &QTextBrowser::forwardAvailable, forward, &QToolButton::setEnabled);
    // A link to a file outside the guide (the sources, ../README.md) is not in the program.
    connect(m_browser, &QTextBrowser::sourceChanged, this, [this](const QUrl &url) {
        const bool there = QFile::exists(QLatin1Char(':') + url.path());
        m_missing->setVisible(!there);
        m_missing->setText(there ? QString()
                                 : tr("%1 is not part of the user guide built into the program.")
                                       .arg(url.path().mid(6)));
        setWindowTitle(tr("FATEK Studio User Guide \u2014 %1").arg(page()));
    });
    showPage(contentsPage);
    resize(900, 640);
}

void UserGuideDialog::showPage(const QString &page)
{
    m_browser->setSource(root().resolved(QUrl(page)), QTextDocument::MarkdownResource);
}

QString UserGuideDialog::page() const
{
    return m_browser->source().path().mid(QStringLiteral("/docs/").size());
}

} // namespace Fatek
