#pragma once
/// A key-frame track (SPEC 6, 9.3, 10.4) written in POV-Ray's own language:
/// an `#if`/`#elseif` over its key intervals, each with f2's interpolation
/// as an SDL expression, so that POV-Ray evaluates the pose at any clock, as
/// track.h does.
#include <string>

#include "core/scene/scene_desc.h"

namespace f2 {

/// Whether povTrackPose writes `track` exactly: keys with every mode but
/// `bezier` (its curve is inverted by bisection), and no drives (SPEC 10.7).
bool povEvaluates(const Track& track);

/// SDL declaring `NAME_Position` and `NAME_Rotation` (degrees) as the pose of
/// `track` (at least one key, povEvaluates) at the frame time `F2_Frame`.
/// Numbers are written to 17 digits; f2 blends in double and stores floats.
std::string povTrackPose(const Track& track, const std::string& name);

}  // namespace f2
