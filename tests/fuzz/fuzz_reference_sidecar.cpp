// libFuzzer target: the reference sidecar reader (`<recording>.reference.json`: closed loop,
// known length). The reader takes the recording's path, so the bytes go to a scratch file.

#include "io/ReferenceSidecar.h"

#include "FuzzInput.h"

#include <QDir>

using namespace footpath;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    fuzz::writeScratchFile(QStringLiteral("walk.csv.reference.json"), data, size);
    Recording recording;
    attachReferenceSidecar(QDir(fuzz::scratchDirectory()).filePath(QStringLiteral("walk.csv")).toStdString(),
                           recording);
    return 0;
}
