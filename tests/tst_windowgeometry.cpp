// Where the main window opens, on an offscreen platform with two screens: a 1280x800 laptop
// (primary) and a 1920x1080 monitor beside it. The window fills the available area, restores a
// saved geometry only where it fits, and leaves the plots most of the height.
#include "AppSettings.h"
#include "MainWindow.h"

#include <QApplication>
#include <QDockWidget>
#include <QFile>
#include <QScreen>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QtTest>

using namespace footpath;

namespace {

const QRect kLaptop(0, 0, 1280, 800);
const QRect kMonitor(1280, 0, 1920, 1080);

QScreen* screenWithGeometry(const QRect& geometry)
{
    for (QScreen* screen : QGuiApplication::screens())
        if (screen->geometry() == geometry)
            return screen;
    return nullptr;
}

/// A window whose saved geometry is `saved` (none when null), as the next start finds it.
QByteArray geometrySavedAt(AppSettings& settings, const QRect& saved)
{
    settings.setWindowGeometry({});
    settings.setWindowState({});
    MainWindow window(settings);
    window.show();  // on its screen, as a window the user moved there
    if (!QTest::qWaitForWindowExposed(&window))
        return {};
    window.setWindowState(Qt::WindowNoState);
    window.setGeometry(saved);
    QTest::qWait(50);
    return window.saveGeometry();
}

}  // namespace

