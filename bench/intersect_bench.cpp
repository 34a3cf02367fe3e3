// Ray-primitive kernels (geometry/intersect.h) on precomputed random rays:
// the cost of one exact test, hit or miss, per shape.
#include <benchmark/benchmark.h>

#include "bench_inputs.h"
#include "core/geometry/intersect.h"

namespace f2::bench {
namespace {

constexpr std::size_t kRays = 4096;  // fits in L1/L2 with the primitive: measures arithmetic, not memory

void intersectShape(benchmark::State& state, ShapeKind kind) {
    const Primitive prim = randomPrimitive(kind, kSeed);
    const std::vector<Ray> rays = randomRays(kRays, kSeed + 1);
    std::size_t hits = 0;
    for (auto _ : state) {
        for (const Ray& ray : rays) {
            float t = kInfinity;
            Face face = Face::Curved;
            hits += intersectPrimitive(prim, ray, 0.0f, kInfinity, t, face);
            benchmark::DoNotOptimize(t);
        }
    }
    const double tested = double(state.iterations()) * double(kRays);
    state.counters["rays/s"] = benchmark::Counter(tested, benchmark::Counter::kIsRate);
    state.counters["hit_fraction"] = double(hits) / tested;
}

void BM_RaySphere(benchmark::State& state) { intersectShape(state, ShapeKind::Sphere); }
void BM_RayCylinder(benchmark::State& state) { intersectShape(state, ShapeKind::Cylinder); }
void BM_RayBox(benchmark::State& state) { intersectShape(state, ShapeKind::Box); }

BENCHMARK(BM_RaySphere);
BENCHMARK(BM_RayCylinder);
BENCHMARK(BM_RayBox);

}  // namespace
}  // namespace f2::bench
