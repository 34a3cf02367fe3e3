// Animation evaluation alone (evaluateFrame: key frames -> part frames ->
// world-space primitives), one thread, on the generated robots grid at a time
// between keys; CPU time, so that other processes on the machine do not count.
// "warm": the scene and the frame stay in the caches from the last iteration;
// "cold": a 64 MiB buffer is streamed through the caches before each
// iteration (untimed); "traced": a whole 800x600 frame is rendered on one
// thread before each iteration (untimed), as in `f2 bench --threads 1`.
#include <benchmark/benchmark.h>

#include <vector>

#include "bench_inputs.h"
#include "core/anim/frame_builder.h"
#include "core/render/renderer.h"

namespace f2::bench {
namespace {

/// Streams `buffer` through the caches so that the next evaluation reads the
/// scene from memory.
void evictCaches(std::vector<unsigned char>& buffer) {
    for (std::size_t i = 0; i < buffer.size(); i += 64) buffer[i] = static_cast<unsigned char>(buffer[i] + 1);
    benchmark::DoNotOptimize(buffer.data());
}

void BM_Evaluate(benchmark::State& state) {
    const SceneDesc scene = generatedScene({BenchShape::Robots, int(state.range(0))});
    const bool cold = state.range(1) != 0;
    std::vector<unsigned char> evictor(cold ? std::size_t{64} << 20 : 0);
    EvaluatedFrame frame;
    evaluateFrame(scene, 6.5, frame);  // sizes the buffers, as the first frame of playback does
    double t = 6.5;
    for (auto _ : state) {
        if (cold) {
            state.PauseTiming();
            evictCaches(evictor);
            state.ResumeTiming();
        }
        evaluateFrame(scene, t, frame);
        benchmark::DoNotOptimize(frame.primitives.data());
        t = t > 40 ? 6.5 : t + 1.25;  // every iteration a new time between keys
    }
    state.counters["primitives"] = double(frame.primitives.size());
    state.counters["prims/s"] = benchmark::Counter(
        double(state.iterations()) * double(frame.primitives.size()), benchmark::Counter::kIsRate);
}

void BM_EvaluateTraced(benchmark::State& state) {
    const SceneDesc scene = generatedScene({BenchShape::Robots, int(state.range(0))});
    const Camera camera = Camera::fromDesc(scene.camera).resized(800, 600);
    Renderer renderer(1);
    Image image;
    EvaluatedFrame frame;
    evaluateFrame(scene, 6.5, frame);
    double t = 6.5;
    for (auto _ : state) {
        state.PauseTiming();
        renderer.render(scene, t, camera, image);
        state.ResumeTiming();
        evaluateFrame(scene, t, frame);
        benchmark::DoNotOptimize(frame.primitives.data());
        t = t > 40 ? 6.5 : t + 1.25;
    }
    state.counters["primitives"] = double(frame.primitives.size());
    state.counters["prims/s"] = benchmark::Counter(
        double(state.iterations()) * double(frame.primitives.size()), benchmark::Counter::kIsRate);
}

BENCHMARK(BM_Evaluate)
    ->ArgsProduct({{10000, 100000}, {0, 1}})
    ->ArgNames({"robots", "cold"})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EvaluateTraced)->Arg(10000)->ArgName("robots")->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace f2::bench
