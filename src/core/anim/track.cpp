#include "core/anim/track.h"

#include <cmath>
#include <numbers>

namespace f2 {

double easeFraction(double u) { return u * u * (3.0 - 2.0 * u); }

double backFraction(double u) {
    constexpr double c1 = 1.70158;  // the classic 10 % overshoot
    constexpr double c3 = c1 + 1.0;
    if (u <= 0.0) return 0.0;  // 1 + c₃(−1) + c₁ is 2e-16 in doubles: a key must be exact
    const double v = u - 1.0;
    return 1.0 + c3 * v * v * v + c1 * v * v;
}

double elasticFraction(double u) {
    if (u <= 0.0) return 0.0;
    if (u >= 1.0) return 1.0;
    constexpr double kTwoPiOverThree = 2.0 * std::numbers::pi / 3.0;
    return std::exp2(-10.0 * u) * std::sin((10.0 * u - 0.75) * kTwoPiOverThree) + 1.0;
}

double bounceFraction(double u) {
    constexpr double n = 7.5625;
    constexpr double d = 2.75;
    if (u < 1.0 / d) return n * u * u;
    if (u < 2.0 / d) {
        const double v = u - 1.5 / d;
        return n * v * v + 0.75;
    }
    if (u < 2.5 / d) {
        const double v = u - 2.25 / d;
        return n * v * v + 0.9375;
    }
    const double v = u - 2.625 / d;
    return n * v * v + 0.984375;
}

double bezierFraction(const BezierCurve& curve, double u) {
    if (u <= 0.0) return 0.0;
    if (u >= 1.0) return 1.0;
    // B(s) = 3(1−s)²s·c1 + 3(1−s)s²·c2 + s³, for x and for y.
    auto along = [](double c1, double c2, double s) {
        const double r = 1.0 - s;
        return 3.0 * r * r * s * c1 + 3.0 * r * s * s * c2 + s * s * s;
    };
    // Bisection, not Newton: the same steps for every u, so w(u) is one exact
    // function of u on every machine; 30 halvings leave s within 1e-9.
    double lo = 0.0, hi = 1.0;
    for (int step = 0; step < 30; ++step) {
        const double mid = 0.5 * (lo + hi);
        if (along(curve.x1, curve.x2, mid) < u)
            lo = mid;
        else
            hi = mid;
    }
    return along(curve.y1, curve.y2, 0.5 * (lo + hi));
}

double interpolationWeight(const Easing& easing, double u) {
    switch (easing.mode) {
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
        case Interpolation::Back:
            return backFraction(u);
        case Interpolation::Elastic:
            return elasticFraction(u);
        case Interpolation::Bounce:
            return bounceFraction(u);
        case Interpolation::Bezier:
            return bezierFraction(easing.curve, u);
        case Interpolation::Linear:
        case Interpolation::Spline:
            break;
    }
    return u;
}

namespace {
Pose keyedPose(const Track& track, double t, const Pose& rest) {
    const std::vector<Key>& keys = track.keys;
    if (keys.empty()) return rest;
    const TrackSegment segment = segmentAt(
        keys.size(), [&](std::size_t i) { return keys[i].time; },
        [&](std::size_t i) -> const Easing& { return track.modeAfter(i); }, t);
    return poseInSegment(segment, [&](std::size_t i) -> const Pose& { return keys[i].pose; });
}
}  // namespace

Pose evaluateTrack(const Track& track, double t, const Pose& rest) {
    Pose pose = keyedPose(track, t, rest);
    if (track.drives) applyDrives(*track.drives, t, pose);
    return pose;
}

}  // namespace f2
