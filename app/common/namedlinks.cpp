#include "namedlinks.h"

#include <QDir>
#include <QFile>
#include <QStandardPaths>

#include <utility>
#include <vector>

namespace Fatek {

namespace {

// The file's entries in order; `error` set when it exists but cannot be read.
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
    while (!file.atEnd()) {
        QString line = QString::fromUtf8(file.readLine());
        if (const qsizetype hash = line.indexOf(QLatin1Char('#')); hash >= 0)
            line.truncate(hash);
        const qsizetype eq = line.indexOf(QLatin1Char('='));
        if (eq <= 0)
            continue;
        entries.emplace_back(line.left(eq).trimmed(), line.mid(eq + 1).trimmed());
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
    QStringList names;
    for (const auto &[entry, url] : entries) {
        if (entry == name.trimmed())
            return url;
        names << entry;
    }
    if (error) {
        if (!readError.isEmpty())
            *error = readError;
        else if (!QFile::exists(namedLinksPath()))
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
