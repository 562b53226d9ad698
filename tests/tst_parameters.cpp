// The parameter set (core/nav/Parameters.h) and its JSON presets (core/io/ParameterIo.h): defaults
// are the paper's values (Guo 2015), validation names the field, setParameter parses text, the field
// table is consistent, and presets round-trip, apply partially and fail without side effects.

#include "io/ParameterIo.h"
#include "nav/Parameters.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

using footpath::ParameterField;
using footpath::Parameters;

namespace {

/// Every field of a against b, exactly (bit-equal doubles); returns the first difference or empty.
QString firstDifference(const Parameters& a, const Parameters& b)
{
    for (const ParameterField& field : footpath::parameterFields()) {
        const double va = footpath::parameterValue(a, field);
        const double vb = footpath::parameterValue(b, field);
        if (!(va == vb))
            return QStringLiteral("%1: %2 != %3")
                .arg(QString::fromLatin1(field.name))
                .arg(va, 0, 'g', 17)
                .arg(vb, 0, 'g', 17);
    }
    return {};
}

#define VERIFY_SAME_PARAMETERS(a, b)                        \
    do {                                                    \
        const QString difference_ = firstDifference(a, b);  \
        QVERIFY2(difference_.isEmpty(), qPrintable(difference_)); \
    } while (false)

/// A set where every field differs from its default: awkward in-range reals, flags flipped, the
/// next choice.
Parameters modifiedParameters()
{
    Parameters params;
    int index = 0;
    for (const ParameterField& field : footpath::parameterFields()) {
        ++index;
        if (field.kind == ParameterField::Kind::Flag) {
            params.*field.flag = !(params.*field.flag);
            continue;
        }
        // A choice has no real member: writing through field.real wrote one byte before params
        // (the sanitizer build caught it). The next choice differs from the default as well.
        if (field.kind == ParameterField::Kind::Choice) {
            params.*field.choice = (params.*field.choice + 1) % static_cast<int>(field.choiceNames.size());
            continue;
        }
        const double fraction = 0.1 + 0.8 * std::fmod(0.618033988749895 * index, 1.0);
        params.*field.real = field.minimum + (field.maximum - field.minimum) * fraction / 3.0;
    }
    // Keep the set valid: acc_min below acc_max.
    params.acc_min_mps2 = 8.123456789012345;
    params.acc_max_mps2 = 12.987654321098765;
    return params;
}

QString joined(const std::vector<std::string>& problems)
{
    QStringList list;
    for (const std::string& problem : problems)
        list << QString::fromStdString(problem);
    return list.join(QStringLiteral(" | "));
}

const char* const kPresetHead = R"({"format": "footpath-parameters", "version": 1, "parameters": )";

}  // namespace

class TestParameters : public QObject {
    Q_OBJECT

private slots:
    void labels_areWordsWithTheUnitAsPeopleWriteIt();
    void defaults_validateWithoutProblems();
    void defaults_areThePaperValues_data();
    void defaults_areThePaperValues();
    void fieldNames_mapToTheirMembers();
    void unmetCondition_saysWhichFieldsThePipelineReads();
    void validate_reportsOutOfRangeWithTheFieldName_data();
    void validate_reportsOutOfRangeWithTheFieldName();
    void validate_acceptsRangeBoundaries_data();
    void validate_acceptsRangeBoundaries();
    void validate_reportsAccMinNotBelowAccMax_data();
    void validate_reportsAccMinNotBelowAccMax();
    void setParameter_parsesNumbersAndFlags_data();
    void setParameter_parsesNumbersAndFlags();
    void setParameter_rejectsBadInputAndKeepsTheValue_data();
    void setParameter_rejectsBadInputAndKeepsTheValue();
    void parameterFields_areUniqueDescribedAndDefaultsInRange();
    void json_roundTripKeepsEveryField();
    void json_partialPresetChangesOnlyWhatItNames();
    void json_malformedNamesSourceAndByteOffset();
    void json_invalidPresetGivesMessageAndLeavesParamsUnchanged_data();
    void json_invalidPresetGivesMessageAndLeavesParamsUnchanged();
    void file_saveThenLoadRestoresEveryField();
    void file_loadingAMissingFileNamesItAndKeepsParams();
    void file_savingIntoAMissingDirectoryFails();
};

