#include "testutil.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QDir>
#include <QEventLoop>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSettings>
#include <QStandardPaths>
#include <QStringList>
#include <QThread>
#include <QTimer>

#ifdef Q_OS_WIN
#include <windows.h>
#endif

namespace TestUtil {

QList<Vector> loadVectors(const QString &protocol)
{
    QFile file(QStringLiteral(FATEK_TEST_DATA "/vectors.json"));
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot open %s", qPrintable(file.fileName()));
    const QJsonArray array
        = QJsonDocument::fromJson(file.readAll()).object().value(protocol).toArray();
    QList<Vector> out;
    for (const QJsonValue &v : array) {
        const QJsonObject o = v.toObject();
        const bool binary = protocol == QLatin1String("binary");
        Vector vec;
        vec.what = o.value(QLatin1String("what")).toString();
        const QString q = o.value(QLatin1String("query")).toString();
        const QString r = o.value(QLatin1String("response")).toString();
        vec.query = binary ? fromHex(q) : fromFacon(q);
        vec.response = binary ? fromHex(r) : fromFacon(r);
        out.append(vec);
    }
    if (out.isEmpty())
        qFatal("no %s vectors in %s", qPrintable(protocol), qPrintable(file.fileName()));
    return out;
}

Fatek::Bytes fromHex(const QString &hex)
{
    const QByteArray raw = QByteArray::fromHex(hex.toLatin1());
    return Fatek::Bytes(raw.begin(), raw.end());
}

Fatek::Bytes fromFacon(const QString &text)
{
    QString s = text;
    s.replace(QLatin1String("<STX>"), QString(QChar(0x02)));
    s.replace(QLatin1String("<ETX>"), QString(QChar(0x03)));
    const QByteArray raw = s.toLatin1();
    return Fatek::Bytes(raw.begin(), raw.end());
}

QString toHex(std::span<const std::uint8_t> bytes)
{
    QByteArray raw(reinterpret_cast<const char *>(bytes.data()), qsizetype(bytes.size()));
    return QString::fromLatin1(raw.toHex(' ').toUpper());
}

QString toFacon(std::span<const std::uint8_t> bytes)
{
    QString s;
    for (std::uint8_t b : bytes) {
        if (b == 0x02)
            s += QLatin1String("<STX>");
        else if (b == 0x03)
            s += QLatin1String("<ETX>");
        else if (b < 0x20 || b > 0x7E)
            s += QStringLiteral("<%1>").arg(b, 2, 16, QLatin1Char('0'));
        else
            s += QChar(b);
    }
    return s;
}

void useTestSettings(const QString &directory, const QString &applicationName)
{
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, directory);
    QCoreApplication::setOrganizationName(QStringLiteral("fatek-studio-tests"));
    QCoreApplication::setApplicationName(applicationName);
}

QStringList ProgramRun::lines() const
{
    // A Windows console program ends its lines with CR LF.
    QString text = out;
    text.remove(QLatin1Char('\r'));
    return text.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
}

QJsonObject ProgramRun::json() const
{
    return QJsonDocument::fromJson(out.section(QLatin1Char('\n'), 0, 0).toUtf8()).object();
}

