// Zheng et al. 2016's motion classes and the methods' notes in the workspace and the PDF, on hand-built
// results (the classifier is core's and tested there): the detector view's motion lane (coloured,
// labelled spans; left out without a barometer, greyed when unclassified) and method-notes lane,
// the step table's Motion and Baro height columns, the summary's counts sentence and notes, the
// 2D and 3D paths coloured by class, and the report's sentence, column and "Method notes" section.
#include "MotionLanes.h"
#include "ReportWriter.h"
#include "StanceFlagsPlot.h"
#include "SummaryPanel.h"
#include "TrajectoryView2D.h"
#include "TrajectoryView3D.h"

#include <QAbstractItemModel>
#include <QGroupBox>
#include <QLabel>
#include <QPainter>
#include <QProcess>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QtTest>
#include <qcustomplot.h>

#include <cmath>
#include <map>

using namespace footpath;

namespace {

using M = MotionClass;

constexpr double kRate_hz = 100.0;
constexpr double kStepPeriod_s = 1.0;
constexpr double kStanceStart_s = 0.5;  ///< within each step period
constexpr double kStanceEnd_s = 0.9;

/// The class of each step, in order: every class, in runs of several steps.
const std::vector<M>& stepClasses()
{
    static const std::vector<M> classes{M::Unknown,    M::Level,        M::Level,        M::Level,      M::StairsUp,
                                        M::StairsUp,   M::StairsUp,     M::StairsUp,     M::StairsUp,   M::StairsUp,
                                        M::Level,      M::Level,        M::Level,        M::StairsDown, M::StairsDown,
                                        M::StairsDown, M::ElevatorUp,   M::ElevatorUp,   M::ElevatorUp, M::Level,
                                        M::Level,      M::ElevatorDown, M::ElevatorDown, M::ElevatorDown, M::Level,
                                        M::Level};
    return classes;
}

/// Height gained over a step of each class (metres).
double heightChange(M motion)
{
    switch (motion) {
    case M::StairsUp: return 1.5;
    case M::StairsDown: return -0.4;
    case M::ElevatorUp: return 1.0;
    case M::ElevatorDown: return -1.0;
    default: return 0.0;
    }
}

/// The English names the user reads (independent of the code under test's wording table).
const std::map<M, QString>& expectedLabels()
{
    static const std::map<M, QString> labels{{M::Level, "Level"},
                                             {M::StairsUp, "Stairs up"},
                                             {M::StairsDown, "Stairs down"},
                                             {M::ElevatorUp, "Elevator up"},
                                             {M::ElevatorDown, "Elevator down"}};
    return labels;
}

double stanceEnd(std::size_t step) { return static_cast<double>(step) * kStepPeriod_s + kStanceEnd_s; }

/// A walk of 1 m/s along x with one step a second, classified as stepClasses() says, with
/// barometric heights (or NaN without a barometer), counts to match and two overlapping notes.
Result handBuiltResult(bool barometer = true)
{
    Result result;
    const std::size_t steps = stepClasses().size();
    const auto samples = static_cast<std::size_t>((static_cast<double>(steps) + 1.5) * kRate_hz);
    double height = 0.0;
    for (std::size_t k = 0; k < steps; ++k) {
        Step step;
        step.stanceStart_s = static_cast<double>(k) * kStepPeriod_s + kStanceStart_s;
        step.stanceEnd_s = stanceEnd(k);
        step.strideLength_m = k == 0 ? 0.0 : 1.0;
        step.strideDuration_s = k == 0 ? 0.0 : kStepPeriod_s;
        step.motion = barometer ? stepClasses()[k] : M::Unknown;
        height += heightChange(stepClasses()[k]);
        step.baroHeight_m = barometer ? height : std::nan("");
        step.position_m = Eigen::Vector3d(step.stanceStart_s, 0.0, height);
        result.steps.push_back(step);
    }
    for (std::size_t k = 0; k < samples; ++k) {
        const double t = static_cast<double>(k) / kRate_hz;
        result.time_s.push_back(t);
        result.position_m.emplace_back(t, 0.2 * std::sin(t), 0.0);
        result.velocity_mps.emplace_back(1.0, 0.0, 0.0);
        result.rollPitchYaw_rad.emplace_back(0.0, 0.0, 0.0);
        result.gyroBias_radps.emplace_back(0.0, 0.0, 0.0);
        result.accBias_mps2.emplace_back(0.0, 0.0, 0.0);
        const double inPeriod = std::fmod(t, kStepPeriod_s);
        result.flags.stance.push_back(inPeriod >= kStanceStart_s && inPeriod < kStanceEnd_s ? 1 : 0);
    }
    Summary& s = result.summary;
    s.samples = samples;
    s.duration_s = result.time_s.back();
    s.stancePhases = steps;
    s.steps = steps - 1;
    s.pathLength_m = static_cast<double>(steps - 1);
    if (barometer) {
        s.stairStepsUp = 6;
        s.stairsClimb_m = 9.0;
        s.stairStepsDown = 3;
        s.stairsDescent_m = 1.2;
        s.elevatorRides = 2;
    }
    result.methodNotes.push_back(MethodNote{"iper", 3.0, 20.0, "not applied: the walk has no straight stretch along an axis"});
    result.methodNotes.push_back(
        MethodNote{"mag", 12.0, 15.5, "skipped: the field is 40 % stronger than at alignment (steel nearby)"});
    return result;
}

struct ExpectedSpan {
    M motion;
    double start_s;
    double end_s;
};

/// Runs of equal classes in stepClasses(), each from the end of the stance before its first step
/// to the end of its last step's stance.
std::vector<ExpectedSpan> expectedSpans()
{
    std::vector<ExpectedSpan> spans;
    const std::vector<M>& classes = stepClasses();
    for (std::size_t k = 1; k < classes.size(); ++k) {
        if (classes[k] == classes[k - 1] && !spans.empty())
            spans.back().end_s = stanceEnd(k);
        else
            spans.push_back({classes[k], stanceEnd(k - 1), stanceEnd(k)});
    }
    return spans;
}

bool near(const QColor& a, const QColor& b, int tolerance = 8)
{
    return std::abs(a.red() - b.red()) <= tolerance && std::abs(a.green() - b.green()) <= tolerance &&
           std::abs(a.blue() - b.blue()) <= tolerance;
}

int pixelsNear(const QImage& image, const QColor& colour)
{
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            count += near(image.pixelColor(x, y), colour, 12) ? 1 : 0;
    return count;
}

/// The pixel a little inside the right end of [from, to] and below the top of the lane, where
/// neither the label (left) nor a neighbour reaches.
QPoint pointInLane(const QCPAxisRect* lane, double from, double to)
{
    const double x = lane->axis(QCPAxis::atBottom)->coordToPixel(from + 0.85 * (to - from));
    return QPoint(static_cast<int>(std::lround(x)), lane->top() + 4);
}

QString motionText(const QTableView& table, int row, const QString& title)
{
    const QAbstractItemModel* model = table.model();
    for (int column = 0; column < model->columnCount(); ++column)
        if (model->headerData(column, Qt::Horizontal).toString() == title)
            return model->index(row, column).data().toString();
    return QStringLiteral("<no column %1>").arg(title);
}

int columnTitled(const QTableView& table, const QString& title)
{
    for (int column = 0; column < table.model()->columnCount(); ++column)
        if (table.model()->headerData(column, Qt::Horizontal).toString() == title)
            return column;
    return -1;
}

QString pdfWords(const QString& pdf)
{
    QProcess process;
    process.start("pdftotext", {pdf, "-"});
    process.waitForFinished(60000);
    // With the typesetter's fi and fl ligatures spelled out.
    return QString::fromUtf8(process.readAllStandardOutput())
        .replace(QChar(0xFB01), QStringLiteral("fi"))
        .replace(QChar(0xFB02), QStringLiteral("fl"))
        .simplified();
}

}  // namespace

