#include "AnalysisSession.h"
#include "ParameterPanel.h"
#include "io/ParameterIo.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
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
    double fraction = 0.37;  // not a default anywhere; rising, so lower bounds stay below upper ones
    for (const ParameterField& f : parameterFields()) {
        switch (f.kind) {
        case ParameterField::Kind::Flag: params.*f.flag = !(params.*f.flag); break;
        case ParameterField::Kind::Choice:
            params.*f.choice = (params.*f.choice + 1) % static_cast<int>(f.choiceNames.size());
            break;
        case ParameterField::Kind::Real: params.*f.real = f.minimum + fraction * (f.maximum - f.minimum); break;
        }
        fraction += 0.001;
    }
    return params;
}

/// The defaults with the 15-state filter, whose bias fields and ZARU then apply.
Parameters withBiasStates()
{
    Parameters params;
    params.filter_states = static_cast<int>(FilterStates::Fifteen);
    return params;
}

/// The defaults with the paper's C1/C2/C3 detector, whose fields are then the ones that apply.
Parameters paperDetector()
{
    Parameters params;
    params.detector = static_cast<int>(DetectorKind::PaperC1C2C3);
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
        int choices = 0;
        for (const ParameterField& f : parameterFields()) {
            const QString name = QString::fromUtf8(f.name);
            switch (f.kind) {
            case ParameterField::Kind::Real:
                ++reals;
                QCOMPARE(panel.findChildren<QSlider*>(QStringLiteral("slider_") + name).size(), 1);
                QCOMPARE(panel.findChildren<QLineEdit*>(QStringLiteral("value_") + name).size(), 1);
                break;
            case ParameterField::Kind::Flag:
                ++flags;
                QCOMPARE(panel.findChildren<QCheckBox*>(QStringLiteral("check_") + name).size(), 1);
                break;
            case ParameterField::Kind::Choice:
                ++choices;
                QCOMPARE(panel.findChildren<QComboBox*>(QStringLiteral("choice_") + name).size(), 1);
                break;
            }
        }
        QCOMPARE(panel.findChildren<QSlider*>().size(), reals);
        QCOMPARE(panel.findChildren<QCheckBox*>().size(), flags);
        QCOMPARE(panel.findChildren<QComboBox*>().size(), choices);
        QVERIFY(flags >= 2);    // use_zupt, use_zaru
        QVERIFY(choices >= 2);  // detector, filter_states
    }

    void everyFieldShowsItsLabelAndUnitWithTheIdentifierInTheToolTip()
    {
        ParameterPanel panel;
        for (const ParameterField& f : parameterFields()) {
            const QString name = QString::fromUtf8(f.name);
            QWidget* nameWidget = f.kind == ParameterField::Kind::Flag
                                      ? static_cast<QWidget*>(panel.findChild<QCheckBox*>(QStringLiteral("check_") + name))
                                      : panel.findChild<QLabel*>(QStringLiteral("label_") + name);
            QVERIFY2(nameWidget, qPrintable(name));
            const QString text = f.kind == ParameterField::Kind::Flag ? static_cast<QCheckBox*>(nameWidget)->text()
                                                                      : static_cast<QLabel*>(nameWidget)->text();
            QCOMPARE(text, QString::fromStdString(labelWithUnit(f)));
            QVERIFY2(text != name && !text.contains(QLatin1Char('_')), qPrintable(name));  // words, not the identifier
            QVERIFY2(nameWidget->toolTip().contains(name), qPrintable(name + ": " + nameWidget->toolTip()));
            QVERIFY2(nameWidget->toolTip().contains(QString::fromUtf8(f.description).toHtmlEscaped()), qPrintable(name));
        }
    }

    void everySliderStepIsFine()
    {
        // One position moves a logarithmic value by a few per cent and a linear one by a thousandth
        // of its range, so no field jumps (a 1 -> 3.16 step over a few pixels was the complaint).
        const Parameters defaults;
        for (const ParameterField& f : parameterFields()) {
            if (f.kind != ParameterField::Kind::Real)
                continue;
            const SliderScale scale = SliderScale::forField(f, parameterValue(defaults, f));
            const int from = scale.hasZeroStop() ? 2 : 1;
            for (int position = from; position <= scale.maximumPosition(); ++position) {
                const double low = scale.toValue(position - 1), high = scale.toValue(position);
                QVERIFY2(high > low, qPrintable(QString::fromUtf8(f.name)));
                if (scale.isLogarithmic())
                    QVERIFY2(high / low < 1.04, qPrintable(QStringLiteral("%1 at %2").arg(f.name).arg(position)));
                else
                    QVERIFY2(high - low <= 1.5e-3 * (f.maximum - f.minimum), qPrintable(QString::fromUtf8(f.name)));
            }
        }
    }

    void upAndDownInTheValueFieldStepOnePosition()
    {
        ParameterPanel panel;
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QSignalSpy edited(&panel, &ParameterPanel::parameterEdited);
        auto* edit = panel.findChild<QLineEdit*>("value_zv_window_s");
        const SliderScale scale = scaleOf("zv_window_s");
        const int start = scale.toPosition(Parameters().zv_window_s);
        QVERIFY(edit->isEnabled());
        edit->setFocus();
        QTest::keyClick(edit, Qt::Key_Up);
        QTRY_VERIFY(!edited.isEmpty());
        QCOMPARE(edited.last().at(0).toString(), QStringLiteral("zv_window_s"));
        QCOMPARE(edited.last().at(1).toDouble(), scale.toValue(start + 1));
        QCOMPARE(panel.parameters().zv_window_s, scale.toValue(start + 1));
        QCOMPARE(edit->text(), QLocale().toString(scale.toValue(start + 1), 'g', 6));
        QTest::keyClick(edit, Qt::Key_PageDown);
        QCOMPARE(panel.parameters().zv_window_s, scale.toValue(start + 1 - scale.pageStep()));
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
            QCOMPARE(scale.toValue(scale.maximumPosition()), scale.sliderMaximum());
            QVERIFY(scale.sliderMaximum() <= f.maximum);
            QCOMPARE(scale.toPosition(f.maximum), scale.maximumPosition());  // a larger typed value: the end
            QCOMPARE(scale.toPosition(scale.hasZeroStop() ? 0.0 : f.minimum), 0);
            for (int position = 0; position <= scale.maximumPosition(); ++position) {
                const double value = scale.toValue(position);
                QVERIFY2(value >= f.minimum && value <= f.maximum, name.constData());
                QVERIFY2(scale.toPosition(value) == position,
                         qPrintable(QStringLiteral("%1 position %2 -> %3").arg(f.name).arg(position).arg(value)));
            }
        }
    }

    void aWideLinearRangeSpansTheUsefulValues()
    {
        // A 50-pixel drag moved the shortest stance from 0.02 to 0.66 s: its slider spanned the
        // whole 0-2 s range. It spans 0-0.5 s now (ten times the default 0.05 s), and the field
        // still takes anything up to 2 s.
        const SliderScale stance = scaleOf("zv_min_stance_s");
        QCOMPARE(stance.sliderMaximum(), 0.5);
        QCOMPARE(stance.toPosition(1.5), stance.maximumPosition());
        const double perPosition = (stance.toValue(stance.maximumPosition()) - stance.toValue(0)) / stance.maximumPosition();
        QVERIFY(perPosition <= 0.5e-3 + 1e-12);
        QStringList spanned;
        for (const ParameterField& f : parameterFields())
            if (f.kind == ParameterField::Kind::Real) {
                const SliderScale scale = SliderScale::forField(f, parameterValue(Parameters(), f));
                if (scale.sliderMaximum() < f.maximum)
                    spanned << QStringLiteral("%1 0-%2 of %3").arg(f.name).arg(scale.sliderMaximum()).arg(f.maximum);
                // Every default is on its slider, never beyond the end.
                QVERIFY2(parameterValue(Parameters(), f) <= scale.sliderMaximum(), f.name);
            }
        qInfo("%s", qPrintable(spanned.join(QStringLiteral("; "))));
        ParameterPanel panel;
        QVERIFY(panel.findChild<QSlider*>("slider_zv_min_stance_s")->toolTip().contains(QStringLiteral("the slider up to 0.5")));
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
        panel.setParameters(paperDetector());  // acc_std_max_mps2 is disabled for the others
        QSignalSpy edited(&panel, &ParameterPanel::parameterEdited);
        auto* edit = panel.findChild<QLineEdit*>(QStringLiteral("value_") + name);
        QVERIFY(edit->isEnabled());
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
        panel.setParameters(withBiasStates());  // ZARU is disabled without them
        QSignalSpy edited(&panel, &ParameterPanel::parameterEdited);
        const bool toggled = !Parameters().use_zaru;
        panel.findChild<QCheckBox*>("check_use_zaru")->click();
        QCOMPARE(edited.count(), 1);
        QCOMPARE(edited.first().at(0).toString(), QStringLiteral("use_zaru"));
        QCOMPARE(edited.first().at(1).toDouble(), toggled ? 1.0 : 0.0);
        QCOMPARE(panel.parameters().use_zaru, toggled);
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
        panel.setParameters(withBiasStates());
        auto* label = panel.findChild<QLabel*>("label_q_att_rad");
        auto* reset = panel.findChild<QToolButton*>("reset_q_att_rad");
        auto* zaru = panel.findChild<QCheckBox*>("check_use_zaru");
        QVERIFY(!label->font().bold());
        QVERIFY(reset->isHidden());
        QVERIFY(!zaru->font().bold());
        Parameters params = withBiasStates();
        params.q_att_rad = 0.02;
        params.use_zaru = !params.use_zaru;
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

    void aChoiceIsAComboBoxOfItsLabels()
    {
        ParameterPanel panel;
        const ParameterField& detector = field("detector");
        auto* combo = panel.findChild<QComboBox*>("choice_detector");
        QVERIFY(combo);
        QCOMPARE(combo->count(), static_cast<int>(detector.choiceLabels.size()));
        for (int i = 0; i < combo->count(); ++i) {
            QCOMPARE(combo->itemText(i), QString::fromUtf8(detector.choiceLabels[static_cast<std::size_t>(i)]));
            // What presets and --set call it.
            QCOMPARE(combo->itemData(i, Qt::ToolTipRole).toString(),
                     QString::fromUtf8(detector.choiceNames[static_cast<std::size_t>(i)]));
        }
        QCOMPARE(combo->currentIndex(), Parameters().detector);
        QVERIFY(combo->toolTip().contains(QStringLiteral("detector")));
        QVERIFY(combo->toolTip().contains(QString::fromUtf8(detector.description)));

        Parameters params;
        params.detector = static_cast<int>(DetectorKind::Ared);
        panel.setParameters(params);  // shown without emitting
        QCOMPARE(combo->currentIndex(), static_cast<int>(DetectorKind::Ared));
        QVERIFY(panel.findChild<QLabel*>("label_detector")->font().bold());  // off its default
    }

    void choosingAChoiceEmitsItsIndex()
    {
        ParameterPanel panel;
        QSignalSpy edited(&panel, &ParameterPanel::parameterEdited);
        auto* combo = panel.findChild<QComboBox*>("choice_detector");
        combo->setFocus();
        QTest::keyClick(combo, Qt::Key_Home);  // what a user does: the first choice, C1/C2/C3
        QCOMPARE(edited.count(), 1);
        QCOMPARE(edited.first().at(0).toString(), QStringLiteral("detector"));
        QCOMPARE(edited.first().at(1).toDouble(), static_cast<double>(DetectorKind::PaperC1C2C3));
        QCOMPARE(panel.parameters().detectorKind(), DetectorKind::PaperC1C2C3);
        QTest::keyClick(combo, Qt::Key_Home);  // the same choice again is no edit
        QCOMPARE(edited.count(), 1);
        panel.findChild<QToolButton*>("reset_detector")->click();
        QCOMPARE(edited.count(), 2);
        QCOMPARE(edited.last().at(1).toDouble(), static_cast<double>(Parameters().detector));
        QCOMPARE(combo->currentIndex(), Parameters().detector);
    }

    void aChosenDetectorReRunsWithUndoAndPresets()
    {
        // Wired as MainWindow wires them: the session owns the parameters and the undo stack.
        AnalysisSession session;
        ParameterPanel panel;
        connect(&panel, &ParameterPanel::parameterEdited, &session, &AnalysisSession::setParameter);
        connect(&panel, &ParameterPanel::parametersReplaced, &session, &AnalysisSession::setParameters);
        connect(&session, &AnalysisSession::parametersChanged, &panel,
                [&] { panel.setParameters(session.parameters()); });
        panel.setUndoStack(session.undoStack());
        auto* combo = panel.findChild<QComboBox*>("choice_filter_states");
        combo->setFocus();
        // The other filter size than the default: 15 states is the first choice, 9 the last.
        const bool nineByDefault = Parameters().filterStates() == FilterStates::Nine;
        const FilterStates other = nineByDefault ? FilterStates::Fifteen : FilterStates::Nine;
        QTest::keyClick(combo, nineByDefault ? Qt::Key_Home : Qt::Key_End);
        QCOMPARE(session.parameters().filterStates(), other);
        session.undoStack()->undo();
        QCOMPARE(session.parameters().filterStates(), Parameters().filterStates());
        QCOMPARE(combo->currentIndex(), Parameters().filter_states);
        session.undoStack()->redo();
        QCOMPARE(combo->currentIndex(), static_cast<int>(other));

        // A preset names the choice; loading it sets the combo box.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("ared.json"));
        Parameters ared;
        ared.detector = static_cast<int>(DetectorKind::Ared);
        QCOMPARE(saveParameters(path.toStdString(), ared), std::string());
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QVERIFY(file.readAll().contains("\"ared\""));
        QVERIFY2(panel.loadPreset(path), qPrintable(panel.presetError()));
        QCOMPARE(session.parameters().detectorKind(), DetectorKind::Ared);
        QCOMPARE(panel.findChild<QComboBox*>("choice_detector")->currentIndex(), static_cast<int>(DetectorKind::Ared));
    }

    void fieldsThatDoNotApplyAreDisabledWithAReason()
    {
        ParameterPanel panel;
        const auto slider = [&](const char* name) { return panel.findChild<QSlider*>(QStringLiteral("slider_") + name); };
        // Defaults: a statistic detector with an adaptive threshold.
        QVERIFY(Parameters().detectorKind() != DetectorKind::PaperC1C2C3 && Parameters().zv_adaptive);
        QVERIFY(!slider("acc_std_max_mps2")->isEnabled());
        QVERIFY(!slider("acc_std_max_mps2")->isHidden());  // greyed, not hidden
        QVERIFY2(slider("acc_std_max_mps2")->toolTip().contains(QStringLiteral("C1/C2/C3")),
                 qPrintable(slider("acc_std_max_mps2")->toolTip()));
        QVERIFY(!panel.findChild<QLineEdit*>("value_acc_std_max_mps2")->isEnabled());
        QVERIFY(slider("zv_window_s")->isEnabled());
        QVERIFY(slider("zv_adapt_offset_dec")->isEnabled());
        QVERIFY(!slider("zv_log_threshold")->isEnabled());
        QVERIFY(slider("zv_log_threshold")->toolTip().contains(QStringLiteral("zv_adaptive")));

        panel.setParameters(paperDetector());
        QVERIFY(slider("acc_std_max_mps2")->isEnabled());
        QVERIFY(!slider("acc_std_max_mps2")->toolTip().contains(QStringLiteral("Not used")));
        QVERIFY(!slider("zv_window_s")->isEnabled());
        QVERIFY(!panel.findChild<QCheckBox*>("check_zv_adaptive")->isEnabled());

        // A fixed threshold: the adaptive settings go, the fixed one comes; as the user clicks.
        panel.setParameters(Parameters());
        panel.findChild<QCheckBox*>("check_zv_adaptive")->click();
        QVERIFY(slider("zv_log_threshold")->isEnabled());
        QVERIFY(!slider("zv_adapt_window_s")->isEnabled());
        QVERIFY(!slider("zv_log_never")->isEnabled());

        Parameters ared;
        ared.detector = static_cast<int>(DetectorKind::Ared);
        ared.filter_states = static_cast<int>(FilterStates::Nine);
        panel.setParameters(ared);
        QVERIFY(!slider("zv_sigma_acc_mps2")->isEnabled());  // ARED reads the gyroscope alone
        QVERIFY(slider("zv_sigma_gyr_radps")->isEnabled());
        QVERIFY(!slider("p0_acc_bias_mps2")->isEnabled());  // no bias states
        QVERIFY(!panel.findChild<QCheckBox*>("check_use_zaru")->isEnabled());  // nothing for ZARU to correct
        QVERIFY(slider("q_att_rad")->isEnabled());
        QVERIFY(panel.findChild<QComboBox*>("choice_detector")->isEnabled());
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
