#pragma once
/// Key-frame interpolation of one target (SPEC 6, modes per key SPEC 9.3).
#include "core/scene/scene_desc.h"

namespace f2 {

/// Pose of `track` at time `t` (frames, may be fractional). Before the first key
/// the first holds, after the last the last holds; `rest` when there are no keys.
/// Between two keys the mode of the earlier one (its own, or the track's) applies.
/// `t` should be finite (the front ends check); NaN gives the first key.
Pose evaluateTrack(const Track& track, double t, const Pose& rest);

/// Smoothstep 3u^2 - 2u^3 used by `/interp ease`.
double easeFraction(double u);

/// w(u) of SPEC 9.3 for the modes that blend two keys, P1 + (P2 - P1)·w(u):
/// linear u, ease 3u² − 2u³, ease_in u³, ease_out 1 − (1 − u)³, step 0.
/// (spline is not a blend of two keys: see catmullRom.)
double interpolationWeight(Interpolation mode, double u);

/// Uniform Catmull-Rom between p1 and p2 with neighbours p0, p3, at u in [0, 1].
double catmullRom(double p0, double p1, double p2, double p3, double u);

}  // namespace f2
