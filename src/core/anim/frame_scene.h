#pragma once
/// One evaluated frame: every primitive in world space with its surface, the
/// lights and the acceleration structure. Rebuilt in place each frame; its
/// vectors keep their capacity so steady-state frames do not allocate.
#include <vector>

#include "core/geometry/bvh.h"
#include "core/geometry/primitive.h"
#include "core/math/transform.h"
#include "core/scene/scene_desc.h"

namespace f2 {

/// Shading inputs of one primitive.
struct Surface {
    Vec3 color;  ///< 0..1
    Material material;
};

struct LightSample {
    Vec3 toLight;  ///< L = -normalize(direction of travel)
    float intensity;
};

struct FrameScene {
    std::vector<Primitive> primitives;
    std::vector<Surface> surfaces;  ///< parallel to primitives
    /// Object i's primitives are [firstPrimitive[i], firstPrimitive[i + 1]).
    std::vector<std::uint32_t> firstPrimitive;
    std::vector<LightSample> lights;
    float ambient = 0;
    Vec3 background;  ///< 0..1
    /// World root frames of attached objects (SPEC 9.2), indexed by object.
    std::vector<Transform> attachedRoots;
    Bvh bvh;
};

}  // namespace f2