class TestMotionView : public QObject {
    Q_OBJECT
private slots:
    void motionLaneColoursAndLabelsEachClassSpan()
    {
        StanceFlagsPlot plot;
        plot.resize(1000, 600);
        plot.setResult(std::make_shared<const Result>(handBuiltResult()));
        plot.setTimeRange(0.0, 27.0);
        QVERIFY(plot.motionLane()->layout() != nullptr);
        QVERIFY(!plot.motionLanes().isMotionGreyed());

        const std::vector<ExpectedSpan> expected = expectedSpans();
        const std::vector<LaneBar>& bars = plot.motionLanes().motionBars();
        QCOMPARE(bars.size(), expected.size());
        const QImage image = plot.plot()->toPixmap(1000, 560).toImage();
        std::map<QRgb, M> classOfColour;
        for (std::size_t i = 0; i < bars.size(); ++i) {
            QCOMPARE(bars[i].start_s, expected[i].start_s);
            QCOMPARE(bars[i].end_s, expected[i].end_s);
            QCOMPARE(bars[i].label, expectedLabels().at(expected[i].motion));
            QVERIFY2(bars[i].toolTip.contains(expectedLabels().at(expected[i].motion)), qPrintable(bars[i].toolTip));
            // Drawn in its colour, and one colour per class.
            const QPoint at = pointInLane(plot.motionLane(), bars[i].start_s, bars[i].end_s);
            QVERIFY2(near(image.pixelColor(at), bars[i].colour),
                     qPrintable(QString("span %1 at (%2, %3): %4 instead of %5")
                                    .arg(i).arg(at.x()).arg(at.y())
                                    .arg(image.pixelColor(at).name(), bars[i].colour.name())));
            const auto [entry, added] = classOfColour.emplace(bars[i].colour.rgb(), expected[i].motion);
            QCOMPARE(entry->second, expected[i].motion);
        }
        QCOMPARE(classOfColour.size(), expectedLabels().size());
        // The lane's tool tip names the class and the steps under the pointer.
        const QString tip = plot.motionLanes().toolTipAt(plot.motionLane(), 6.0);
        QVERIFY2(tip.contains("Stairs up") && tip.contains("steps 5"), qPrintable(tip));
    }

