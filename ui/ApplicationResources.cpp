#include "ui/ApplicationResources.hpp"

#include "io/GdalVersion.hpp"

#include <QCoreApplication>
#include <QFile>

// Q_INIT_RESOURCE names a global function: called outside any namespace. A static library's resources
// are otherwise dropped by the linker.
static void initialiseResources() {
    Q_INIT_RESOURCE(mcpp);
}

namespace mcpp::ui {
namespace {

void ensureResources() {
    static const bool initialised = [] {
        initialiseResources();
        return true;
    }();
    (void)initialised;
}

} // namespace

QIcon actionIcon(const char* name) {
    ensureResources();
    return QIcon(QStringLiteral(":/icons/%1.svg").arg(QLatin1String(name)));
}

QString aboutText() {
    ensureResources();
    QFile file(QStringLiteral(":/about.html"));
    if (!file.open(QIODevice::ReadOnly))
        return QStringLiteral("mcpp %1").arg(QCoreApplication::applicationVersion());
    const QString version = QCoreApplication::applicationVersion().isEmpty()
                                ? QStringLiteral("(version unknown)")
                                : QCoreApplication::applicationVersion();
    return QString::fromUtf8(file.readAll())
        .arg(version, QString::fromLatin1(qVersion()), QString::fromStdString(io::gdalVersion()));
}

} // namespace mcpp::ui
