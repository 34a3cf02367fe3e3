#pragma once
/// Key-frame interpolation of one target (SPEC 6, modes per key SPEC 9.3).
/// Evaluation is in two steps so that tracks with the same key frames and
/// modes share the first: `segmentAt` finds where a time falls among the key
/// frames (which keys, which fraction), `poseInSegment` blends the poses of
/// those keys.
#include <cstddef>
#include <cstdint>

#include "core/scene/scene_desc.h"

namespace f2 {

/// Pose of `track` at time `t` (frames, may be fractional). Before the first key
/// the first holds, after the last the last holds; `rest` when there are no keys.
/// Between two keys the mode of the earlier one (its own, or the track's) applies.
/// `t` should be finite (the front ends check); NaN gives the first key.
/// The track's drives (SPEC 10.7) then replace the numbers they drive.
Pose evaluateTrack(const Track& track, double t, const Pose& rest);

/// Smoothstep 3u^2 - 2u^3 used by `/interp ease`.
double easeFraction(double u);

/// SPEC 10.4's overshooting and settling easings, w(0) = 0 and w(1) = 1:
/// `back` 1 + c₃(u−1)³ + c₁(u−1)² (c₁ = 1.70158, c₃ = c₁ + 1), past 1 then
/// back; `elastic` 2^(−10u)·sin((10u − 0.75)·2π/3) + 1, a dying wobble
/// about 1; `bounce` the standard ease-out bounce (n = 7.5625, d = 2.75),
/// touching 1 three times before it rests there.
double backFraction(double u);
double elasticFraction(double u);
double bounceFraction(double u);

/// SPEC 10.4's `bezier x1 y1 x2 y2`, CSS's cubic-bezier: y(s) where x(s) = u,
/// s found by bisection to within 1e-9 (the curve's x is monotonic for x1 and
/// x2 in [0, 1]); exactly 0 at u <= 0 and 1 at u >= 1.
double bezierFraction(const BezierCurve& curve, double u);

/// w(u) of SPEC 9.3 for the modes that blend two keys, P1 + (P2 - P1)·w(u):
/// linear u, ease 3u² − 2u³, ease_in u³, ease_out 1 − (1 − u)³, step 0, and
/// back, elastic, bounce, bezier above. (spline is not a blend of two keys: see catmullRom.)
double interpolationWeight(const Easing& easing, double u);

/// Uniform Catmull-Rom between p1 and p2 with neighbours p0, p3, at u in [0, 1].
/// Inline: evaluation computes it for six channels at once.
inline double catmullRom(double p0, double p1, double p2, double p3, double u) {
    double u2 = u * u, u3 = u2 * u;
    return 0.5 * (2.0 * p1 + (p2 - p0) * u + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * u2 +
                  (3.0 * p1 - p0 - 3.0 * p2 + p3) * u3);
}

/// Where a time falls among the key frames of a track (at least one key): the
/// keys whose poses make the pose at that time, and how.
struct TrackSegment {
    enum class Kind : std::uint8_t {
        Hold,    ///< exactly key p1's pose (before the first key, after the last, or a step)
        Blend,   ///< p1 + (p2 - p1)·weight
        Spline,  ///< Catmull-Rom through p0, p1, p2, p3 at fraction `weight`
    };
    Kind kind = Kind::Hold;
    std::uint32_t p0 = 0, p1 = 0, p2 = 0, p3 = 0;  ///< key indices
    double weight = 0;                             ///< w(u) for Blend, u for Spline
};

/// The segment of time `t` among `keyCount` keys (at least one) whose times,
/// sorted and unique, are `timeOf(i)` and whose segment modes are `modeOf(i)`
/// (the Easing from key i to key i + 1). NaN gives the first key.
template <class TimeOf, class ModeOf>
TrackSegment segmentAt(std::size_t keyCount, TimeOf timeOf, ModeOf modeOf, double t) {
    const std::uint32_t last = std::uint32_t(keyCount - 1);
    // `!(t > first)` also sends NaN to the first key, so the search below
    // always finds a key after t.
    if (!(t > timeOf(0))) return {};
    if (t >= timeOf(last)) return {TrackSegment::Kind::Hold, last, last, last, last, 0};
    // First key strictly after t (timeOf(0) <= t < timeOf(last)); the segment is [i1, i2].
    std::uint32_t lo = 1, hi = last;
    while (lo < hi) {
        const std::uint32_t mid = lo + (hi - lo) / 2;
        if (t < timeOf(mid))
            hi = mid;
        else
            lo = mid + 1;
    }
    const std::uint32_t i2 = lo, i1 = i2 - 1;
    const double u = (t - timeOf(i1)) / (timeOf(i2) - timeOf(i1));
    const Easing& easing = modeOf(i1);
    const Interpolation mode = easing.mode;
    if (mode == Interpolation::Step)
        return {TrackSegment::Kind::Hold, i1, i1, i1, i1, 0};  // until the next key
    if (mode == Interpolation::Spline) {
        // The neighbours are the keys around, whatever their own modes; an end
        // key stands in for a missing one.
        return {TrackSegment::Kind::Spline, i1 == 0 ? i1 : i1 - 1, i1, i2, i2 < last ? i2 + 1 : i2, u};
    }
    return {TrackSegment::Kind::Blend, i1, i1, i2, i2, interpolationWeight(easing, u)};
}

/// One channel in a Blend or Spline `segment`, from that channel of keys p0..p3.
inline double blendInSegment(const TrackSegment& segment, double p0, double p1, double p2, double p3) {
    if (segment.kind == TrackSegment::Kind::Spline) return catmullRom(p0, p1, p2, p3, segment.weight);
    return p1 + (p2 - p1) * segment.weight;
}

/// Channel c (0..5) of a pose: position x, y, z, then rotation x, y, z.
inline double poseChannel(const Pose& pose, int c) { return c < 3 ? pose.position[c] : pose.rotation[c - 3]; }

/// The pose in `segment` of keys whose poses are `poseOf(i)`.
template <class PoseOf>
Pose poseInSegment(const TrackSegment& segment, PoseOf poseOf) {
    const Pose& a = poseOf(segment.p1);
    if (segment.kind == TrackSegment::Kind::Hold) return a;
    const Pose& b = poseOf(segment.p2);
    // A Blend segment has p0 = p1 and p3 = p2 (segmentAt).
    const Pose& p0 = poseOf(segment.p0);
    const Pose& p3 = poseOf(segment.p3);
    double out[6];
    for (int c = 0; c < 6; ++c)
        out[c] = blendInSegment(segment, poseChannel(p0, c), poseChannel(a, c), poseChannel(b, c),
                                poseChannel(p3, c));
    return {{float(out[0]), float(out[1]), float(out[2])}, {float(out[3]), float(out[4]), float(out[5])}};
}

}  // namespace f2