    void motionLaneIsLeftOutWithoutABarometerAndGreyWhenUnclassified()
    {
        StanceFlagsPlot plot;
        plot.resize(1000, 600);
        QVERIFY(plot.motionLane()->layout() == nullptr);  // no result, no lane
        plot.setResult(std::make_shared<const Result>(handBuiltResult(false)));
        QVERIFY(plot.motionLane()->layout() == nullptr);  // no pressure: nothing to show, no height taken

        Result unclassified = handBuiltResult();
        for (Step& step : unclassified.steps)
            step.motion = M::Unknown;
        plot.setResult(std::make_shared<const Result>(unclassified));
        plot.setTimeRange(0.0, 27.0);
        QVERIFY(plot.motionLane()->layout() != nullptr);
        QVERIFY(plot.motionLanes().isMotionGreyed());
        QVERIFY(plot.motionLanes().motionBars().empty());
        QVERIFY2(plot.motionLanes().placeholder().contains("not classified"), qPrintable(plot.motionLanes().placeholder()));
        QCOMPARE(plot.motionLanes().toolTipAt(plot.motionLane(), 10.0), plot.motionLanes().placeholder());
        const QImage image = plot.plot()->toPixmap(1000, 560).toImage();
        const QColor grey = image.pixelColor(pointInLane(plot.motionLane(), 20.0, 26.0));
        QVERIFY2(grey.red() == grey.green() && grey.green() == grey.blue() && grey.red() > 200 && grey.red() < 250,
                 qPrintable(grey.name()));
    }

    void methodNotesLaneShowsEachNoteWithItsMessage()
    {
        StanceFlagsPlot plot;
        plot.resize(1000, 600);
        const Result result = handBuiltResult();
        plot.setResult(std::make_shared<const Result>(result));
        plot.setTimeRange(0.0, 27.0);
        QVERIFY(plot.methodNotesLane()->layout() != nullptr);
        const std::vector<LaneBar>& bars = plot.motionLanes().noteBars();
        QCOMPARE(bars.size(), result.methodNotes.size());
        for (std::size_t i = 0; i < bars.size(); ++i) {
            QCOMPARE(bars[i].start_s, result.methodNotes[i].start_s);
            QCOMPARE(bars[i].end_s, result.methodNotes[i].end_s);
        }
        QCOMPARE(bars[1].label, QString("Magnetometer heading"));  // the parameter list's label
        // Where the notes overlap the tool tip has both messages; outside them, none.
        const QString both = plot.motionLanes().toolTipAt(plot.methodNotesLane(), 13.0);
        QVERIFY2(both.contains("40 % stronger than at alignment") && both.contains("no straight stretch"), qPrintable(both));
        QVERIFY2(both.contains("12.0") && both.contains("15.5"), qPrintable(both));
        QVERIFY(plot.motionLanes().toolTipAt(plot.methodNotesLane(), 22.0).isEmpty());
        // The overlapping notes take two levels: the lane is taller than the one-level motion lane.
        plot.plot()->toPixmap(1000, 560);
        QVERIFY(plot.methodNotesLane()->height() > plot.motionLane()->height() + 5);

        Result noNotes = result;
        noNotes.methodNotes.clear();
        plot.setResult(std::make_shared<const Result>(noNotes));
        QVERIFY(plot.methodNotesLane()->layout() == nullptr);
    }

