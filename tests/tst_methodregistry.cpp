// The method registry (core/methods/): a new detector, measurement source or file format is its own
// code plus one registration, and every list of the program follows: the detector choice and
// --set, the method sets and their labels, the measurement sources the filter runs, the import
// dispatch, --format and the file dialog's patterns. Each example below is registered the way an
// extension would be, and checked in those lists.
#include "io/Import.h"
#include "methods/MethodRegistry.h"
#include "nav/MeasurementSources.h"
#include "nav/MethodSets.h"
#include "nav/Pipeline.h"
#include "nav/sources/SourceSupport.h"
#include "sim/WalkSimulator.h"

#include <QtTest>

#include <algorithm>
#include <sstream>

using namespace footpath;

namespace {

// ---- a detector: the largest normalised angular rate in the window --------------------------

double peakRateStatistic(const StatisticConstants& constants, const ImuSample* window, std::size_t count)
{
    double largest = 0.0;
    for (std::size_t k = 0; k < count; ++k)
        largest = std::max(largest, window[k].gyr_radps.squaredNorm());
    return largest * constants.invVarGyr;
}

// ---- a source: counts the stances it sees, and leaves a note saying how many -----------------

bool stanceCounterOn = false;  // its switch (a real source has a use_... field in Parameters)

class StanceCounterSource : public MeasurementSource {
public:
    explicit StanceCounterSource(const Parameters&) {}
    const char* name() const override { return "stances"; }
    void apply(ErrorStateEkf&, const SourceContext& context) override
    {
        if (context.flags.stance && !inStance_)
            ++stances_;
        inStance_ = context.flags.stance;
    }
    void finish(double endTime_s, std::vector<MethodNote>& notes) override
    {
        notes.push_back({name(), 0.0, endTime_s, std::to_string(stances_) + " stances"});
    }

private:
    bool inStance_ = false;
    int stances_ = 0;
};

SourceMethod stanceCounterMethod()
{
    return {"stances",
            "stance count",
            "",
            [](const Parameters&) { return stanceCounterOn; },
            [](Parameters&, bool on) { stanceCounterOn = on; },
            [](const Parameters& params) -> std::unique_ptr<MeasurementSource> {
                return stanceCounterOn ? std::make_unique<StanceCounterSource>(params) : nullptr;
            },
            nullptr,
            100};
}

// ---- a source that is always wrong: the innovation gate refuses it --------------------------

bool wrongHeadingOn = false;

/// Claims at every stance that the heading is a radian off, with a confidence no filter shares.
class WrongHeadingSource : public MeasurementSource {
public:
    explicit WrongHeadingSource(const Parameters&) {}
    const char* name() const override { return "wrongheading"; }
    void apply(ErrorStateEkf& ekf, const SourceContext& context) override
    {
        if (trigger_.fires(context.flags.stance, context.sample.time_s))
            sources::updateYaw(ekf, 1.0, 0.001);
    }

private:
    sources::StanceTrigger trigger_{0.03};
};

SourceMethod wrongHeadingMethod()
{
    return {"wrongheading",
            "wrong heading",
            "",
            [](const Parameters&) { return wrongHeadingOn; },
            [](Parameters&, bool on) { wrongHeadingOn = on; },
            [](const Parameters& params) -> std::unique_ptr<MeasurementSource> {
                return wrongHeadingOn ? std::make_unique<WrongHeadingSource>(params) : nullptr;
            },
            nullptr,
            101};
}

// ---- a format: "#trivial-imu" then rows of "t ax ay az gx gy gz" in SI units -----------------

bool recognisesTrivialImu(const std::string& head, const ImportOptions&)
{
    return head.rfind("#trivial-imu", 0) == 0;
}

ImportResult readTrivialImu(std::istream& in, const std::string& path, const ImportOptions&, std::size_t)
{
    ImportResult result;
    result.recording.source = path;
    std::string line;
    std::getline(in, line);  // the magic line
    for (std::size_t number = 2; std::getline(in, line); ++number) {
        std::istringstream row(line);
        ImuSample sample;
        if (!(row >> sample.time_s >> sample.acc_mps2.x() >> sample.acc_mps2.y() >> sample.acc_mps2.z()
              >> sample.gyr_radps.x() >> sample.gyr_radps.y() >> sample.gyr_radps.z())) {
            result.error = ReadError{path, number, 0, "expected seven numbers: t ax ay az gx gy gz"};
            return result;
        }
        result.recording.samples.push_back(sample);
    }
    result.info.accUnitAsRead = AccUnit::MetresPerSecond2;
    result.info.gyrUnitAsRead = GyrUnit::RadiansPerSecond;
    return result;
}

std::string trivialImuText(const Recording& recording)
{
    std::ostringstream text;
    text.precision(17);
    text << "#trivial-imu\n";
    for (const ImuSample& s : recording.samples)
        text << s.time_s << ' ' << s.acc_mps2.x() << ' ' << s.acc_mps2.y() << ' ' << s.acc_mps2.z() << ' '
             << s.gyr_radps.x() << ' ' << s.gyr_radps.y() << ' ' << s.gyr_radps.z() << '\n';
    return text.str();
}

template <class List>
bool contains(const List& list, const std::string& value)
{
    return std::find(list.begin(), list.end(), value) != list.end();
}

}  // namespace

