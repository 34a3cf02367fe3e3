// Attachments (SPEC 9.2): world frames through rotated parts and chains, the
// same in the renderer's frame, the exports' primitives and worldFromRef.
#include <gtest/gtest.h>

#include "core/anim/frame_builder.h"
#include "io/frame_primitives.h"
#include "test_scenes.h"

namespace f2 {
namespace {

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
    EXPECT_VEC_NEAR(worldFromRef(s, {std::uint32_t(h), int(PartId::Head)}, 10).translation,
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

}  // namespace
}  // namespace f2
