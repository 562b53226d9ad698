#include "cli/ReportCommand.h"

#include "ReportWriter.h"
#include "cli/CliSupport.h"

#include "gait/BilateralGait.h"
#include "io/FootPairing.h"

#include <QApplication>
#include <QFileInfo>

#include <cstdio>
#include <cstdlib>

namespace footpath::cli {

namespace {

/// The left and the right file of one walk, as the window shows them: the left foot's report with
/// the right foot's path turned onto it, and what both feet give together.
void addBothFeet(const CommandLine& cmd, ReportContent& content)
{
    std::string problem;
    const std::optional<FootPair> pair = pairFeet(cmd.inputs[0], cmd.inputs[1], problem);
    if (!pair)
        throw BadInput{problem};
    const ImportOptions options = importOptionsOf(cmd);
    ImportResult left = importFile(pair->left, options);
    printImportWarnings(pair->left, left.recording.warnings);
    ImportResult right = importFile(pair->right, options);
    printImportWarnings(pair->right, right.recording.warnings);
    content.recordingPath = QString::fromStdString(pair->left) + QStringLiteral(" + ")
                            + QFileInfo(QString::fromStdString(pair->right)).fileName();
    content.info = left.info;
    content.recording = std::make_shared<const Recording>(std::move(left.recording));
    content.result = std::make_shared<const Result>(estimate(*content.recording, content.parameters));
    const Result rightResult = estimate(right.recording, content.parameters);
    BilateralGait walk = analyseBilateralGait(*content.result, rightResult);
    for (auto note = pair->notes.rbegin(); note != pair->notes.rend(); ++note)
        walk.warnings.insert(walk.warnings.begin(), *note);
    content.bothFeet = std::move(walk);
    content.pathLabel = QStringLiteral("Left foot");
    content.otherPaths = {PathOverlay{QStringLiteral("Right foot"), otherFootColour(),
                                      otherFootPathAligned(*content.result, rightResult)}};
}

}  // namespace

int runReport(const CommandLine& cmd)
{
    // The figures are the workspace's own widgets: they need a QApplication, which needs a
    // platform; without a display the offscreen one draws just as well.
    if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY")
        && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    int argc = 1;
    char name[] = "footpath-cli";
    char* argv[] = {name, nullptr};
    QApplication app(argc, argv);
    QApplication::setApplicationVersion(QStringLiteral(FOOTPATH_VERSION));

    ReportContent content;
    content.parameters = loadParameterSet(cmd);
    content.parameterSource = QString::fromStdString(describeParameters(cmd));
    if (cmd.inputs.size() == 2) {
        addBothFeet(cmd, content);
    } else {
        ImportResult read = importInput(cmd);
        content.recordingPath = QString::fromStdString(cmd.input);
        content.info = read.info;
        content.recording = std::make_shared<const Recording>(std::move(read.recording));
        content.result = std::make_shared<const Result>(estimate(*content.recording, content.parameters));
    }
    const QString problem = writePdfReport(content, QString::fromStdString(cmd.pdfOut),
                                           cmd.pageSize == "letter" ? QPageSize::Letter : QPageSize::A4);
    if (!problem.isEmpty())
        throw BadInput{problem.toStdString()};
    std::printf("%s: report written to %s\n", content.recordingPath.toStdString().c_str(), cmd.pdfOut.c_str());
    return 0;
}

}  // namespace footpath::cli
