// BVH build of one frame's primitives: the per-frame rebuild every animated
// frame pays. Sizes from the robots grid: robots:167 (1,003 primitives) and
// robots:10000 (60,001), evaluated at frame 6 (arms mid-swing); serial, and
// on a pool of every core as Renderer::render builds it.
#include <benchmark/benchmark.h>

#include <memory>

#include "bench_inputs.h"
#include "core/geometry/bvh.h"
#include "core/util/thread_pool.h"

namespace f2::bench {
namespace {

void BM_BvhBuild(benchmark::State& state) {
    const PreparedFrame frame =
        evaluatedFrame(generatedScene({BenchShape::Robots, int(state.range(0))}), 6.0);
    const bool pooled = state.range(1) != 0;
    std::unique_ptr<ThreadPool> pool = pooled ? std::make_unique<ThreadPool>(0) : nullptr;
    Bvh bvh;
    bvh.build(frame.primitives,
              pool.get());  // first build allocates; the timed ones reuse buffers, as in a frame loop
    for (auto _ : state) {
        bvh.build(frame.primitives, pool.get());
        benchmark::DoNotOptimize(bvh.nodes().data());
    }
    state.counters["primitives"] = double(frame.primitives.size());
    state.counters["threads"] = pool ? pool->threadCount() : 1;
    state.counters["prims/s"] = benchmark::Counter(
        double(state.iterations()) * double(frame.primitives.size()), benchmark::Counter::kIsRate);
}

BENCHMARK(BM_BvhBuild)
    ->ArgsProduct({{167, 10000}, {0, 1}})
    ->ArgNames({"robots", "pool"})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();  // the pooled build runs on other threads too

}  // namespace
}  // namespace f2::bench
