// fatek-rendericon: renders the application icon SVG to the PNG sizes of the hicolor theme and
// to a Windows .ico at build time, so no generated bitmaps live in the repository.
// Usage: fatek-rendericon ICON.svg OUTDIR SIZE... [--ico FILE]
// Writes OUTDIR/<size>x<size>/fatek-studio.png for every SIZE.

#include <QCoreApplication>
#include <QDir>
#include <QImage>
#include <QImageWriter>
#include <QPainter>
#include <QStringList>
#include <QSvgRenderer>

#include <cstdio>

namespace {

int fail(const QString &message)
{
    std::fprintf(stderr, "fatek-rendericon: %s\n", qPrintable(message));
    return 1;
}

QImage render(QSvgRenderer &renderer, int size)
{
    QImage image(size, size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    renderer.render(&painter, QRectF(0, 0, size, size));
    painter.end();
    return image;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QStringList args = QCoreApplication::arguments().mid(1);
    QString icoPath;
    const qsizetype icoAt = args.indexOf(QStringLiteral("--ico"));
    if (icoAt >= 0) {
        if (icoAt + 1 >= args.size())
            return fail(QStringLiteral("--ico needs a file name"));
        icoPath = args.at(icoAt + 1);
        args.remove(icoAt, 2);
    }
    if (args.size() < 3)
        return fail(QStringLiteral("usage: fatek-rendericon ICON.svg OUTDIR SIZE... [--ico FILE]"));

    QSvgRenderer renderer(args.at(0));
    if (!renderer.isValid())
        return fail(QStringLiteral("%1 is not a readable SVG file").arg(args.at(0)));

    const QDir outDir(args.at(1));
    for (qsizetype i = 2; i < args.size(); ++i) {
        bool ok = false;
        const int size = args.at(i).toInt(&ok);
        if (!ok || size < 8 || size > 1024)
            return fail(QStringLiteral("icon size must be 8..1024, not \"%1\"").arg(args.at(i)));
        const QString sub = QStringLiteral("%1x%1").arg(size);
        if (!outDir.mkpath(sub))
            return fail(QStringLiteral("cannot create %1").arg(outDir.filePath(sub)));
        const QString path = outDir.filePath(sub + QStringLiteral("/fatek-studio.png"));
        if (!render(renderer, size).save(path, "PNG"))
            return fail(QStringLiteral("cannot write %1").arg(path));
    }

    // Windows shows the largest fitting entry; Qt's ICO writer stores one image, so 256 px.
    if (!icoPath.isEmpty()) {
        QImageWriter writer(icoPath, "ico");
        if (!writer.write(render(renderer, 256)))
            return fail(QStringLiteral("cannot write %1: %2").arg(icoPath, writer.errorString()));
    }
    return 0;
}
