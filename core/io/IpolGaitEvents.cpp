#include "io/IpolGaitEvents.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QJsonValue>
#include <QString>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace footpath {

namespace {

// The sidecars are under 1 KB; anything far larger is not one.
constexpr qint64 kMaxSidecarBytes = 1 << 20;
// Sample indices are stored as JSON numbers (doubles): beyond 2^53 they are not exact.
constexpr double kLargestExactIndex = 9007199254740992.0;
// An interval longer than this many median intervals is lost packets (as GapReport defines a gap).
constexpr double kGapFactor = 1.5;
/// The length of one IPOL trial: 10 m out and 10 m back.
constexpr double kIpolOutAndBack_m = 20.0;

std::string formatMetres(double metres)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g m", metres);
    return text;
}

struct Sidecar {
    QString path;
    QString fileName;
    const char* eventsKey;
    const char* footName;
};

/// `<stem>_lf.txt` -> `<stem>.json`, left foot; `_rf.txt` -> right foot; anything else: none.
std::optional<Sidecar> sidecarFor(const std::string& recordingPath)
{
    const QFileInfo recording(QString::fromStdString(recordingPath));
    const QString name = recording.fileName();
    const QString suffix = name.right(7).toLower();
    const bool left = suffix == QLatin1String("_lf.txt");
    if (!left && suffix != QLatin1String("_rf.txt"))
        return std::nullopt;
    const QString fileName = name.left(name.size() - 7) + QLatin1String(".json");
    return Sidecar{recording.dir().filePath(fileName), fileName, left ? "LeftFootEvents" : "RightFootEvents",
                   left ? "left foot" : "right foot"};
}

/// Python's json module writes NaN (and Infinity) for unknown numbers (Height in 10-1.json and
/// 14-1.json); strict JSON, and so QJsonDocument, rejects them. Outside strings they can only be
/// such tokens, so they become null.
QByteArray withNullForNonFiniteNumbers(const QByteArray& text)
{
    QByteArray out;
    out.reserve(text.size());
    bool inString = false;
    for (qsizetype i = 0; i < text.size(); ++i) {
        const char ch = text[i];
        if (inString) {
            out += ch;
            if (ch == '\\' && i + 1 < text.size())
                out += text[++i];
            else if (ch == '"')
                inString = false;
            continue;
        }
        inString = ch == '"';
        bool replaced = false;
        for (const char* token : {"-Infinity", "Infinity", "NaN"}) {
            const QByteArrayView tokenView(token);
            if (QByteArrayView(text).sliced(i).startsWith(tokenView)) {
                out += "null";
                i += tokenView.size() - 1;
                replaced = true;
                break;
            }
        }
        if (!replaced)
            out += ch;
    }
    return out;
}

std::optional<std::size_t> sampleIndex(const QJsonValue& value)
{
    if (!value.isDouble())
        return std::nullopt;
    const double number = value.toDouble();
    if (!(number >= 0.0 && number < kLargestExactIndex) || number != std::floor(number))
        return std::nullopt;
    return static_cast<std::size_t>(number);
}

/// [first, last] with first <= last.
std::optional<SampleRange> sampleRange(const QJsonValue& value)
{
    const QJsonArray pair = value.toArray();
    if (!value.isArray() || pair.size() != 2)
        return std::nullopt;
    const std::optional<std::size_t> first = sampleIndex(pair[0]);
    const std::optional<std::size_t> last = sampleIndex(pair[1]);
    if (!first || !last || *first > *last)
        return std::nullopt;
    return SampleRange{*first, *last};
}

std::string describeKeyProblem(const QJsonObject& root, const char* key, const char* expected)
{
    return root.contains(QLatin1String(key)) ? std::string(key) + " is not " + expected
                                             : "missing " + std::string(key);
}

struct GaitEvents {
    SampleRange trial;
    std::vector<SampleRange> swings;
};

/// The events of one foot, or what is wrong with the document.
std::optional<GaitEvents> parseGaitEvents(const QJsonObject& root, const Sidecar& sidecar, std::string& problem)
{
    GaitEvents events;
    const std::optional<SampleRange> trial = sampleRange(root.value(QLatin1String("TrialBoundaries")));
    if (!trial)
        problem = describeKeyProblem(root, "TrialBoundaries", "a pair of sample indices [first, last]");
    else
        events.trial = *trial;
    const QJsonValue list = root.value(QLatin1String(sidecar.eventsKey));
    const QJsonArray pairs = list.toArray();
    for (qsizetype i = 0; i < pairs.size(); ++i) {
        const std::optional<SampleRange> swing = sampleRange(pairs[i]);
        if (!swing) {
            problem += (problem.empty() ? "" : "; ") + std::string(sidecar.eventsKey) + " entry " + std::to_string(i + 1)
                       + " is not a [toe-off, heel-strike] pair of sample indices";
            break;
        }
        events.swings.push_back(*swing);
    }
    if (!list.isArray())
        problem += (problem.empty() ? "" : "; ") + describeKeyProblem(root, sidecar.eventsKey, "a list of [toe-off, heel-strike] pairs");
    if (!problem.empty())
        return std::nullopt;
    std::sort(events.swings.begin(), events.swings.end(),
              [](const SampleRange& a, const SampleRange& b) { return a.first < b.first; });
    return events;
}

