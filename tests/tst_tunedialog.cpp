// The tuning dialogs offscreen on small simulated walks: the criteria a recording cannot be scored
// by are disabled with the reason; a run fills the progress bar to its budget and shows the best
// value the search returned; Accept applies the tuned parameters as one undo step, Reject leaves
// everything as it was, Stop ends early with the best so far. Over a folder: two walks written as
// CSV files beside one that cannot be read; the table holds both walks before and after, the bad
// file is listed, the preset is written and "Apply" is one undo step.
#include "AnalysisSession.h"
#include "TrajectoryView2D.h"
#include "TuneDialog.h"
#include "TuneFolderDialog.h"
#include "io/ParameterIo.h"
#include "sim/WalkSimulator.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include <cmath>

using namespace footpath;

namespace {

constexpr int kTimeout_ms = 120000 * FOOTPATH_TIMEOUT_SCALE;

/// The brief's walk: an 8 x 5 m rectangle from an MTi-class sensor, marked closed, with nothing
/// else known (no reference positions, no length), so only the closed-loop criterion applies.
std::shared_ptr<const Recording> closedWalk()
{
    SimulatedWalk walk = simulateWalk(closedRectanglePath(8.0, 5.0), mtiClassSensor(100.0, 1));
    walk.recording.reference.closedLoop = true;
    walk.recording.reference.positions_m.clear();
    walk.recording.reference.knownLength_m = 0.0;
    return std::make_shared<const Recording>(std::move(walk.recording));
}

/// Detector settings far from the defaults, so a short search finds something better.
Parameters poorStart()
{
    Parameters params;
    params.zv_adapt_fraction = 0.48;
    params.zv_log_never = 5.2;
    params.q_vel_mps = 2.5e-3;
    return params;
}

QPushButton* button(const QWidget& dialog, const char* name)
{
    auto* found = dialog.findChild<QPushButton*>(QString::fromLatin1(name));
    if (!found)
        qFatal("no button %s", name);
    return found;
}

/// The walk's samples as a CSV file with a header, the way footpath-cli's tests write them.
bool writeWalkCsv(const QString& path, const std::vector<ImuSample>& samples)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return false;
    QByteArray text = "time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n";
    for (const ImuSample& s : samples) {
        text += QByteArray::number(s.time_s, 'g', 17);
        for (int axis = 0; axis < 3; ++axis)
            text += ',' + QByteArray::number(s.acc_mps2[axis], 'g', 17);
        for (int axis = 0; axis < 3; ++axis)
            text += ',' + QByteArray::number(s.gyr_radps[axis], 'g', 17);
        text += '\n';
    }
    return file.write(text) == text.size();
}

}  // namespace

