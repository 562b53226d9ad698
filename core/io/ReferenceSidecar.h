#pragma once

#include "Recording.h"

#include <string>

namespace footpath {

/// Reference facts that travel beside a recording rather than inside it:
/// - a sidecar file `<recording>.reference.json`: {"closed_loop": true, "length_m": 72.0};
/// - a walked length in the file name, as in `rectangle_72m.TXT` or `straight_40.4m.txt`.
/// What is found goes into recording.reference with a note saying where it came from; a malformed
/// sidecar adds a warning naming the file and is otherwise ignored.
void attachReferenceSidecar(const std::string& recordingPath, Recording& recording);

/// The length a file name states ("_72m", "_40.4m" before the extension or an underscore), or 0.
double lengthFromFileName(const std::string& path);

}  // namespace footpath
