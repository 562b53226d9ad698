// footpath: the desktop application. With no argument it opens the bundled sample walk.
#include "AnalysisSession.h"
#include "AppSettings.h"
#include "ComparisonPanel.h"
#include "ImportDialog.h"
#include "MainWindow.h"
#include "RecordingLoader.h"
#include "Result.h"
#include "io/ImportPresets.h"
#include "io/ParameterIo.h"
#include "nav/BulkAllocator.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QLibraryInfo>
#include <QLocale>
#include <QTimer>
#include <QTranslator>

#include <csignal>
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
        const std::string error = footpath::setParameterByName(params, assignment.left(equals).toStdString(),
                                                         assignment.mid(equals + 1).toStdString());
        if (!error.empty())
            return QString::fromStdString(error);
    }
    const std::vector<std::string> problems = params.validate();
    return problems.empty() ? QString() : QString::fromStdString(problems.front());
}

/// The import options --columns and --import-preset give (empty when neither is set); an error
/// message on failure.
QString readImportOptions(const QString& columns, const QString& presetName, footpath::ImportOptions& options)
{
    for (const QString& role : columns.split(QLatin1Char(','), Qt::SkipEmptyParts))
        options.columnMap.push_back(role.trimmed().toStdString());
    if (presetName.isEmpty())
        return {};
    footpath::ImportPreset preset;
    if (const std::string problem = footpath::loadImportPreset(presetName.toStdString(), preset); !problem.empty())
        return QString::fromStdString(problem);
    footpath::applyImportPreset(preset, options);
    return {};
}

/// The command line's options, declared once for the help-only run and the real one.
struct GuiOptions {
    QCommandLineOption screenshot{"screenshot",
                                  QCoreApplication::translate("main", "Save a PNG of the window once estimated, then quit"),
                                  "file"};
    QCommandLineOption language{"language", QCoreApplication::translate("main", "Language (en, de, zh_CN)"), "code"};
    QCommandLineOption connectPort{
        "connect", QCoreApplication::translate("main", "Connect the live input to this serial port or emulator link"),
        "port"};
    QCommandLineOption preset{"params",
                              QCoreApplication::translate("main", "Start with the parameters of this preset (JSON)"),
                              "preset.json"};
    QCommandLineOption assignment{
        "set", QCoreApplication::translate("main", "Set one parameter, as footpath-cli does (repeatable)"), "name=value"};
    QCommandLineOption view{
        "view", QCoreApplication::translate("main", "Show this view: signals, detector, states, trajectory2d, trajectory3d, motion, summary, steps or gait"),
        "name"};
    QCommandLineOption columns{
        "columns",
        QCoreApplication::translate("main", "Read the recording with this column map, as footpath-cli does "
                                            "(time_ms,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,...)"),
        "roles"};
    QCommandLineOption importPreset{
        "import-preset", QCoreApplication::translate("main", "Read the recording with a saved import preset"),
        "name|file"};
    QCommandLineOption compare{
        "compare",
        QCoreApplication::translate("main", "Open the method comparison and run these sets, e.g. \"zupt;zupt,zaru;feliz\""),
        "sets"};

    void addTo(QCommandLineParser& parser) const
    {
        parser.setApplicationDescription(QCoreApplication::translate("main", "Foot-mounted inertial navigation"));
        parser.addHelpOption();
        parser.addVersionOption();
        parser.addPositionalArgument(
            "recording", QCoreApplication::translate("main", "Recording to open; two files (or a folder): the left and "
                                                             "the right foot of one walk"),
            "[recording [recording]]");
        for (const QCommandLineOption* option : {&screenshot, &preset, &assignment, &view, &compare, &columns,
                                                 &importPreset, &language, &connectPort})
            parser.addOption(*option);
    }
};

void setApplicationNames()
{
    QCoreApplication::setApplicationName(QStringLiteral("Footpath"));
    QCoreApplication::setOrganizationName(QStringLiteral("Footpath"));
    QCoreApplication::setApplicationVersion(QStringLiteral(FOOTPATH_VERSION));
}

/// --help and --version need no window: answered before a QApplication wants a display.
bool asksOnlyForHelpOrVersion(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i) {
        const QByteArray arg(argv[i]);
        if (arg == "-h" || arg == "--help" || arg == "-?" || arg == "--help-all" || arg == "-v" || arg == "--version")
            return true;
    }
    return false;
}

