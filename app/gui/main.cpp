// footpath: the desktop application. With no argument it opens the bundled sample walk.
#include "MainWindow.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QTimer>

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    QApplication::setApplicationName("Footpath");
    QApplication::setOrganizationName("Footpath");
    qRegisterMetaType<std::shared_ptr<const footpath::Result>>();

    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate("main", "Foot-mounted inertial navigation"));
    parser.addHelpOption();
    parser.addPositionalArgument("recording", QApplication::translate("main", "Recording to open (CSV)"));
    QCommandLineOption screenshot("screenshot",
                                  QApplication::translate("main", "Save a PNG of the window once estimated, then quit"),
                                  "file");
    parser.addOption(screenshot);
    parser.process(app);

    footpath::MainWindow window;
    window.show();
    const QStringList files = parser.positionalArguments();
    window.openRecording(files.isEmpty() ? ":/samples/pyshoe-vicon-2017-11-22-11-27-30.csv" : files.first());
    if (parser.isSet(screenshot)) {
        // For documentation and visual checks under xvfb-run: wait for the estimate, grab, quit.
        QTimer::singleShot(3000, &window, [&window, path = parser.value(screenshot)] {
            window.grab().save(path);
            QApplication::quit();
        });
    }
    return app.exec();
}
