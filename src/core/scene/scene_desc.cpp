#include "core/scene/scene_desc.h"

#include <algorithm>
#include <cmath>

#include "core/scene/models.h"

namespace f2 {

std::string_view interpolationName(Interpolation mode) {
    switch (mode) {
        case Interpolation::Linear:
            return "linear";
        case Interpolation::Ease:
            return "ease";
        case Interpolation::Spline:
            return "spline";
        case Interpolation::EaseIn:
            return "ease_in";
        case Interpolation::EaseOut:
            return "ease_out";
        case Interpolation::Step:
            return "step";
        case Interpolation::Back:
            return "back";
        case Interpolation::Elastic:
            return "elastic";
        case Interpolation::Bounce:
            return "bounce";
        case Interpolation::Bezier:
            return "bezier";
    }
    return "linear";
}

int SceneDesc::lastFrame() const {
    double last = 0;
    auto scan = [&](const Track& t) {
        if (!t.keys.empty()) last = std::max(last, t.keys.back().time);
    };
    for (const SceneObject& o : objects) {
        scan(o.track);
        for (const Track& t : o.partTracks) scan(t);
        if (!o.attachChanges.empty()) last = std::max(last, o.attachChanges.back().time);
    }
    scan(camera.track);
    scan(camera.zoom);
    for (const LightMotion& l : lightMotions) {
        scan(l.track);
        scan(l.intensity);
    }
    for (const TargetTrack& c : colourTracks) scan(c.track);
    for (const TargetTrack& v : visibilityTracks) scan(v.track);
    for (const Caption& c : captions) last = std::max(last, c.to);
    return int(std::ceil(last));
}

std::size_t SceneDesc::primitiveCount() const {
    std::size_t n = 0;
    for (const SceneObject& o : objects) n += primitiveCountOf(o);
    return n;
}

}  // namespace f2
