#include "core/scene/scene_desc.h"

#include <algorithm>

#include "core/scene/models.h"

namespace f2 {

int SceneDesc::lastFrame() const {
    int last = 0;
    auto scan = [&](const Track& t) {
        if (!t.keys.empty()) last = std::max(last, t.keys.back().frame);
    };
    for (const SceneObject& o : objects) {
        scan(o.track);
        for (const Track& t : o.partTracks) scan(t);
    }
    return last;
}

std::size_t SceneDesc::primitiveCount() const {
    std::size_t n = 0;
    for (const SceneObject& o : objects) n += primitiveCountOf(o.kind);
    return n;
}

}  // namespace f2