class TestMethodRegistry : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void aRegisteredDetectorIsAChoiceAndDetects();
    void aRegisteredSourceJoinsTheMethodSetsAndRuns();
    void aRegisteredFormatIsRecognisedAndListed();
    void theBuiltInListsComeFromTheRegistry();
    void theInnovationGateRefusesAndSaysSo();

private:
    SimulatedWalk walk_;
};

void TestMethodRegistry::initTestCase()
{
    addDetectorMethod({"peak", "Peak angular rate", peakRateStatistic, false, true});
    addSourceMethod(stanceCounterMethod());
    addSourceMethod(wrongHeadingMethod());
    addImporterMethod({"trivial-imu", "a test's example format", "*.trivial", false, false, recognisesTrivialImu,
                       readTrivialImu});
    walk_ = simulateWalk(straightLinePath(8.0), mtiClassSensor());
}

void TestMethodRegistry::aRegisteredDetectorIsAChoiceAndDetects()
{
    const ParameterField* detector = findParameterField("detector");
    QVERIFY(detector);
    QVERIFY(contains(std::vector<std::string>(detector->choiceNames.begin(), detector->choiceNames.end()), "peak"));
    Parameters params;
    QCOMPARE(setParameter(params, "detector", "peak"), std::string());
    QVERIFY(chosenDetector(params).statistic == &peakRateStatistic);
    // The statistic detector's fields apply to it; the C1/C2/C3 bounds and the accelerometer noise do not.
    QVERIFY(!unmetCondition(*findParameterField("zv_sigma_gyr_radps"), params));
    QVERIFY(unmetCondition(*findParameterField("zv_sigma_acc_mps2"), params));
    QVERIFY(unmetCondition(*findParameterField("acc_std_max_mps2"), params));

    const PipelineOutput output = runPipeline(walk_.recording, params);
    QVERIFY2(output.error.empty(), output.error.c_str());
    // It finds the simulated walk's strides as the built-in SHOE does, and the path is as long.
    const Result shoe = runPipeline(walk_.recording, Parameters()).result;
    const Result& peak = output.result;
    QVERIFY2(std::abs(static_cast<long>(peak.steps.size()) - static_cast<long>(shoe.steps.size())) <= 1,
             qPrintable(QString("%1 against %2").arg(peak.steps.size()).arg(shoe.steps.size())));
    QVERIFY(std::abs(peak.position_m.back().x() - 8.0) < 1.0);
}

