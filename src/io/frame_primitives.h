#pragma once
/// The primitives of one evaluated frame as exact placed shapes (kind, size,
/// local-to-world transform, colour, material), in scene order — what the
/// exporters write. Built from the animation API rather than from the
/// renderer's PreparedFrame, whose intersection layout is free to change.
#include <string>
#include <vector>

#include "core/math/transform.h"
#include "core/scene/models.h"

namespace f2 {

struct PlacedPrimitive {
    std::string label;  ///< "floor", "r1.head.face", "r1.head.leye"... (the shape's name in the language)
    ShapeKind kind = ShapeKind::Sphere;
    Vec3 size;                 ///< sphere (r, 0, 0); cylinder (r, h, 0); box (sx, sy, sz)
    Transform worldFromLocal;  ///< canonical frame: centred, cylinder axis local y
    Color8 color;
    Material material;
    Checker checker;          ///< size 0: plain `color`
    bool castsShadow = true;  ///< false under `/no_shadow` (SPEC 10.8)
    bool hidden = false;      ///< hidden at that time (SPEC 10.7); only with keepHidden
};

/// Every primitive seen at time `t` (frames; hidden ones, SPEC 10.7, left out, or kept and marked with
/// `keepHidden`, so that the list is the same at every time): objects as created, a model instance as
/// its shapes in its model's order (the robot: torso, face, two eyes, two arms), the order of the
/// renderer and of the Embree peer's format.
std::vector<PlacedPrimitive> framePrimitives(const SceneDesc& scene, double t, bool keepHidden = false);

/// Text of a float that reads back to the same float, in the C locale.
std::string formatNumber(float value);
/// The same for a double (key times, the clock's range).
std::string formatNumber(double value);

}  // namespace f2
