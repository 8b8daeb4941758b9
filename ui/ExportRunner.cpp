#include "ui/ExportRunner.hpp"

#include "io/ExportCatalogue.hpp"
#include "render/PlanImageWriter.hpp"

#include <QtConcurrent/QtConcurrentRun>
#include <exception>

namespace mcpp::ui {

namespace {

ExportOutcome runJob(const ExportJob& job, const std::atomic<bool>& cancelRequested,
                     const std::function<void(int, int)>& progress) {
    ExportOutcome outcome;
    const io::ExportFormat* format = io::findExportFormat(job.formatKey);
    if (format == nullptr) {
        outcome.error = QObject::tr("Unknown export format %1.").arg(QString::fromStdString(job.formatKey));
        return outcome;
    }
    io::ExportContext context{*job.plan, job.raster->georeference, job.classes, job.settings};
    context.grid = &job.raster->grid;
    context.area = &job.raster->area;
    context.drawImage = render::planImageWriter(job.imageSide);
    context.cancelRequested = &cancelRequested;
    context.robotNames = job.robotNames;
    context.vehicles = job.vehicles;
    context.inputWarnings = job.raster->warnings; // the raster's and its area's, as batch mode's report has
    const int files = static_cast<int>(job.files.size());
    for (int file = 0; file < files; ++file) {
        if (cancelRequested.load()) {
            outcome.cancelled = true;
            return outcome;
        }
        const auto& [robot, path] = job.files[static_cast<std::size_t>(file)];
        const io::Status status = format->write(context, robot, path.toStdString());
        if (!status.ok()) {
            outcome.cancelled = cancelRequested.load();
            // Writers name the file in their errors, most often: it is said once.
            const QString error = QString::fromStdString(status.error());
            outcome.error = error.contains(path)
                                ? QObject::tr("Cannot export the plan: %1").arg(error)
                                : QObject::tr("Cannot export the plan to %1: %2").arg(path, error);
            return outcome;
        }
        if (format->noteOf)
            if (const std::string said = format->noteOf(context, path.toStdString()); !said.empty())
                outcome.notes << QString::fromStdString(said) + QStringLiteral(".");
        const std::size_t parts =
            format->splitByItemLimit ? io::autopilotMissionOf(context, robot).parts.size() : 1;
        if (format->splitByItemLimit)
            io::removeStaleMissionFiles(path.toStdString(), parts); // an earlier export's other form
        if (parts <= 1) {
            outcome.written << path;
        } else {
            for (std::size_t part = 0; part < parts; ++part)
                outcome.written << QString::fromStdString(
                    io::missionPartPath(path.toStdString(), part, parts));
            outcome.notes << QString::fromStdString(
                                 io::splitMissionNote(context, robot, path.toStdString())) +
                                 QStringLiteral(".");
        }
        if (format->splitByItemLimit)
            if (const std::string sorties = io::sortieFilesNote(context, robot, path.toStdString());
                !sorties.empty())
                outcome.notes << QString::fromStdString(sorties) + QStringLiteral(".");
        if (format->splitByItemLimit)
            if (const std::string tooLong = io::flightTimeWarning(context, robot, path.toStdString());
                !tooLong.empty())
                outcome.notes << QString::fromStdString(tooLong) + QStringLiteral(".");
        progress(file + 1, files);
    }
    return outcome;
}

} // namespace

ExportRunner::ExportRunner(QObject* parent) : QObject(parent) {
    connect(&watcher_, &QFutureWatcher<ExportOutcome>::finished, this,
            [this] { emit finished(watcher_.result()); });
}

ExportRunner::~ExportRunner() {
    disconnect(&watcher_, nullptr, this, nullptr);
    cancel();
    waitForFinished();
}

bool ExportRunner::isRunning() const {
    return watcher_.isRunning();
}

void ExportRunner::cancel() {
    if (cancelRequested_)
        cancelRequested_->store(true);
}

void ExportRunner::waitForFinished() {
    watcher_.waitForFinished();
}

bool ExportRunner::start(ExportJob job) {
    if (isRunning() || !job.plan || !job.raster)
        return false;
    cancelRequested_ = std::make_shared<std::atomic<bool>>(false);
    auto cancelFlag = cancelRequested_;
    // The destructor waits for the job, so the worker may use `this`.
    auto work = [this, cancelFlag, job = std::move(job)]() -> ExportOutcome {
        const auto progress = [this](int done, int files) {
            QMetaObject::invokeMethod(
                this, [this, done, files] { emit progressed(done, files); }, Qt::QueuedConnection);
        };
        try {
            return runJob(job, *cancelFlag, progress);
        } catch (const std::bad_alloc&) {
            return ExportOutcome{{}, {}, QObject::tr("Out of memory while exporting."), false};
        } catch (const std::exception& error) {
            return ExportOutcome{
                {}, {}, QObject::tr("Export failed: %1").arg(QString::fromStdString(error.what())), false};
        }
    };
    watcher_.setFuture(QtConcurrent::run(std::move(work)));
    return true;
}

} // namespace mcpp::ui
