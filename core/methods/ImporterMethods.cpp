// The file formats, in the order they are recognised: a more specific format before the general
// one it is a case of (pyshoe's VICON CSV before delimited text). A new format: its reader in
// io/ (streaming, returning an ImportResult), its recogniser, and one line here.

#include "io/DelimitedTextReader.h"
#include "io/Import.h"
#include "io/MtbReader.h"
#include "io/XsensTextReader.h"
#include "methods/MethodRegistry.h"

#include <set>
#include <sstream>

namespace footpath {

namespace {

std::string firstNonBlankLine(const std::string& head)
{
    std::istringstream in(head);
    std::string line;
    while (std::getline(in, line) && line.find_first_not_of(" \t\r") == std::string::npos) {
    }
    return line;
}

bool startsWithXbusPreamble(const std::string& head, const ImportOptions&)
{
    return !head.empty() && static_cast<unsigned char>(head.front()) == 0xFA;
}

bool recognisesXsensText(const std::string& head, const ImportOptions&)
{
    return looksLikeXsensText(head);
}

bool recognisesPyshoeVicon(const std::string& head, const ImportOptions&)
{
    return looksLikeSensorText(head) && firstNonBlankLine(head).find("vicon_x_m") != std::string::npos;
}

/// Delimited text needs a header row or the column map that stands for one.
bool recognisesDelimited(const std::string& head, const ImportOptions& options)
{
    return looksLikeSensorText(head) && (startsWithHeaderRow(head) || !options.columnMap.empty());
}

ImportResult readViconReference(std::istream& in, const std::string& path, const ImportOptions& options,
                                std::size_t size)
{
    // The VICON horizontal axes are mirrored relative to a right-handed z-up frame.
    ImportOptions withReference = options;
    withReference.referenceColumns = {"vicon_x_m", "-vicon_y_m", "vicon_z_m"};
    ImportResult r = readDelimitedText(in, path, withReference, size);
    r.recording.reference.notes.push_back("reference positions from vicon_x_m, -vicon_y_m, vicon_z_m "
                                          "(VICON axes are mirrored)");
    if (!r.recording.reference.stance.empty())
        r.recording.reference.notes.push_back("reference stance from zv_vicon_opt (zero velocity by motion capture)");
    return r;
}

/// pyshoe's CSV: delimited text whose VICON columns are the reference positions (unless the user
/// names others), of trials that each end where they started.
ImportResult readPyshoeVicon(std::istream& in, const std::string& path, const ImportOptions& options,
                             std::size_t size)
{
    ImportResult r = options.referenceColumns.empty() ? readViconReference(in, path, options, size)
                                                      : readDelimitedText(in, path, options, size);
    if (r.ok()) {
        r.recording.reference.closedLoop = true;
        r.recording.reference.notes.push_back("closed loop: every pyshoe-vicon trial ends where it started");
    }
    return r;
}

std::vector<ImporterMethod>& registry()
{
    static std::vector<ImporterMethod> importers{
        {"xsens-text", "Xsens MT Manager text export", "*.txt *.TXT", false, false, recognisesXsensText, readXsensText},
        {"xsens-mtb", "Xsens MT Manager binary log (.mtb)", "*.mtb", true, false, startsWithXbusPreamble, readMtb},
        {"pyshoe-vicon", "pyshoe VICON CSV (IMU with reference positions)", "*.csv *.CSV", false, false,
         recognisesPyshoeVicon, readPyshoeVicon},
        {"delimited", "delimited text with a header row or a column map (CSV, TSV, ...)", "*.csv *.CSV *.txt *.TXT",
         false, true, recognisesDelimited, readDelimitedText},
    };
    return importers;
}

}  // namespace

const std::vector<ImporterMethod>& importerMethods()
{
    return registry();
}

const ImporterMethod* findImporter(const std::string& name)
{
    for (const ImporterMethod& importer : registry())
        if (name == importer.name)
            return &importer;
    return nullptr;
}

void addImporterMethod(const ImporterMethod& method)
{
    registry().push_back(method);
    noteMethodRegistryChange();
}

std::string importerNamesText()
{
    std::string text;
    for (const ImporterMethod& importer : registry())
        text += (text.empty() ? "" : ", ") + std::string(importer.name);
    return text;
}

std::string importerFilePatterns()
{
    std::string text;
    std::set<std::string> seen;
    for (const ImporterMethod& importer : registry()) {
        std::istringstream patterns(importer.filePatterns);
        for (std::string pattern; patterns >> pattern;)
            if (seen.insert(pattern).second)
                text += (text.empty() ? "" : " ") + pattern;
    }
    return text;
}

}  // namespace footpath
