#pragma once
/// The story of one pixel, told by the single-ray reference path: its ray,
/// every primitive along it, the hit chosen, the normal, each light's term
/// and shadow verdict, and the colour. What `f2 render --pixel X,Y` prints.
#include <cstdint>
#include <string>
#include <vector>

#include "core/render/camera.h"
#include "core/render/image.h"
#include "core/render/prepared_frame.h"
#include "core/render/shading.h"

namespace f2 {

struct PixelReport {
    float px = 0, py = 0;  ///< the image point traced (a pixel's centre)
    Ray ray;
    float tMin = 0;  ///< hits nearer than this are behind the eye (primaryRayStart)

    /// A primitive the ray crosses beyond tMin: its nearest crossing there.
    struct Crossing {
        std::uint32_t primitive = 0;  ///< index in the frame (scene order)
        float t = 0;
        Face face = Face::Curved;
    };
    std::vector<Crossing> crossings;  ///< nearest first; equal distances by index

    bool hit = false;  ///< false: the background
    HitRecord chosen;  ///< the reference path's nearest hit (Bvh::intersect)
    ShadingPoint surface;
    Vec3 surfaceColor;  ///< the primitive's colour at the hit (its checker's cell), 0..1
    Material material;
    float ambientTerm = 0;  ///< ka * ambient (+ the material's `emit`, SPEC 10.8)

    struct Light {
        LightTerm term;
        Vec3 toLight;
        /// When shadowed: the nearest primitive on the shadow ray, and where.
        std::uint32_t occluder = Bvh::kNoPrimitive;
        float occluderT = 0;
    };
    std::vector<Light> lights;

    /// A mirror's own shading, before it adds `material.reflection` times what
    /// its mirrored rays see (`color` - `ownColor`, reflection.h).
    Vec3 ownColor;
    Vec3 color;  ///< unclamped, as shaded
    Rgb8 pixel;  ///< what the reference path writes
};

/// Traces the centre of pixel (x, y) of `camera` through `frame` (its BVH
/// built) by the reference path and reports each step.
PixelReport tracePixel(const PreparedFrame& frame, const Camera& camera, int x, int y);

/// "r1.head.face (box)", "s1 (sphere)": the object (and part and shape) a frame primitive
/// belongs to. `frame` must have been evaluated from `scene`.
std::string primitiveName(const SceneDesc& scene, const EvaluatedFrame& frame, std::uint32_t primitive);

}  // namespace f2