void TestParameters::labels_areWordsWithTheUnitAsPeopleWriteIt()
{
    QSet<QString> labels;
    for (const ParameterField& field : footpath::parameterFields()) {
        const QString name = QString::fromLatin1(field.name);
        const QString label = QString::fromUtf8(field.label);
        QVERIFY2(label.size() > 3 && label != name && !label.contains(QLatin1Char('_')), qPrintable(name));
        QVERIFY2(!labels.contains(label), qPrintable("two fields labelled " + label));
        labels.insert(label);
        const QString withUnit = QString::fromStdString(footpath::labelWithUnit(field));
        const QString unit = QString::fromStdString(footpath::displayUnit(field));
        QVERIFY2(!unit.contains(QLatin1Char('^')), qPrintable(unit));
        QCOMPARE(withUnit, unit.isEmpty() ? label : label + " (" + unit + ")");
    }
    const ParameterField* accStd = footpath::findParameterField("acc_std_max_mps2");
    QCOMPARE(QString::fromStdString(footpath::labelWithUnit(*accStd)), QString::fromUtf8(accStd->label) + QStringLiteral(" (m/s\u00b2)"));
    QCOMPARE(QString::fromStdString(footpath::displayUnit(*footpath::findParameterField("motion_elevator_var_pa2"))),
             QStringLiteral("Pa\u00b2"));
    QCOMPARE(QString::fromStdString(footpath::displayUnit(*footpath::findParameterField("zv_adapt_fraction"))), QString());
}

void TestParameters::defaults_validateWithoutProblems()
{
    const std::vector<std::string> problems = Parameters().validate();
    QVERIFY2(problems.empty(), qPrintable(joined(problems)));
}

void TestParameters::defaults_areThePaperValues_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<double>("expected");

    // Guo 2015, sections 2.3 (detector) and 2.6 (filter tuning), at the paper's 100 Hz.
    QTest::newRow("C1 lower bound") << "acc_min_mps2" << 9.0;
    QTest::newRow("C1 upper bound") << "acc_max_mps2" << 11.0;
    QTest::newRow("C2 threshold") << "acc_std_max_mps2" << 0.5;
    QTest::newRow("C2 half-window, 15 samples") << "window_half_s" << 0.15;
    QTest::newRow("C3 threshold") << "gyr_max_radps" << 1.0;
    QTest::newRow("median filter, 11 samples") << "median_window_s" << 0.11;
    QTest::newRow("Q attitude") << "q_att_rad" << 1e-4;
    QTest::newRow("Q velocity") << "q_vel_mps" << 1e-4;
    QTest::newRow("R ZUPT") << "r_zupt_mps" << 0.01;
    QTest::newRow("R ZARU") << "r_zaru_radps" << 0.1;
    QTest::newRow("P0 gyro bias") << "p0_gyro_bias_radps" << 1e-2;
    QTest::newRow("P0 accelerometer bias") << "p0_acc_bias_mps2" << 1e-2;
    QTest::newRow("ZUPT on") << "use_zupt" << 1.0;
    QTest::newRow("ZARU on") << "use_zaru" << 1.0;
}

void TestParameters::defaults_areThePaperValues()
{
    QFETCH(QString, name);
    QFETCH(double, expected);
    const ParameterField* field = footpath::findParameterField(name.toStdString());
    QVERIFY2(field, qPrintable(name));
    QCOMPARE(footpath::parameterValue(footpath::guo2015Parameters(), *field), expected);
}

void TestParameters::unmetCondition_saysWhichFieldsThePipelineReads()
{
    const auto unmet = [](const Parameters& params, const char* name) -> std::string {
        const footpath::FieldCondition* condition = footpath::unmetCondition(*footpath::findParameterField(name), params);
        return condition ? condition->id : "";
    };
    const Parameters defaults;  // SHOE, adaptive threshold, 9 states
    QCOMPARE(unmet(defaults, "detector"), std::string());
    QCOMPARE(unmet(defaults, "zv_adapt_window_s"), std::string());
    QCOMPARE(unmet(defaults, "zv_log_threshold"), std::string("fixed_threshold"));
    QCOMPARE(unmet(defaults, "acc_std_max_mps2"), std::string("paper_detector"));
    QCOMPARE(unmet(defaults, "p0_acc_bias_mps2"), std::string("bias_states"));
    QCOMPARE(unmet(defaults, "use_zaru"), std::string("zaru"));
    QCOMPARE(unmet(defaults, "hdr_lag_s"), std::string("hdr"));
    QCOMPARE(unmet(defaults, "iper_axis_rad"), std::string("iper"));  // IPER off says more than "auto axis"
    const Parameters paper = footpath::guo2015Parameters();  // C1/C2/C3, 15 states
    QCOMPARE(unmet(paper, "acc_std_max_mps2"), std::string());
    QCOMPARE(unmet(paper, "zv_log_threshold"), std::string("statistic_detectors"));  // the detector first
    QCOMPARE(unmet(paper, "use_zaru"), std::string());
    Parameters ared;
    QVERIFY(footpath::setParameter(ared, "detector", "ared").empty());
    QCOMPARE(unmet(ared, "zv_sigma_acc_mps2"), std::string("detector_accelerometer"));
    QCOMPARE(unmet(ared, "zv_sigma_gyr_radps"), std::string());
    Parameters amvd;
    QVERIFY(footpath::setParameter(amvd, "detector", "amvd").empty());
    QCOMPARE(unmet(amvd, "zv_sigma_gyr_radps"), std::string("detector_gyroscope"));
    Parameters iper;
    iper.use_iper = true;
    QCOMPARE(unmet(iper, "iper_axis_rad"), std::string("iper_fixed_axis"));
    iper.iper_axis_auto = false;
    QCOMPARE(unmet(iper, "iper_axis_rad"), std::string());
}