    void stepTableHasMotionAndBaroHeightColumns()
    {
        SummaryPanel panel;
        const Result result = handBuiltResult();
        panel.setResult(std::make_shared<const Result>(result));
        auto* table = panel.findChild<QTableView*>("stepTable");
        QVERIFY(table);
        const int motion = columnTitled(*table, "Motion"), height = columnTitled(*table, "Baro height (m)");
        QVERIFY(motion >= 0 && height >= 0);
        QVERIFY(!table->isColumnHidden(motion) && !table->isColumnHidden(height));
        QCOMPARE(table->model()->rowCount(), static_cast<int>(result.steps.size()));
        for (int row = 0; row < table->model()->rowCount(); ++row) {  // sorted by step number
            const M expected = stepClasses()[static_cast<std::size_t>(row)];
            QCOMPARE(motionText(*table, row, "Motion"),
                     expected == M::Unknown ? QStringLiteral("\u2013") : expectedLabels().at(expected));
            QCOMPARE(motionText(*table, row, "Baro height (m)"),
                     QLocale().toString(result.steps[static_cast<std::size_t>(row)].baroHeight_m, 'f', 2));
        }
        // Without pressure the columns would only hold dashes: hidden.
        panel.setResult(std::make_shared<const Result>(handBuiltResult(false)));
        QVERIFY(table->isColumnHidden(motion) && table->isColumnHidden(height));
    }

    void summarySentenceCountsFloorsAndRides_data()
    {
        QTest::addColumn<double>("climb_m");
        QTest::addColumn<double>("descent_m");
        QTest::addColumn<int>("rides");
        QTest::addColumn<QStringList>("phrases");
        QTest::newRow("9 m up") << 9.0 << 1.2 << 2
                                << QStringList{"3 floors up by stairs (9.0 m)", "1.2 m down by stairs", "2 elevator rides"};
        QTest::newRow("9.1 m up, 1 ride") << 9.1 << 0.0 << 1 << QStringList{"3 floors up by stairs (9.1 m)", "1 elevator ride"};
        QTest::newRow("one floor down") << 0.0 << 4.4 << 0 << QStringList{"1 floor down by stairs (4.4 m)"};
        QTest::newRow("level") << 0.0 << 0.0 << 0 << QStringList{"Level walking only"};
    }

    void summarySentenceCountsFloorsAndRides()
    {
        QFETCH(double, climb_m);
        QFETCH(double, descent_m);
        QFETCH(int, rides);
        QFETCH(QStringList, phrases);
        Result result = handBuiltResult();
        Summary& s = result.summary;
        s.stairsClimb_m = climb_m;
        s.stairStepsUp = climb_m > 0.0 ? 6 : 0;
        s.stairsDescent_m = descent_m;
        s.stairStepsDown = descent_m > 0.0 ? 3 : 0;
        s.elevatorRides = static_cast<std::size_t>(rides);
        SummaryPanel panel;
        panel.setResult(std::make_shared<const Result>(result));
        auto* sentence = panel.findChild<QLabel*>("motionSentence");
        QVERIFY(sentence);
        QVERIFY(!sentence->isHidden());
        for (const QString& phrase : phrases)
            QVERIFY2(sentence->text().contains(phrase), qPrintable(sentence->text()));
        if (rides == 0)
            QVERIFY2(!sentence->text().contains("elevator ride"), qPrintable(sentence->text()));
    }

