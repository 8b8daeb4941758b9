#include "app/BatchRunner.hpp"
#include "app/CommandLine.hpp"
#include "app/GuiLauncher.hpp"
#include "core/model/MemoryBudget.hpp"
#include "core/model/ParallelFor.hpp"
#include "io/CrsDatabaseWarmUp.hpp"
#include "render/PreparedPictureMemory.hpp"

#include <QGuiApplication>
#include <QMessageLogContext>
#include <QString>
#include <QtGlobal>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <malloc.h>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

// Batch stderr is part of the contract (progress lines, or one error line), so Qt's own chatter such as
// "XDG_RUNTIME_DIR not set" stays out; only its critical messages get through.
void batchMessageHandler(QtMsgType type, const QMessageLogContext& /*context*/, const QString& message) {
    if (type == QtCriticalMsg || type == QtFatalMsg)
        std::cerr << "mcpp: qt: " << message.toStdString() << '\n';
}

// A batch run is a short-lived process: blocks of up to 32 MB that a stage frees are kept for the next stage
// (or the next planner of --compare) rather than handed back to the system and faulted in again, page by
// zeroed page. On a 4.8 M-cell map that is 54 000 page faults instead of 62 000-86 000 and 2.1-2.5 s of
// system time instead of 2.7-3.7 s, for 2 % more peak memory; heap blocks for everything (no mmap) saved more
// time but took up to 17 % more memory. The window keeps glibc's defaults, so that memory goes back to the
// system between plans.
void keepFreedMemoryForReuse() {
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
    constexpr int largestReusedBlock = 32 << 20; // glibc's ceiling for this setting
    mallopt(M_MMAP_THRESHOLD, largestReusedBlock);
    mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
#endif
}

int runBatch(char* programName, const mcpp::app::CommandLineOptions& options) {
    keepFreedMemoryForReuse();
    // plan.png is painted with QPainter, which needs a QGuiApplication; offscreen needs no display.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    // After the last change to the environment: the warm-up thread reads it (glibc's setenv is not safe
    // beside a getenv on another thread).
    const mcpp::io::CrsDatabaseWarmUp warmUp;
    // plan.png's sheet: a map of at most 1 600 pixels a side with its title and legend, about 2 100 x 1 700
    // pixels of 4 bytes.
    const mcpp::render::PreparedPictureMemory pictureMemory(std::size_t{16} << 20);
    qInstallMessageHandler(batchMessageHandler);
    mcpp::setWorkerThreads(options.threads);
    int qtArgumentCount = 1;
    char* qtArguments[] = {programName, nullptr};
    const QGuiApplication application(qtArgumentCount, qtArguments);
    QGuiApplication::setApplicationName(QStringLiteral("mcpp"));
    QGuiApplication::setApplicationVersion(QStringLiteral(MCPP_VERSION));
    const int exitCode = mcpp::app::BatchRunner(options, std::cout, std::cerr).run();
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
    // Every output is written and closed: tearing down PROJ's database cache, fontconfig and the plan's
    // memory would only make the caller wait about 10 ms longer. Sanitizer builds exit normally, so that
    // their checks at exit run.
    std::_Exit(exitCode);
#endif
    return exitCode;
}

} // namespace

// Plans may use most of the machine's memory; beyond it the planner says so, with a FOV that would fit.
void setMemoryBudgetFromMachine() {
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long pageSize = sysconf(_SC_PAGE_SIZE);
    if (pages > 0 && pageSize > 0)
        mcpp::setMemoryBudgetBytes(static_cast<std::int64_t>(pages) * pageSize / 10 * 8);
}

int main(int argc, char* argv[]) {
    setMemoryBudgetFromMachine();
    const std::vector<std::string> arguments(argv + 1, argv + argc);
    const auto parsed = mcpp::app::CommandLine::parse(arguments);
    if (!parsed.ok()) {
        std::cerr << "mcpp: " << parsed.error << '\n';
        return parsed.exitCode;
    }
    switch (parsed.options.mode) {
    case mcpp::app::RunMode::Help:
        std::cout << mcpp::app::CommandLine::usage();
        return 0;
    case mcpp::app::RunMode::PlannerHelp:
        std::cout << mcpp::app::CommandLine::plannerHelp(parsed.options.helpPlanner);
        return 0;
    case mcpp::app::RunMode::Version:
        std::cout << mcpp::app::CommandLine::versionText();
        return 0;
    case mcpp::app::RunMode::Batch:
        return runBatch(argv[0], parsed.options);
    case mcpp::app::RunMode::Gui:
        break;
    }
    return mcpp::app::GuiLauncher::run(argv[0], parsed.options.guiFile);
}
