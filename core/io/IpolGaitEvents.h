#pragma once

#include "Recording.h"

#include <string>
#include <vector>

namespace footpath {

/// Attaches the hand-labelled gait events of the IPOL MTw dataset (Voisard et al. 2023; folder
/// xsens-mtw-ipol): when `recordingPath` ends with `_lf.txt` or `_rf.txt` and `<stem>.json` lies
/// beside it, its TrialBoundaries and the [toe-off, heel-strike] pairs of that foot (LeftFootEvents
/// for _lf, RightFootEvents for _rf) go to recording.reference (trialBoundaries, swings) with a note.
/// A trial with UTurnBoundaries is the protocol's out-and-back walk: marked closed, 20 m long
/// (unless a length is known already).
///
/// Returns true when events were attached. No sidecar file: false, nothing said. A sidecar that is
/// not valid JSON or lacks what is needed: false and a warning naming the file and what is missing.
/// Attached with a warning: the recording's time base has gaps (the indices then do not line up with
/// rows), swings or boundaries beyond the recording (dropped), swings outside the trial boundaries.
/// The JSON's NaN (Python's json writes it for an unknown height) is accepted.
bool attachIpolGaitEvents(const std::string& recordingPath, Recording& recording, std::vector<std::string>& warnings);

}  // namespace footpath
