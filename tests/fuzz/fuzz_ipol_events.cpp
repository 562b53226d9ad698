// libFuzzer target: the IPOL gait-event reader (`<stem>.json` beside `<stem>_lf.txt`). The first
// two bytes give the recording's length (so events fall inside, across and beyond its end) and
// whether it has a gap in its time base; the rest is the JSON file.

#include "io/IpolGaitEvents.h"

#include "FuzzInput.h"

#include <QDir>

using namespace footpath;

namespace {

Recording recordingOf(std::size_t sampleCount, bool withGap)
{
    Recording recording;
    recording.samples.resize(sampleCount);
    for (std::size_t i = 0; i < sampleCount; ++i)
        recording.samples[i].time_s = 0.01 * static_cast<double>(i) + (withGap && i > sampleCount / 2 ? 0.5 : 0.0);
    return recording;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size < 2)
        return 0;
    const std::size_t sampleCount = std::size_t{data[0]} * 32;
    const bool withGap = data[1] & 1;
    const bool leftFoot = data[1] & 2;
    fuzz::writeScratchFile(QStringLiteral("trial.json"), data + 2, size - 2);
    Recording recording = recordingOf(sampleCount, withGap);
    std::vector<std::string> warnings;
    const QString name = leftFoot ? QStringLiteral("trial_lf.txt") : QStringLiteral("trial_rf.txt");
    (void)attachIpolGaitEvents(QDir(fuzz::scratchDirectory()).filePath(name).toStdString(), recording, warnings);
    return 0;
}
