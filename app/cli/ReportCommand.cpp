#include "cli/ReportCommand.h"

#include "ReportWriter.h"
#include "cli/CliSupport.h"

#include <QApplication>

#include <cstdio>
#include <cstdlib>

namespace footpath::cli {

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
    ImportResult read = importInput(cmd);
    content.recordingPath = QString::fromStdString(cmd.input);
    content.info = read.info;
    content.recording = std::make_shared<const Recording>(std::move(read.recording));
    content.result = std::make_shared<const Result>(estimate(*content.recording, content.parameters));
    const QString problem = writePdfReport(content, QString::fromStdString(cmd.pdfOut),
                                           cmd.pageSize == "letter" ? QPageSize::Letter : QPageSize::A4);
    if (!problem.isEmpty())
        throw BadInput{problem.toStdString()};
    std::printf("%s: report written to %s\n", cmd.input.c_str(), cmd.pdfOut.c_str());
    return 0;
}

}  // namespace footpath::cli
