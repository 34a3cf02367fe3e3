// Whole frames through Renderer::render (evaluate + build + trace + shade) at
// 800x600 on every core, as `f2 bench` measures them: the default scene and
// two generated ones. rays/s counts primary rays only (the renderer keeps no
// shadow-ray counter; `f2 bench` counts both).
#include <benchmark/benchmark.h>

#include "bench_inputs.h"
#include "core/parse/parser.h"
#include "core/render/renderer.h"
#include "core/scene/default_scene.h"

namespace f2::bench {
namespace {

void renderFrames(benchmark::State& state, const SceneDesc& scene) {
    Camera camera = Camera::fromDesc(scene.camera).resized(800, 600);
    Renderer renderer;
    Image image;
    for (int i = 0; i < 5; ++i) renderer.render(scene, 0.0, camera, image);  // warm-up
    for (auto _ : state) {
        FrameTimings t = renderer.render(scene, 0.0, camera, image);
        benchmark::DoNotOptimize(image.pixels.data());
        benchmark::DoNotOptimize(t);
    }
    const double frames = double(state.iterations());
    state.counters["fps"] = benchmark::Counter(frames, benchmark::Counter::kIsRate);
    state.counters["primary_rays/s"] =
        benchmark::Counter(frames * 800.0 * 600.0, benchmark::Counter::kIsRate);
    state.counters["threads"] = renderer.threadCount();
}

void BM_FrameDefaultScene(benchmark::State& state) {
    ParseResult parsed = parseScene(defaultSceneText(), kDefaultSceneName);
    if (!parsed.ok()) {
        state.SkipWithError("default scene does not parse");
        return;
    }
    renderFrames(state, *parsed.scene);
}

void BM_FrameRobots(benchmark::State& state) {
    renderFrames(state, generatedScene({BenchShape::Robots, int(state.range(0))}));
}

void BM_FrameSpheres(benchmark::State& state) {
    renderFrames(state, generatedScene({BenchShape::Spheres, int(state.range(0))}));
}

// Real time: the frame runs on the pool's threads, not only the benchmark's.
BENCHMARK(BM_FrameDefaultScene)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_FrameRobots)->Arg(1000)->ArgName("robots")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_FrameSpheres)->Arg(1000)->ArgName("spheres")->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace f2::bench
