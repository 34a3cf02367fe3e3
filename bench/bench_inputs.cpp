#include "bench_inputs.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "core/anim/frame_builder.h"
#include "core/parse/parser.h"

namespace f2::bench {

Primitive randomPrimitive(ShapeKind kind, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> angle(0.0f, 360.0f), size(1.0f, 2.0f);
    Transform frame{rotationFromEulerDegrees(angle(rng), angle(rng), angle(rng)), Vec3{}};
    // Sizes as SceneObject::size: sphere (r), cylinder (r, h), box (sx, sy, sz).
    Vec3 dims{size(rng), 2 * size(rng), 2 * size(rng)};
    if (kind == ShapeKind::Box) dims.x *= 2;
    return makePrimitive(kind, dims, frame);
}

std::vector<Ray> randomRays(std::size_t count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    auto direction = [&] {
        Vec3 v{gauss(rng), gauss(rng), gauss(rng)};
        return normalize(v);
    };
    std::vector<Ray> rays;
    rays.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        Vec3 origin = direction() * 10.0f;
        Vec3 target = direction() * (3.0f * std::cbrt(unit(rng)));
        rays.push_back({origin, normalize(target - origin)});
    }
    return rays;
}

SceneDesc generatedScene(const BenchSceneSpec& spec) {
    ParseResult parsed = parseScene(benchSceneText(spec), benchSceneName(spec));
    if (!parsed.ok()) {
        for (const Diagnostic& d : parsed.diagnostics) std::fprintf(stderr, "%s\n", d.format().c_str());
        std::abort();
    }
    return std::move(*parsed.scene);
}

PreparedFrame evaluatedFrame(const SceneDesc& scene, double t) {
    PreparedFrame frame;
    evaluateFrame(scene, t, frame);
    return frame;
}

}  // namespace f2::bench