    void summaryHasNoMotionSentenceWithoutABarometer()
    {
        SummaryPanel panel;
        panel.setResult(std::make_shared<const Result>(handBuiltResult(false)));
        auto* sentence = panel.findChild<QLabel*>("motionSentence");
        QVERIFY(sentence);
        QVERIFY(sentence->isHidden());
    }

    void summaryListsMethodNotes()
    {
        SummaryPanel panel;
        const Result result = handBuiltResult();
        panel.setResult(std::make_shared<const Result>(result));
        auto* group = panel.findChild<QGroupBox*>("methodNotes");
        QVERIFY(group);
        QVERIFY(!group->isHidden());
        auto* mag = panel.findChild<QLabel*>("methodNote_1");
        QVERIFY(mag);
        for (const char* part : {"Magnetometer", "12.0", "15.5", "40 % stronger than at alignment"})
            QVERIFY2(mag->text().contains(part), qPrintable(mag->text()));
        QVERIFY(panel.findChild<QLabel*>("methodNote_0")->text().contains("Position error reduction"));
        // Its span links to the moment, as the warnings' do.
        QSignalSpy requested(&panel, &SummaryPanel::timeCursorRequested);
        emit mag->linkActivated("1");
        QCOMPARE(requested.size(), 1);
        QCOMPARE(requested.first().first().toDouble(), 12.0);

        Result noNotes = result;
        noNotes.methodNotes.clear();
        panel.setResult(std::make_shared<const Result>(noNotes));
        QVERIFY(group->isHidden());
        QVERIFY(!panel.findChild<QLabel*>("methodNote_0"));
    }

    void pathIn2DIsColouredByMotionClass()
    {
        TrajectoryView2D view;
        view.resize(700, 500);
        const Result result = handBuiltResult();
        view.setResult(std::make_shared<const Result>(result));
        const QColor plain = view.pathColourAt(0);
        view.setColouring(TrajectoryView2D::Colouring::Motion);
        // Each sample takes the class of the step its stride leads to: 6.0 s lies in step 6's
        // stride (stance 5 ends at 5.9 s, stance 6 at 6.9 s), a stairs-up step.
        const auto sampleAt = [](double t) { return static_cast<std::size_t>(std::lround(t * kRate_hz)); };
        const QColor stairsUp = view.pathColourAt(sampleAt(6.0));
        const QColor level = view.pathColourAt(sampleAt(2.0));
        const QColor stairsDown = view.pathColourAt(sampleAt(14.0));
        QVERIFY(stairsUp != level && stairsUp != stairsDown && level != stairsDown && stairsUp != plain);
        const QImage image = view.plot()->toPixmap(700, 500).toImage();
        QVERIFY2(pixelsNear(image, stairsUp) > 20 && pixelsNear(image, stairsDown) > 5,
                 qPrintable(QString("%1 stairs-up, %2 stairs-down pixels").arg(pixelsNear(image, stairsUp)).arg(pixelsNear(image, stairsDown))));
        QCOMPARE(view.pathColourAt(sampleAt(5.95)), stairsUp);  // after stance 5 ends: already step 6's stride
        QCOMPARE(view.pathColourAt(sampleAt(3.95)), stairsUp);  // step 4's stride: the first stairs-up step
        QCOMPARE(view.pathColourAt(sampleAt(3.85)), level);
        // A legend entry per class on the path (the first step and after the last: unclassified).
        QStringList names;
        for (const QCPGraph* entry : view.motionLegendEntries()) {
            names << entry->name();
            QVERIFY(view.plot()->legend->hasItemWithPlottable(entry));
        }
        for (const auto& [motion, label] : expectedLabels())
            QVERIFY2(names.contains(label), qPrintable(names.join(", ")));
        QVERIFY2(names.contains("Unclassified"), qPrintable(names.join(", ")));
        QCOMPARE(names.size(), 6);

        view.setColouring(TrajectoryView2D::Colouring::None);
        QVERIFY(view.motionLegendEntries().empty());
        QCOMPARE(view.pathColourAt(sampleAt(6.0)), plain);
    }

