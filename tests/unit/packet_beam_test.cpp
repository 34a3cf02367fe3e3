// The per-packet narrowing of a soft sun's shadow entry nodes (packet_beam.h):
// tracing from the narrowed nodes answers every any-hit query as from the root.
#include "core/render/packet_beam.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <iostream>
#include <random>

#include "core/anim/frame_builder.h"
#include "core/geometry/bvh_packet.h"
#include "core/render/prepared_frame.h"
#include "io/bench_scenes.h"
#include "test_scenes.h"

namespace f2 {
namespace {

TEST(PacketBeam, NarrowedEntryNodesAnswerLikeTheRoot) {
    BenchSceneSpec spec;
    spec.shape = BenchShape::Robots;
    spec.count = 100;
    const SceneDesc scene =
        test::sceneFromText(benchSceneText(spec, 160, 120) + "/dir_light 0.4 -0.2 -1 0.5 angle 6 4\n");
    PreparedFrame frame;
    evaluateFrame(scene, 0, frame);
    frame.bvh.build(frame.primitives);
    ASSERT_FALSE(frame.lights.empty());
    const LightSample& sun = frame.lights.back();
    ASSERT_EQ(sun.sampleCount, 16u);
    const std::span<const Vec3> samples(&frame.sunDirections[sun.firstSample], sun.sampleCount);
    const Bounds sceneBox = frame.bvh.nodes()[0].bounds;
    const std::uint32_t primitiveCount = std::uint32_t(frame.bvh.orderedPrimitives().size());

    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    int packets = 0, narrowed = 0, emptied = 0, blocked = 0;
    for (int trial = 0; trial < 400; ++trial) {
        // A cluster of origins (as the shadow origins of a block), each
        // skipping a primitive: all the same one (a floor) or each its own.
        const float spread = trial % 2 ? 20.0f : 200.0f;
        const Vec3 centre{sceneBox.lo.x + u01(rng) * (sceneBox.hi.x - sceneBox.lo.x),
                          sceneBox.lo.y + u01(rng) * (sceneBox.hi.y - sceneBox.lo.y) * 0.5f,
                          sceneBox.lo.z + u01(rng) * (sceneBox.hi.z - sceneBox.lo.z)};
        const std::int32_t sharedSkip = std::int32_t(rng() % primitiveCount);
        alignas(64) float x[simd::kWidth], y[simd::kWidth], z[simd::kWidth];
        alignas(64) std::int32_t skips[simd::kWidth];
        Bounds origins;
        for (int i = 0; i < simd::kWidth; ++i) {
            x[i] = centre.x + (u01(rng) - 0.5f) * spread;
            y[i] = centre.y + (u01(rng) - 0.5f) * spread;
            z[i] = centre.z + (u01(rng) - 0.5f) * spread;
            skips[i] = trial % 3 == 0 ? std::int32_t(rng() % primitiveCount) : sharedSkip;
            origins.grow(Vec3{x[i], y[i], z[i]});
        }
        const Vec3P origin(simd::load(x), simd::load(y), simd::load(z));
        float skipBits[simd::kWidth];
        std::memcpy(skipBits, skips, sizeof skips);
        const Int skip = simd::bitsOf(simd::load(skipBits));
        const Mask active = trial % 5 == 0 ? simd::Mask(origin.x < Float(centre.x)) : simd::allLanes();
        if (simd::none(active)) continue;

        // As a tile does: the nodes the beam of its origins (a wider box, the
        // tile holding many packets) reaches, then the packet's own.
        const Vec3 margin{300.0f, 300.0f, 300.0f};
        const Bounds tileOrigins{origins.lo - margin, origins.hi + margin};
        LightEntry light;
        std::uint32_t tileStore[8], packetStore[8];
        light.nodes = {tileStore, frame.bvh.beamEntryNodes(tileOrigins, samples, tileStore)};
        for (const Vec3 d : samples) {
            light.directions.lo = vmin(light.directions.lo, d);
            light.directions.hi = vmax(light.directions.hi, d);
        }
        light.slack = beamSlack(frame.bvh);
        const std::size_t n = packetEntryNodes(frame.bvh, light, origin, active, skip, packetStore);
        ASSERT_LE(n, std::size_t(9));
        if (n > 8) continue;
        ++packets;
        narrowed += n < light.nodes.size() || !std::equal(packetStore, packetStore + n, light.nodes.begin());
        emptied += n == 0 && !light.nodes.empty();
        for (const Vec3 d : samples) {
            const ParallelRays rays(origin, d);
            const Mask fromRoot =
                occludedPacket(frame.bvh, rays, active, Float(0.0f), Float(kInfinity), skip);
            const Mask fromPacket = occludedPacket(frame.bvh, rays, active, Float(0.0f), Float(kInfinity),
                                                   skip, {packetStore, n});
            ASSERT_EQ(simd::bits(fromRoot), simd::bits(fromPacket)) << "trial " << trial;
            blocked += __builtin_popcount(simd::bits(fromRoot));
        }
    }
    // Not vacuous: many packets start below the tile's nodes, some from none
    // at all, and many of the rays are blocked.
    EXPECT_GT(narrowed, packets / 5);
    EXPECT_GT(emptied, 10);
    EXPECT_GT(blocked, 200);
    std::cout << "[   INFO   ] " << packets << " packets: " << narrowed << " narrowed, " << emptied
              << " from no node; " << blocked << " rays blocked\n";
}

}  // namespace
}  // namespace f2
