#include "core/planners/PlannerRegistry.hpp"
#include "ui/PlannerSettingsPanel.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QPointer>
#include <QSignalSpy>
#include <QSpinBox>
#include <QtTest>
#include <algorithm>

using namespace mcpp;

Q_DECLARE_METATYPE(mcpp::PlannerChoice)

// The panel is generated from each planner's declaration: every planner, every parameter, the declared
// ranges, and edits that reach the choice.
class TestPlannerSettingsPanel : public QObject {
    Q_OBJECT

  private slots:
    void everyPlannerShowsItsDeclaredParameters() {
        ui::PlannerSettingsPanel panel;
        auto* combo = panel.findChild<QComboBox*>(QStringLiteral("plannerCombo"));
        QVERIFY(combo != nullptr);
        const auto planners = plannerDescriptions();
        QCOMPARE(combo->count(), static_cast<int>(planners.size()));
        for (const PlannerDescription& planner : planners) {
            combo->setCurrentIndex(combo->findData(QString::fromStdString(planner.name)));
            QCOMPARE(panel.choice().planner, planner.name);
            for (const ParameterSpec& spec : planner.parameters) {
                QWidget* editor = panel.editorOf(spec.key);
                QVERIFY2(editor != nullptr, spec.key.c_str());
                QCOMPARE(editor->objectName(), QString::fromStdString("parameter_" + spec.key));
                QVERIFY(editor->toolTip().contains(QString::fromStdString(spec.key)));
                if (!spec.onlyWith.empty()) { // a boolean of the same planner, declared before it: no loop
                    const auto switchSpec =
                        std::find_if(planner.parameters.begin(), planner.parameters.end(),
                                     [&](const ParameterSpec& other) { return other.key == spec.onlyWith; });
                    QVERIFY2(switchSpec != planner.parameters.end(), spec.onlyWith.c_str());
                    QVERIFY2(switchSpec < planner.parameters.begin() + (&spec - planner.parameters.data()),
                             spec.key.c_str());
                    QCOMPARE(static_cast<int>(switchSpec->type), static_cast<int>(ParameterType::Boolean));
                    QVERIFY(editor->toolTip().contains(QString::fromStdString(switchSpec->label)));
                }
                switch (spec.type) {
                case ParameterType::Boolean:
                    QVERIFY(qobject_cast<QCheckBox*>(editor) != nullptr);
                    break;
                case ParameterType::Integer:
                    QVERIFY(qobject_cast<QSpinBox*>(editor) != nullptr);
                    break;
                case ParameterType::Real: {
                    auto* spin = qobject_cast<QDoubleSpinBox*>(editor);
                    QVERIFY(spin != nullptr);
                    if (spec.automatic.empty()) {
                        QCOMPARE(spin->minimum(), spec.minimum);
                    } else { // one step below the range, shown as the word
                        QVERIFY(spin->minimum() < spec.minimum);
                        QCOMPARE(spin->specialValueText(), QString::fromStdString(spec.automatic));
                    }
                    QVERIFY(spin->maximum() <= spec.maximum);
                    break;
                }
                case ParameterType::Choice:
                    QVERIFY(qobject_cast<QComboBox*>(editor) != nullptr);
                    break;
                }
            }
        }
    }

    // A parameter without effect unless a switch is on is greyed out, label too, until that switch and the
    // one it needs in turn are on: MSTC's slack needs subtree pieces, which need balanced pieces.
    void parametersWaitForTheirSwitches() {
        ui::PlannerSettingsPanel panel;
        panel.setChoice(defaultPlannerChoice("mstc"));
        auto* balanced = qobject_cast<QCheckBox*>(panel.editorOf("balanced"));
        auto* subtrees = qobject_cast<QCheckBox*>(panel.editorOf("subtree_pieces"));
        QWidget* slack = panel.editorOf("subtree_turns_slack");
        QVERIFY(balanced != nullptr && subtrees != nullptr && slack != nullptr);
        QWidget* slackLabel = nullptr;
        for (auto* form : panel.findChildren<QFormLayout*>())
            if (form->labelForField(slack) != nullptr)
                slackLabel = form->labelForField(slack);
        QVERIFY(slackLabel != nullptr);
        QVERIFY(balanced->isEnabled());
        QVERIFY(!subtrees->isEnabled());
        QVERIFY(!slack->isEnabled());
        QVERIFY(!slackLabel->isEnabled());
        subtrees->setChecked(true); // on, but balanced pieces are still off
        QVERIFY(!slack->isEnabled());
        balanced->setChecked(true);
        QVERIFY(subtrees->isEnabled());
        QVERIFY(slack->isEnabled());
        QVERIFY(slackLabel->isEnabled());
        subtrees->setChecked(false);
        QVERIFY(!slack->isEnabled());
        // A choice set from a mission greys out the same way.
        PlannerChoice fromMission = defaultPlannerChoice("mstc");
        fromMission.parameters.set("balanced", true);
        fromMission.parameters.set("subtree_pieces", true);
        panel.setChoice(fromMission);
        QVERIFY(slack->isEnabled());
        // Back to MSTC's defaults through another planner: greyed out again.
        panel.setChoice(defaultPlannerChoice("mcpp-mlct"));
        QVERIFY(panel.editorOf("purity_tolerance")->isEnabled());
        panel.setChoice(defaultPlannerChoice("mstc"));
        QVERIFY(!panel.editorOf("subtree_turns_slack")->isEnabled());
    }

