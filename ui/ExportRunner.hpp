#pragma once

#include "core/model/ClassTable.hpp"
#include "core/model/Plan.hpp"
#include "io/LoadedRaster.hpp"
#include "io/Mission.hpp"

#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <QStringList>
#include <atomic>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace mcpp::ui {

// One export the window asked for: a format of the catalogue and the files it writes. The plan and raster
// are shared, so the job is unaffected by what the user does while it runs.
struct ExportJob {
    std::string formatKey;
    std::vector<std::pair<int, QString>> files; // robot (ignored by whole-plan formats) and path
    std::shared_ptr<const Plan> plan;
    std::shared_ptr<const io::LoadedRaster> raster;
    ClassTable classes;
    io::ExportSettings settings;
    std::vector<std::string> robotNames;
    std::vector<io::VehicleSettings> vehicles; // by robot
    int imageSide = 3000;
};

struct ExportOutcome {
    QStringList written;
    QStringList notes; // what the user should know about the files, such as a mission split into parts
    QString error;     // empty on success
    bool cancelled = false;
};

// Writes an export on a worker thread so the window never blocks on a writer (a GeoPackage of a big plan
// takes seconds). Progress arrives per file as queued signals; cancel() stops the writer at its next
// feature, row or file, and the unfinished file is removed (writers write to a temporary name).
class ExportRunner : public QObject {
    Q_OBJECT

  public:
    explicit ExportRunner(QObject* parent = nullptr);
    ~ExportRunner() override;

    bool start(ExportJob job); // false (and nothing started) while an export runs
    void cancel();
    [[nodiscard]] bool isRunning() const;
    void waitForFinished();

  signals:
    void progressed(int filesDone, int files);
    void finished(const mcpp::ui::ExportOutcome& outcome);

  private:
    QFutureWatcher<ExportOutcome> watcher_;
    std::shared_ptr<std::atomic<bool>> cancelRequested_;
};

} // namespace mcpp::ui
