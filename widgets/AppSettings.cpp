#include "AppSettings.h"

namespace footpath {

namespace {
// Every key in one place, spelt once.
constexpr const char* kKeyVersion = "version";
constexpr const char* kKeyGeometry = "window/geometry";
constexpr const char* kKeyState = "window/state";
constexpr const char* kKeyLastFolder = "files/lastFolder";
constexpr const char* kKeyRecent = "files/recent";
constexpr const char* kKeyLanguage = "ui/language";
}  // namespace

AppSettings::AppSettings()
{
    migrate();
}

AppSettings::AppSettings(const QString& organisation, const QString& application)
    : settings_(organisation, application)
{
    migrate();
}

void AppSettings::migrate()
{
    // Version 1 is the first layout; later versions translate older keys here instead of
    // clearing what the user had.
    if (settings_.value(kKeyVersion, 0).toInt() < kVersion)
        settings_.setValue(kKeyVersion, kVersion);
}

QByteArray AppSettings::windowGeometry() const { return settings_.value(kKeyGeometry).toByteArray(); }
void AppSettings::setWindowGeometry(const QByteArray& geometry) { settings_.setValue(kKeyGeometry, geometry); }
QByteArray AppSettings::windowState() const { return settings_.value(kKeyState).toByteArray(); }
void AppSettings::setWindowState(const QByteArray& state) { settings_.setValue(kKeyState, state); }
QString AppSettings::lastFolder() const { return settings_.value(kKeyLastFolder).toString(); }
void AppSettings::setLastFolder(const QString& folder) { settings_.setValue(kKeyLastFolder, folder); }
QStringList AppSettings::recentFiles() const { return settings_.value(kKeyRecent).toStringList(); }
QString AppSettings::language() const { return settings_.value(kKeyLanguage).toString(); }
void AppSettings::setLanguage(const QString& language) { settings_.setValue(kKeyLanguage, language); }

void AppSettings::addRecentFile(const QString& path)
{
    QStringList files = recentFiles();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > kMaxRecentFiles)
        files.removeLast();
    settings_.setValue(kKeyRecent, files);
}

}  // namespace footpath
