#include "app/GuiLauncher.hpp"

#include "io/CrsDatabaseWarmUp.hpp"

#include <QApplication>
#include <QString>
#include <iostream>

#ifdef MCPP_HAVE_UI
#include "ui/MainWindow.hpp"
#endif

namespace mcpp::app {

int GuiLauncher::run(char* programName, const std::string& fileToOpen) {
    const io::CrsDatabaseWarmUp warmUp; // while the window is built, before a raster is opened
    // Only the program name goes to Qt: every other argument is mcpp's and was parsed already.
    int qtArgumentCount = 1;
    char* qtArguments[] = {programName, nullptr};
    QApplication application(qtArgumentCount, qtArguments);
    QApplication::setApplicationName(QStringLiteral("mcpp"));
    QApplication::setOrganizationName(QStringLiteral("mcpp"));
    QApplication::setApplicationVersion(QStringLiteral(MCPP_VERSION));
#ifdef MCPP_HAVE_UI
    ui::MainWindow window;
    window.show();
    if (!fileToOpen.empty()) {
        const auto path = QString::fromLocal8Bit(fileToOpen.c_str());
        if (path.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)) {
            window.openMission(path);
        } else {
            window.openRaster(path);
        }
    }
    return QApplication::exec();
#else
    (void)fileToOpen;
    std::cerr << "mcpp: this build has no window; plan with mcpp --batch (see mcpp --help)\n";
    return 1;
#endif
}

} // namespace mcpp::app
