#pragma once
/// Key-frame interpolation of one target (SPEC 6).
#include "core/scene/scene_desc.h"

namespace f2 {

/// Pose of `track` at time `t` (frames, may be fractional). Before the first key
/// the first holds, after the last the last holds; `rest` when there are no keys.
/// `t` should be finite (the front ends check); NaN gives the first key.
Pose evaluateTrack(const Track& track, double t, const Pose& rest);

/// Smoothstep 3u^2 - 2u^3 used by `/interp ease`.
double easeFraction(double u);

/// Uniform Catmull-Rom between p1 and p2 with neighbours p0, p3, at u in [0, 1].
double catmullRom(double p0, double p1, double p2, double p3, double u);

}  // namespace f2
