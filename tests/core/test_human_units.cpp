// Numbers in messages: no exponents, no trailing zeros, the unit that suits the size.
#include "core/model/HumanUnits.hpp"

#include <QTest>
#include <limits>

using namespace mcpp;

class TestHumanUnits : public QObject {
    Q_OBJECT

  private slots:
    void quantities_data() {
        QTest::addColumn<double>("value");
        QTest::addColumn<int>("significant");
        QTest::addColumn<QString>("expected");
        QTest::newRow("whole") << 30.0 << 6 << "30";
        QTest::newRow("fraction") << 0.3168316831 << 4 << "0.3168";
        QTest::newRow("no exponent when large") << 2.75055e8 << 6 << "275055000";
        QTest::newRow("rounded to its digits") << 123456789.0 << 3 << "123000000";
        QTest::newRow("small") << 0.000125 << 3 << "0.000125";
        QTest::newRow("negative") << -2.5 << 6 << "-2.5";
        QTest::newRow("zero") << 0.0 << 6 << "0";
        QTest::newRow("NaN") << std::numeric_limits<double>::quiet_NaN() << 6 << "NaN";
        QTest::newRow("infinity") << std::numeric_limits<double>::infinity() << 6 << "infinity";
    }
    void quantities() {
        QFETCH(double, value);
        QFETCH(int, significant);
        QFETCH(QString, expected);
        QCOMPARE(QString::fromStdString(formatQuantity(value, significant)), expected);
    }

    void areas_data() {
        QTest::addColumn<double>("squareMetres");
        QTest::addColumn<QString>("expected");
        QTest::newRow("square metres") << 850.4 << "850 m2";
        QTest::newRow("hectares") << 275000.0 << "27.5 ha";
        QTest::newRow("the message of the issue") << 2.75055e8 << "275 km2";
        QTest::newRow("large") << 6.76134e7 << "67.6 km2";
        QTest::newRow("one hectare") << 1e4 << "1 ha";
    }
    void areas() {
        QFETCH(double, squareMetres);
        QFETCH(QString, expected);
        QCOMPARE(QString::fromStdString(formatArea(squareMetres)), expected);
    }

    void percentages_data() {
        QTest::addColumn<double>("fraction");
        QTest::addColumn<QString>("expected");
        QTest::newRow("half") << 0.5 << "50%";
        QTest::newRow("one decimal") << 0.12345 << "12.3%";
        QTest::newRow("small share") << 0.00123 << "0.12%";
        QTest::newRow("whole") << 1.0 << "100%";
    }
    void percentages() {
        QFETCH(double, fraction);
        QFETCH(QString, expected);
        QCOMPARE(QString::fromStdString(formatPercent(fraction)), expected);
    }

    void durations_data() {
        QTest::addColumn<double>("seconds");
        QTest::addColumn<QString>("expected");
        QTest::newRow("seconds") << 45.0 << "45 s";
        QTest::newRow("short") << 2.345 << "2.3 s";
        QTest::newRow("minutes") << 725.0 << "12 min 5 s";
        QTest::newRow("hours") << 3.0 * 3600 + 12 * 60 + 10 << "3 h 12 min";
        QTest::newRow("days, rounded to the hour") << 8909.0 * 3600 + 53 * 60 << "371 d 6 h";
        QTest::newRow("days, down to the hour") << 8909.0 * 3600 + 29 * 60 << "371 d 5 h";
        QTest::newRow("whole hour") << 7200.0 << "2 h";
        QTest::newRow("a day and a half, rounded to the minute")
            << 33.0 * 3600 + 54 * 60 + 46 << "1 d 9 h 55 min";
        QTest::newRow("hours, rounded to the minute") << 5036.8 << "1 h 24 min";
        QTest::newRow("hours, down to the minute") << 5009.0 << "1 h 23 min";
        // A flight of 59 min 58 s on a battery of an hour must not read as the hour.
        QTest::newRow("just under an hour keeps its seconds") << 3597.6 << "59 min 58 s";
        QTest::newRow("under an hour by less than the last second") << 3599.7 << "1 h";
        QTest::newRow("minutes keep their seconds") << 3569.0 << "59 min 29 s";
        QTest::newRow("just under ten days") << 10 * 86400.0 - 60 << "10 d";
        QTest::newRow("a whole day") << 86400.0 << "1 d 0 h";
    }
    void durations() {
        QFETCH(double, seconds);
        QFETCH(QString, expected);
        QCOMPARE(QString::fromStdString(formatDuration(seconds)), expected);
    }

    void distances() {
        QCOMPARE(QString::fromStdString(formatDistance(999.4)), QStringLiteral("999 m"));
        QCOMPARE(QString::fromStdString(formatDistance(12345.0)), QStringLiteral("12.3 km"));
    }
};

QTEST_APPLESS_MAIN(TestHumanUnits)
#include "test_human_units.moc"
