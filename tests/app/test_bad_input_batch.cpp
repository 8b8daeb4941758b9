// The bad-input suite over batch mode: every row of the table gives its exit code and, on bad input, one
// line on stderr naming what is wrong; no output folder is made, and no input file is written.
#include "BadInputCases.hpp"

#include <QCryptographicHash>
#include <QDir>
#include <QDirIterator>
#include <QFileInfo>
#include <QMap>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using mcpp::test::BadInputCase;
using mcpp::test::badInputCases;

namespace {

// Every file under a folder with a digest of its bytes: a changed or added side file shows.
QMap<QString, QByteArray> snapshot(const QString& folder) {
    QMap<QString, QByteArray> files;
    QDirIterator entries(folder, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
    while (entries.hasNext()) {
        const QString path = entries.next();
        QFile file(path);
        if (file.open(QIODevice::ReadOnly))
            files.insert(path, QCryptographicHash::hash(file.readAll(), QCryptographicHash::Sha256));
    }
    return files;
}

} // namespace

class TestBadInputBatch : public QObject {
    Q_OBJECT

  private:
    QTemporaryDir scratch_;
    QString fixtures_;
    QMap<QString, QByteArray> before_;

  private slots:
    void initTestCase() {
        QVERIFY(scratch_.isValid());
        fixtures_ = scratch_.filePath(QStringLiteral("inputs"));
        QVERIFY(QDir().mkpath(fixtures_));
        const QString error = mcpp::test::writeBadInputFixtures(fixtures_);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        before_ = snapshot(fixtures_);
        QVERIFY(badInputCases().size() >= 50);
    }

    void exitCodeAndMessage_data() {
        QTest::addColumn<int>("index");
        for (std::size_t i = 0; i < badInputCases().size(); ++i)
            QTest::newRow(badInputCases()[i].name) << static_cast<int>(i);
    }

    void exitCodeAndMessage() {
        QFETCH(int, index);
        const BadInputCase& badInput = badInputCases()[static_cast<std::size_t>(index)];
        const QString out = scratch_.filePath(QStringLiteral("out-%1").arg(index));
        QProcess process;
        process.start(qEnvironmentVariable("MCPP_EXECUTABLE"),
                      QStringList{"--batch"} + mcpp::test::expandArguments(badInput, fixtures_, out));
        QVERIFY(process.waitForFinished(120000));
        const QString standardError = QString::fromUtf8(process.readAllStandardError());
        QVERIFY2(process.exitStatus() == QProcess::NormalExit, qPrintable("crashed: " + standardError));
        QVERIFY2(process.exitCode() == badInput.exitCode,
                 qPrintable(QStringLiteral("exit %1, expected %2: %3")
                                .arg(process.exitCode())
                                .arg(badInput.exitCode)
                                .arg(standardError)));
        const QString fragment = QString(badInput.fragment).replace(QStringLiteral("{dir}"), fixtures_);
        QVERIFY2(standardError.contains(fragment),
                 qPrintable("\"" + fragment + "\" not in: " + standardError));
        if (badInput.exitCode == 2) {
            QVERIFY2(standardError.startsWith(QStringLiteral("mcpp: ")) && standardError.count('\n') == 1 &&
                         standardError.endsWith('\n'),
                     qPrintable("not one line: " + standardError));
            QVERIFY(process.readAllStandardOutput().isEmpty());
            QVERIFY2(!QFileInfo::exists(out), "bad input must not create the output folder");
        }
    }

    void inputsAreNeverWritten() {
        // Runs after every case: the fixtures, rasters and their side files included, are as made.
        QCOMPARE(snapshot(fixtures_), before_);
    }
};

QTEST_GUILESS_MAIN(TestBadInputBatch)
#include "test_bad_input_batch.moc"
