#pragma once
/// Inputs shared by the micro-benchmarks: seeded random rays and primitives,
/// and evaluated frames of the generated scenes (io/bench_scenes.h).
#include <cstdint>
#include <vector>

#include "core/render/prepared_frame.h"
#include "io/bench_scenes.h"

namespace f2::bench {

/// Fixed seed: every run measures the same rays.
inline constexpr std::uint32_t kSeed = 20240601;

/// A primitive of `kind` with a random orientation near the origin, about
/// unit size 1..2 (radius, half height, half sides).
Primitive randomPrimitive(ShapeKind kind, std::uint32_t seed);

/// `count` unit-direction rays from a sphere of radius 10 around the origin,
/// aimed at random points within radius 3 of it: about half hit a primitive
/// of size 1..2, half miss, as in a real frame.
std::vector<Ray> randomRays(std::size_t count, std::uint32_t seed);

/// The scene parsed from its generated text (aborts on a parse error, which
/// would be a bug in the generator).
SceneDesc generatedScene(const BenchSceneSpec& spec);

/// The scene evaluated at time t, BVH not built.
PreparedFrame evaluatedFrame(const SceneDesc& scene, double t);

}  // namespace f2::bench