    void editsReachTheChoiceAndStayInRange() {
        ui::PlannerSettingsPanel panel;
        panel.setChoice(defaultPlannerChoice("mcpp-mlct"));
        QSignalSpy edited(&panel, &ui::PlannerSettingsPanel::choiceEdited);
        auto* purity = qobject_cast<QDoubleSpinBox*>(panel.editorOf("purity_tolerance"));
        QVERIFY(purity != nullptr);
        purity->setValue(0.04);
        QCOMPARE(edited.count(), 1);
        QCOMPARE(panel.choice().parameters.real("purity_tolerance"), 0.04);
        // The declaration says purity stays below 1: the editor cannot reach it.
        purity->setValue(5.0);
        QVERIFY(panel.choice().parameters.real("purity_tolerance") < 1.0);
        auto* closed = qobject_cast<QCheckBox*>(panel.editorOf("closed_tour"));
        closed->setChecked(false);
        QCOMPARE(panel.choice().parameters.boolean("closed_tour"), false);
    }

    // The turn time shows "auto" one step below its range: one step up is 0 s, one step down auto again.
    void turnTimeStepsBetweenAutoAndNumbers() {
        ui::PlannerSettingsPanel panel;
        panel.setChoice(defaultPlannerChoice("mcpp-mlct"));
        auto* turn = qobject_cast<QDoubleSpinBox*>(panel.editorOf("turn_s"));
        QVERIFY(turn != nullptr);
        QCOMPARE(turn->text(), QString("auto"));
        turn->stepUp();
        QCOMPARE(panel.choice().parameters.real("turn_s"), 0.0);
        turn->setValue(4.5);
        QCOMPARE(panel.choice().parameters.real("turn_s"), 4.5);
        turn->setValue(turn->minimum());
        const ParameterSpec spec = TurnTimeModel::turnSecondsParameter();
        QVERIFY(spec.isAutomatic(*panel.choice().parameters.find("turn_s")));
        QCOMPARE(turn->text(), QString("auto"));
    }

    // The window hands every edit to the mission, which shows it back here while the editor still handles
    // the key or click that made it: that editor must outlive it (it was deleted under the key press, and
    // the window crashed at any edit). Another planner's choice does rebuild the form.
    void anEditShownBackKeepsItsEditor() {
        ui::PlannerSettingsPanel panel;
        panel.setChoice(defaultPlannerChoice("mcpp-mlct"));
        connect(&panel, &ui::PlannerSettingsPanel::choiceEdited, &panel,
                &ui::PlannerSettingsPanel::setChoice);
        const QPointer<QDoubleSpinBox> purity =
            qobject_cast<QDoubleSpinBox*>(panel.editorOf("purity_tolerance"));
        QVERIFY(purity != nullptr);
        purity->selectAll();
        QTest::keyClicks(purity.data(), QStringLiteral("0.03"));
        QTest::keyClick(purity.data(), Qt::Key_Enter);
        QVERIFY(purity != nullptr);
        QCOMPARE(panel.editorOf("purity_tolerance"), purity.data());
        QCOMPARE(panel.choice().parameters.real("purity_tolerance"), 0.03);
        const QPointer<QCheckBox> closed = qobject_cast<QCheckBox*>(panel.editorOf("closed_tour"));
        QTest::mouseClick(closed.data(), Qt::LeftButton, {}, QPoint(4, closed->height() / 2));
        QVERIFY(closed != nullptr);
        QCOMPARE(panel.choice().parameters.boolean("closed_tour"), false);
        panel.setChoice(defaultPlannerChoice("darp"));
        QVERIFY(purity == nullptr); // darp's form in its place
        QVERIFY(panel.editorOf("purity_tolerance") == nullptr);
    }

    void showingAChoiceIsNoEdit() {
        ui::PlannerSettingsPanel panel;
        QSignalSpy edited(&panel, &ui::PlannerSettingsPanel::choiceEdited);
        PlannerChoice choice = defaultPlannerChoice("mcpp-mlct");
        choice.parameters.set("blocked_threshold", 0.7);
        panel.setChoice(choice);
        QCOMPARE(edited.count(), 0);
        QCOMPARE(qobject_cast<QDoubleSpinBox*>(panel.editorOf("blocked_threshold"))->value(), 0.7);
        QVERIFY(panel.choice() == choice);
    }
};

QTEST_MAIN(TestPlannerSettingsPanel)
#include "test_planner_settings_panel.moc"