class TestTuneDialog : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        recording_ = closedWalk();
        QVERIFY(recording_->samples.size() > 1000);
    }

    void init()
    {
        session_ = std::make_unique<AnalysisSession>();
        session_->setParameters(poorStart(), QStringLiteral("start"));
        session_->setRecording(recording_, RecordingInfo(), QStringLiteral("rectangle.csv"));
    }

    void cleanup() { session_.reset(); }

    void criteriaTheRecordingCannotScoreAreDisabled()
    {
        TuneDialog dialog(*session_);
        QVERIFY(dialog.isCriterionAvailable(TuneCriterion::ClosedLoop));
        QVERIFY(!dialog.isCriterionAvailable(TuneCriterion::KnownLength));
        QVERIFY(!dialog.isCriterionAvailable(TuneCriterion::Reference));
        QCOMPARE(dialog.criterion(), TuneCriterion::ClosedLoop);
        for (const char* name : {"criterion_length", "criterion_reference"})
            QVERIFY(!dialog.findChild<QWidget*>(QString::fromLatin1(name))->isEnabled());
        // The reason is shown beside a disabled choice, none beside the possible one.
        QVERIFY(!dialog.findChild<QLabel*>(QStringLiteral("whyNot_reference"))->text().isEmpty());
        QVERIFY(dialog.findChild<QLabel*>(QStringLiteral("whyNot_closed-loop"))->text().isEmpty());

        // Saying the walk's length makes that criterion possible; saying it is not closed removes
        // the closed-loop one, and the choice moves to what is left.
        dialog.findChild<QDoubleSpinBox*>(QStringLiteral("tuneLength"))->setValue(26.0);
        QVERIFY(dialog.isCriterionAvailable(TuneCriterion::KnownLength));
        dialog.findChild<QCheckBox*>(QStringLiteral("tuneClosed"))->setChecked(false);
        QVERIFY(!dialog.isCriterionAvailable(TuneCriterion::ClosedLoop));
        QCOMPARE(dialog.criterion(), TuneCriterion::KnownLength);
        QVERIFY(button(dialog, "tuneStart")->isEnabled());
        dialog.findChild<QDoubleSpinBox*>(QStringLiteral("tuneLength"))->setValue(0.0);
        QVERIFY(!button(dialog, "tuneStart")->isEnabled());
    }

    void aReferenceMakesTheReferenceCriterionPossible()
    {
        SimulatedWalk walk = simulateWalk(closedRectanglePath(8.0, 5.0), mtiClassSensor(100.0, 2));
        session_->setRecording(std::make_shared<const Recording>(std::move(walk.recording)), RecordingInfo(),
                               QStringLiteral("walk.csv"));
        TuneDialog dialog(*session_);
        QVERIFY(dialog.isCriterionAvailable(TuneCriterion::Reference));
        QCOMPARE(dialog.criterion(), TuneCriterion::Reference);  // it says the most
    }

    void aRunFillsTheProgressBarAndShowsTheBest()
    {
        TuneDialog dialog(*session_);
        dialog.setEvaluations(16);
        QSignalSpy progressed(dialog.progressBar(), &QProgressBar::valueChanged);
        QSignalSpy finished(&dialog, &TuneDialog::tuningFinished);
        button(dialog, "tuneStart")->click();
        QVERIFY(dialog.isRunning());
        QVERIFY(!button(dialog, "tuneAccept")->isEnabled());
        QVERIFY(finished.wait(kTimeout_ms));
        const TuneOutcome& outcome = dialog.outcome();
        QVERIFY2(outcome.error.empty(), outcome.error.c_str());
        QCOMPARE(outcome.evaluations, 16);
        QVERIFY(!outcome.cancelled);
        QCOMPARE(dialog.progressBar()->maximum(), 16);
        QCOMPARE(dialog.progressBar()->value(), 16);
        QVERIFY(progressed.size() >= 2);  // a generation before the end was reported too
        QVERIFY2(dialog.bestLabel()->text().contains(formatTuneScore(TuneCriterion::ClosedLoop, outcome.bestScore)),
                 qPrintable(dialog.bestLabel()->text()));
        QVERIFY(dialog.bestLabel()->text().contains(QStringLiteral("%")));
        QVERIFY(outcome.bestScore <= outcome.baseScore);

        // The criterion before -> after first, the path's length and end-to-start distance beside
        // it (what the criterion does not show), then a row per changed parameter.
        QVERIFY2(outcome.best != poorStart(), "a search from a poor start should find better parameters");
        const QTableWidget* table = dialog.changesTable();
        QVERIFY(table->rowCount() >= 4);
        QCOMPARE(table->item(0, 1)->text(), formatTuneScore(TuneCriterion::ClosedLoop, outcome.baseScore));
        QCOMPARE(table->item(0, 2)->text(), formatTuneScore(TuneCriterion::ClosedLoop, outcome.bestScore));
        for (int row = 1; row <= 2; ++row)
            for (int column = 1; column <= 2; ++column)
                QVERIFY(table->item(row, column)->text().endsWith(QStringLiteral(" m")));
        // A path much shorter or longer than before is pointed out (it shrinks the end-to-start distance too).
        const auto metres = [table](int column) {
            return QLocale().toDouble(table->item(1, column)->text().chopped(2));
        };
        QVERIFY(metres(1) > 0.0 && metres(2) > 0.0);
        const bool lengthChanged = std::abs(metres(2) / metres(1) - 1.0) > 0.1;
        QCOMPARE(dialog.findChild<QLabel*>(QStringLiteral("tuneWarning"))->isVisibleTo(&dialog), lengthChanged);
        for (int row = 3; row < table->rowCount(); ++row) {
            const ParameterField* field = findParameterField(table->item(row, 0)->toolTip().toStdString());
            QVERIFY2(field, qPrintable(table->item(row, 0)->toolTip()));
            QVERIFY(parameterValue(poorStart(), *field) != parameterValue(outcome.best, *field));
            QVERIFY(table->item(row, 0)->text().endsWith(QStringLiteral(")")) || displayUnit(*field).empty());
        }
        // The path before and after: the tuned one drawn, the current one over it.
        QVERIFY(dialog.pathView()->overlayCurves().size() == 1);
    }

    void acceptAppliesTheParametersAsOneUndoStep()
    {
        TuneDialog dialog(*session_);
        dialog.setEvaluations(16);
        QSignalSpy finished(&dialog, &TuneDialog::tuningFinished);
        dialog.start();
        QVERIFY(finished.wait(kTimeout_ms));
        const Parameters best = dialog.outcome().best;
        QVERIFY(best != poorStart());
        const int steps = session_->undoStack()->count();
        QVERIFY(button(dialog, "tuneAccept")->isEnabled());
        button(dialog, "tuneAccept")->click();
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
        QVERIFY(session_->parameters() == best);
        QCOMPARE(session_->undoStack()->count(), steps + 1);
        session_->undoStack()->undo();
        QVERIFY(session_->parameters() == poorStart());
    }

    void rejectChangesNothing()
    {
        TuneDialog dialog(*session_);
        dialog.setEvaluations(16);
        QSignalSpy finished(&dialog, &TuneDialog::tuningFinished);
        dialog.start();
        QVERIFY(finished.wait(kTimeout_ms));
        QVERIFY(dialog.outcome().best != poorStart());
        const int steps = session_->undoStack()->count();
        button(dialog, "tuneReject")->click();
        QCOMPARE(dialog.result(), int(QDialog::Rejected));
        QVERIFY(session_->parameters() == poorStart());
        QCOMPARE(session_->undoStack()->count(), steps);
    }

    void stopEndsEarlyWithTheBestSoFar()
    {
        TuneDialog dialog(*session_);
        dialog.setEvaluations(2000);
        QSignalSpy finished(&dialog, &TuneDialog::tuningFinished);
        dialog.start();
        // Stopped once the first generation (the spread over the space) has reported.
        QTRY_VERIFY_WITH_TIMEOUT(dialog.progressBar()->value() > 0, kTimeout_ms);
        QVERIFY(button(dialog, "tuneStop")->isEnabled());
        button(dialog, "tuneStop")->click();
        QVERIFY(finished.wait(kTimeout_ms));
        const TuneOutcome& outcome = dialog.outcome();
        QVERIFY(outcome.cancelled);
        QVERIFY(outcome.evaluations < 2000);
        QCOMPARE(dialog.progressBar()->value(), outcome.evaluations);
        QVERIFY(dialog.bestLabel()->text().contains(formatTuneScore(TuneCriterion::ClosedLoop, outcome.bestScore)));
        QCOMPARE(button(dialog, "tuneAccept")->isEnabled(), outcome.best != poorStart());
    }

    void folderTableHoldsEveryRecordingBeforeAndAfter()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        // Named with their length, so the importer knows it (the CSV carries no reference).
        QStringList walks;
        for (const std::uint32_t seed : {3u, 4u}) {
            const SimulatedWalk walk = simulateWalk(closedRectanglePath(8.0, 5.0), mtiClassSensor(100.0, seed));
            const QString name = QStringLiteral("walk%1_%2m.csv").arg(seed).arg(std::lround(walk.truePathLength_m));
            QVERIFY(writeWalkCsv(dir.filePath(name), walk.recording.samples));
            walks << name;
        }
        // One more walk whose length nobody knows: listed, but not scored by the length criterion.
        const SimulatedWalk unknown = simulateWalk(closedRectanglePath(6.0, 4.0), mtiClassSensor(100.0, 5));
        QVERIFY(writeWalkCsv(dir.filePath(QStringLiteral("walk5.csv")), unknown.recording.samples));
        walks << QStringLiteral("walk5.csv");
        QFile broken(dir.filePath(QStringLiteral("broken.csv")));
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("this is not,a recording\n1,2\n");
        broken.close();
        QFile notes(dir.filePath(QStringLiteral("notes.md")));
        QVERIFY(notes.open(QIODevice::WriteOnly));
        notes.write("# how they were walked\n");
        notes.close();

        TuneFolderDialog dialog(*session_, QString());
        QSignalSpy read(&dialog, &TuneFolderDialog::folderRead);
        dialog.setFolder(dir.path());
        QVERIFY(read.wait(kTimeout_ms));
        QCOMPARE(dialog.contents().names, walks);
        QCOMPARE(dialog.contents().skipped.size(), 1);  // the notes are no recording, not a failure
        QVERIFY(dialog.contents().skipped.front().startsWith(QStringLiteral("broken.csv: ")));
        QVERIFY(dialog.skippedLabel()->text().contains(QStringLiteral("broken.csv")));
        QVERIFY(dialog.isCriterionAvailable(TuneCriterion::KnownLength));
        QVERIFY(!dialog.isCriterionAvailable(TuneCriterion::ClosedLoop));
        QVERIFY(!dialog.isCriterionAvailable(TuneCriterion::Reference));
        dialog.findChild<QCheckBox*>(QStringLiteral("tuneAllClosed"))->setChecked(true);
        QVERIFY(dialog.isCriterionAvailable(TuneCriterion::ClosedLoop));
        QCOMPARE(dialog.criterion(), TuneCriterion::ClosedLoop);
        dialog.setCriterion(TuneCriterion::KnownLength);

        dialog.setEvaluations(16);
        QSignalSpy finished(&dialog, &TuneFolderDialog::tuningFinished);
        button(dialog, "tuneStart")->click();
        QVERIFY(finished.wait(kTimeout_ms));
        const TuneOutcome& outcome = dialog.outcome();
        QVERIFY2(outcome.error.empty(), outcome.error.c_str());
        QCOMPARE(dialog.progressBar()->value(), 16);
        QVERIFY(dialog.bestLabel()->text().contains(formatTuneScore(TuneCriterion::KnownLength, outcome.bestScore)));
        const QTableWidget* table = dialog.recordingsTable();
        QCOMPARE(table->rowCount(), 4);  // the three walks and the mean
        QCOMPARE(outcome.basePerRecording.size(), std::size_t(2));  // the unscorable one was not run
        for (int row = 0; row < 2; ++row) {
            const auto r = static_cast<std::size_t>(row);
            QCOMPARE(table->item(row, 0)->text(), walks[row]);
            QVERIFY(std::isfinite(outcome.basePerRecording[r]) && std::isfinite(outcome.bestPerRecording[r]));
            QCOMPARE(table->item(row, 1)->text(), formatTuneScore(TuneCriterion::KnownLength, outcome.basePerRecording[r]));
            QCOMPARE(table->item(row, 2)->text(), formatTuneScore(TuneCriterion::KnownLength, outcome.bestPerRecording[r]));
        }
        QCOMPARE(table->item(2, 0)->text(), walks[2]);
        QCOMPARE(table->item(2, 1)->text(), formatTuneScore(TuneCriterion::KnownLength, NAN));
        QCOMPARE(table->item(3, 2)->text(), formatTuneScore(TuneCriterion::KnownLength, outcome.bestScore));
        QVERIFY(outcome.best != poorStart());

        // The preset holds the tuned values.
        const QString preset = dir.filePath(QStringLiteral("tuned.json"));
        QCOMPARE(dialog.savePreset(preset), QString());
        Parameters loaded;
        QCOMPARE(loadParameters(preset.toStdString(), loaded), std::string());
        for (const ParameterField& field : parameterFields())
            if (field.kind == ParameterField::Kind::Real)
                QVERIFY(std::abs(parameterValue(loaded, field) - parameterValue(outcome.best, field))
                        <= 1e-9 * std::abs(parameterValue(outcome.best, field)));

        // Applied to the workspace as one step that Undo takes back.
        const Parameters best = outcome.best;
        const int steps = session_->undoStack()->count();
        button(dialog, "tuneApply")->click();
        QVERIFY(session_->parameters() == best);
        QCOMPARE(session_->undoStack()->count(), steps + 1);
        session_->undoStack()->undo();
        QVERIFY(session_->parameters() == poorStart());
    }

private:
    std::shared_ptr<const Recording> recording_;
    std::unique_ptr<AnalysisSession> session_;
};

QTEST_MAIN(TestTuneDialog)
#include "tst_tunedialog.moc"
