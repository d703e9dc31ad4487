#include "namedlinks.h"

#include <QDir>
#include <QFile>
#include <QStandardPaths>

#include <utility>
#include <vector>

namespace Fatek {

namespace {

// The file's entries in order; `error` set when it exists but cannot be read, or when a line is
// not NAME = URL or names a link a second time (the file is refused rather than one of two
// meanings picked silently).
std::vector<std::pair<QString, QString>> readEntries(QString *error)
{
    std::vector<std::pair<QString, QString>> entries;
    QFile file(namedLinksPath());
    if (!file.exists())
        return entries;
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        if (error)
            *error = QStringLiteral("cannot read %1: %2").arg(file.fileName(), file.errorString());
        return entries;
    }
    std::vector<int> lineOf;
    for (int number = 1; !file.atEnd(); ++number) {
        QString line = QString::fromUtf8(file.readLine());
        if (const qsizetype hash = line.indexOf(QLatin1Char('#')); hash >= 0)
            line.truncate(hash);
        if (line.trimmed().isEmpty())
            continue;
        const qsizetype eq = line.indexOf(QLatin1Char('='));
        const QString name = eq > 0 ? line.left(eq).trimmed() : QString();
        const QString url = eq > 0 ? line.mid(eq + 1).trimmed() : QString();
        if (name.isEmpty() || url.isEmpty()) {
            if (error && error->isEmpty())
                *error = QStringLiteral("line %1 of %2 is not NAME = URL: \"%3\"")
                             .arg(number)
                             .arg(file.fileName(), line.trimmed());
            continue;
        }
        for (std::size_t i = 0; i < entries.size(); ++i) {
            if (entries[i].first == name && error && error->isEmpty())
                *error = QStringLiteral("line %1 of %2 names \"%3\" again (first on line %4)")
                             .arg(number)
                             .arg(file.fileName(), name)
                             .arg(lineOf[i]);
        }
        entries.emplace_back(name, url);
        lineOf.push_back(number);
    }
    return entries;
}

} // namespace

QString namedLinksPath()
{
    const QString overridden = qEnvironmentVariable("FATEK_LINKS");
    if (!overridden.isEmpty())
        return overridden;
    return QDir(QStandardPaths::writableLocation(QStandardPaths::GenericConfigLocation))
        .filePath(QStringLiteral("fatek-studio/links.conf"));
}

QStringList namedLinkNames()
{
    QStringList names;
    for (const auto &[name, url] : readEntries(nullptr))
        names << name;
    return names;
}

QString lookUpNamedLink(const QString &name, QString *error)
{
    QString readError;
    const auto entries = readEntries(&readError);
    if (!readError.isEmpty()) {
        if (error)
            *error = readError;
        return {};
    }
    QStringList names;
    for (const auto &[entry, url] : entries) {
        if (entry == name.trimmed())
            return url;
        names << entry;
    }
    if (error) {
        if (!QFile::exists(namedLinksPath()))
            *error = QStringLiteral("no link named \"%1\": %2 does not exist (one line per link: "
                                    "NAME = URL).")
                         .arg(name, namedLinksPath());
        else
            *error = QStringLiteral("no link named \"%1\" in %2 (it names %3).")
                         .arg(name, namedLinksPath(),
                              names.isEmpty() ? QStringLiteral("none")
                                              : names.join(QStringLiteral(", ")));
    }
    return {};
}

} // namespace Fatek
