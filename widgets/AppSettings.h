#pragma once

#include <QByteArray>
#include <QSettings>
#include <QString>
#include <QStringList>

namespace footpath {

/// The one owner of every QSettings key the application uses, with a version and migrations.
/// Tests construct it with their own organisation/application names so a user's settings are
/// never touched.
class AppSettings {
public:
    static constexpr int kVersion = 1;
    static constexpr int kMaxRecentFiles = 10;

    AppSettings();  ///< the application's settings (QCoreApplication names)
    AppSettings(const QString& organisation, const QString& application);

    QByteArray windowGeometry() const;
    void setWindowGeometry(const QByteArray& geometry);
    QByteArray windowState() const;
    void setWindowState(const QByteArray& state);

    QString lastFolder() const;
    void setLastFolder(const QString& folder);

    QStringList recentFiles() const;
    /// Moves or adds the path to the front; the list keeps at most kMaxRecentFiles entries.
    void addRecentFile(const QString& path);

    QString language() const;  ///< "" follows the system; "en", "de", "zh_CN"
    void setLanguage(const QString& language);

private:
    void migrate();
    mutable QSettings settings_;
};

}  // namespace footpath
