// The robots a message names by number, for callers that know them by name.
#include "core/model/RobotNumbers.hpp"

#include <QTest>

using namespace mcpp;

class TestRobotNumbers : public QObject {
    Q_OBJECT

  private slots:
    void numbers_data() {
        QTest::addColumn<QString>("message");
        QTest::addColumn<QList<int>>("expected");
        QTest::newRow("one") << "robot 3 start moved" << QList<int>{3};
        QTest::newRow("each once, in order")
            << "robot 4 waits for robot 2, and robot 4 then" << QList<int>{2, 4};
        QTest::newRow("a list") << "closed in by the starts of robots 1, 2 and 5: its" << QList<int>{1, 2, 5};
        QTest::newRow("a pair") << "robots 2 and 13 cover less" << QList<int>{2, 13};
        QTest::newRow("robots not named") << "robots 1, 2 and 13 more cover less" << QList<int>{1, 2};
        QTest::newRow("a figure after a robot")
            << "robot 2, 30 m away, and robot 4 and 5 m more" << QList<int>{2, 4};
        QTest::newRow("no robot") << "robotic 3 and 4 robots" << QList<int>{};
    }
    void numbers() {
        QFETCH(QString, message);
        QFETCH(QList<int>, expected);
        QList<int> found;
        for (const std::size_t robot : robotNumbersIn(message.toStdString()))
            found.push_back(static_cast<int>(robot));
        QCOMPARE(found, expected);
    }
};

QTEST_APPLESS_MAIN(TestRobotNumbers)
#include "test_robot_numbers.moc"
