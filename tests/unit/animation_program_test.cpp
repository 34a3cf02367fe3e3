// The compiled animation (anim/animation_program.h) gives what evaluating the
// parser's SceneDesc object by object gives (evaluateTrack, modelPartFrames,
// makePrimitive), bit for bit: every primitive and surface of every scene of
// the repository and of the benchmarks, at many times, with every mode,
// one-key tracks, attachments and a pool of threads.
#include "core/anim/animation_program.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "core/anim/frame_builder.h"
#include "core/scene/models.h"
#include "io/bench_scenes.h"
#include "robot_parts.h"
#include "test_scenes.h"

namespace f2 {

using test::RobotPart;
namespace {

Vec3 unitColor(Color8 c) { return Vec3{float(c.r), float(c.g), float(c.b)} / 255.0f; }

/// The frame as evaluating the SceneDesc itself gives it: object by object,
/// each track searched in its own key array.
EvaluatedFrame referenceFrame(const SceneDesc& scene, double t) {
    EvaluatedFrame frame;
    attachedRootFrames(scene, t, frame.attachedRoots);
    std::vector<std::size_t> firstPrimitive;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        firstPrimitive.push_back(frame.primitives.size());
        const Transform root = worldFromRoot(scene, i, t, frame.attachedRoots);
        if (!object.model) {
            frame.primitives.push_back(makePrimitive(shapeKindOf(object.kind), object.size, root));
            const Appearance& look = object.appearance[0];
            frame.surfaces.push_back(
                {unitColor(look.color), look.material, unitColor(look.checker.color), look.checker.size});
            continue;
        }
        const auto worldFromPart = modelPartFrames(object, root, t);
        for (std::size_t k = 0; k < object.model->shapes.size(); ++k) {
            const ModelShape& shape = object.model->shapes[k];
            frame.primitives.push_back(
                makePrimitive(shape.kind, shape.size, modelShapeFrame(object, k, worldFromPart)));
            const Appearance& look = object.appearance[k];
            frame.surfaces.push_back(
                {unitColor(look.color), look.material, unitColor(look.checker.color), look.checker.size});
        }
    }
    // Colour keys and drives (SPEC 10.3, 10.7) over `/paint`, the last call for a shape winning.
    forEachKeyedColour(scene, t, [&](std::size_t object, std::size_t shape, Vec3 rgb) {
        frame.surfaces[firstPrimitive[object] + shape].color = rgb / 255.0f;
    });
    return frame;
}

bool sameBits(Vec3 a, Vec3 b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Every primitive and surface of `frame` has the reference's bits.
void expectSameFrame(const EvaluatedFrame& reference, const EvaluatedFrame& frame, const std::string& what) {
    ASSERT_EQ(frame.primitives.size(), reference.primitives.size()) << what;
    ASSERT_EQ(frame.surfaces.size(), reference.surfaces.size()) << what;
    for (std::size_t i = 0; i < frame.primitives.size(); ++i) {
        const Primitive &a = reference.primitives[i], &b = frame.primitives[i];
        const bool same = sameBits(a.centre, b.centre) && sameBits(a.axes[0], b.axes[0]) &&
                          sameBits(a.axes[1], b.axes[1]) && sameBits(a.axes[2], b.axes[2]) &&
                          sameBits(a.half, b.half) && a.kind == b.kind && a.axisAligned == b.axisAligned;
        ASSERT_TRUE(same) << what << ": primitive " << i << " centre " << b.centre << " want " << a.centre;
        const Surface &s = reference.surfaces[i], &r = frame.surfaces[i];
        ASSERT_TRUE(sameBits(s.color, r.color) && sameBits(s.material.ka, r.material.ka) &&
                    sameBits(s.material.kd, r.material.kd) && sameBits(s.material.ks, r.material.ks) &&
                    sameBits(s.material.n, r.material.n) &&
                    sameBits(s.material.reflection, r.material.reflection) &&
                    sameBits(s.checkerColor, r.checkerColor) && sameBits(s.checkerSize, r.checkerSize))
            << what << ": surface " << i;
    }
}

/// Times across the whole animation and outside it: keys, between keys,
/// fractional, before 0 and after the end.
std::vector<double> timesOf(const SceneDesc& scene) {
    std::vector<double> times = {-3.0, 0.0, 1e-9, double(scene.lastFrame()), scene.lastFrame() + 7.25};
    const int last = std::max(1, scene.lastFrame());
    for (int k = 0; k <= 97; ++k) times.push_back(last * k / 97.0);
    for (int f = 0; f <= last; f += std::max(1, last / 40)) times.push_back(f);
    return times;
}

void expectProgramMatchesReference(const SceneDesc& scene, const std::string& name) {
    ThreadPool pool(2);
    EvaluatedFrame serial, pooled;
    for (double t : timesOf(scene)) {
        const EvaluatedFrame reference = referenceFrame(scene, t);
        const std::string what = name + " at t = " + std::to_string(t);
        evaluateFrame(scene, t, serial);
        expectSameFrame(reference, serial, what);
        evaluateFrame(scene, t, pooled, &pool);
        expectSameFrame(reference, pooled, what + " (pool)");
        if (::testing::Test::HasFatalFailure()) return;
    }
}

TEST(AnimationProgram, RepositoryScenesMatchTheirSceneDescBitForBit) {
    // Not the scenes with colour keys (explainer.f2, torch.f2): the reference
    // here takes the looks of /paint only, without applyColourTracks.
    for (const char* name :
         {"demo.f2", "seed_example.f2", "gallery/catch.f2", "gallery/dance.f2", "gallery/easing.f2",
          "gallery/flyaround.f2", "gallery/pov.f2", "gallery/pendulum.f2", "gallery/desk_lamps.f2",
          "gallery/windmill.f2", "gallery/clock.f2"}) {
        expectProgramMatchesReference(test::sceneFromRepo(name), name);
    }
}

TEST(AnimationProgram, BenchScenesMatchTheirSceneDescBitForBit) {
    for (BenchSceneSpec spec :
         {BenchSceneSpec{BenchShape::Robots, 1}, BenchSceneSpec{BenchShape::Robots, 300},
          BenchSceneSpec{BenchShape::Spheres, 300}, BenchSceneSpec{BenchShape::Drives, 300},
          BenchSceneSpec{BenchShape::DriveKeys, 300}, BenchSceneSpec{BenchShape::Lamps, 30}}) {
        expectProgramMatchesReference(test::sceneFromText(benchSceneText(spec)), benchSceneName(spec));
    }
}

// Every mode on objects and parts, per key and per track; one-key tracks
// (constant, but not the rest pose); negative zeros; keys of a primitive that
// rides on a part; and objects that never move.
constexpr const char* kEveryKind =
    "/robot r 10 0 5 0 30 0\n"
    "/human h -100 0 40 0 -90 0\n"
    "/sphere s 5 0 0 0\n"
    "/box b 10 20 30 -0 5 -0 0 45 0\n"
    "/cylinder c 3 8 1 2 3 90 180 270\n"
    "/attach s r.rhand\n"
    "/attach c s\n"
    "/interp r spline\n"
    "/key 0 r\n/key 7 r 40 0 5 0 90 0\n/key 13 r 40 10 -5 10 90 -20 step\n/key 20 r 0 0 0 -0 0 -0 ease_in\n"
    "/key 31 r 5 5 5 5 5 5\n"
    "/key 4 r.head 0 0 0 0 -40 0 ease_out\n/key 9 r.head 0 1 0 10 40 0\n/key 15 r.head\n"
    "/key 3 r.lhand 0 0 0 -0 0 0\n"
    "/key 6 r.rhand 0 0 0 60 0 0\n"
    "/interp h.body ease\n/key 0 h.body\n/key 10 h.body 0 0 0 20 0 0 spline\n/key 11 h.body 0 0 0 21 0 0\n"
    "/key 25 h.body 0 0 0 -30 0 0 linear\n/key 26 h.body\n"
    "/key 2 s 0 -100 0 0 0 0\n/key 8 s 0 -80 0 0 90 0 ease\n"
    "/key 5 c 10 0 0 0 0 90\n";

TEST(AnimationProgram, EveryModeAndAttachmentMatchesTheSceneDescBitForBit) {
    expectProgramMatchesReference(test::sceneFromText(kEveryKind), "every kind");
}

// Parts that only turn about one axis (turn tracks): each axis, every mode,
// a constant offset, turns past 360 degrees and of exactly 0; and tracks that
// look alike but must stay on the general path (two axes, a moving offset,
// and, set below since the language reads -0 as 0, an offset of -0 and other
// angles of -0).
constexpr const char* kTurns =
    "/robot a 0 0 0 0 0 0\n/robot b 200 0 0 0 45 0\n/human h -200 0 0 0 0 0\n/human g 0 0 200 0 0 0\n"
    "/interp a.head spline\n"
    "/key 0 a.head 0 0 0 0 0 0\n/key 10 a.head 0 0 0 0 50 0\n/key 20 a.head 0 0 0 0 -400 0\n"
    "/key 30 a.head 0 0 0 0 90 0 ease_out\n/key 33 a.head 0 0 0 0 0 0\n"
    "/key 0 a.lhand 3 -2 0.5 -30 0 0 ease\n/key 12 a.lhand 3 -2 0.5 45 0 0 ease_in\n"
    "/key 14 a.lhand 3 -2 0.5 180 0 0 step\n/key 17 a.lhand 3 -2 0.5 -0 0 0\n"
    "/key 0 a.rhand 0 0 0 0 0 10\n/key 9 a.rhand 0 0 0 0 0 -725 linear\n/key 12 a.rhand 0 0 0 0 0 270\n"
    "/key 0 b.rhand 0 0 0 0 0 10\n/key 9 b.rhand 0 0 0 0 0 -10\n"
    "/key 0 b.lhand 0 0 0 10 5 0\n/key 9 b.lhand 0 0 0 -10 0 0\n"
    "/key 0 b.head 0 0 0 0 10 0\n/key 9 b.head 0 1 0 0 -10 0\n"
    "/key 0 h.body\n/key 5 h.body 0 0 0 0 0 0\n/key 0 h.head 0 0 0 0 0 720\n/key 10 h.head 0 0 0 0 0 -90\n"
    "/interp g.lhand ease\n/key 0 g.lhand 1 2 3 1e-30 0 0\n/key 40 g.lhand 1 2 3 -1e-30 0 0\n";

TEST(AnimationProgram, PartsTurningAboutOneAxisMatchTheSceneDescBitForBit) {
    SceneDesc scene = test::sceneFromText(kTurns);
    for (Key& key : scene.objects[1].partTracks[int(RobotPart::RHand)].keys) key.pose.position.x = -0.0f;
    for (Key& key : scene.objects[0].partTracks[int(RobotPart::Head)].keys) key.pose.rotation.z = -0.0f;
    const auto program = AnimationProgram::compile(scene);
    // a: head, lhand, rhand; h: body, head; g: lhand. b's three stay general.
    EXPECT_EQ(program->turnTracks.size(), 6u);
    EXPECT_EQ(program->tracks.size(), 3u);
    expectProgramMatchesReference(scene, "turns");
}

TEST(AnimationProgram, ATurnAboutOneAxisIsTheEulerRotationBitForBit) {
    const Transform parent = Transform::fromPose({1, -2, 3}, {10, 200, -30});
    std::vector<float> angles = {0.0f, -0.0f, 90,    180,    270,     -90,
                                 360,  720,   -1080, 1e-30f, -1e-30f, 359.99997f};
    for (int i = 0; i <= 20000; ++i) angles.push_back(-1000.0f + 0.1f * float(i) + 1e-3f * float(i % 7));
    for (float angle : angles) {
        for (std::uint32_t axis = 0; axis < 3; ++axis) {
            Vec3 euler{-0.0f, 0.0f, -0.0f};
            euler[int(axis)] = angle;
            const Transform want = childFrame(parent, {4, 5, 6}, euler);
            const Transform got = childFrameTurned(parent, {4, 5, 6}, angle, axis);
            ASSERT_EQ(std::memcmp(&want, &got, sizeof want), 0) << "angle " << angle << " axis " << axis;
        }
    }
}

TEST(AnimationProgram, TracksKeyedAlikeShareOneLayoutAndEqualSurfacesAreStoredOnce) {
    const SceneDesc scene = test::sceneFromText(benchSceneText({BenchShape::Robots, 200}));
    const auto program = AnimationProgram::compile(scene);
    // Robots: head (ease, 3 keys) and both arms (spline, 5 keys): two layouts;
    // 200 robots of 4 colours and the floor: 5 runs of surfaces.
    EXPECT_EQ(program->layouts.size(), 2u);
    // Each of them only turns about one axis: one angle per key.
    EXPECT_EQ(program->tracks.size(), 0u);
    EXPECT_EQ(program->turnTracks.size(), 3u * 200u);
    EXPECT_EQ(program->angles.size(), 13u * 200u);
    EXPECT_EQ(program->surfaces.size(), 4u * 6u + 1u);
    // The floor and the robots' roots have no keys: constant.
    for (std::uint32_t source : program->rootSource) EXPECT_EQ(source, AnimationProgram::kConstantRoot);
}

TEST(AnimationProgram, IsCompiledOnceAndNotSharedByAChangedCopy) {
    SceneDesc scene = test::sceneFromText("/sphere s 5 0 0 0\n/key 0 s\n/key 10 s 100 0 0 0 0 0\n");
    EvaluatedFrame frame;
    evaluateFrame(scene, 5, frame);
    const auto program = scene.animation.get();
    ASSERT_NE(program, nullptr);
    evaluateFrame(scene, 6, frame);
    EXPECT_EQ(scene.animation.get(), program);  // kept with the scene
    EXPECT_FLOAT_EQ(frame.primitives[0].centre.x, 60);

    SceneDesc changed = scene;  // a copy starts without a program
    EXPECT_EQ(changed.animation.get(), nullptr);
    changed.objects[0].track.keys[1].pose.position.x = 200;
    evaluateFrame(changed, 6, frame);
    EXPECT_FLOAT_EQ(frame.primitives[0].centre.x, 120);
    evaluateFrame(scene, 6, frame);
    EXPECT_FLOAT_EQ(frame.primitives[0].centre.x, 60);
}

}  // namespace
}  // namespace f2