void TestParameters::fieldNames_mapToTheirMembers()
{
    // Each name must address the member of the same name (a swapped pointer would pass every
    // round trip but tune the wrong thing).
    const std::pair<const char*, double Parameters::*> reals[] = {
        {"alignment_s", &Parameters::alignment_s},
        {"gravity_mps2", &Parameters::gravity_mps2},
        {"declination_rad", &Parameters::declination_rad},
        {"acc_min_mps2", &Parameters::acc_min_mps2},
        {"acc_max_mps2", &Parameters::acc_max_mps2},
        {"acc_std_max_mps2", &Parameters::acc_std_max_mps2},
        {"window_half_s", &Parameters::window_half_s},
        {"gyr_max_radps", &Parameters::gyr_max_radps},
        {"median_window_s", &Parameters::median_window_s},
        {"zv_window_s", &Parameters::zv_window_s},
        {"zv_sigma_acc_mps2", &Parameters::zv_sigma_acc_mps2},
        {"zv_sigma_gyr_radps", &Parameters::zv_sigma_gyr_radps},
        {"zv_log_threshold", &Parameters::zv_log_threshold},
        {"zv_adapt_window_s", &Parameters::zv_adapt_window_s},
        {"zv_adapt_offset_dec", &Parameters::zv_adapt_offset_dec},
        {"zv_adapt_fraction", &Parameters::zv_adapt_fraction},
        {"zv_log_always", &Parameters::zv_log_always},
        {"zv_log_never", &Parameters::zv_log_never},
        {"zv_min_stance_s", &Parameters::zv_min_stance_s},
        {"q_att_rad", &Parameters::q_att_rad},
        {"q_gyro_bias_radps", &Parameters::q_gyro_bias_radps},
        {"q_pos_m", &Parameters::q_pos_m},
        {"q_vel_mps", &Parameters::q_vel_mps},
        {"q_acc_bias_mps2", &Parameters::q_acc_bias_mps2},
        {"r_zupt_mps", &Parameters::r_zupt_mps},
        {"r_zaru_radps", &Parameters::r_zaru_radps},
        {"gate_probability", &Parameters::gate_probability},
        {"p0_att_rad", &Parameters::p0_att_rad},
        {"p0_gyro_bias_radps", &Parameters::p0_gyro_bias_radps},
        {"p0_pos_m", &Parameters::p0_pos_m},
        {"p0_vel_mps", &Parameters::p0_vel_mps},
        {"p0_acc_bias_mps2", &Parameters::p0_acc_bias_mps2},
        {"hdr_lag_s", &Parameters::hdr_lag_s},
        {"hdr_threshold_rad", &Parameters::hdr_threshold_rad},
        {"r_hdr_rad", &Parameters::r_hdr_rad},
        {"iper_axis_rad", &Parameters::iper_axis_rad},
        {"iper_threshold_rad", &Parameters::iper_threshold_rad},
        {"iper_window_s", &Parameters::iper_window_s},
        {"r_iper_m", &Parameters::r_iper_m},
        {"r_iper_height_m", &Parameters::r_iper_height_m},
        {"zuna_reference_s", &Parameters::zuna_reference_s},
        {"zuna_min_stance_s", &Parameters::zuna_min_stance_s},
        {"zuna_margin_dec", &Parameters::zuna_margin_dec},
        {"r_zuna_mps2", &Parameters::r_zuna_mps2},
        {"baro_linear_m_per_pa", &Parameters::baro_linear_m_per_pa},
        {"r_baro_m", &Parameters::r_baro_m},
        {"motion_level_max_m", &Parameters::motion_level_max_m},
        {"motion_elevator_var_pa2", &Parameters::motion_elevator_var_pa2},
        {"r_mag_rad", &Parameters::r_mag_rad},
        {"mag_norm_tolerance", &Parameters::mag_norm_tolerance},
        {"mag_dip_tolerance_rad", &Parameters::mag_dip_tolerance_rad},
    };
    const std::pair<const char*, bool Parameters::*> flags[] = {
        {"use_zupt", &Parameters::use_zupt},
        {"use_zaru", &Parameters::use_zaru},
        {"zv_adaptive", &Parameters::zv_adaptive},
        {"use_hdr", &Parameters::use_hdr},
        {"use_iper", &Parameters::use_iper},
        {"use_zuna", &Parameters::use_zuna},
        {"use_baro", &Parameters::use_baro},
        {"use_mag_heading", &Parameters::use_mag_heading},
        {"iper_axis_auto", &Parameters::iper_axis_auto},
    };
    const std::pair<const char*, int Parameters::*> choices[] = {
        {"detector", &Parameters::detector},
        {"filter_states", &Parameters::filter_states},
        {"estimator", &Parameters::estimator},
        {"baro_model", &Parameters::baro_model},
    };
    QCOMPARE(footpath::parameterFields().size(), std::size(reals) + std::size(flags) + std::size(choices));
    for (const auto& [name, member] : choices) {
        const ParameterField* field = footpath::findParameterField(name);
        QVERIFY2(field && field->choice == member, name);
        Parameters params;
        const char* last = field->choiceNames.back();
        QVERIFY2(footpath::setParameter(params, name, last).empty(), name);
        QCOMPARE(params.*member, static_cast<int>(field->choiceNames.size()) - 1);
        QCOMPARE(footpath::choiceName(params, *field), std::string(last));
        QVERIFY(!footpath::setParameter(params, name, "no-such-choice").empty());
    }
    for (const auto& [name, member] : reals) {
        Parameters params;
        QVERIFY2(footpath::setParameter(params, name, "0.4375").empty(), name);
        QVERIFY2(params.*member == 0.4375, name);
        Parameters expected;
        expected.*member = 0.4375;
        VERIFY_SAME_PARAMETERS(params, expected);
    }
    for (const auto& [name, member] : flags) {
        Parameters params;
        QVERIFY2(footpath::setParameter(params, name, "false").empty(), name);
        QVERIFY2(!(params.*member), name);
        Parameters expected;
        expected.*member = false;
        VERIFY_SAME_PARAMETERS(params, expected);
    }
}

