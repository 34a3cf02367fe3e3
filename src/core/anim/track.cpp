#include "core/anim/track.h"

#include <algorithm>

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

double catmullRom(double p0, double p1, double p2, double p3, double u) {
    double u2 = u * u, u3 = u2 * u;
    return 0.5 * (2.0 * p1 + (p2 - p0) * u + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * u2 +
                  (3.0 * p1 - p0 - 3.0 * p2 + p3) * u3);
}

namespace {
// The six numbers of a pose as an indexable array.
struct PoseValues {
    double v[6];
    explicit PoseValues(const Pose& p)
        : v{p.position.x, p.position.y, p.position.z, p.rotation.x, p.rotation.y, p.rotation.z} {}
};

Pose poseFrom(const double (&v)[6]) {
    return {{float(v[0]), float(v[1]), float(v[2])}, {float(v[3]), float(v[4]), float(v[5])}};
}
}  // namespace

Pose evaluateTrack(const Track& track, double t, const Pose& rest) {
    const std::vector<Key>& keys = track.keys;
    if (keys.empty()) return rest;
    // Callers pass finite times; `!(t > first)` still sends NaN to the first
    // key, so the search below always finds a key after t (never end()).
    if (!(t > keys.front().frame)) return keys.front().pose;
    if (t >= keys.back().frame) return keys.back().pose;

    // First key strictly after t; the segment is [i1, i2].
    auto after = std::upper_bound(keys.begin(), keys.end(), t,
                                  [](double time, const Key& k) { return time < k.frame; });
    std::size_t i2 = std::size_t(after - keys.begin());
    std::size_t i1 = i2 - 1;
    double u = (t - keys[i1].frame) / double(keys[i2].frame - keys[i1].frame);

    const Interpolation mode = track.modeAfter(i1);
    if (mode == Interpolation::Step) return keys[i1].pose;  // held until the next key's frame
    PoseValues a(keys[i1].pose), b(keys[i2].pose);
    double out[6];
    if (mode == Interpolation::Spline) {
        // The neighbours are the keys around, whatever their own modes; an end
        // key stands in for a missing one.
        PoseValues p0(keys[i1 == 0 ? i1 : i1 - 1].pose);
        PoseValues p3(keys[i2 + 1 < keys.size() ? i2 + 1 : i2].pose);
        for (int c = 0; c < 6; ++c) out[c] = catmullRom(p0.v[c], a.v[c], b.v[c], p3.v[c], u);
    } else {
        const double w = interpolationWeight(mode, u);
        for (int c = 0; c < 6; ++c) out[c] = a.v[c] + (b.v[c] - a.v[c]) * w;
    }
    return poseFrom(out);
}

}  // namespace f2
