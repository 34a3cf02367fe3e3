#include "core/anim/track.h"

namespace f2 {

double easeFraction(double u) { return u * u * (3.0 - 2.0 * u); }

double interpolationWeight(Interpolation mode, double u) {
    switch (mode) {
        case Interpolation::Ease:
            return easeFraction(u);
        case Interpolation::EaseIn:
            return u * u * u;
        case Interpolation::EaseOut: {
            const double v = 1.0 - u;
            return 1.0 - v * v * v;
        }
        case Interpolation::Step:
            return 0.0;
        case Interpolation::Linear:
        case Interpolation::Spline:
            break;
    }
    return u;
}

Pose evaluateTrack(const Track& track, double t, const Pose& rest) {
    const std::vector<Key>& keys = track.keys;
    if (keys.empty()) return rest;
    const TrackSegment segment = segmentAt(
        keys.size(), [&](std::size_t i) { return keys[i].frame; },
        [&](std::size_t i) { return track.modeAfter(i); }, t);
    return poseInSegment(segment, [&](std::size_t i) -> const Pose& { return keys[i].pose; });
}

}  // namespace f2