void TestParameters::validate_reportsOutOfRangeWithTheFieldName_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("expected");

    QTest::newRow("gravity above") << "gravity_mps2" << 12.0 << "gravity_mps2 (12) must be between 9.7 and 9.9 m/s\u00b2";
    QTest::newRow("gravity below") << "gravity_mps2" << 9.0 << "gravity_mps2 (9) must be between 9.7 and 9.9 m/s\u00b2";
    QTest::newRow("alignment too short") << "alignment_s" << 0.01 << "alignment_s (0.01) must be between 0.05 and 600 s";
    QTest::newRow("negative std") << "acc_std_max_mps2" << -0.5
                                  << "acc_std_max_mps2 (-0.5) must be between 0 and 20 m/s\u00b2";
    QTest::newRow("zero R ZUPT") << "r_zupt_mps" << 0.0 << "r_zupt_mps (0) must be between 1e-06 and 10 m/s";
    QTest::newRow("declination beyond pi") << "declination_rad" << 4.0 << "declination_rad (4) must be between";
    QTest::newRow("window too long") << "median_window_s" << 2.5 << "median_window_s (2.5) must be between 0 and 2 s";
    QTest::newRow("NaN") << "q_att_rad" << std::numeric_limits<double>::quiet_NaN() << "q_att_rad (nan) must be between";
    QTest::newRow("infinity") << "p0_pos_m" << std::numeric_limits<double>::infinity() << "p0_pos_m (inf) must be between";
}

void TestParameters::validate_reportsOutOfRangeWithTheFieldName()
{
    QFETCH(QString, name);
    QFETCH(double, value);
    QFETCH(QString, expected);

    Parameters params;
    const ParameterField* field = footpath::findParameterField(name.toStdString());
    QVERIFY(field && field->kind == ParameterField::Kind::Real);
    params.*field->real = value;
    const std::vector<std::string> problems = params.validate();
    QCOMPARE(problems.size(), std::size_t(1));
    const QString problem = QString::fromStdString(problems.front());
    QVERIFY2(problem.startsWith(expected), qPrintable(problem));
}

