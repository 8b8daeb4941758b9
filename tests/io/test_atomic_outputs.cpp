// Nothing the user made is lost: every writer (each export format, the mission, the class table, the
// comparison files) is made to fail half way through by a file-size limit (RLIMIT_FSIZE, as a full disk
// would), and the file it was replacing is found intact, with no partial or temporary file beside it.
#include "PlanFixture.hpp"
#include "core/model/DetectionLayer.hpp"
#include "io/ClassTableSources.hpp"
#include "io/ComparisonExport.hpp"
#include "io/ExportCatalogue.hpp"
#include "io/GeoReference.hpp"
#include "io/Mission.hpp"
#include "io/PlanExport.hpp"
#include "render/PlanImageWriter.hpp"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>
#include <csignal>
#include <functional>
#include <sys/resource.h>

using namespace mcpp;
using namespace mcpp::io;

namespace {

using Writer = std::function<Status(const std::string& path)>;

QByteArray readAll(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// Runs `write` with files limited to `bytes`; a write past the limit fails with EFBIG (the signal that
// would end the process is ignored meanwhile).
Status writeWithSizeLimit(const Writer& write, const std::string& path, rlim_t bytes) {
    rlimit before{};
    getrlimit(RLIMIT_FSIZE, &before);
    rlimit limited = before;
    limited.rlim_cur = bytes;
    const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
    setrlimit(RLIMIT_FSIZE, &limited);
    Status status = write(path);
    setrlimit(RLIMIT_FSIZE, &before);
    std::signal(SIGXFSZ, previousHandler);
    return status;
}

} // namespace

class TestAtomicOutputs : public QObject {
    Q_OBJECT

  private:
    Plan plan_ = test::makeFixturePlan();
    Plan planWithDetection_;
    GeoReference reference_ = GeoReference::fromDefinition("EPSG:26912").value();
    ClassTable classes_;
    ClassGrid grid_;

    void addCase(const std::string& name, const Writer& writer) { QTest::newRow(name.c_str()) << writer; }

  private slots:
    void initTestCase() {
        classes_.set(LandCoverClass{4, "Forest", 0x2e7d32, 0.5, 10.0, true});
        classes_.set(LandCoverClass{6, "Grass", 0xd4e157, 1.5, 20.0, true});
        grid_.columns = 4;
        grid_.rows = 2;
        grid_.pixelWidth = 10.0;
        grid_.pixelHeight = 10.0;
        grid_.originX = plan_.cells.frame().originX;
        grid_.originY = plan_.cells.frame().originY;
        grid_.values = {4, 4, 6, 6, 4, 4, 6, 6};
        planWithDetection_ = plan_;
        DetectionGrid detection;
        detection.originX = grid_.originX;
        detection.originY = grid_.originY;
        detection.cellSize = 5.0;
        detection.columns = 8;
        detection.rows = 4;
        for (int cell = 0; cell < detection.columns * detection.rows; ++cell) {
            detection.probability.push_back(0.9F + 0.003F * static_cast<float>(cell));
            detection.required.push_back(0.9F);
        }
        planWithDetection_.layers.push_back(std::make_shared<DetectionLayer>(detection, DetectionSummary{}));
    }

    void failedWriteKeepsThePreviousFile_data() {
        QTest::addColumn<Writer>("writer");
        for (const ExportFormat& format : exportFormats()) {
            addCase("export " + format.key, [this, &format](const std::string& path) {
                // A format for what only some plans have gets a plan that has it.
                const Plan& plan = formatApplies(format, plan_) ? plan_ : planWithDetection_;
                ExportContext context{plan, reference_, classes_, {}};
                context.grid = &grid_;
                context.drawImage = render::planImageWriter(512);
                return format.write(context, 0, path);
            });
        }
        addCase("mission", [this](const std::string& path) {
            Mission mission;
            mission.rasterPath = "land-cover.tif";
            mission.classes = classes_;
            mission.robots = {RobotSpec{"north", MapPoint{301905, 4154075}, {}}};
            return saveMission(mission, path);
        });
        addCase("class table", [this](const std::string& path) { return saveClassTableCsv(classes_, path); });
        const std::vector<ComparisonRow> rows{
            {"mcpp-mlct", ComparisonRow::Outcome::Planned, {}, plan_.metrics, 12.0, 80.0, {}},
            {"darp", ComparisonRow::Outcome::Failed, "did not converge", {}, 0, 0, {}}};
        addCase("comparison csv", [rows](const std::string& path) { return writeComparisonCsv(rows, path); });
        addCase("comparison json",
                [rows](const std::string& path) { return writeComparisonJson(rows, path); });
    }

    void failedWriteKeepsThePreviousFile() {
        QFETCH(Writer, writer);
        QTemporaryDir folder;
        const QString target = folder.filePath(QStringLiteral("output"));
        // A full write first: its size sets the limit at half of it.
        const QString probe = folder.filePath(QStringLiteral("probe"));
        const Status full = writer(probe.toStdString());
        QVERIFY2(full.ok(), full.error().c_str());
        const qint64 size = QFileInfo(probe).size();
        QVERIFY(size > 16);
        QVERIFY(QFile::remove(probe));

        const QByteArray previous = "the user's previous file\n";
        {
            QFile file(target);
            QVERIFY(file.open(QIODevice::WriteOnly) && file.write(previous) == previous.size());
        }
        const Status failed = writeWithSizeLimit(writer, target.toStdString(), static_cast<rlim_t>(size / 2));
        QVERIFY2(!failed.ok(), "the writer did not notice that the disk was full");
        QVERIFY2(failed.error().find("output") != std::string::npos, failed.error().c_str());
        QCOMPARE(readAll(target), previous);
        QCOMPARE(QDir(folder.path()).entryList(QDir::Files | QDir::Hidden | QDir::NoDotAndDotDot),
                 QStringList{QStringLiteral("output")});

        // Without the limit the same writer replaces the file.
        const Status again = writer(target.toStdString());
        QVERIFY2(again.ok(), again.error().c_str());
        QVERIFY(readAll(target) != previous);
        QCOMPARE(QFileInfo(target).size(), size);
    }
};

QTEST_MAIN(TestAtomicOutputs)
#include "test_atomic_outputs.moc"