namespace {

// The run of `p` once it ended, or killed when it did not.
ProgramRun resultOf(QProcess &p, const QString &program, int timeoutMs)
{
    ProgramRun r;
    if (p.state() != QProcess::NotRunning) {
        p.kill();
        p.waitForFinished();
        r.err = QStringLiteral("%1 did not end within %2 ms").arg(program).arg(timeoutMs);
        return r;
    }
    r.code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

} // namespace

ProgramRun runProgram(const QString &program, const QStringList &arguments, int timeoutMs)
{
    QProcess p;
    QEventLoop loop;
    QObject::connect(&p, &QProcess::finished, &loop, &QEventLoop::quit);
    QObject::connect(&p, &QProcess::errorOccurred, &loop, &QEventLoop::quit);
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    p.start(program, arguments);
    if (p.state() != QProcess::NotRunning)
        loop.exec();
    return resultOf(p, program, timeoutMs);
}

ProgramRun runProgramWith(const QString &program, const QStringList &arguments,
                          const QByteArray &input, const QProcessEnvironment &env, int timeoutMs)
{
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(program, arguments);
    if (!p.waitForStarted(10000))
        return {};
    p.write(input);
    p.closeWriteChannel();
    p.waitForFinished(timeoutMs);
    return resultOf(p, program, timeoutMs);
}

TmpfsMount::~TmpfsMount()
{
    if (!m_dir.isEmpty())
        QProcess::execute(QStringLiteral("umount"), {m_dir});
}

QString TmpfsMount::mount(const QString &dir, int kilobytes)
{
    QDir().mkpath(dir);
    QProcess mounter;
    mounter.start(QStringLiteral("mount"),
                  {QStringLiteral("-t"), QStringLiteral("tmpfs"), QStringLiteral("-o"),
                   QStringLiteral("size=%1k").arg(kilobytes), QStringLiteral("tmpfs"), dir});
    if (!mounter.waitForFinished(10000) || mounter.exitStatus() != QProcess::NormalExit
        || mounter.exitCode() != 0)
        return QStringLiteral("Cannot mount a %1 KiB tmpfs (needs root and the right to mount in "
                              "this container): %2")
            .arg(kilobytes)
            .arg(QString::fromLocal8Bit(mounter.readAllStandardError()).trimmed());
    m_dir = dir;
    return {};
}

QString TmpfsMount::makeReadOnly()
{
    if (QProcess::execute(QStringLiteral("mount"),
                          {QStringLiteral("-o"), QStringLiteral("remount,ro"), m_dir})
        != 0)
        return QStringLiteral("Cannot remount %1 read-only").arg(m_dir);
    return {};
}

#ifdef Q_OS_WIN
namespace {
// Wine's kernel32 has it; Windows itself does not.
using ToUnix = char *(*)(const wchar_t *);
ToUnix wineToUnix()
{
    static const auto toUnix = reinterpret_cast<ToUnix>(reinterpret_cast<void (*)()>(
        GetProcAddress(GetModuleHandleW(L"kernel32.dll"), "wine_get_unix_file_name")));
    return toUnix;
}
} // namespace
#endif

bool underWine()
{
#ifdef Q_OS_WIN
    return wineToUnix() != nullptr;
#else
    return false;
#endif
}

QString hostPath(const QString &path)
{
#ifdef Q_OS_WIN
    const ToUnix toUnix = wineToUnix();
    if (!toUnix)
        return path;
    const std::wstring native = QDir::toNativeSeparators(path).toStdWString();
    char *unixPath = toUnix(native.c_str());
    if (!unixPath)
        return path;
    const QString result = QString::fromUtf8(unixPath);
    HeapFree(GetProcessHeap(), 0, unixPath);
    return result;
#else
    return path;
#endif
}

void startConsoleProgram(QProcess *process, const QString &program, const QStringList &arguments)
{
#ifdef Q_OS_WIN
    process->setCreateProcessArgumentsModifier(
        [](QProcess::CreateProcessArguments *args) { args->flags |= CREATE_NEW_PROCESS_GROUP; });
#endif
    process->start(program, arguments);
}

std::shared_ptr<QProcess> startPtyPair(const QString &a, const QString &b)
{
    const QString socat = QStandardPaths::findExecutable(QStringLiteral("socat"));
    if (socat.isEmpty())
        return nullptr;
    std::shared_ptr<QProcess> process(new QProcess, [](QProcess *p) {
        p->terminate();
        p->waitForFinished(5000);
        delete p;
    });
    process->start(socat, {QStringLiteral("pty,raw,echo=0,link=") + a,
                           QStringLiteral("pty,raw,echo=0,link=") + b});
    if (!process->waitForStarted(5000))
        return nullptr;
    // socat makes the links itself: nothing of ours needs the event loop meanwhile.
    QDeadlineTimer deadline(5000);
    while (!(QFile::exists(a) && QFile::exists(b)) && !deadline.hasExpired())
        QThread::msleep(10);
    return QFile::exists(a) && QFile::exists(b) ? process : nullptr;
}

void stopConsoleProgram(QProcess *process)
{
#ifdef Q_OS_WIN
    if (!GenerateConsoleCtrlEvent(CTRL_BREAK_EVENT, static_cast<DWORD>(process->processId())))
        qWarning("GenerateConsoleCtrlEvent failed: error %lu", GetLastError());
#else
    process->terminate();
#endif
}

} // namespace TestUtil