int answerHelpOrVersion(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    setApplicationNames();
    QCommandLineParser parser;
    const GuiOptions options;
    options.addTo(parser);
    parser.process(app);  // prints the help or version and exits; a bad option exits too
    return 0;
}

/// In a screenshot run nobody answers dialogs: a file that needs import settings is read with the
/// dialog's confident guess, or the run ends with the reason; a file that cannot be read ends it too.
void runUnattended(footpath::MainWindow& window)
{
    footpath::ImportDialog::setUnattended([](const QString& reason) {
        std::fprintf(stderr, "footpath: %s\n", qPrintable(reason));
        QCoreApplication::exit(2);
    });
    auto* loader = window.findChild<footpath::RecordingLoader*>();
    if (!loader)
        return;
    // Connected after the window's own handler: when that opened the file again (the import
    // guess), a newer read was asked for and this failure is not the end.
    QObject::connect(loader, &footpath::RecordingLoader::failed, &window, [loader](const QString&, const QString& message) {
        if (loader->superseded())
            return;
        std::fprintf(stderr, "footpath: %s\n", qPrintable(message));
        QCoreApplication::exit(2);
    });
}

}  // namespace

int main(int argc, char** argv)
{
    if (asksOnlyForHelpOrVersion(argc, argv))
        return answerHelpOrVersion(argc, argv);
    footpath::keepFreedMemoryForReruns();  // every slider move re-runs the estimate
    QApplication app(argc, argv);
    // Past a file size limit (ulimit -f) a write then fails with EFBIG, which the recorder reports
    // and survives, instead of the signal ending the program with the recording in flight.
    std::signal(SIGXFSZ, SIG_IGN);
    setApplicationNames();
    qRegisterMetaType<std::shared_ptr<const footpath::Result>>();

    footpath::AppSettings settings;
    QCommandLineParser parser;
    const GuiOptions options;
    options.addTo(parser);
    const QCommandLineOption& screenshot = options.screenshot;
    const QCommandLineOption& language = options.language;
    const QCommandLineOption& connectPort = options.connectPort;
    const QCommandLineOption& preset = options.preset;
    const QCommandLineOption& assignment = options.assignment;
    const QCommandLineOption& view = options.view;
    const QCommandLineOption& compare = options.compare;
    parser.process(app);
    installTranslations(app, parser.isSet(language) ? parser.value(language) : settings.language());

    footpath::Parameters params;
    if (const QString error = readParameters(parser.value(preset), parser.values(assignment), params); !error.isEmpty()) {
        std::fprintf(stderr, "footpath: %s\n", qPrintable(error));
        return 2;
    }

    footpath::ImportOptions importOptions;
    if (const QString error = readImportOptions(parser.value(options.columns), parser.value(options.importPreset), importOptions);
        !error.isEmpty()) {
        std::fprintf(stderr, "footpath: %s\n", qPrintable(error));
        return 2;
    }

    footpath::MainWindow window(settings);
    if (params != footpath::Parameters())
        window.session()->setParameters(params, QApplication::translate("main", "Parameters from the command line"));
    if (parser.isSet(view))
        if (const QString error = window.showView(parser.value(view)); !error.isEmpty()) {
            std::fprintf(stderr, "footpath: %s\n", qPrintable(error));
            return 2;
        }
    if (parser.isSet(compare))
        if (const QString error = window.showComparison(parser.value(compare)); !error.isEmpty()) {
            std::fprintf(stderr, "footpath: %s\n", qPrintable(error));
            return 2;
        }
    if (parser.isSet(screenshot) && !parser.isSet(connectPort))
        runUnattended(window);
    window.show();
    const QStringList files = parser.positionalArguments();
    if (files.isEmpty())
        window.openRecording(QString::fromUtf8(kSampleWalk));
    else if (files.size() == 1 && (parser.isSet(options.columns) || parser.isSet(options.importPreset)))
        window.openRecording(files.first(), importOptions);
    else if (const QString problem = window.openRecordings(files); !problem.isEmpty()) {
        std::fprintf(stderr, "footpath: %s\n", qPrintable(problem));
        if (parser.isSet(screenshot))
            return 2;  // nothing will be drawn to grab: waiting for it would never end
    }
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