void TestParameters::validate_acceptsRangeBoundaries_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<bool>("atMaximum");

    QTest::newRow("gravity min") << "gravity_mps2" << false;
    QTest::newRow("gravity max") << "gravity_mps2" << true;
    QTest::newRow("alignment min") << "alignment_s" << false;
    QTest::newRow("r_zupt min") << "r_zupt_mps" << false;
    QTest::newRow("declination max") << "declination_rad" << true;
    QTest::newRow("gyr_max max") << "gyr_max_radps" << true;
}

void TestParameters::validate_acceptsRangeBoundaries()
{
    QFETCH(QString, name);
    QFETCH(bool, atMaximum);
    const ParameterField* field = footpath::findParameterField(name.toStdString());
    QVERIFY(field);
    Parameters params;
    params.*field->real = atMaximum ? field->maximum : field->minimum;
    const std::vector<std::string> problems = params.validate();
    QVERIFY2(problems.empty(), qPrintable(joined(problems)));
}

void TestParameters::validate_reportsAccMinNotBelowAccMax_data()
{
    QTest::addColumn<double>("accMin");
    QTest::addColumn<double>("accMax");
    QTest::addColumn<QString>("expected");

    QTest::newRow("equal") << 11.0 << 11.0 << "acc_min_mps2 (11) must be below acc_max_mps2 (11)";
    QTest::newRow("above") << 12.5 << 11.0 << "acc_min_mps2 (12.5) must be below acc_max_mps2 (11)";
    QTest::newRow("max lowered") << 9.0 << 8.0 << "acc_min_mps2 (9) must be below acc_max_mps2 (8)";
}

void TestParameters::validate_reportsAccMinNotBelowAccMax()
{
    QFETCH(double, accMin);
    QFETCH(double, accMax);
    QFETCH(QString, expected);
    Parameters params;
    params.acc_min_mps2 = accMin;
    params.acc_max_mps2 = accMax;
    const std::vector<std::string> problems = params.validate();
    // Both values are in range, so the ordering is the only problem.
    QCOMPARE(problems.size(), std::size_t(1));
    QCOMPARE(QString::fromStdString(problems.front()), expected);
}

void TestParameters::setParameter_parsesNumbersAndFlags_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("text");
    QTest::addColumn<double>("expected");

    QTest::newRow("decimal") << "acc_std_max_mps2" << "0.3" << 0.3;
    QTest::newRow("exponent") << "q_att_rad" << "2.5e-5" << 2.5e-5;
    QTest::newRow("negative") << "declination_rad" << "-0.2" << -0.2;
    QTest::newRow("integer") << "acc_max_mps2" << "12" << 12.0;
    QTest::newRow("flag true") << "use_zupt" << "true" << 1.0;
    QTest::newRow("flag off") << "use_zupt" << "off" << 0.0;
    QTest::newRow("flag 1") << "use_zaru" << "1" << 1.0;
    QTest::newRow("flag 0") << "use_zaru" << "0" << 0.0;
    QTest::newRow("flag FALSE") << "use_zaru" << "FALSE" << 0.0;
    QTest::newRow("flag yes") << "use_zupt" << "yes" << 1.0;
    QTest::newRow("flag no") << "use_zupt" << "no" << 0.0;
    QTest::newRow("flag On") << "use_zupt" << "On" << 1.0;
}

void TestParameters::setParameter_parsesNumbersAndFlags()
{
    QFETCH(QString, name);
    QFETCH(QString, text);
    QFETCH(double, expected);

    const ParameterField* field = footpath::findParameterField(name.toStdString());
    QVERIFY(field);
    // Start from the opposite value so that a no-op cannot pass.
    Parameters params;
    if (field->kind == ParameterField::Kind::Flag)
        params.*field->flag = expected == 0.0;
    QVERIFY(footpath::parameterValue(params, *field) != expected);

    const std::string problem = footpath::setParameter(params, name.toStdString(), text.toStdString());
    QVERIFY2(problem.empty(), problem.c_str());
    QCOMPARE(footpath::parameterValue(params, *field), expected);

    // Nothing else moved.
    Parameters reference;
    if (field->kind == ParameterField::Kind::Flag)
        reference.*field->flag = expected != 0.0;
    else
        reference.*field->real = expected;
    VERIFY_SAME_PARAMETERS(params, reference);
}