    void pathIn2DIsColouredWhenTheColouringPrecedesTheResult()
    {
        TrajectoryView2D view;  // as the window does for --view motion: colouring first, result later
        view.resize(700, 500);
        view.setColouring(TrajectoryView2D::Colouring::Motion);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        view.setResult(std::make_shared<const Result>(handBuiltResult()));
        QTest::qWait(50);
        const QColor stairsUp = view.pathColourAt(600);
        const QImage image = view.grab().toImage();
        QVERIFY2(pixelsNear(image, stairsUp) > 20, qPrintable(QString::number(pixelsNear(image, stairsUp))));
    }

    void pathIn2DKeepsOneColourWithoutClasses()
    {
        TrajectoryView2D view;
        view.setResult(std::make_shared<const Result>(handBuiltResult(false)));
        const QColor plain = view.pathColourAt(600);
        view.setColouring(TrajectoryView2D::Colouring::Motion);
        QCOMPARE(view.pathColourAt(600), plain);
        QVERIFY(view.motionLegendEntries().empty());
    }

    void pathIn3DIsColouredByMotionClass()
    {
        TrajectoryView3D view;
        view.resize(800, 600);
        view.setResult(std::make_shared<const Result>(handBuiltResult()));
        const auto render = [&view] {
            QImage image(800, 600, QImage::Format_RGB32);
            QPainter painter(&image);
            view.render(painter, QRectF(0, 0, 800, 600));
            return image;
        };
        TrajectoryView2D reference;  // the 2D view's colours are the classes' colours
        reference.setResult(std::make_shared<const Result>(handBuiltResult()));
        reference.setColouring(TrajectoryView2D::Colouring::Motion);
        const QColor upColour = reference.pathColourAt(600), downColour = reference.pathColourAt(1400);
        const int upBefore = pixelsNear(render(), upColour);
        view.setMotionColouring(true);
        QVERIFY(view.showsMotionColours());
        const QImage coloured = render();
        // The short stairs-up stretch: some twenty-odd pixels of its colour, none before (the path is
        // fitted above the key since the key must not cover it, so it is drawn a little smaller).
        QVERIFY2(pixelsNear(coloured, upColour) > upBefore + 20,
                 qPrintable(QString("%1 -> %2").arg(upBefore).arg(pixelsNear(coloured, upColour))));
        QVERIFY(pixelsNear(coloured, downColour) > 10);

        view.setResult(std::make_shared<const Result>(handBuiltResult(false)));
        QVERIFY(!view.showsMotionColours());  // nothing classified: the one path colour
    }

    void pdfHasCountsSentenceMotionColumnAndMethodNotes()
    {
        if (QStandardPaths::findExecutable("pdftotext").isEmpty())
            QSKIP("pdftotext (Debian: poppler-utils) is not installed");
        ReportContent content;
        content.recordingPath = "stairs.txt";
        const Result result = handBuiltResult();
        auto recording = std::make_shared<Recording>();
        for (const double t : result.time_s) {
            ImuSample sample;
            sample.time_s = t;
            sample.acc_mps2 = Eigen::Vector3d(0.0, 0.0, 9.81);
            sample.pressure_pa = 101325.0;
            recording->samples.push_back(sample);
        }
        content.recording = recording;
        content.result = std::make_shared<const Result>(result);
        QTemporaryDir dir;
        const QString pdf = dir.path() + "/motion.pdf";
        QCOMPARE(writePdfReport(content, pdf), QString());
        const QString words = pdfWords(pdf);
        for (const QString phrase : {"3 floors up by stairs (9.0 m)", "2 elevator rides", "Method notes",
                                      "40 % stronger than at alignment", "Magnetometer", "Motion", "Stairs up",
                                      "Elevator down"})
            QVERIFY2(words.contains(phrase), qPrintable(phrase + " not in: " + words.left(3000)));

        // Without notes and barometer: no section, no sentence.
        Result plain = handBuiltResult(false);
        plain.methodNotes.clear();
        content.result = std::make_shared<const Result>(plain);
        QCOMPARE(writePdfReport(content, pdf), QString());
        const QString plainWords = pdfWords(pdf);
        QVERIFY(!plainWords.contains("Method notes"));
        QVERIFY(!plainWords.contains("floors up"));
        QVERIFY(!plainWords.contains("Stairs up"));
    }
};

QTEST_MAIN(TestMotionView)
#include "tst_motionview.moc"
