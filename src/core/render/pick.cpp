#include "core/render/pick.h"

#include <algorithm>

#include "core/anim/frame_builder.h"
#include "core/render/shading.h"
#include "core/scene/models.h"

namespace f2 {

std::optional<PickHit> pickPoint(const SceneDesc& scene, const PreparedFrame& frame, const Camera& camera,
                                 float px, float py) {
    const Ray ray = camera.rayThrough(px, py);
    HitRecord hit;
    if (!frame.bvh.intersect(ray, primaryRayStart(ray.origin), kInfinity, hit)) return std::nullopt;

    // Primitives are laid out object by object (EvaluatedFrame::firstPrimitive).
    const auto& first = frame.firstPrimitive;
    const auto after = std::upper_bound(first.begin(), first.end(), hit.primitive);
    const std::size_t object = std::size_t(after - first.begin()) - 1;
    if (object >= scene.objects.size()) return std::nullopt;

    PickHit result;
    result.object = object;
    result.distance = hit.t;
    result.point = ray.origin + ray.direction * hit.t;
    const std::size_t shape = hit.primitive - first[object];
    result.shape = int(shape);
    if (const ModelType* model = scene.objects[object].model.get(); model && shape < model->shapes.size())
        result.part = model->shapes[shape].part;
    return result;
}

std::optional<PickHit> pickPixel(const SceneDesc& scene, double t, const Camera& camera, int x, int y) {
    PreparedFrame frame;
    evaluateFrame(scene, t, frame);
    frame.bvh.build(frame.primitives);
    frame.bvh.setRayMask(frame.rayMask);  // hidden things cannot be picked (SPEC 10.7)
    return pickPoint(scene, frame, camera, float(x) + 0.5f, float(y) + 0.5f);
}

Bounds selectionBounds(const SceneDesc& scene, const EvaluatedFrame& frame, std::size_t object,
                       std::optional<int> part) {
    Bounds bounds;
    if (object + 1 >= frame.firstPrimitive.size() || object >= scene.objects.size()) return bounds;
    const ModelType* model = scene.objects[object].model.get();
    for (std::uint32_t i = frame.firstPrimitive[object]; i < frame.firstPrimitive[object + 1]; ++i) {
        const std::size_t shape = i - frame.firstPrimitive[object];
        if (part && model && model->shapes[shape].part != *part) continue;
        bounds.grow(primitiveBounds(frame.primitives[i]));
    }
    return bounds;
}

}  // namespace f2
