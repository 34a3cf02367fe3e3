#include "io/frame_primitives.h"

#include <charconv>
#include <cmath>

#include "core/anim/frame_builder.h"

namespace f2 {

std::vector<PlacedPrimitive> framePrimitives(const SceneDesc& scene, double t, bool keepHidden) {
    std::vector<PlacedPrimitive> out;
    out.reserve(scene.primitiveCount());
    std::vector<std::size_t> firstOf(scene.objects.size());  // each object's first primitive in `out`
    std::vector<Transform> attachedRoots;
    attachedRootFrames(scene, t, attachedRoots);
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        firstOf[i] = out.size();
        Transform worldFromObject = worldFromRoot(scene, i, t, attachedRoots);
        if (!object.model) {
            const Appearance& look = object.appearance[0];
            out.push_back({object.name, shapeKindOf(object.kind), object.size, worldFromObject, look.color,
                           look.material, look.checker, look.castsShadow, false});
            continue;
        }
        const std::vector<Transform> worldFromPart = modelPartFrames(object, worldFromObject, t);
        const ModelType& model = *object.model;
        for (std::size_t k = 0; k < model.shapes.size(); ++k) {
            const ModelShape& shape = model.shapes[k];
            const Appearance& look = object.appearance[k];
            // Its full name in the language: `r1.head.leye`.
            out.push_back({object.name + "." + model.parts[std::size_t(shape.part)].name + "." + shape.name,
                           shape.kind, shape.size, modelShapeFrame(object, k, worldFromPart), look.color,
                           look.material, look.checker, look.castsShadow, false});
        }
    }
    // Colour keys (SPEC 10.3), to the nearest of the formats' whole numbers.
    forEachKeyedColour(scene, t, [&](std::size_t object, std::size_t shape, Vec3 rgb) {
        out[firstOf[object] + shape].color = {std::uint8_t(std::lround(rgb.x)),
                                              std::uint8_t(std::lround(rgb.y)),
                                              std::uint8_t(std::lround(rgb.z))};
    });
    // Hidden shapes (SPEC 10.7) are left out: no format shows them.
    if (!scene.visibilityTracks.empty()) {
        std::vector<std::uint8_t> hidden(out.size(), 0);
        forEachHiddenShape(
            scene, t, [&](std::size_t object, std::size_t shape) { hidden[firstOf[object] + shape] = 1; });
        if (keepHidden) {
            for (std::size_t i = 0; i < out.size(); ++i) out[i].hidden = hidden[i] != 0;
            return out;
        }
        std::size_t kept = 0;
        for (std::size_t i = 0; i < out.size(); ++i)
            if (!hidden[i]) out[kept++] = std::move(out[i]);
        out.resize(kept);
    }
    return out;
}

namespace {
template <class Number>
std::string shortestText(Number value) {
    if (value == 0) return "0";  // also turns -0 into 0
    char text[32];
    auto result = std::to_chars(text, text + sizeof text, value);
    return std::string(text, result.ptr);
}
}  // namespace

std::string formatNumber(float value) { return shortestText(value); }
std::string formatNumber(double value) { return shortestText(value); }

}  // namespace f2
