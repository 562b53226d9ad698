#pragma once

// What defines each method of the pipeline, in one place per method: its token, its labels, its
// parameter rows and when they are read, and how to build it. Every central list (method sets,
// the measurement sources, the parameter table and its "not used" reasons, the method lanes, the
// detector's statistic label, the import dispatch, the CLI help, the file dialog's filter)
// iterates these registries, so a new detector, source or format is its own files plus one line
// in DetectorMethods.cpp, SourceMethods.cpp or ImporterMethods.cpp (docs/architecture.md).

#include "Recording.h"
#include "nav/Parameters.h"

#include <cstddef>
#include <istream>
#include <memory>
#include <string>
#include <vector>

namespace footpath {

class MeasurementSource;
struct ImportOptions;
struct ImportResult;

/// A measurement source of the error-state filter (ZUPT, HDR, the barometer, ...).
struct SourceMethod {
    const char* token;     ///< in method sets, notes and comparisons ("hdr"); the source's name()
    const char* setLabel;  ///< how a method set spells it ("HDR" in "ZUPT+HDR")
    const char* switchName;                  ///< its switch in the parameter table ("use_hdr")
    bool (*isOn)(const Parameters&);         ///< the switch's value
    void (*setOn)(Parameters&, bool on);     ///< sets the switch (method sets turn methods on and off)
    /// Its source for these parameters, or nullptr when the parameters leave it off (or another
    /// method's source carries it: ZARU rides in the zero-velocity update).
    std::unique_ptr<MeasurementSource> (*make)(const Parameters&);
    /// Its rows of the parameter table: the switch first, then its own (nullptr: none).
    std::vector<ParameterField> (*fields)();
    int applyRank;  ///< the order sources apply at one sample (smaller first): ZUPT before all
};

/// The sources in the order the parameter table lists them (sorted by applyRank where they apply).
const std::vector<SourceMethod>& sourceMethods();
const SourceMethod* findSourceMethod(const std::string& token);
/// Adds a source after the built-in ones (an extension; a test's example). Call before any use
/// of the registry on other threads.
void addSourceMethod(const SourceMethod& method);

/// What the zero-velocity statistics share: the noise they are normalised by, worked out once.
struct StatisticConstants {
    double gravity_mps2 = 9.81;
    double varAcc = 1.0;  ///< zv_sigma_acc_mps2^2
    double varGyr = 1.0;
    double invVarAcc = 1.0;
    double invVarGyr = 1.0;
};
using ZeroVelocityStatisticFunction = double (*)(const StatisticConstants&, const ImuSample* window,
                                                 std::size_t count);

/// A stance detector: the value of the `detector` choice at its index in the registry (presets
/// store its token, so the order is kept: a new one is appended).
struct DetectorMethod {
    const char* token;  ///< the choice's name ("shoe")
    const char* label;  ///< the choice's label ("SHOE (GLRT)"), translated in "footpath::ParameterFields"
    /// The normalised statistic over a window; nullptr for the C1/C2/C3 detector, whose fixed
    /// bounds decide without one.
    ZeroVelocityStatisticFunction statistic;
    bool readsAccelerometer;
    bool readsGyroscope;
};

const std::vector<DetectorMethod>& detectorMethods();
/// The detector params choose (the registry's first when the index is out of range).
const DetectorMethod& chosenDetector(const Parameters& params);
void addDetectorMethod(const DetectorMethod& method);

/// What turns the samples into a path (the `estimator` choice) and the filter sizes, as method
/// sets name them.
struct EstimatorMethod {
    const char* token;     ///< the choice's name ("rts") and its method-set token
    const char* label;     ///< the choice's label, translated in "footpath::ParameterFields"
    const char* setLabel;  ///< in method sets ("RTS smoother"); empty: not named in a set (the plain filter)
    const char* laneLabel; ///< the method lanes' name for its notes (empty: none of its own)
};
const std::vector<EstimatorMethod>& estimatorMethods();

/// A file format: recognised from its content, read streaming.
struct ImporterMethod {
    const char* name;          ///< what --format and `info` say ("xsens-mtb")
    const char* description;   ///< for the CLI help ("Xsens MT Manager binary log")
    const char* filePatterns;  ///< for the file dialog's filter ("*.mtb"), space separated
    bool binary;               ///< recognised among binary heads (else among text heads)
    /// Takes any file of its kind that no other format recognises (delimited text): tried after
    /// every other, so a format registered later is still recognised first.
    bool catchAll;
    /// Whether the first 64 KiB are this format; tried in registry order, so a more specific
    /// format (pyshoe's VICON CSV) comes before a more general one.
    bool (*recognises)(const std::string& head, const ImportOptions& options);
    ImportResult (*read)(std::istream& in, const std::string& path, const ImportOptions& options, std::size_t size);
};
const std::vector<ImporterMethod>& importerMethods();
const ImporterMethod* findImporter(const std::string& name);
void addImporterMethod(const ImporterMethod& method);
/// "xsens-text, xsens-mtb, delimited, pyshoe-vicon": the names for help texts and messages.
std::string importerNamesText();
/// The patterns of every importer, deduplicated, for a file dialog ("*.txt *.csv *.mtb").
std::string importerFilePatterns();

/// Counts the additions to the registries (add*Method), so tables built from them (the parameter
/// table) are rebuilt after an extension registers itself.
int methodRegistryGeneration();
void noteMethodRegistryChange();

/// The tokens method sets accept, in a stable order: the sources, then the estimators, then the
/// filter sizes ("9state", "15state").
std::vector<std::string> methodSetTokens();
/// "zupt, zaru, hdr, ...": the tokens for help texts.
std::string methodSetTokensText();

}  // namespace footpath
