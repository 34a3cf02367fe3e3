// pickPixel names what the renderer drew: every pixel of a flat-lit scene
// (ambient only, so each object and part shows its own paint) is picked as
// the object or part whose paint the packet renderer put there.
#include "core/render/pick.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>

#include "core/anim/frame_builder.h"
#include "core/render/renderer.h"
#include "robot_parts.h"
#include "test_scenes.h"

using namespace f2;
using f2::test::RobotPart;

namespace {

// Ambient light only and ka = 1: a pixel is exactly its surface's paint.
constexpr const char* kFlatScene = R"(/camera 120 90 0.6 0 60 -320
/background 1 2 3
/amb_light 1
/sphere ball 30 -95 40 0
/box crate 40 40 40 95 20 0 0 30 0
/robot r 0 0 40 0 180 0
/paint ball 200 0 0
/paint crate 0 200 0
/paint r.body 0 0 200
/paint r.head 200 200 0
/paint r.lhand 0 200 200
/paint r.rhand 200 0 200
/material ball 1 0 0 1
/material crate 1 0 0 1
/material r 1 0 0 1
/key 0 r
/key 10 r 0 0 40 0 150 0
)";

Color8 paintOf(const SceneDesc& scene, const PickHit& hit) {
    const SceneObject& object = scene.objects[hit.object];
    return object.appearance[std::size_t(hit.shape)].color;
}

}  // namespace

TEST(Pick, EveryPixelNamesWhatTheRendererDrew) {
    const SceneDesc scene = test::sceneFromText(kFlatScene);
    const Camera camera = Camera::fromDesc(scene.camera);
    for (double t : {0.0, 6.5}) {
        Renderer renderer(2);
        Image image;
        renderer.render(scene, t, camera, image);
        std::set<std::pair<std::size_t, int>> seen;
        int eyes = 0;
        for (int y = 0; y < camera.height; ++y) {
            for (int x = 0; x < camera.width; ++x) {
                const Rgb8 drawn = image.at(x, y);
                const std::optional<PickHit> hit = pickPixel(scene, t, camera, x, y);
                if (!hit) {
                    EXPECT_EQ(drawn, (Rgb8{1, 2, 3})) << "pixel " << x << "," << y << " t=" << t;
                    continue;
                }
                seen.insert({hit->object, hit->part ? int(*hit->part) : -1});
                const Color8 paint = paintOf(scene, *hit);
                // The eyes keep their own colour; they are shapes of the head.
                const ModelType* model = scene.objects[hit->object].model.get();
                if (model && model->shapes[std::size_t(hit->shape)].ownColor) {
                    EXPECT_EQ(hit->part, RobotPart::Head);
                    ++eyes;
                }
                EXPECT_EQ(drawn, (Rgb8{paint.r, paint.g, paint.b}))
                    << "pixel " << x << "," << y << " t=" << t;
            }
        }
        // The ball, the crate and all four parts of the robot were picked somewhere.
        EXPECT_EQ(seen.size(), 6u) << "t=" << t;
        EXPECT_GT(eyes, 0) << "t=" << t;
    }
}

TEST(Pick, HitPointLiesOnTheSurface) {
    const SceneDesc scene = test::sceneFromText(kFlatScene);
    const Camera camera = Camera::fromDesc(scene.camera);
    // The ball's centre projects near the left of the picture; scan its row.
    int hits = 0;
    for (int x = 0; x < camera.width; ++x) {
        const std::optional<PickHit> hit = pickPixel(scene, 0, camera, x, 45);
        if (!hit || scene.objects[hit->object].name != "ball") continue;
        ++hits;
        EXPECT_FALSE(hit->part.has_value());
        EXPECT_NEAR(length(hit->point - Vec3{-95, 40, 0}), 30.0f, 1e-2f);
        EXPECT_NEAR(length(hit->point - camera.eye), hit->distance, 1e-2f);
    }
    EXPECT_GT(hits, 0);
}

TEST(Pick, BackgroundIsNothing) {
    const SceneDesc scene = test::sceneFromText(kFlatScene);
    EXPECT_FALSE(pickPixel(scene, 0, Camera::fromDesc(scene.camera), 0, 0).has_value());
}

TEST(Pick, ProjectInvertsRayThrough) {
    const SceneDesc scene = test::sceneFromText(kFlatScene);
    const Camera camera = Camera::fromDesc(scene.camera);
    for (float px : {0.5f, 33.25f, 119.5f})
        for (float py : {0.5f, 50.0f, 89.5f}) {
            const Ray ray = camera.rayThrough(px, py);
            float qx = -1, qy = -1;
            ASSERT_TRUE(camera.project(ray.origin + ray.direction * 250.0f, qx, qy));
            EXPECT_NEAR(qx, px, 1e-3f);
            EXPECT_NEAR(qy, py, 1e-3f);
        }
    float qx, qy;
    EXPECT_FALSE(camera.project(camera.eye - camera.worldFromCamera * Vec3{0, 0, 1}, qx, qy));  // behind
}

TEST(Pick, SelectionBoundsHoldWhatIsPicked) {
    const SceneDesc scene = test::sceneFromText(kFlatScene);
    const Camera camera = Camera::fromDesc(scene.camera);
    PreparedFrame frame;
    evaluateFrame(scene, 3, frame);
    frame.bvh.build(frame.primitives);
    int checked = 0;
    for (int y = 0; y < camera.height; y += 3)
        for (int x = 0; x < camera.width; x += 3) {
            const auto hit = pickPoint(scene, frame, camera, float(x) + 0.5f, float(y) + 0.5f);
            if (!hit) continue;
            const Bounds b = selectionBounds(scene, frame, hit->object, hit->part);
            for (float v : {hit->point.x - b.lo.x, b.hi.x - hit->point.x, hit->point.y - b.lo.y,
                            b.hi.y - hit->point.y, hit->point.z - b.lo.z, b.hi.z - hit->point.z})
                EXPECT_GE(v, -1e-2f) << x << "," << y;
            ++checked;
        }
    EXPECT_GT(checked, 100);
    // A part's bounds lie inside its model's.
    const std::size_t robot = 2;
    const Bounds whole = selectionBounds(scene, frame, robot, std::nullopt);
    const Bounds head = selectionBounds(scene, frame, robot, RobotPart::Head);
    EXPECT_GT(head.lo.y, whole.lo.y);
    EXPECT_LE(head.hi.y, whole.hi.y);
}