void TestParameters::setParameter_rejectsBadInputAndKeepsTheValue_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("expected");

    QTest::newRow("unknown name") << "acc_std_mps2" << "0.3" << "unknown parameter 'acc_std_mps2'";
    QTest::newRow("empty name") << "" << "0.3" << "unknown parameter ''";
    QTest::newRow("not a number") << "acc_std_max_mps2" << "abc"
                                  << "parameter 'acc_std_max_mps2' expects a number, got 'abc'";
    QTest::newRow("trailing garbage") << "acc_std_max_mps2" << "0.3m/s"
                                      << "parameter 'acc_std_max_mps2' expects a number, got '0.3m/s'";
    QTest::newRow("empty number") << "gyr_max_radps" << "" << "parameter 'gyr_max_radps' expects a number, got ''";
    QTest::newRow("nan") << "gyr_max_radps" << "nan" << "parameter 'gyr_max_radps' expects a number, got 'nan'";
    QTest::newRow("inf") << "gyr_max_radps" << "inf" << "parameter 'gyr_max_radps' expects a number, got 'inf'";
    QTest::newRow("bad flag") << "use_zupt" << "maybe" << "parameter 'use_zupt' expects true/false, got 'maybe'";
    QTest::newRow("flag 2") << "use_zaru" << "2" << "parameter 'use_zaru' expects true/false, got '2'";
}

void TestParameters::setParameter_rejectsBadInputAndKeepsTheValue()
{
    QFETCH(QString, name);
    QFETCH(QString, text);
    QFETCH(QString, expected);

    const Parameters before = modifiedParameters();
    Parameters params = before;
    const std::string problem = footpath::setParameter(params, name.toStdString(), text.toStdString());
    QCOMPARE(QString::fromStdString(problem), expected);
    VERIFY_SAME_PARAMETERS(params, before);
}

void TestParameters::parameterFields_areUniqueDescribedAndDefaultsInRange()
{
    const std::vector<ParameterField>& fields = footpath::parameterFields();
    QVERIFY(fields.size() >= 20);
    const Parameters defaults;
    QSet<QString> names;
    QSet<QString> groups;
    std::vector<double Parameters::*> realMembers;
    std::vector<bool Parameters::*> flagMembers;
    for (const ParameterField& field : fields) {
        const QString name = QString::fromLatin1(field.name);
        QVERIFY2(!name.isEmpty(), "a field without a name");
        QVERIFY2(!names.contains(name), qPrintable("duplicate name " + name));
        names.insert(name);
        QVERIFY2(!name.contains(QLatin1Char('=')) && !name.contains(QLatin1Char(' ')), qPrintable(name));
        QCOMPARE(footpath::findParameterField(field.name), &field);

        QVERIFY2(field.description && std::string(field.description).size() > 3, qPrintable(name));
        QVERIFY2(field.group && *field.group, qPrintable(name));
        groups.insert(QString::fromLatin1(field.group));
        QVERIFY2(field.unit, qPrintable(name));
        QVERIFY2(field.minimum <= field.maximum, qPrintable(name));

        if (field.kind == ParameterField::Kind::Real) {
            QVERIFY2(field.real && !field.flag, qPrintable(name));
            QVERIFY2(*field.unit, qPrintable(name + " has no unit"));
            const double value = defaults.*field.real;
            QVERIFY2(field.minimum <= value && value <= field.maximum,
                     qPrintable(QStringLiteral("%1 default %2 outside [%3, %4]")
                                    .arg(name)
                                    .arg(value)
                                    .arg(field.minimum)
                                    .arg(field.maximum)));
            for (double Parameters::*other : realMembers)
                QVERIFY2(other != field.real, qPrintable(name + " shares a member with another field"));
            realMembers.push_back(field.real);
        } else if (field.kind == ParameterField::Kind::Choice) {
            QVERIFY2(field.choice && !field.real && !field.flag, qPrintable(name));
            QVERIFY2(field.choiceNames.size() >= 2 && field.choiceNames.size() == field.choiceLabels.size(),
                     qPrintable(name));
            const int value = defaults.*field.choice;
            QVERIFY2(value >= 0 && value < static_cast<int>(field.choiceNames.size()), qPrintable(name));
        } else {
            QVERIFY2(field.flag && !field.real, qPrintable(name));
            for (bool Parameters::*other : flagMembers)
                QVERIFY2(other != field.flag, qPrintable(name + " shares a member with another field"));
            flagMembers.push_back(field.flag);
        }
    }
    QVERIFY(groups.size() >= 3);
    QCOMPARE(footpath::findParameterField("no_such_parameter"), nullptr);
}

