#include "core/render/pixel_report.h"

#include <algorithm>
#include <tuple>

#include "core/render/reflection.h"
#include "core/scene/models.h"

namespace f2 {

namespace {
/// Every primitive `ray` crosses within (tMin, inf) other than `skip`, by
/// brute force (not the BVH, which the report is there to check), nearest
/// first and equal distances by index.
std::vector<PixelReport::Crossing> crossingsOf(const EvaluatedFrame& frame, const Ray& ray, float tMin,
                                               std::uint32_t skip = Bvh::kNoPrimitive) {
    std::vector<PixelReport::Crossing> out;
    for (std::uint32_t i = 0; i < frame.primitives.size(); ++i) {
        PixelReport::Crossing c{i, 0, Face::Curved};
        if (!frame.rayMask.empty() && (frame.rayMask[i] & ray_mask::kHidden)) continue;  // SPEC 10.7
        if (i != skip && intersectPrimitive(frame.primitives[i], ray, tMin, kInfinity, c.t, c.face))
            out.push_back(c);
    }
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
        return std::tie(a.t, a.primitive) < std::tie(b.t, b.primitive);
    });
    return out;
}
}  // namespace

PixelReport tracePixel(const PreparedFrame& frame, const Camera& camera, int x, int y) {
    PixelReport r;
    r.px = float(x) + 0.5f;
    r.py = float(y) + 0.5f;
    r.ray = camera.rayThrough(r.px, r.py);
    r.tMin = primaryRayStart(r.ray.origin);
    r.crossings = crossingsOf(frame, r.ray, r.tMin);
    r.hit = frame.bvh.intersect(r.ray, r.tMin, kInfinity, r.chosen);
    if (!r.hit) {
        r.color = frame.background;
    } else {
        const Surface& surface = frame.surfaces[r.chosen.primitive];
        r.surface = shadingPoint(frame, r.ray, r.chosen);
        r.surfaceColor = surfaceColorAt(surface, frame.primitives[r.chosen.primitive], r.surface.position,
                                        r.surface.inside ? -r.surface.normal : r.surface.normal,
                                        shadowOffset(r.surface.position));
        r.material = surface.material;
        r.ambientTerm = unlitSum(surface.material, frame.ambient);
        r.color = shadeHit(frame, r.ray, r.chosen, [&](const LightTerm& term) {
            PixelReport::Light light{term, term.toLight};
            if (term.shadowed) {
                // The occluder on the ray toward the light's centre, nearer than a point light.
                // (A primitive under `/no_shadow` is passed through, SPEC 10.8.)
                auto blockers =
                    crossingsOf(frame, {r.surface.shadowOrigin, light.toLight}, 0.0f, r.surface.skip);
                std::erase_if(blockers, [&](const PixelReport::Crossing& c) {
                    return !frame.rayMask.empty() && frame.rayMask[c.primitive] != 0;
                });
                if (!blockers.empty() && blockers.front().t < term.distance) {
                    light.occluder = blockers.front().primitive;
                    light.occluderT = blockers.front().t;
                }
            }
            r.lights.push_back(light);
        });
    }
    r.ownColor = r.color;
    if (r.hit && r.material.reflection > 0) r.color = shadeWithReflections(frame, r.ray, r.chosen, 1);
    r.pixel = {toByte(r.color.x), toByte(r.color.y), toByte(r.color.z)};
    return r;
}

std::string primitiveName(const SceneDesc& scene, const EvaluatedFrame& frame, std::uint32_t primitive) {
    if (primitive >= frame.primitives.size()) return "?";
    // The object whose run of primitives holds this one.
    auto next = std::upper_bound(frame.firstPrimitive.begin(), frame.firstPrimitive.end(), primitive);
    std::size_t object = std::size_t(next - frame.firstPrimitive.begin()) - 1;
    if (object >= scene.objects.size()) return "?";
    const SceneObject& o = scene.objects[object];
    std::string name = o.name;
    if (o.model) {
        const std::size_t shape = primitive - frame.firstPrimitive[object];
        if (shape < o.model->shapes.size()) {
            const ModelShape& s = o.model->shapes[shape];
            name += "." + o.model->parts[std::size_t(s.part)].name + "." + s.name;
        }
    }
    return name + " (" + std::string(shapeKindName(frame.primitives[primitive].kind)) + ")";
}

}  // namespace f2
