#include "ui/SampleMission.hpp"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QStringList>

namespace mcpp::ui {

QString findSampleMission() {
    const QString relative = QStringLiteral("samples/zion-nlcd/mission.json");
    QStringList candidates;
    const QString override = qEnvironmentVariable("MCPP_SAMPLE_MISSION");
    if (!override.isEmpty())
        candidates << override;
    QDir directory(QCoreApplication::applicationDirPath());
    for (int up = 0; up < 5; ++up) {
        candidates << directory.filePath(relative)
                   << directory.filePath(QStringLiteral("share/mcpp/") + relative);
        if (!directory.cdUp())
            break;
    }
#ifdef MCPP_SOURCE_DIR
    candidates << QDir(QStringLiteral(MCPP_SOURCE_DIR)).filePath(relative);
#endif
    for (const QString& candidate : candidates)
        if (QFileInfo(candidate).isFile())
            return QFileInfo(candidate).absoluteFilePath();
    return {};
}

} // namespace mcpp::ui
