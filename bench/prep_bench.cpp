// A frame's preparation of the generated robots grid, as Renderer::render
// does it before tracing: prepareFrame, the evaluation and Bvh::update (the
// last tree refitted, the evaluation written straight into its leaves). "step": 0 renders the same time every
// iteration, as `f2 bench` without --step; 1 advances one frame each time, as playback. "cold": a 64 MiB
// buffer is streamed through the caches before each iteration (untimed), as a traced frame leaves them. CPU
// time of the whole process (the pool's threads included) and wall time.
#include <benchmark/benchmark.h>

#include <vector>

#include "bench_inputs.h"
#include "core/render/frame_preparation.h"
#include "core/util/thread_pool.h"

namespace f2::bench {
namespace {

void BM_Prepare(benchmark::State& state) {
    const SceneDesc scene = generatedScene({BenchShape::Robots, int(state.range(0))});
    ThreadPool pool(int(state.range(1)));
    const double step = double(state.range(2));
    const bool cold = state.range(3) != 0;
    std::vector<unsigned char> evictor(cold ? std::size_t{64} << 20 : 0);
    PreparedFrame frame;
    double t = 6.5;
    prepareFrame(scene, t, frame, &pool);  // sizes the buffers and builds the tree
    for (auto _ : state) {
        if (cold) {
            state.PauseTiming();
            for (std::size_t i = 0; i < evictor.size(); i += 64) evictor[i] = (unsigned char)(evictor[i] + 1);
            benchmark::DoNotOptimize(evictor.data());
            state.ResumeTiming();
        }
        prepareFrame(scene, t, frame, &pool);
        benchmark::DoNotOptimize(frame.bvh.nodes().data());
        t = t + step > 47 ? 6.5 : t + step;
    }
    state.counters["primitives"] = double(frame.primitives.size());
}

BENCHMARK(BM_Prepare)
    ->ArgsProduct({{10000, 100000}, {1, 2}, {0, 1}, {0, 1}})
    ->ArgNames({"robots", "threads", "step", "cold"})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();

}  // namespace
}  // namespace f2::bench
