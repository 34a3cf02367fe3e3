// Attachments (SPEC 9.2): world frames through rotated parts and chains, the
// same in the renderer's frame, the exports' primitives and worldFromRef.
#include <gtest/gtest.h>

#include "core/anim/frame_builder.h"
#include "core/parse/parser.h"
#include "io/frame_primitives.h"
#include "robot_parts.h"
#include "test_scenes.h"

namespace f2 {

using test::RobotPart;
namespace {

using test::expectOnlyError;
using test::sceneFromText;

constexpr float kTol = 1e-3f;

std::size_t indexOf(const SceneDesc& s, std::string_view name) {
    for (std::size_t i = 0; i < s.objects.size(); ++i)
        if (s.objects[i].name == name) return i;
    ADD_FAILURE() << "no object " << name;
    return 0;
}

/// World centre of primitive object `name` in the renderer's frame and in the exporters' list.
void expectCentre(const SceneDesc& s, std::string_view name, double t, Vec3 want) {
    SCOPED_TRACE(std::string(name));
    EvaluatedFrame frame;
    evaluateFrame(s, t, frame);
    const std::size_t i = indexOf(s, name);
    EXPECT_VEC_NEAR(frame.primitives[frame.firstPrimitive[i]].centre, want, kTol);
    for (const PlacedPrimitive& p : framePrimitives(s, t)) {
        if (p.label == name) {
            EXPECT_VEC_NEAR(p.worldFromLocal.translation, want, kTol);
        }
    }
    EXPECT_VEC_NEAR(worldFromRef(s, {std::uint32_t(i), -1}, t).translation, want, kTol);
}

// A ball at the tip of F-2's right hand, the hand swung forward-up (rx −90).
// Hand frame in the root: body pivot (0, −105, 0) + rhand pivot (52, 140, 0)
// = (52, 35, 0), turned Rx(−90), which takes (0, −100, 0) to (0, 0, 100):
// the tip is at (52, 35, 100) in the root. F-2 stands at (10, 0, 0) turned
// ry 90, which takes (x, y, z) to (z, y, −x): the tip is at (110, 35, −52).
constexpr const char* kCatch =
    "/robot f2 10 0 0 0 90 0\n"
    "/sphere ball 8 0 -100 0\n"
    "/attach ball f2.rhand\n"
    "/key 0 f2.rhand\n"
    "/key 10 f2.rhand 0 0 0 -90 0 0\n";

TEST(Attach, ObjectOnARotatedPart) {
    const SceneDesc s = sceneFromText(kCatch);
    expectCentre(s, "ball", 10, {110, 35, -52});
    // At rest the arm hangs: tip (52, −65, 0) in the root, (10, −65, −52) in the world.
    expectCentre(s, "ball", 0, {10, -65, -52});
    // Halfway the arm is at rx −45: (0, −100, 0) -> (0, −70.71, 70.71).
    expectCentre(s, "ball", 5, {10 + 70.710678f, 35 - 70.710678f, -52});
}

TEST(Attach, ChainsOfAttachmentsDeclaredInAnyOrder) {
    // b2 rides on the ball 10 up in the ball's frame (the ball's axes are the
    // hand's: Ry(90)·Rx(−90) takes (0, 10, 0) to (−10, 0, 0)). b2's /attach
    // comes first: evaluation order does not follow the file.
    std::string text = "/sphere b2 1 0 10 0\n";
    text += kCatch;
    text += "/attach b2 ball\n";
    const SceneDesc s = sceneFromText(text);
    ASSERT_EQ(s.attachOrder.size(), 2u);
    EXPECT_EQ(s.objects[s.attachOrder[0]].name, "ball");
    EXPECT_EQ(s.objects[s.attachOrder[1]].name, "b2");
    expectCentre(s, "b2", 10, {100, 35, -52});
}

TEST(Attach, AModelOnAnObjectCarriesItsParts) {
    // A human standing on a moving box: its root frame is the box's times its pose.
    const SceneDesc s = sceneFromText(
        "/box cart 100 10 100 0 0 0 0 90 0\n"
        "/human h 0 110 20\n"
        "/attach h cart\n"
        "/key 0 cart\n"
        "/key 10 cart 300 0 0 0 90 0\n");
    const std::size_t h = indexOf(s, "h");
    // Root: cart (300, 0, 0) turned Ry(90): (0, 110, 20) -> (20, 110, 0) + (300, 0, 0).
    const Transform root = worldFromRef(s, {std::uint32_t(h), -1}, 10);
    EXPECT_VEC_NEAR(root.translation, (Vec3{320, 110, 0}), kTol);
    // The head's pivot frame: root + (0, −105, 0) + (0, 140, 0).
    EXPECT_VEC_NEAR(worldFromRef(s, {std::uint32_t(h), int(RobotPart::Head)}, 10).translation,
                    (Vec3{320, 145, 0}), kTol);
    EvaluatedFrame frame;
    evaluateFrame(s, 10, frame);
    // Human body cylinder centre: root + (0, −105 + 70, 0).
    EXPECT_VEC_NEAR(frame.primitives[frame.firstPrimitive[h]].centre, (Vec3{320, 75, 0}), kTol);
}

TEST(Attach, NoAttachmentsMeansNoOrder) {
    EXPECT_TRUE(sceneFromText("/sphere a 1 0 0 0\n/sphere b 1 0 0 0\n").attachOrder.empty());
}

TEST(Attach, LongChainParsesAndEvaluatesInLinearTime) {
    // 20,000 spheres, each on the previous, attached from the last one up.
    constexpr int kCount = 20000;
    std::string text;
    for (int i = 0; i < kCount; ++i) text += "/sphere s" + std::to_string(i) + " 1 1 0 0\n";
    for (int i = kCount - 1; i > 0; --i)
        text += "/attach s" + std::to_string(i) + " s" + std::to_string(i - 1) + "\n";
    const SceneDesc s = sceneFromText(text);
    ASSERT_EQ(s.attachOrder.size(), std::size_t(kCount - 1));
    EvaluatedFrame frame;
    evaluateFrame(s, 0, frame);
    EXPECT_VEC_NEAR(frame.primitives.back().centre, (Vec3{float(kCount), 0, 0}), kTol);
}

// Changing attachments (SPEC 10.7): a ball handed from F-2 to a human.
// F-2 at the origin, its right hand swung forward (rx −90): the hand frame
// sits at (52, 35, 0) turned Rx(−90), which takes (0, −100, 0) to (0, 0, 100),
// so the ball keyed there is at (52, 35, 100). The human at (200, 0, 0)
// turned ry 180 (x, y, z) -> (−x, y, −z): its hand frame is at
// (200 − 33, −105 + 133, 0) = (167, 28, 0), so (0, −90, 0) in it is (167, −62, 0).
constexpr const char* kHandOver =
    "/robot f2 0 0 0\n"
    "/human h 200 0 0 0 180 0\n"
    "/sphere ball 8 0 -100 0\n"
    "/key 0 f2.rhand 0 0 0 -90 0 0\n"
    "/attach ball f2.rhand\n"
    "/attach ball h.rhand at 48\n"
    "/attach ball world at 60\n"
    "/key 47 ball 0 -100 0 0 0 0\n"
    "/key 48 ball 0 -90 0 0 0 0\n"
    "/key 59 ball 0 -90 0 0 0 0\n"
    "/key 60 ball 100 50 0 0 0 0\n"
    "/key 70 ball 100 0 0 0 0 0\n";

TEST(AttachAt, HandOverAtExactFrames) {
    const SceneDesc s = sceneFromText(kHandOver);
    EXPECT_TRUE(s.attachmentsChange);
    ASSERT_EQ(s.attachOrder.size(), 1u);
    expectCentre(s, "ball", 0, {52, 35, 100});
    expectCentre(s, "ball", 47, {52, 35, 100});
    // Between 47 and 48 the keys blend, read in F-2's hand, which still holds.
    expectCentre(s, "ball", 47.5, {52, 35, 95});
    expectCentre(s, "ball", 48, {167, -62, 0});
    expectCentre(s, "ball", 59, {167, -62, 0});
    // `world` ends the ride: the keys are world positions from 60 on.
    expectCentre(s, "ball", 60, {100, 50, 0});
    expectCentre(s, "ball", 65, {100, 25, 0});
    expectCentre(s, "ball", 70, {100, 0, 0});
    EXPECT_EQ(s.lastFrame(), 70);
}

TEST(AttachAt, TheRideFollowsItsHolderAtEveryFrame) {
    // The human walks +x after the catch: the ball goes with its hand.
    const SceneDesc s = sceneFromText(std::string(kHandOver) + "/key 48 h\n/key 58 h 300 0 0 0 180 0\n");
    expectCentre(s, "ball", 53, {217, -62, 0});
    expectCentre(s, "ball", 58, {267, -62, 0});
}

TEST(AttachAt, MountAtTakesTheLatestChangeAtOrBeforeT) {
    const SceneDesc s = sceneFromText(kHandOver);
    const SceneObject& ball = s.objects[indexOf(s, "ball")];
    const FrameRef f2Hand{0, int(RobotPart::RHand)}, hHand{1, int(RobotPart::RHand)};
    EXPECT_EQ(mountAt(ball, 0), f2Hand);
    EXPECT_EQ(mountAt(ball, 47.999), f2Hand);
    EXPECT_EQ(mountAt(ball, 48), hHand);
    EXPECT_EQ(mountAt(ball, 59.5), hHand);
    EXPECT_FALSE(mountAt(ball, 60).has_value());
    EXPECT_FALSE(mountAt(ball, 1000).has_value());
}

TEST(AttachAt, TimesInSecondsAndNoStartRide) {
    // No ride before 1 s = 24 frames at /fps 24: its keys are world positions.
    const SceneDesc s = sceneFromText(
        "/fps 24\n/sphere a 1 0 0 0\n/sphere b 1 50 0 0\n/attach a b at 1s\n"
        "/key 0 a 10 0 0 0 0 0\n/key 23 a 10 0 0 0 0 0\n/key 24 a 0 5 0 0 0 0\n");
    expectCentre(s, "a", 23, {10, 0, 0});
    expectCentre(s, "a", 24, {50, 5, 0});
    ASSERT_EQ(s.objects[0].attachChanges.size(), 1u);
    EXPECT_EQ(s.objects[0].attachChanges[0].time, 24);
}

TEST(AttachAt, ChainsWhoseOrderChanges) {
    // a on b until 10, then b on a: the order of evaluation turns around.
    const SceneDesc s = sceneFromText(
        "/sphere a 1 0 0 0\n/sphere b 1 0 0 0\n/attach a b\n/attach a world at 10\n/attach b a at 10\n"
        "/key 0 b 100 0 0 0 0 0\n/key 0 a 0 7 0 0 0 0\n/key 10 a 30 0 0 0 0 0\n"
        "/key 10 b 0 0 4 0 0 0\n");
    expectCentre(s, "a", 0, {100, 7, 0});
    expectCentre(s, "b", 0, {100, 0, 0});
    expectCentre(s, "a", 10, {30, 0, 0});
    expectCentre(s, "b", 10, {30, 0, 4});
}

TEST(AttachAt, LongChainWithAChangeEvaluatesInLinearTime) {
    // 20,000 spheres, each on the previous from the start; s1 lets go at 5.
    constexpr int kCount = 20000;
    std::string text;
    for (int i = 0; i < kCount; ++i) text += "/sphere s" + std::to_string(i) + " 1 1 0 0\n";
    for (int i = kCount - 1; i > 0; --i)
        text += "/attach s" + std::to_string(i) + " s" + std::to_string(i - 1) + "\n";
    text += "/attach s1 world at 5\n";
    const SceneDesc s = sceneFromText(text);
    ASSERT_EQ(s.attachOrder.size(), std::size_t(kCount - 1));
    EvaluatedFrame frame;
    evaluateFrame(s, 0, frame);
    EXPECT_VEC_NEAR(frame.primitives.back().centre, (Vec3{float(kCount), 0, 0}), kTol);
    evaluateFrame(s, 5, frame);
    EXPECT_VEC_NEAR(frame.primitives.back().centre, (Vec3{float(kCount - 1), 0, 0}), kTol);
    EXPECT_VEC_NEAR(frame.primitives[1].centre, (Vec3{1, 0, 0}), kTol);
}

TEST(AttachAt, CyclesAreCheckedPerInterval) {
    const std::string two = "/sphere a 1 0 0 0\n/sphere b 1 0 0 0\n";
    // a on b in [0, 24), b on a from 24 with a's ride ended at 24: no cycle.
    EXPECT_NO_THROW(sceneFromText(two + "/attach a b\n/attach a world at 24\n/attach b a at 24\n"));
    EXPECT_NO_THROW(sceneFromText(two + "/attach b a at 24\n/attach a world at 24\n/attach a b\n"));
    // Overlapping: a still rides on b from 24.
    expectOnlyError(two + "/attach a b\n/attach b a at 24\n", 4, 1,
                    "attaching 'b' to 'a' at frame 24 makes a cycle: 'a' rides on 'b' from the start");
    expectOnlyError(two + "/attach a b at 10\n/attach b a at 24\n", 4, 1,
                    "attaching 'b' to 'a' at frame 24 makes a cycle: 'a' rides on 'b' from frame 10");
    // Found at the change that closes it, whatever the file order.
    expectOnlyError(two + "/attach b a at 24\n/attach a b at 10\n", 3, 1,
                    "attaching 'b' to 'a' at frame 24 makes a cycle: 'a' rides on 'b' from frame 10");
    // A longer one, through a part, closed by a change from the start's tree.
    expectOnlyError(two + "/robot r 0 0 0\n/attach a r.lhand\n/attach r b\n/attach b a at 5\n", 6, 1,
                    "attaching 'b' to 'a' at frame 5 makes a cycle: 'a' rides on 'b' from the start");
    // Ended again before the other one starts: fine.
    EXPECT_NO_THROW(sceneFromText(two + "/attach a b at 10\n/attach a world at 20\n/attach b a at 20\n"));
}

TEST(AttachAt, CycleCheckAgreesWithEveryIntervalCheckedByHand) {
    // Random rides of 5 spheres (from the start and at times 0..4, on objects
    // or world): the file has an error exactly when some interval's rides,
    // each the latest at or before its start, or the rides from the start
    // alone, make a cycle.
    std::uint32_t seed = 12345;
    auto next = [&](std::uint32_t n) {
        seed = seed * 1664525u + 1013904223u;
        return (seed >> 16) % n;
    };
    constexpr int kObjects = 5, kTimes = 5;
    int withCycles = 0;
    for (int round = 0; round < 400; ++round) {
        // mount[o][0]: from the start, mount[o][1 + t]: at t; -1 none given, kObjects: world.
        std::array<std::array<int, kTimes + 1>, kObjects> mount;
        for (auto& m : mount) m.fill(-1);
        std::string text;
        for (int o = 0; o < kObjects; ++o) text += "/sphere s" + std::to_string(o) + " 1 0 0 0\n";
        for (int k = 0, count = 1 + int(next(8)); k < count; ++k) {
            const int o = int(next(kObjects)), slot = int(next(kTimes + 1));
            int target = int(next(kObjects + 1));
            if (slot == 0 && target == kObjects) target = int(next(kObjects));
            if (target == o || mount[o][slot] >= 0) continue;
            mount[o][slot] = target;
            text += "/attach s" + std::to_string(o) + " " +
                    (target == kObjects ? std::string("world") : "s" + std::to_string(target)) +
                    (slot == 0 ? std::string() : " at " + std::to_string(slot - 1)) + "\n";
        }
        bool cycle = false;
        // t = -1: the rides from the start by themselves, which must make no
        // cycle even where an `at 0` replaces them.
        for (int t = -1; t < kTimes; ++t) {
            std::array<int, kObjects> holder;
            for (int o = 0; o < kObjects; ++o) {
                holder[o] = mount[o][0] >= 0 ? mount[o][0] : kObjects;
                for (int u = 0; u <= t; ++u)
                    if (mount[o][1 + u] >= 0) holder[o] = mount[o][1 + u];
            }
            for (int o = 0; o < kObjects; ++o) {
                int x = o;
                for (int steps = 0; steps <= kObjects && holder[x] != kObjects; ++steps) x = holder[x];
                cycle = cycle || holder[x] != kObjects;
            }
        }
        withCycles += cycle;
        const ParseResult r = parseScene(text, "t.f2");
        EXPECT_EQ(r.ok(), !cycle) << text << test::formatDiagnostics(r);
    }
    EXPECT_GT(withCycles, 20);
    EXPECT_LT(withCycles, 380);
}

TEST(AttachAt, Errors) {
    const std::string two = "/sphere a 1 0 0 0\n/robot r 0 0 0\n";
    expectOnlyError(two + "/attach a r at\n", 3, 13, "'at' needs a time: '/attach <name> <target> at <t>'");
    expectOnlyError(two + "/attach a r on 5\n", 3, 13, "expected 'at' before the time, got 'on'");
    expectOnlyError(two + "/attach a r at -1\n", 3, 16, "a key time must be >= 0, got -1");
    expectOnlyError(two + "/attach a r at x\n", 3, 16, "");
    expectOnlyError(two + "/attach a r\n/attach a r.head\n", 4, 9,
                    "'a' is already attached (at 3:1); one '/attach' per name without 'at' (a change of "
                    "ride: '/attach a <target> at <t>')");
    expectOnlyError(two + "/attach a r at 48\n/attach a r.head at 48\n", 4, 1,
                    "'a' is already attached at frame 48 (at 3:1); one '/attach' per name and time");
    // The same time once in seconds: told when /fps is known, at the later line.
    expectOnlyError(two + "/attach a r at 2s\n/attach a r.head at 48\n/fps 24\n", 4, 1,
                    "'a' is already attached at frame 48 (at 3:1); one '/attach' per name and time");
    expectOnlyError(two + "/attach a world\n", 3, 11,
                    "'world' ends a ride, so it needs a time: '/attach <name> world at <t>' (without "
                    "'/attach' an object rides on nothing)");
    expectOnlyError(two + "/attach camera r at 5\n", 3, 18,
                    "'camera' cannot change what it rides on: 'at' is for objects (one '/attach' of the "
                    "camera, from the start)");
    expectOnlyError(two + "/point_light 1 0 0 0 name lamp\n/attach lamp r at 5\n", 4, 16,
                    "'lamp' cannot change what it rides on: 'at' is for objects (one '/attach' of a "
                    "light, from the start)");
    expectOnlyError(two + "/attach a a at 5\n", 3, 1, "'a' cannot be attached to itself");
    expectOnlyError(two + "/attach r r.rhand at 5\n", 3, 1, "'r' cannot be attached to its own part");
    expectOnlyError(two + "/attach a r at 5 6\n", 3, 1, "'/attach' takes 2 or 4 arguments, got 5");
}

TEST(AttachAt, AnObjectNamedWorldIsStillATarget) {
    const SceneDesc s = sceneFromText(
        "/sphere a 1 0 0 0\n/sphere world 1 5 0 0\n/attach a world\n"
        "/attach a world at 10\n");
    EXPECT_EQ(s.objects[0].attachedTo, (FrameRef{1, -1}));
    ASSERT_EQ(s.objects[0].attachChanges.size(), 1u);
    EXPECT_EQ(s.objects[0].attachChanges[0].mount, (FrameRef{1, -1}));
}

TEST(AttachAt, ScenesWithoutAtKeepTheirStaticOrder) {
    const SceneDesc s = sceneFromText(kCatch);
    EXPECT_FALSE(s.attachmentsChange);
    EXPECT_TRUE(s.objects[1].attachChanges.empty());
}

}  // namespace
}  // namespace f2
