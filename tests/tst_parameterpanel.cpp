#include "ParameterPanel.h"
#include "io/ParameterIo.h"

#include <QAction>
#include <QCheckBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QTemporaryDir>
#include <QToolButton>
#include <QUndoCommand>
#include <QUndoStack>
#include <QVBoxLayout>
#include <QtTest>

#include <cmath>

using namespace footpath;

namespace {

const ParameterField& field(const char* name)
{
    const ParameterField* found = findParameterField(name);
    if (!found)
        qFatal("no parameter field %s", name);
    return *found;
}

SliderScale scaleOf(const char* name)
{
    return SliderScale::forField(field(name), parameterValue(Parameters(), field(name)));
}

/// Names the first field where a and b differ, or returns an empty string.
QString firstDifference(const Parameters& a, const Parameters& b)
{
    for (const ParameterField& f : parameterFields())
        if (parameterValue(a, f) != parameterValue(b, f))
            return QStringLiteral("%1: %2 vs %3").arg(f.name).arg(parameterValue(a, f)).arg(parameterValue(b, f));
    return {};
}

/// A valid set in which every field differs from its default.
Parameters everyFieldChanged()
{
    Parameters params;
    for (const ParameterField& f : parameterFields()) {
        if (f.kind == ParameterField::Kind::Flag)
            params.*f.flag = !(params.*f.flag);
        else
            params.*f.real = f.minimum + 0.37 * (f.maximum - f.minimum);  // 0.37: not a default anywhere
    }
    return params;
}

/// Records what undo/redo did, so a test can count the steps taken.
class CountingCommand : public QUndoCommand {
public:
    explicit CountingCommand(int& value) : QUndoCommand(QStringLiteral("count")), value_(value) {}
    void undo() override { --value_; }
    void redo() override { ++value_; }

private:
    int& value_;
};

}  // namespace

