// footpath: the desktop application. With no argument it opens the bundled sample walk.
#include "AnalysisSession.h"
#include "AppSettings.h"
#include "ComparisonPanel.h"
#include "MainWindow.h"
#include "Result.h"
#include "io/ParameterIo.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QLibraryInfo>
#include <QLocale>
#include <QTimer>
#include <QTranslator>

#include <cstdio>

namespace {

const char* const kSampleWalk = ":/samples/pyshoe-vicon-2017-11-22-11-27-30.csv";

/// The chosen language, or the system's; Qt's own strings (dialog buttons) too.
void installTranslations(QApplication& app, const QString& language)
{
    const QLocale locale = language.isEmpty() ? QLocale::system() : QLocale(language);
    auto* own = new QTranslator(&app);
    if (own->load(locale, QStringLiteral("footpath"), QStringLiteral("_"), QStringLiteral(":/i18n")))
        QApplication::installTranslator(own);
    auto* qt = new QTranslator(&app);
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QApplication::installTranslator(qt);
}

/// The parameters --params and --set ask for, over the defaults (as footpath-cli reads them);
/// an error message on failure.
QString readParameters(const QString& preset, const QStringList& assignments, footpath::Parameters& params)
{
    if (!preset.isEmpty())
        if (const std::string error = footpath::loadParameters(preset.toStdString(), params); !error.empty())
            return QString::fromStdString(error);
    for (const QString& assignment : assignments) {
        const qsizetype equals = assignment.indexOf(QLatin1Char('='));
        if (equals <= 0)
            return QApplication::translate("main", "--set expects name=value, got '%1'").arg(assignment);
        const std::string error = footpath::setParameter(params, assignment.left(equals).toStdString(),
                                                         assignment.mid(equals + 1).toStdString());
        if (!error.empty())
            return QString::fromStdString(error);
    }
    const std::vector<std::string> problems = params.validate();
    return problems.empty() ? QString() : QString::fromStdString(problems.front());
}

}  // namespace

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("Footpath"));
    QApplication::setOrganizationName(QStringLiteral("Footpath"));
    QApplication::setApplicationVersion(QStringLiteral(FOOTPATH_VERSION));
    qRegisterMetaType<std::shared_ptr<const footpath::Result>>();

    footpath::AppSettings settings;
    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate("main", "Foot-mounted inertial navigation"));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument("recording", QApplication::translate("main", "Recording to open"));
    const QCommandLineOption screenshot(
        "screenshot", QApplication::translate("main", "Save a PNG of the window once estimated, then quit"), "file");
    const QCommandLineOption language("language", QApplication::translate("main", "Language (en, de, zh_CN)"), "code");
    const QCommandLineOption connectPort(
        "connect", QApplication::translate("main", "Connect the live input to this serial port or emulator link"), "port");
    const QCommandLineOption preset(
        "params", QApplication::translate("main", "Start with the parameters of this preset (JSON)"), "preset.json");
    const QCommandLineOption assignment(
        "set", QApplication::translate("main", "Set one parameter, as footpath-cli does (repeatable)"), "name=value");
    const QCommandLineOption view(
        "view", QApplication::translate("main", "Show this view: signals, detector, trajectory2d or trajectory3d"), "name");
    parser.addOption(screenshot);
    parser.addOption(preset);
    parser.addOption(assignment);
    parser.addOption(view);
    const QCommandLineOption compare(
        "compare", QApplication::translate("main", "Open the method comparison and run these sets, e.g. \"zupt;zupt,zaru;feliz\""),
        "sets");
    parser.addOption(compare);
    parser.addOption(language);
    parser.addOption(connectPort);
    parser.process(app);
    installTranslations(app, parser.isSet(language) ? parser.value(language) : settings.language());

    footpath::Parameters params;
    if (const QString error = readParameters(parser.value(preset), parser.values(assignment), params); !error.isEmpty()) {
        std::fprintf(stderr, "footpath: %s\n", qPrintable(error));
        return 2;
    }

    footpath::MainWindow window(settings);
    if (params != footpath::Parameters())
        window.session()->setParameters(params, QApplication::translate("main", "Parameters from the command line"));
    if (parser.isSet(view))
        window.showView(parser.value(view));
    if (parser.isSet(compare))
        if (const QString error = window.showComparison(parser.value(compare)); !error.isEmpty()) {
            std::fprintf(stderr, "footpath: %s\n", qPrintable(error));
            return 2;
        }
    window.show();
    const QStringList files = parser.positionalArguments();
    window.openRecording(files.isEmpty() ? QString::fromUtf8(kSampleWalk) : files.first());
    if (parser.isSet(connectPort))
        window.connectLive(parser.value(connectPort));
    if (parser.isSet(screenshot) && parser.isSet(connectPort)) {
        // Live: grab after some seconds of streaming, so the path and the lanes have grown.
        QTimer::singleShot(12000, &window, [&window, path = parser.value(screenshot)] {
            window.grab().save(path);
            QApplication::quit();
        });
    } else if (parser.isSet(screenshot) && parser.isSet(compare)) {
        // The comparison takes longer than the main estimate: grab once its table is filled.
        QObject::connect(window.comparisonPanel(), &footpath::ComparisonPanel::finished, &window,
                         [&window, path = parser.value(screenshot)] {
                             QTimer::singleShot(800, &window, [&window, path] {
                                 window.grab().save(path);
                                 QApplication::quit();
                             });
                         });
    } else if (parser.isSet(screenshot)) {
        // For documentation and visual checks under xvfb-run: grab once the first result is drawn.
        QObject::connect(&window, &footpath::MainWindow::resultShown, &window, [&window, path = parser.value(screenshot)] {
            QTimer::singleShot(500, &window, [&window, path] {
                window.grab().save(path);
                QApplication::quit();
            });
        });
    }
    return app.exec();
}
