#pragma once

// Internal to the parameter panel: how its rows and the panel itself write numbers and field texts,
// in one place so a value reads the same in a field, a tool tip and a reset button.

#include <QCoreApplication>
#include <QLocale>
#include <QString>

namespace footpath {

/// The user's locale without group separators: "1234.5" reads back as typed.
inline QLocale numberLocale()
{
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale;
}

inline QString formatValue(double value)
{
    return numberLocale().toString(value, 'g', 6);
}

/// Names, descriptions and groups come from core as plain text; translated here when a
/// translation provides them under this context.
inline QString fieldText(const char* text)
{
    return QCoreApplication::translate("footpath::ParameterFields", text);
}

}  // namespace footpath