std::optional<QJsonObject> readSidecar(const Sidecar& sidecar, std::string& problem)
{
    QFile file(sidecar.path);
    if (!file.open(QIODevice::ReadOnly)) {
        problem = "cannot be opened (" + file.errorString().toStdString() + ")";
        return std::nullopt;
    }
    if (file.size() > kMaxSidecarBytes) {
        problem = "is " + std::to_string(file.size()) + " bytes, far more than a gait-event file";
        return std::nullopt;
    }
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(withNullForNonFiniteNumbers(file.readAll()), &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        problem = "is not valid JSON (" + parseError.errorString().toStdString() + " at byte "
                  + std::to_string(parseError.offset) + ")";
        return std::nullopt;
    }
    if (!document.isObject()) {
        problem = "does not hold a JSON object";
        return std::nullopt;
    }
    return document.object();
}

/// Intervals longer than 1.5 times the median interval.
std::size_t countTimeGaps(const std::vector<ImuSample>& samples)
{
    if (samples.size() < 3)
        return 0;
    std::vector<double> intervals(samples.size() - 1);
    for (std::size_t i = 1; i < samples.size(); ++i)
        intervals[i - 1] = samples[i].time_s - samples[i - 1].time_s;
    std::vector<double> sorted = intervals;
    const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
    std::nth_element(sorted.begin(), middle, sorted.end());
    const double limit = kGapFactor * *middle;
    return static_cast<std::size_t>(
        std::count_if(intervals.begin(), intervals.end(), [limit](double interval) { return interval > limit; }));
}

std::string rangeText(const SampleRange& range)
{
    return std::to_string(range.first) + "-" + std::to_string(range.last);
}

/// Drops swings past the end of the recording and says which remain outside the trial.
void checkAgainstRecording(GaitEvents& events, const Recording& recording, const Sidecar& sidecar,
                           std::vector<std::string>& warnings)
{
    const std::string file = sidecar.fileName.toStdString();
    const std::size_t sampleCount = recording.samples.size();
    const auto beyondEnd = [sampleCount](const SampleRange& swing) { return swing.last >= sampleCount; };
    const std::size_t dropped = static_cast<std::size_t>(std::count_if(events.swings.begin(), events.swings.end(), beyondEnd));
    events.swings.erase(std::remove_if(events.swings.begin(), events.swings.end(), beyondEnd), events.swings.end());
    if (dropped > 0)
        warnings.push_back(std::to_string(dropped) + " " + sidecar.footName + " swing(s) in " + file
                           + " end beyond the recording's " + std::to_string(sampleCount) + " samples and were dropped");
    const std::size_t outside = static_cast<std::size_t>(std::count_if(
        events.swings.begin(), events.swings.end(),
        [&events](const SampleRange& swing) { return swing.first < events.trial.first || swing.last > events.trial.last; }));
    if (outside > 0)
        warnings.push_back(std::to_string(outside) + " " + sidecar.footName + " swing(s) in " + file
                           + " lie outside its TrialBoundaries " + rangeText(events.trial));
}

void warnAboutGaps(const std::string& recordingPath, const Recording& recording, const Sidecar& sidecar,
                   std::vector<std::string>& warnings)
{
    const std::size_t gaps = countTimeGaps(recording.samples);
    if (gaps == 0)
        return;
    warnings.push_back("the time base of " + QFileInfo(QString::fromStdString(recordingPath)).fileName().toStdString()
                       + " has " + std::to_string(gaps) + " gap(s) from lost packets: the sample indices in "
                       + sidecar.fileName.toStdString()
                       + " do not line up with its rows after the first gap, so its gait events are approximate");
}

/// A trial with a U-turn follows the dataset's protocol (Voisard et al. 2023): 10 m out, a U-turn,
/// 10 m back to the start. So it is a closed walk of 20 m, and its closure and distance error can
/// be reported like any other walk's.
void markOutAndBack(const QJsonObject& root, const std::string& file, Reference& reference)
{
    if (!root.value("UTurnBoundaries").isArray() || root.value("UTurnBoundaries").toArray().size() != 2)
        return;
    reference.closedLoop = true;
    if (reference.knownLength_m <= 0.0)
        reference.knownLength_m = kIpolOutAndBack_m;
    reference.notes.push_back("closed walk of " + formatMetres(reference.knownLength_m) + " (UTurnBoundaries in " + file
                              + ": the protocol walks 10 m out, turns and walks 10 m back to the start)");
}

}  // namespace

bool attachIpolGaitEvents(const std::string& recordingPath, Recording& recording, std::vector<std::string>& warnings)
{
    const std::optional<Sidecar> sidecar = sidecarFor(recordingPath);
    if (!sidecar || !QFileInfo::exists(sidecar->path))
        return false;
    const std::string file = sidecar->fileName.toStdString();
    std::string problem;
    const std::optional<QJsonObject> root = readSidecar(*sidecar, problem);
    std::optional<GaitEvents> events = root ? parseGaitEvents(*root, *sidecar, problem) : std::nullopt;
    if (!events) {
        warnings.push_back(file + (root ? ": " : " ") + problem + "; gait events not attached");
        return false;
    }
    checkAgainstRecording(*events, recording, *sidecar, warnings);
    warnAboutGaps(recordingPath, recording, *sidecar, warnings);
    Reference& reference = recording.reference;
    reference.swings = events->swings;
    reference.hasTrialBoundaries = events->trial.last < recording.samples.size();
    reference.trialBoundaries = reference.hasTrialBoundaries ? events->trial : SampleRange{};
    if (!reference.hasTrialBoundaries)
        warnings.push_back("TrialBoundaries " + rangeText(events->trial) + " in " + file + " end beyond the recording's "
                           + std::to_string(recording.samples.size()) + " samples and were not attached");
    reference.notes.push_back("gait events from " + file + " (" + sidecar->footName + ": "
                              + std::to_string(reference.swings.size()) + " swing(s), trial samples "
                              + rangeText(events->trial) + ")");
    markOutAndBack(*root, file, reference);
    return true;
}

}  // namespace footpath