void TestParameters::json_roundTripKeepsEveryField()
{
    const Parameters modified = modifiedParameters();
    QVERIFY2(modified.validate().empty(), qPrintable(joined(modified.validate())));
    QVERIFY(!firstDifference(modified, Parameters()).isEmpty());

    const std::string json = footpath::parametersToJson(modified);

    // The document is the documented preset format with every field in it.
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(QByteArray::fromStdString(json), &parseError);
    QVERIFY2(!document.isNull(), qPrintable(parseError.errorString()));
    const QJsonObject root = document.object();
    QCOMPARE(root.value(QStringLiteral("format")).toString(), QStringLiteral("footpath-parameters"));
    QCOMPARE(root.value(QStringLiteral("version")).toInt(), 1);
    const QJsonObject values = root.value(QStringLiteral("parameters")).toObject();
    QCOMPARE(std::size_t(values.size()), footpath::parameterFields().size());
    QCOMPARE(values.value(QStringLiteral("use_zupt")).toBool(), modified.use_zupt);
    QCOMPARE(values.value(QStringLiteral("acc_max_mps2")).toDouble(), modified.acc_max_mps2);

    Parameters restored;
    const std::string problem = footpath::parametersFromJson(json, "roundtrip.json", restored);
    QVERIFY2(problem.empty(), problem.c_str());
    VERIFY_SAME_PARAMETERS(restored, modified);
}

void TestParameters::json_partialPresetChangesOnlyWhatItNames()
{
    Parameters params;
    params.gyr_max_radps = 2.0;  // set earlier (e.g. by a slider): a partial preset must keep it
    const std::string json = std::string(kPresetHead) + R"({"acc_std_max_mps2": 0.3, "use_zaru": false}})";

    const std::string problem = footpath::parametersFromJson(json, "partial.json", params);
    QVERIFY2(problem.empty(), problem.c_str());

    Parameters expected;
    expected.gyr_max_radps = 2.0;
    expected.acc_std_max_mps2 = 0.3;
    expected.use_zaru = false;
    VERIFY_SAME_PARAMETERS(params, expected);

    // An empty "parameters" object (or none) changes nothing.
    const Parameters before = params;
    QVERIFY(footpath::parametersFromJson(std::string(kPresetHead) + "{}}", "empty.json", params).empty());
    VERIFY_SAME_PARAMETERS(params, before);
    QVERIFY(footpath::parametersFromJson(R"({"format": "footpath-parameters", "version": 1})", "none.json", params)
                .empty());
    VERIFY_SAME_PARAMETERS(params, before);
}

void TestParameters::json_malformedNamesSourceAndByteOffset()
{
    // The same syntax error (a doubled comma), once as is and once pushed 40 bytes further.
    const std::string broken = std::string(kPresetHead) + R"({"acc_std_max_mps2": 0.3,, "use_zaru": false}})";
    const std::string shifted = std::string(40, ' ') + broken;
    const QRegularExpression pattern(QStringLiteral("^my preset\\.json: byte (\\d+): \\S.*$"));

    const Parameters before = modifiedParameters();
    Parameters params = before;
    const QString first = QString::fromStdString(footpath::parametersFromJson(broken, "my preset.json", params));
    const QRegularExpressionMatch firstMatch = pattern.match(first);
    QVERIFY2(firstMatch.hasMatch(), qPrintable(first));
    VERIFY_SAME_PARAMETERS(params, before);

    const QString second = QString::fromStdString(footpath::parametersFromJson(shifted, "my preset.json", params));
    const QRegularExpressionMatch secondMatch = pattern.match(second);
    QVERIFY2(secondMatch.hasMatch(), qPrintable(second));

    const int firstOffset = firstMatch.captured(1).toInt();
    const int secondOffset = secondMatch.captured(1).toInt();
    // The offset points at the doubled comma (within a couple of bytes, whatever Qt's convention).
    const int comma = int(broken.find(",,"));
    QVERIFY2(std::abs(firstOffset - comma) <= 3, qPrintable(first));
    QCOMPARE(secondOffset - firstOffset, 40);

    // Truncated and empty documents are errors too, never a silent no-op.
    QVERIFY(pattern.match(QString::fromStdString(
                              footpath::parametersFromJson(std::string(kPresetHead) + "{", "my preset.json", params)))
                .hasMatch());
    QVERIFY(pattern.match(QString::fromStdString(footpath::parametersFromJson("", "my preset.json", params)))
                .hasMatch());
    VERIFY_SAME_PARAMETERS(params, before);
}