void TestMethodRegistry::aRegisteredSourceJoinsTheMethodSetsAndRuns()
{
    QVERIFY(contains(methodTokens(), "stances"));
    std::string error;
    const std::optional<MethodSet> set = parseMethodSet("zupt,stances", Parameters(), error);
    QVERIFY2(set, error.c_str());
    QCOMPARE(methodSetLabel(set->name), std::string("ZUPT+stance count"));
    QVERIFY(stanceCounterOn);
    QCOMPARE(methodSetSpec(set->params), std::string("zupt,stances"));
    QCOMPARE(MeasurementSources(set->params).size(), std::size_t(2));

    const PipelineOutput output = runPipeline(walk_.recording, set->params);
    QVERIFY2(output.error.empty(), output.error.c_str());
    const auto note = std::find_if(output.result.methodNotes.begin(), output.result.methodNotes.end(),
                                   [](const MethodNote& n) { return n.method == "stances"; });
    QVERIFY(note != output.result.methodNotes.end());
    QVERIFY2(note->message != "0 stances", note->message.c_str());

    QVERIFY(parseMethodSet("zupt", Parameters(), error));  // every method a set does not name is off
    QVERIFY(!stanceCounterOn);
}

void TestMethodRegistry::aRegisteredFormatIsRecognisedAndListed()
{
    QVERIFY(contains(importFormatNames(), "trivial-imu"));
    QVERIFY(importerFilePatterns().find("*.trivial") != std::string::npos);
    QVERIFY(importerNamesText().find("trivial-imu") != std::string::npos);

    std::istringstream text(trivialImuText(walk_.recording));
    const std::size_t size = text.str().size();
    const ImportResult imported = importStream(text, size, "walk.trivial");
    QVERIFY2(imported.ok(), imported.ok() ? "" : imported.error->message.c_str());
    QCOMPARE(imported.info.format, std::string("trivial-imu"));
    QCOMPARE(imported.recording.samples.size(), walk_.recording.samples.size());

    std::istringstream broken("#trivial-imu\n0 0 0 9.8 0 0\n");
    const ImportResult failed = importStream(broken, broken.str().size(), "broken.trivial");
    QVERIFY(!failed.ok());
    QCOMPARE(failed.error->line, std::size_t(2));
}

void TestMethodRegistry::theBuiltInListsComeFromTheRegistry()
{
    // The labels people read come from one place: the lanes, the panel and the method sets agree.
    for (const SourceMethod& source : sourceMethods()) {
        if (!*source.switchName)
            continue;
        const ParameterField* field = findParameterField(source.switchName);
        QVERIFY2(field && field->kind == ParameterField::Kind::Flag, source.switchName);
        Parameters params;
        source.setOn(params, true);
        QVERIFY2(source.isOn(params) && params.*(field->flag), source.token);
    }
    QCOMPARE(methodSetLabel("zupt,zaru,hdr,iper,zuna,baro,mag"),
             std::string("ZUPT+ZARU+HDR+IPER+ZUNA+barometer+magnetometer"));
    QCOMPARE(methodSetLabel("feliz"), std::string("Feliz"));
    QCOMPARE(methodSetLabel("zupt,15state,rts"), std::string("ZUPT+15-state+RTS smoother"));
    for (const char* name : {"xsens-text", "xsens-mtb", "delimited", "pyshoe-vicon"})
        QVERIFY2(findImporter(name), name);
}

void TestMethodRegistry::theInnovationGateRefusesAndSaysSo()
{
    std::string error;
    std::optional<MethodSet> set = parseMethodSet("zupt,wrongheading", Parameters(), error);
    QVERIFY2(set, error.c_str());
    const Result ungated = runPipeline(walk_.recording, set->params).result;
    set->params.gate_probability = 0.999;
    const Result gated = runPipeline(walk_.recording, set->params).result;
    wrongHeadingOn = false;
    const Result plain = runPipeline(walk_.recording, Parameters()).result;

    const auto gateNote = std::find_if(gated.methodNotes.begin(), gated.methodNotes.end(), [](const MethodNote& n) {
        return n.method == "wrongheading" && n.message.find("innovation gate") != std::string::npos;
    });
    QVERIFY(gateNote != gated.methodNotes.end());
    QVERIFY2(gateNote->message.find(" of ") != std::string::npos, gateNote->message.c_str());
    // Refused, the wrong heading leaves the path as it was; let through, it turns the path.
    const Eigen::Vector3d end = plain.position_m.back();
    QVERIFY((gated.position_m.back() - end).norm() < 0.05);
    QVERIFY((ungated.position_m.back() - end).norm() > 1.0);
}

QTEST_GUILESS_MAIN(TestMethodRegistry)
#include "tst_methodregistry.moc"