class TestParameterPanel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { qRegisterMetaType<footpath::Parameters>(); }

    void hasOneControlPerField()
    {
        ParameterPanel panel;
        int reals = 0;
        int flags = 0;
        for (const ParameterField& f : parameterFields()) {
            const QString name = QString::fromUtf8(f.name);
            if (f.kind == ParameterField::Kind::Real) {
                ++reals;
                QCOMPARE(panel.findChildren<QSlider*>(QStringLiteral("slider_") + name).size(), 1);
                QCOMPARE(panel.findChildren<QLineEdit*>(QStringLiteral("value_") + name).size(), 1);
            } else {
                ++flags;
                QCOMPARE(panel.findChildren<QCheckBox*>(QStringLiteral("check_") + name).size(), 1);
            }
        }
        QCOMPARE(panel.findChildren<QSlider*>().size(), reals);
        QCOMPARE(panel.findChildren<QCheckBox*>().size(), flags);
        QVERIFY(flags >= 2);  // use_zupt, use_zaru
    }

    void showsTheGivenValuesWithoutEmitting()
    {
        ParameterPanel panel;
        QSignalSpy edited(&panel, &ParameterPanel::parameterEdited);
        Parameters params;
        params.acc_std_max_mps2 = 1.25;
        params.q_vel_mps = 3e-3;
        params.use_zaru = false;
        panel.setParameters(params);
        QCOMPARE(edited.count(), 0);
        QCOMPARE(panel.findChild<QLineEdit*>("value_acc_std_max_mps2")->text(), QStringLiteral("1.25"));
        QCOMPARE(panel.findChild<QSlider*>("slider_q_vel_mps")->value(), scaleOf("q_vel_mps").toPosition(3e-3));
        QVERIFY(!panel.findChild<QCheckBox*>("check_use_zaru")->isChecked());
        QVERIFY(firstDifference(panel.parameters(), params).isEmpty());
    }

    void choosesALogarithmicScaleWhereTheRangeSpansDecades_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<bool>("logarithmic");
        QTest::addColumn<bool>("zeroStop");
        QTest::newRow("q from 0, small default") << "q_att_rad" << true << true;
        QTest::newRow("q from 0, default 0") << "q_gyro_bias_radps" << true << true;
        QTest::newRow("p0 from 0") << "p0_acc_bias_mps2" << true << true;
        QTest::newRow("r from 1e-6") << "r_zupt_mps" << true << false;
        QTest::newRow("alignment 0.05..600") << "alignment_s" << true << false;
        QTest::newRow("detector threshold") << "acc_std_max_mps2" << false << false;
        QTest::newRow("gravity") << "gravity_mps2" << false << false;
        QTest::newRow("declination, negative minimum") << "declination_rad" << false << false;
    }

    void choosesALogarithmicScaleWhereTheRangeSpansDecades()
    {
        QFETCH(QString, name);
        QFETCH(bool, logarithmic);
        QFETCH(bool, zeroStop);
        const SliderScale scale = scaleOf(name.toUtf8().constData());
        QCOMPARE(scale.isLogarithmic(), logarithmic);
        QCOMPARE(scale.hasZeroStop(), zeroStop);
    }

    void everyPositionRoundTripsAndTheEndsAreExact()
    {
        for (const ParameterField& f : parameterFields()) {
            if (f.kind != ParameterField::Kind::Real)
                continue;
            const SliderScale scale = SliderScale::forField(f, parameterValue(Parameters(), f));
            const QByteArray name(f.name);
            QCOMPARE(scale.toValue(0), scale.hasZeroStop() ? 0.0 : f.minimum);
            QCOMPARE(scale.toValue(scale.maximumPosition()), f.maximum);
            QCOMPARE(scale.toPosition(f.maximum), scale.maximumPosition());
            QCOMPARE(scale.toPosition(scale.hasZeroStop() ? 0.0 : f.minimum), 0);
            for (int position = 0; position <= scale.maximumPosition(); ++position) {
                const double value = scale.toValue(position);
                QVERIFY2(value >= f.minimum && value <= f.maximum, name.constData());
                QVERIFY2(scale.toPosition(value) == position,
                         qPrintable(QStringLiteral("%1 position %2 -> %3").arg(f.name).arg(position).arg(value)));
            }
        }
    }

    void theLogMappingHitsTheMiddleWithinOnePosition_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<double>("value");
        QTest::newRow("q_att_rad 1e-3") << "q_att_rad" << 1e-3;
        QTest::newRow("q_att_rad default 1e-4") << "q_att_rad" << 1e-4;
        QTest::newRow("r_zupt_mps 3.16e-3") << "r_zupt_mps" << 3.16e-3;
        QTest::newRow("p0_pos_m 0.1") << "p0_pos_m" << 0.1;
        QTest::newRow("alignment_s 5.5") << "alignment_s" << 5.5;
    }

    void theLogMappingHitsTheMiddleWithinOnePosition()
    {
        QFETCH(QString, name);
        QFETCH(double, value);
        const SliderScale scale = scaleOf(name.toUtf8().constData());
        const double shown = scale.toValue(scale.toPosition(value));
        const double onePosition = std::pow(10.0, 1.0 / 100.0);  // 100 positions per decade
        QVERIFY2(shown / value < std::sqrt(onePosition) * 1.001 && value / shown < std::sqrt(onePosition) * 1.001,
                 qPrintable(QStringLiteral("%1 -> %2").arg(value).arg(shown)));
        // The first position above the zero stop is six decades below the maximum.
        if (scale.hasZeroStop())
            QCOMPARE(scale.toValue(1), field(name.toUtf8().constData()).maximum * 1e-6);
    }

    void movingASliderEmitsTheMappedValue_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("position");
        QTest::newRow("log, middle") << "q_att_rad" << 301;
        QTest::newRow("log, zero stop") << "q_att_rad" << 0;
        QTest::newRow("log, top") << "r_zaru_radps" << 700;
        QTest::newRow("linear") << "acc_std_max_mps2" << 40;
        QTest::newRow("linear, negative range") << "declination_rad" << 250;
    }

    void movingASliderEmitsTheMappedValue()
    {
        QFETCH(QString, name);
        QFETCH(int, position);
        ParameterPanel panel;
        QSignalSpy edited(&panel, &ParameterPanel::parameterEdited);
        auto* slider = panel.findChild<QSlider*>(QStringLiteral("slider_") + name);
        QVERIFY(slider);
        slider->setValue(position);
        QCOMPARE(edited.count(), 1);
        const double expected = scaleOf(name.toUtf8().constData()).toValue(position);
        QCOMPARE(edited.first().at(0).toString(), name);
        QCOMPARE(edited.first().at(1).toDouble(), expected);
        QCOMPARE(panel.findChild<QLineEdit*>(QStringLiteral("value_") + name)->text(),
                 QLocale().toString(expected, 'g', 6));
    }

    void draggingReportsContinuouslyAndAlwaysTheFinalValue()
    {
        ParameterPanel panel;
        QSignalSpy edited(&panel, &ParameterPanel::parameterEdited);
        auto* slider = panel.findChild<QSlider*>("slider_acc_std_max_mps2");
        slider->setSliderDown(true);
        slider->setValue(30);  // the first move is reported at once
        QCOMPARE(edited.count(), 1);
        slider->setValue(31);
        slider->setValue(32);  // within the throttle interval: only the newest is kept
        QVERIFY(edited.wait(1000));
        QCOMPARE(edited.count(), 2);
        QCOMPARE(edited.last().at(1).toDouble(), scaleOf("acc_std_max_mps2").toValue(32));

        slider->setValue(33);
        slider->setValue(34);
        slider->setSliderDown(false);  // release: the last value goes out without waiting
        QCOMPARE(edited.last().at(1).toDouble(), scaleOf("acc_std_max_mps2").toValue(34));
        const qsizetype afterRelease = edited.count();
        QTest::qWait(100);
        QCOMPARE(edited.count(), afterRelease);  // nothing stale follows
    }

    void aDraggedSliderIsNotMovedFromOutside()
    {
        ParameterPanel panel;
        auto* dragged = panel.findChild<QSlider*>("slider_gyr_max_radps");
        dragged->setSliderDown(true);
        dragged->setValue(700);
        Parameters fromSession;  // the session echoes an older value while the user drags
        fromSession.acc_std_max_mps2 = 2.0;
        panel.setParameters(fromSession);
        QCOMPARE(dragged->value(), 700);
        QCOMPARE(panel.parameters().gyr_max_radps, scaleOf("gyr_max_radps").toValue(700));
        QCOMPARE(panel.findChild<QSlider*>("slider_acc_std_max_mps2")->value(), scaleOf("acc_std_max_mps2").toPosition(2.0));
        dragged->setSliderDown(false);
        panel.setParameters(fromSession);  // released: outside values apply again
        QCOMPARE(dragged->value(), scaleOf("gyr_max_radps").toPosition(fromSession.gyr_max_radps));
    }

    void typingAValueEmitsIt_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("typed");
        QTest::addColumn<double>("expected");
        QTest::newRow("plain") << "acc_std_max_mps2" << "0.75" << 0.75;
        QTest::newRow("scientific") << "q_att_rad" << "2.5e-3" << 2.5e-3;
        QTest::newRow("zero on a log scale") << "q_vel_mps" << "0" << 0.0;
        QTest::newRow("above the range is clamped") << "acc_std_max_mps2" << "50" << 20.0;
        QTest::newRow("negative") << "declination_rad" << "-0.1" << -0.1;
    }

    void typingAValueEmitsIt()
    {
        QFETCH(QString, name);
        QFETCH(QString, typed);
        QFETCH(double, expected);
        ParameterPanel panel;
        QSignalSpy edited(&panel, &ParameterPanel::parameterEdited);
        auto* edit = panel.findChild<QLineEdit*>(QStringLiteral("value_") + name);
        edit->selectAll();
        QTest::keyClicks(edit, typed);
        QTest::keyClick(edit, Qt::Key_Return);
        QCOMPARE(edited.count(), 1);
        QCOMPARE(edited.first().at(0).toString(), name);
        QCOMPARE(edited.first().at(1).toDouble(), expected);
        const SliderScale scale = scaleOf(name.toUtf8().constData());
        QCOMPARE(panel.findChild<QSlider*>(QStringLiteral("slider_") + name)->value(), scale.toPosition(expected));
    }

    void togglingAMethodEmitsIt()
    {
        ParameterPanel panel;
        QSignalSpy edited(&panel, &ParameterPanel::parameterEdited);
        panel.findChild<QCheckBox*>("check_use_zaru")->click();
        QCOMPARE(edited.count(), 1);
        QCOMPARE(edited.first().at(0).toString(), QStringLiteral("use_zaru"));
        QCOMPARE(edited.first().at(1).toDouble(), 0.0);
        QVERIFY(!panel.parameters().use_zaru);
    }

    void resetEmitsTheDefaults()
    {
        ParameterPanel panel;
        panel.setParameters(everyFieldChanged());
        QSignalSpy replaced(&panel, &ParameterPanel::parametersReplaced);
        panel.findChild<QPushButton*>("resetAll")->click();
        QCOMPARE(replaced.count(), 1);
        const auto params = replaced.first().at(0).value<footpath::Parameters>();
        QCOMPARE(firstDifference(params, Parameters()), QString());
        QCOMPARE(firstDifference(panel.parameters(), Parameters()), QString());
        QVERIFY(!replaced.first().at(1).toString().isEmpty());  // the undo step's text
    }

    void aSavedPresetLoadsBackEveryValue()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("every field.json"));
        const Parameters changed = everyFieldChanged();
        QVERIFY(changed.validate().empty());
        ParameterPanel panel;
        panel.setParameters(changed);
        QVERIFY2(panel.savePreset(path), qPrintable(panel.presetError()));
        panel.setParameters(Parameters());
        QSignalSpy replaced(&panel, &ParameterPanel::parametersReplaced);
        QVERIFY2(panel.loadPreset(path), qPrintable(panel.presetError()));
        QCOMPARE(replaced.count(), 1);
        QCOMPARE(firstDifference(replaced.first().at(0).value<footpath::Parameters>(), changed), QString());
        QCOMPARE(firstDifference(panel.parameters(), changed), QString());
        QVERIFY(replaced.first().at(1).toString().contains(QStringLiteral("every field.json")));
    }

    void aBrokenPresetIsReportedInWordsAndChangesNothing_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("not JSON") << QByteArray("{ nope") << "byte";
        QTest::newRow("unknown field")
            << QByteArray(R"({"format": "footpath-parameters", "version": 1, "parameters": {"nonsense": 1}})")
            << "nonsense";
        QTest::newRow("invalid set")
            << QByteArray(R"({"format": "footpath-parameters", "version": 1, "parameters": {"acc_min_mps2": 30}})")
            << "acc_min_mps2";
    }

    void aBrokenPresetIsReportedInWordsAndChangesNothing()
    {
        QFETCH(QByteArray, content);
        QFETCH(QString, mentions);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("broken.json"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(content);
        file.close();
        ParameterPanel panel;
        QSignalSpy replaced(&panel, &ParameterPanel::parametersReplaced);
        QVERIFY(!panel.loadPreset(path));
        QVERIFY2(panel.presetError().contains(mentions), qPrintable(panel.presetError()));
        QCOMPARE(replaced.count(), 0);
        QCOMPARE(firstDifference(panel.parameters(), Parameters()), QString());
        QVERIFY(!panel.loadPreset(dir.filePath(QStringLiteral("missing.json"))));
        QVERIFY(panel.presetError().contains(QStringLiteral("missing.json")));
    }

    void aValueOffItsDefaultIsMarked()
    {
        ParameterPanel panel;
        auto* label = panel.findChild<QLabel*>("label_q_att_rad");
        auto* reset = panel.findChild<QToolButton*>("reset_q_att_rad");
        auto* zaru = panel.findChild<QCheckBox*>("check_use_zaru");
        QVERIFY(!label->font().bold());
        QVERIFY(reset->isHidden());
        QVERIFY(!zaru->font().bold());
        Parameters params;
        params.q_att_rad = 0.02;
        params.use_zaru = false;
        panel.setParameters(params);
        QVERIFY(label->font().bold());
        QVERIFY(!reset->isHidden());
        QVERIFY(zaru->font().bold());
        QVERIFY(!panel.findChild<QLabel*>("label_q_vel_mps")->font().bold());

        QSignalSpy edited(&panel, &ParameterPanel::parameterEdited);
        reset->click();  // back to the default, reported like any edit
        QCOMPARE(edited.count(), 1);
        QCOMPARE(edited.first().at(1).toDouble(), Parameters().q_att_rad);
        QVERIFY(!label->font().bold());
        QVERIFY(reset->isHidden());
    }

    void anInvalidCombinationIsShownInWords()
    {
        ParameterPanel panel;
        auto* problems = panel.findChild<QLabel*>("problems");
        QVERIFY(problems->isHidden());
        auto* accMin = panel.findChild<QSlider*>("slider_acc_min_mps2");
        accMin->setValue(accMin->maximum());  // 50 m/s^2, above acc_max_mps2 (11)
        QVERIFY(!problems->isHidden());
        QVERIFY2(problems->text().contains(QStringLiteral("acc_max_mps2")), qPrintable(problems->text()));
        panel.setParameters(Parameters());
        QVERIFY(problems->isHidden());
    }

    void undoAndRedoFollowTheStack()
    {
        ParameterPanel panel;
        auto* undo = panel.findChild<QToolButton*>("undo");
        auto* redo = panel.findChild<QToolButton*>("redo");
        QVERIFY(!undo->isEnabled());  // no stack yet
        QUndoStack stack;
        int value = 0;
        panel.setUndoStack(&stack);
        QVERIFY(!undo->isEnabled());
        stack.push(new CountingCommand(value));
        stack.push(new CountingCommand(value));
        QCOMPARE(value, 2);
        QVERIFY(undo->isEnabled());
        undo->click();
        QCOMPARE(value, 1);
        QVERIFY(redo->isEnabled());
        redo->click();
        QCOMPARE(value, 2);
    }

    void undoKeysWorkInsideThePanelBesideAWindowUndo()
    {
        // The main window binds the same keys in its Edit menu; both must not cancel each other.
        QUndoStack stack;
        int value = 0;
        QWidget window;
        auto* outside = new QPushButton(QStringLiteral("outside"));
        auto* panel = new ParameterPanel;
        auto* layout = new QVBoxLayout(&window);
        layout->addWidget(outside);
        layout->addWidget(panel);
        QAction* windowUndo = stack.createUndoAction(&window);
        windowUndo->setShortcut(QKeySequence::Undo);
        window.addAction(windowUndo);
        panel->setUndoStack(&stack);
        for (int i = 0; i < 3; ++i)
            stack.push(new CountingCommand(value));
        window.show();
        window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&window));

        outside->setFocus();
        QTest::keySequence(outside, QKeySequence::Undo);
        QCOMPARE(value, 2);  // the window's own Undo
        auto* slider = panel->findChild<QSlider*>("slider_q_att_rad");
        slider->setFocus();
        QTest::keySequence(slider, QKeySequence::Undo);
        QCOMPARE(value, 1);  // exactly one step, not none (ambiguous) and not two
        QTest::keySequence(slider, QKeySequence::Redo);
        QCOMPARE(value, 2);
    }
};

QTEST_MAIN(TestParameterPanel)
#include "tst_parameterpanel.moc"