void TestParameters::json_invalidPresetGivesMessageAndLeavesParamsUnchanged_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("expected");

    const QByteArray head = kPresetHead;
    QTest::newRow("wrong format") << QByteArray(R"({"format": "something-else", "version": 1, "parameters": {"acc_std_max_mps2": 0.3}})")
                                  << R"(p.json: expected "format": "footpath-parameters")";
    QTest::newRow("no format") << QByteArray(R"({"version": 1, "parameters": {"acc_std_max_mps2": 0.3}})")
                               << R"(p.json: expected "format": "footpath-parameters")";
    QTest::newRow("an array") << QByteArray(R"([{"format": "footpath-parameters"}])")
                              << R"(p.json: expected "format": "footpath-parameters")";
    QTest::newRow("newer version")
        << QByteArray(R"({"format": "footpath-parameters", "version": 2, "parameters": {"acc_std_max_mps2": 0.3}})")
        << "p.json: preset version 2 is newer than this Footpath understands (1)";
    // Keys apply in order; the valid one before the bad one must not leak into params.
    QTest::newRow("unknown parameter") << head + R"({"acc_std_max_mps2": 0.3, "zzz_turbo": 1}})"
                                       << "p.json: unknown parameter 'zzz_turbo'";
    QTest::newRow("number as text") << head + R"({"acc_std_max_mps2": 0.3, "gyr_max_radps": "2"}})"
                                    << "p.json: 'gyr_max_radps' must be a number";
    QTest::newRow("null number") << head + R"({"acc_std_max_mps2": 0.3, "r_zupt_mps": null}})"
                                 << "p.json: 'r_zupt_mps' must be a number";
    QTest::newRow("flag as number") << head + R"({"acc_std_max_mps2": 0.3, "use_zupt": 1}})"
                                    << "p.json: 'use_zupt' must be true or false";
    QTest::newRow("flag as text") << head + R"({"acc_std_max_mps2": 0.3, "use_zaru": "false"}})"
                                  << "p.json: 'use_zaru' must be true or false";
}

void TestParameters::json_invalidPresetGivesMessageAndLeavesParamsUnchanged()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, expected);

    const Parameters before = modifiedParameters();
    Parameters params = before;
    const std::string problem = footpath::parametersFromJson(json.toStdString(), "p.json", params);
    QCOMPARE(QString::fromStdString(problem), expected);
    VERIFY_SAME_PARAMETERS(params, before);
}

void TestParameters::file_saveThenLoadRestoresEveryField()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string path = dir.filePath(QStringLiteral("preset.json")).toStdString();
    const Parameters modified = modifiedParameters();

    const std::string saveProblem = footpath::saveParameters(path, modified);
    QVERIFY2(saveProblem.empty(), saveProblem.c_str());
    QVERIFY(QFile::exists(QString::fromStdString(path)));
    // Only the preset itself is left in the directory (no temporary file).
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{QStringLiteral("preset.json")});

    Parameters loaded;
    const std::string loadProblem = footpath::loadParameters(path, loaded);
    QVERIFY2(loadProblem.empty(), loadProblem.c_str());
    VERIFY_SAME_PARAMETERS(loaded, modified);

    // Saving again replaces the file rather than appending to it.
    QVERIFY(footpath::saveParameters(path, Parameters()).empty());
    Parameters reloaded = modified;
    QVERIFY(footpath::loadParameters(path, reloaded).empty());
    VERIFY_SAME_PARAMETERS(reloaded, Parameters());
}

void TestParameters::file_loadingAMissingFileNamesItAndKeepsParams()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string path = dir.filePath(QStringLiteral("absent.json")).toStdString();
    const Parameters before = modifiedParameters();
    Parameters params = before;
    const QString problem = QString::fromStdString(footpath::loadParameters(path, params));
    QVERIFY2(problem.startsWith(QString::fromStdString(path) + QStringLiteral(": cannot open the preset")),
             qPrintable(problem));
    VERIFY_SAME_PARAMETERS(params, before);
}

void TestParameters::file_savingIntoAMissingDirectoryFails()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string path = dir.filePath(QStringLiteral("missing/preset.json")).toStdString();
    const QString problem = QString::fromStdString(footpath::saveParameters(path, Parameters()));
    QVERIFY2(problem.startsWith(QString::fromStdString(path) + QStringLiteral(": cannot write the preset")),
             qPrintable(problem));
    QVERIFY(!QFile::exists(QString::fromStdString(path)));
}

QTEST_APPLESS_MAIN(TestParameters)
#include "tst_parameters.moc"