class TestWindowGeometry : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY2(screenWithGeometry(kLaptop) && screenWithGeometry(kMonitor),
                 "the offscreen platform did not take the two-screen configuration");
    }

    void init()
    {
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_windowgeometry"));
        settings.setWindowGeometry({});
        settings.setWindowState({});
    }

    void fillsTheAvailableAreaOfEachScreen_data()
    {
        QTest::addColumn<QRect>("screen");
        QTest::newRow("1280x800") << kLaptop;
        QTest::newRow("1920x1080") << kMonitor;
    }

    void fillsTheAvailableAreaOfEachScreen()
    {
        QFETCH(QRect, screen);
        const QRect available = screenWithGeometry(screen)->availableGeometry();
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_windowgeometry"));
        MainWindow window(settings);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.placeOnScreen(available);
        QTRY_VERIFY2(available.contains(window.frameGeometry()),
                     qPrintable(QStringLiteral("%1,%2 %3x%4").arg(window.frameGeometry().x()).arg(window.frameGeometry().y())
                                    .arg(window.frameGeometry().width()).arg(window.frameGeometry().height())));
        QVERIFY(window.frameGeometry().width() >= available.width() - 8);  // no more than the frame less
        QVERIFY(window.frameGeometry().height() >= available.height() - 40);
        // Everything inside: the status bar at the bottom edge, not below it.
        const QRect status = window.statusBar()->geometry();
        QVERIFY(window.statusBar()->isVisible() && status.height() > 0);
        QVERIFY(status.bottom() < window.height());
        // The plots get the room: summary and history a quarter of the height, not 40 %.
        auto* summary = window.findChild<QDockWidget*>(QStringLiteral("summaryDock"));
        QTRY_VERIFY2(summary->height() <= 0.3 * window.height(),
                     qPrintable(QStringLiteral("%1 of %2").arg(summary->height()).arg(window.height())));
        QVERIFY(summary->height() >= 0.12 * window.height());
        QVERIFY(summary->isVisible());  // in front of the history that shares its place
        QVERIFY(window.centralWidget()->height() >= 0.55 * window.height());
    }

    void everyTabIsReadableAtTheLaptopSize()
    {
        // At 1280x800 the central tab bars once scrolled ("Li" and "Live si" at their ends): the live
        // views' tabs come with the live input, and the recorded walk's tabs fit without scrolling.
        const QRect available = screenWithGeometry(kLaptop)->availableGeometry();
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_windowgeometry"));
        MainWindow window(settings);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.placeOnScreen(available);
        QTRY_VERIFY(available.contains(window.frameGeometry()));
        QTest::qWait(50);  // the docks' first sizes
        const QList<QTabWidget*> central = window.centralWidget()->findChildren<QTabWidget*>(QString(), Qt::FindDirectChildrenOnly);
        QCOMPARE(central.size(), 2);
        const auto visibleTabs = [](const QTabWidget* tabs) {
            QStringList names;
            for (int i = 0; i < tabs->count(); ++i)
                if (tabs->isTabVisible(i))
                    names << tabs->tabText(i);
            return names;
        };
        // Every visible tab in full beside the corner button: the bar never needs its scroll arrows.
        const auto verifyTabsFit = [&](const QTabWidget* tabs) {
            const QStringList shown = visibleTabs(tabs);
            const QWidget* corner = tabs->cornerWidget(Qt::TopRightCorner);
            const int needed = tabs->tabBar()->sizeHint().width() + (corner ? corner->sizeHint().width() : 0);
            QVERIFY2(needed <= tabs->width(), qPrintable(QStringLiteral("%1: %2 px needed, %3 px there")
                                                             .arg(shown.join(", ")).arg(needed).arg(tabs->width())));
            for (int i = 0; i < tabs->count(); ++i)
                if (tabs->isTabVisible(i))
                    QVERIFY2(tabs->tabBar()->tabRect(i).right() < tabs->tabBar()->width(), qPrintable(tabs->tabText(i)));
        };
        for (const QTabWidget* tabs : central) {
            QVERIFY2(visibleTabs(tabs).filter(QStringLiteral("Live")).isEmpty(), qPrintable(visibleTabs(tabs).join(", ")));  // no session yet
            verifyTabsFit(tabs);
        }
        if (QTest::currentTestFailed())
            return;
        const QStringList recordedTabs = visibleTabs(central[0]) + visibleTabs(central[1]);
        auto* liveDock = window.findChild<QDockWidget*>(QStringLiteral("liveDock"));
        liveDock->raise();
        for (const QTabWidget* tabs : central)
            QTRY_VERIFY2(visibleTabs(tabs).filter(QStringLiteral("Live")).size() == 2, qPrintable(visibleTabs(tabs).join(", ")));
        QTest::qWait(50);  // the tab bars' new layout
        // With the live views beside the recorded walk's, both sets still fit, and each label still
        // names its view: every tab's full name is in its tool tip.
        for (const QTabWidget* tabs : central) {
            verifyTabsFit(tabs);
            for (int i = 0; i < tabs->count(); ++i)
                QVERIFY2(!tabs->tabToolTip(i).isEmpty(), qPrintable(tabs->tabText(i)));
        }
        if (QTest::currentTestFailed())
            return;
        window.findChild<QDockWidget*>(QStringLiteral("inputDock"))->raise();
        for (const QTabWidget* tabs : central)
            QTRY_VERIFY(visibleTabs(tabs).filter(QStringLiteral("Live")).isEmpty());
        QCOMPARE(visibleTabs(central[0]) + visibleTabs(central[1]), recordedTabs);  // the full labels are back
    }

    void opensAtTheScreenSizeWithoutASavedGeometry()
    {
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_windowgeometry"));
        MainWindow window(settings);
        const QRect available = window.screen()->availableGeometry();
        QVERIFY(window.windowState() & Qt::WindowMaximized);
        QCOMPARE(window.geometry(), available);  // also the area it restores to when unmaximized
    }

    void aSavedGeometryIsRestoredWhereItFits_data()
    {
        QTest::addColumn<QRect>("saved");
        QTest::newRow("on the laptop") << QRect(100, 50, 1100, 700);
        QTest::newRow("on the monitor") << QRect(kMonitor.topLeft() + QPoint(60, 40), QSize(1500, 950));
    }

    void aSavedGeometryIsRestoredWhereItFits()
    {
        QFETCH(QRect, saved);
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_windowgeometry"));
        const QByteArray geometry = geometrySavedAt(settings, saved);
        QVERIFY(!geometry.isEmpty());
        settings.setWindowGeometry(geometry);
        MainWindow window(settings);
        QCOMPARE(window.geometry(), saved);
        QVERIFY(!(window.windowState() & Qt::WindowMaximized));
    }

    void aGeometryTooLargeForTheScreenIsNotRestored()
    {
        // 1400x900 on the laptop: the old fixed size, larger than the screen.
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_windowgeometry"));
        const QByteArray geometry = geometrySavedAt(settings, QRect(0, 0, 1400, 900));
        settings.setWindowGeometry(geometry);
        MainWindow window(settings);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const QRect available = screenWithGeometry(kLaptop)->availableGeometry();
        QTRY_VERIFY2(available.contains(window.frameGeometry()),
                     qPrintable(QStringLiteral("%1x%2").arg(window.width()).arg(window.height())));
        QVERIFY(window.width() >= available.width() - 8 && window.height() >= available.height() - 40);
    }

    void cleanupTestCase()
    {
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_windowgeometry"));
        settings.setWindowGeometry({});
        settings.setWindowState({});
    }
};

int main(int argc, char** argv)
{
    // Two screens side by side, with window frames, instead of the offscreen platform's one 800x800.
    QTemporaryDir dir;
    const QString config = dir.filePath(QStringLiteral("screens.json"));
    QFile file(config);
    if (!dir.isValid() || !file.open(QIODevice::WriteOnly))
        return 1;
    file.write(R"({"windowFrameMargins": true, "screens": [
        {"name": "laptop", "x": 0, "y": 0, "width": 1280, "height": 800, "logicalDpi": 96, "logicalBaseDpi": 96, "dpr": 1},
        {"name": "monitor", "x": 1280, "y": 0, "width": 1920, "height": 1080, "logicalDpi": 96, "logicalBaseDpi": 96, "dpr": 1}]})");
    file.close();
    qputenv("QT_QPA_PLATFORM", ("offscreen:configfile=" + config).toUtf8());
    QStandardPaths::setTestModeEnabled(true);
    QApplication app(argc, argv);
    TestWindowGeometry test;
    return QTest::qExec(&test, argc, argv);
}

#include "tst_windowgeometry.moc"
