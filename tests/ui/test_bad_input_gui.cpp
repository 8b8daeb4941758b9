// The bad-input suite over the GUI's open paths (open raster, open mission, Load CSV): each broken file
// gives a message box that names it, never a crash, and the mission open before is untouched.
#include "BadInputCases.hpp"
#include "ui/MainWindow.hpp"
#include "ui/MissionDocument.hpp"

#include <QApplication>
#include <QDir>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

using mcpp::test::BadInputCase;
using mcpp::test::badInputCases;
using mcpp::test::GuiOpenPath;

namespace {

// Closes the next message box once it shows and keeps its text.
class MessageBoxCatcher : public QObject {
  public:
    explicit MessageBoxCatcher(QObject* parent) : QObject(parent) {
        timer_.setInterval(20);
        connect(&timer_, &QTimer::timeout, this, [this] {
            if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
                text_ = box->text();
                ++shown_;
                box->close();
            }
        });
        timer_.start();
    }
    [[nodiscard]] const QString& text() const { return text_; }
    [[nodiscard]] int shown() const { return shown_; }

  private:
    QTimer timer_;
    QString text_;
    int shown_ = 0;
};

bool open(mcpp::ui::MainWindow& window, GuiOpenPath path, const QString& file) {
    switch (path) {
    case GuiOpenPath::Raster:
        return window.openRaster(file);
    case GuiOpenPath::Mission:
        return window.openMission(file);
    case GuiOpenPath::ClassTable:
        return window.loadClassTable(file);
    case GuiOpenPath::None:
        break;
    }
    return true;
}

} // namespace

class TestBadInputGui : public QObject {
    Q_OBJECT

  private:
    QTemporaryDir scratch_;

  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("mcpp"));
        QCoreApplication::setApplicationName(QStringLiteral("mcpp-bad-input-test"));
        QSettings().clear();
        QVERIFY(scratch_.isValid());
        const QString error = mcpp::test::writeBadInputFixtures(scratch_.path());
        QVERIFY2(error.isEmpty(), qPrintable(error));
    }

    void messageBoxAndMissionKept_data() {
        QTest::addColumn<int>("index");
        int rows = 0;
        for (std::size_t i = 0; i < badInputCases().size(); ++i) {
            if (badInputCases()[i].guiPath == GuiOpenPath::None)
                continue;
            QTest::newRow(badInputCases()[i].name) << static_cast<int>(i);
            ++rows;
        }
        QVERIFY(rows >= 30);
    }

    void messageBoxAndMissionKept() {
        QFETCH(int, index);
        const BadInputCase& badInput = badInputCases()[static_cast<std::size_t>(index)];
        mcpp::ui::MainWindow window;
        window.setOpenSampleOnFirstStart(false);
        window.setDialogsEnabled(false);
        QVERIFY2(window.openMission(QDir(scratch_.path()).filePath(QStringLiteral("good.json"))),
                 qPrintable(window.lastError()));
        const mcpp::io::Mission before = window.document()->mission();
        const QString missionPath = window.document()->missionPath();
        const int undoSteps = window.undoStack()->count();

        window.setDialogsEnabled(true);
        MessageBoxCatcher catcher(&window);
        const bool opened = open(window, badInput.guiPath, QDir(scratch_.path()).filePath(badInput.guiFile));
        QVERIFY2(!opened, "a broken file was accepted");
        QCOMPARE(catcher.shown(), 1);
        QVERIFY2(catcher.text().contains(badInput.guiFile),
                 qPrintable(badInput.guiFile + " not in: " + catcher.text()));
        QVERIFY(window.document()->mission() == before);
        QCOMPARE(window.document()->missionPath(), missionPath);
        QCOMPARE(window.undoStack()->count(), undoSteps);
        QVERIFY(!window.isMissionModified());
    }
};

QTEST_MAIN(TestBadInputGui)
#include "test_bad_input_gui.moc"
