#include "ui/ExportFileName.hpp"

#include <QFileInfo>

namespace mcpp::ui {

QString suggestedExportFileName(const io::ExportFormat& format, const QString& missionPath) {
    const QString extension = QString::fromStdString(format.extension);
    const QString batchName = QString::fromStdString(format.batchFileName);
    const QString plain =
        !format.perRobot && !batchName.isEmpty() ? batchName : QStringLiteral("plan.") + extension;
    if (missionPath.isEmpty())
        return plain;
    const QFileInfo mission(missionPath);
    // Per-robot files take the robot after the name (survey-robot1.plan): the mission's name alone reads
    // best.
    QString suggested = format.perRobot ? mission.completeBaseName() + QStringLiteral(".") + extension
                                        : mission.completeBaseName() + QStringLiteral("-") + plain;
    if (suggested == mission.fileName())
        suggested = mission.completeBaseName() + QStringLiteral("-") + plain;
    return suggested;
}

} // namespace mcpp::ui
