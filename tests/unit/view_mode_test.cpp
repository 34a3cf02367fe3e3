// The view modes (docs/rendering.md, "View modes"): each mode's pixels on a
// tiny scene whose values follow from the formulas by hand, and the cost
// view's counts against traversals counted by hand on small trees.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/render/diagnostic_view.h"
#include "core/render/renderer.h"
#include "core/render/shading.h"
#include "core/render/view_legend.h"
#include "test_scenes.h"

namespace f2 {
namespace {

// Eye at the origin looking along +z, 53° wide (d = 1), 9 x 9 pixels: the centre
// pixel's ray is exactly +z. A ball (primitive 0, radius 30) straight ahead at
// distance 100, over a floor (primitive 1, top at y = -45, z from 50 to 350)
// lit straight down: the floor under the ball is in its shadow.
constexpr const char* kBallOverFloor =
    "/camera 9 9 1 0 0 0\n"
    "/sphere ball 30 0 0 100\n"
    "/box floor 400 10 300 0 -50 200\n"
    "/amb_light 0.2\n/dir_light 0.8 0 -1 0\n";
constexpr int kCentre = 4;

struct Frame {
    SceneDesc scene;
    Renderer renderer{1};
    Camera camera;
    explicit Frame(const char* text)
        : scene(test::sceneFromText(text)), camera(Camera::fromDesc(scene.camera)) {
        Image shaded;
        renderer.render(scene, 0, camera, shaded);
    }
    Image view(ViewMode mode, int threads = 1) {
        Renderer r(threads);
        Image out;
        r.render(scene, 0, camera, out, {1, mode});
        return out;
    }
    RayProbe probe(int x, int y) const {
        return probeRay(renderer.frame(), camera.rayThrough(float(x) + 0.5f, float(y) + 0.5f));
    }
};

TEST(ViewModes, NamesRoundTrip) {
    for (ViewMode mode : kViewModes) EXPECT_EQ(viewModeNamed(viewModeName(mode)), mode);
    EXPECT_FALSE(viewModeNamed("Normals"));
    EXPECT_FALSE(viewModeNamed(""));
}

TEST(ViewModes, ShadedIsTheImage) {
    Frame f(kBallOverFloor);
    Image image;
    f.renderer.trace(f.renderer.frame(), f.camera, image);
    EXPECT_EQ(f.view(ViewMode::Shaded), image);
}

TEST(ViewModes, NormalsAreTheFacingNormalMappedToColour) {
    Frame f(kBallOverFloor);
    ASSERT_EQ(f.camera.rayThrough(kCentre + 0.5f, kCentre + 0.5f).direction, (Vec3{0, 0, 1}));
    const Image image = f.view(ViewMode::Normals);
    // The ball's nearest point faces the eye: n = (0, 0, -1) -> (0.5, 0.5, 0).
    EXPECT_EQ(image.at(kCentre, kCentre), (Rgb8{128, 128, 0}));
    // The floor's top: n = (0, 1, 0) -> (0.5, 1, 0.5).
    EXPECT_EQ(image.at(0, 8), (Rgb8{128, 255, 128}));
    // The top row looks over everything: background black.
    EXPECT_EQ(image.at(kCentre, 0), (Rgb8{0, 0, 0}));
}

TEST(ViewModes, DepthRunsFromTheNearestHitWhiteToTheFarthestDark) {
    Frame f(kBallOverFloor);
    const RayProbe centre = f.probe(kCentre, kCentre);
    ASSERT_TRUE(centre.hit);
    EXPECT_NEAR(centre.distance, 70.0f, 1e-4f);  // the ball's front at z = 100 - 30
    const Image image = f.view(ViewMode::Depth);
    ViewRange range;
    Image again;
    traceView(f.renderer.frame(), f.camera, ViewMode::Depth, again, nullptr, nullptr, &range);
    EXPECT_EQ(range.low, centre.distance);  // nothing in the image is nearer
    EXPECT_EQ(image.at(kCentre, kCentre), (Rgb8{255, 255, 255}));
    // The farthest hit pixel is 1 - 0.9 = 0.1 grey; the background black.
    int farthest = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const RayProbe p = f.probe(x, y);
            if (!p.hit) {
                EXPECT_EQ(image.at(x, y), (Rgb8{0, 0, 0}));
                continue;
            }
            EXPECT_LE(p.distance, range.high);
            if (p.distance == range.high) {
                EXPECT_EQ(image.at(x, y), (Rgb8{26, 26, 26}));
                ++farthest;
            }
            EXPECT_EQ(image.at(x, y), depthColor(p.distance, range.low, range.high));
        }
    EXPECT_GE(farthest, 1);
}

TEST(ViewModes, ShadowMaskShowsLitBlockedAndTurnedAway) {
    Frame f(kBallOverFloor);
    const Image image = f.view(ViewMode::ShadowMask);
    // Under the ball, on the floor (bottom row, centre): the shadow ray up meets the ball.
    const RayProbe under = f.probe(kCentre, 8);
    ASSERT_TRUE(under.hit);
    EXPECT_EQ(under.primitive, 1u);
    EXPECT_EQ(under.blocked, 1);
    EXPECT_EQ(image.at(kCentre, 8), (Rgb8{255, 0, 0}));
    // The floor off to the side is lit.
    EXPECT_EQ(f.probe(0, 8).lit, 1);
    EXPECT_EQ(image.at(0, 8), (Rgb8{255, 255, 255}));
    // The ball's front faces the eye, at right angles to the light: N.L = 0, turned away.
    EXPECT_EQ(image.at(kCentre, kCentre), (Rgb8{0, 0, 0}));
    // Its upper part faces the light.
    EXPECT_EQ(image.at(kCentre, 3), (Rgb8{255, 255, 255}));
    EXPECT_EQ(image.at(kCentre, 0), kMaskBackground);
}

TEST(ViewModes, ShadowMaskIsTheFractionOfLights) {
    // A second light, from the eye's upper left, reaches the floor under the
    // ball (its shadow ray passes 36 from the ball's centre) and the ball's front.
    std::string text = kBallOverFloor;
    text += "/dir_light 0.5 1 -1 1\n";
    Frame f(text.c_str());
    const Image image = f.view(ViewMode::ShadowMask);
    EXPECT_EQ(image.at(kCentre, 8), (Rgb8{255, 128, 128}));        // (1/2 + 1/2, 1/2, 1/2)
    EXPECT_EQ(image.at(kCentre, kCentre), (Rgb8{128, 128, 128}));  // one lit, one turned away
}

TEST(ViewModes, ShadowMaskCountsASoftLightsVisibleFraction) {
    // The light is a sun of angular radius 10°: a floor point 33.5 to the side of
    // the ball's centre sees the ball's rim 4.4° from straight up, inside the sun's disc.
    std::string text = kBallOverFloor;
    text.replace(text.find("/dir_light 0.8 0 -1 0"), 21, "/dir_light 0.8 0 -1 0 angle 10 4");
    Frame f(text.c_str());
    const Vec3 edge{33.5f, -45, 100};
    const RayProbe p = probeRay(f.renderer.frame(), {{0, 0, 0}, normalize(edge)});
    ASSERT_TRUE(p.hit);
    ASSERT_EQ(p.primitive, 1u);
    EXPECT_GT(p.lit, 0.0f);
    EXPECT_GT(p.blocked, 0.0f);
    EXPECT_FLOAT_EQ(p.lit + p.blocked, 1.0f);
    EXPECT_EQ(p.shadowRays, 16u);  // 4 x 4 samples
    EXPECT_EQ(shadowMaskColor(p), (Rgb8{255, toByte(p.lit), toByte(p.lit)}));
}

TEST(ViewModes, PrimitiveIdsAreDistinctFixedColours) {
    Frame f(kBallOverFloor);
    const Image image = f.view(ViewMode::PrimitiveIds);
    EXPECT_EQ(image.at(kCentre, kCentre), primitiveIdColor(0));
    EXPECT_EQ(image.at(0, 8), primitiveIdColor(1));
    EXPECT_NE(primitiveIdColor(0), primitiveIdColor(1));
    EXPECT_EQ(image.at(kCentre, 0), (Rgb8{0, 0, 0}));
    // No two of the first thousand indices share a colour, and none is dark.
    std::vector<std::uint32_t> colours;
    for (std::uint32_t i = 0; i < 1000; ++i) {
        const Rgb8 c = primitiveIdColor(i);
        EXPECT_GE(std::min({c.r, c.g, c.b}), 48);
        colours.push_back(std::uint32_t(c.r) << 16 | std::uint32_t(c.g) << 8 | c.b);
    }
    std::sort(colours.begin(), colours.end());
    EXPECT_EQ(std::adjacent_find(colours.begin(), colours.end()), colours.end());
}

TEST(ViewModes, CostCountsPrimaryAndShadowTraversals) {
    Frame f(kBallOverFloor);
    // Two primitives: the tree is one leaf, the root.
    ASSERT_EQ(f.renderer.frame().bvh.nodes().size(), 1u);
    // The ball's front: root box + both primitives; N.L = 0, so no shadow ray.
    const RayProbe front = f.probe(kCentre, kCentre);
    EXPECT_EQ(front.cost.nodes, 1u);
    EXPECT_EQ(front.cost.primitives, 2u);
    EXPECT_EQ(front.shadowRays, 0u);
    // Under the ball: 3, then the shadow ray: root box + the ball (the floor it starts on is skipped).
    const RayProbe under = f.probe(kCentre, 8);
    EXPECT_EQ(under.shadowRays, 1u);
    EXPECT_EQ(under.cost.nodes, 2u);
    EXPECT_EQ(under.cost.primitives, 3u);
    // A ray that misses the root's box: one box test.
    const RayProbe back = probeRay(f.renderer.frame(), {{0, 0, 0}, {0, 0, -1}});
    EXPECT_FALSE(back.hit);
    EXPECT_EQ(back.cost.nodes, 1u);
    EXPECT_EQ(back.cost.primitives, 0u);

    // The image: the heat ramp of each pixel's total over the image's largest.
    Image image;
    ViewRange range;
    traceView(f.renderer.frame(), f.camera, ViewMode::Cost, image, nullptr, nullptr, &range);
    EXPECT_EQ(range.high, 5.0f);  // a hit with one shadow ray
    EXPECT_EQ(image.at(kCentre, kCentre), costColor(3, 5));
    EXPECT_EQ(image.at(kCentre, 8), costColor(5, 5));
    EXPECT_EQ(costColor(5, 5), (Rgb8{255, 255, 255}));  // the top of the ramp
    EXPECT_EQ(costColor(0, 5), (Rgb8{0, 0, 0}));
}

// Eight spheres of radius 10 in a row along x, 100 apart: the
// build splits them 4 + 4 into two leaves under the root.
std::vector<Primitive> rowOfSpheres() {
    std::vector<Primitive> prims;
    for (int i = 0; i < 8; ++i)
        prims.push_back(
            makePrimitive(ShapeKind::Sphere, {10, 0, 0}, Transform::fromPose({100.0f * float(i), 0, 0}, {})));
    return prims;
}

TEST(ViewModes, CostIsTheCountedTraversalOfATwoLevelTree) {
    const std::vector<Primitive> prims = rowOfSpheres();
    Bvh bvh;
    bvh.build(prims);
    const auto nodes = bvh.nodes();
    ASSERT_EQ(nodes.size(), 3u);
    ASSERT_EQ(nodes[0].count, 0u);
    ASSERT_EQ(nodes[1].count, 4u);
    ASSERT_EQ(nodes[2].count, 4u);

    // Along +z through sphere 0: root, both children's boxes (only the left is
    // crossed), the left leaf's four spheres. 3 nodes + 4 primitives.
    HitRecord hit;
    TraversalCount count;
    ASSERT_TRUE(bvh.intersect({{0, 0, -100}, {0, 0, 1}}, 0, kInfinity, hit, count));
    EXPECT_EQ(hit.primitive, 0u);
    EXPECT_EQ(count.nodes, 3u);
    EXPECT_EQ(count.primitives, 4u);

    // Along +x through every sphere: root, both children (both crossed, the
    // left nearer), the left leaf's four; then the right child is popped and its
    // box tested again, now beyond the hit at t = 90: 4 nodes + 4 primitives.
    count = {};
    ASSERT_TRUE(bvh.intersect({{-100, 0, 0}, {1, 0, 0}}, 0, kInfinity, hit, count));
    EXPECT_EQ(hit.primitive, 0u);
    EXPECT_EQ(count.nodes, 4u);
    EXPECT_EQ(count.primitives, 4u);

    // Along +x at y = z = 9: inside both leaves' boxes but 12.7 from every
    // centre, so nothing is hit and every sphere is tested. intersect: root,
    // two children, left leaf, the right popped and entered: 4 + 8.
    // occluded: root, left, right popped in turn: 3 + 8.
    const Ray grazing{{-100, 9, 9}, {1, 0, 0}};
    count = {};
    EXPECT_FALSE(bvh.intersect(grazing, 0, kInfinity, hit, count));
    EXPECT_EQ(count.nodes, 4u);
    EXPECT_EQ(count.primitives, 8u);
    count = {};
    EXPECT_FALSE(bvh.occluded(grazing, 0, kInfinity, Bvh::kNoPrimitive, count));
    EXPECT_EQ(count.nodes, 3u);
    EXPECT_EQ(count.primitives, 8u);
    // A skipped primitive is not tested.
    count = {};
    EXPECT_FALSE(bvh.occluded(grazing, 0, kInfinity, 3, count));
    EXPECT_EQ(count.primitives, 7u);

    // Missing the root's box: one box test, nothing else.
    count = {};
    EXPECT_FALSE(bvh.intersect({{0, 0, -100}, {0, 0, -1}}, 0, kInfinity, hit, count));
    EXPECT_EQ(count.nodes, 1u);
    EXPECT_EQ(count.primitives, 0u);
}

TEST(ViewModes, CountingChangesNoAnswer) {
    // The counted traversal is the traversal: same hits on the default scene.
    SceneDesc scene = test::sceneFromRepo("demo.f2");
    Renderer renderer(1);
    Image image;
    const Camera camera = Camera::fromDesc(scene.camera).resized(80, 60);
    renderer.render(scene, 118, camera, image);
    const PreparedFrame& frame = renderer.frame();
    for (int y = 0; y < camera.height; ++y)
        for (int x = 0; x < camera.width; ++x) {
            const Ray ray = camera.rayThrough(float(x) + 0.5f, float(y) + 0.5f);
            HitRecord plain, counted;
            TraversalCount count;
            const float start = primaryRayStart(ray.origin);
            ASSERT_EQ(frame.bvh.intersect(ray, start, kInfinity, plain),
                      frame.bvh.intersect(ray, start, kInfinity, counted, count));
            EXPECT_EQ(plain.t, counted.t);
            EXPECT_EQ(plain.primitive, counted.primitive);
            EXPECT_GE(count.nodes, 1u);
        }
}

TEST(ViewModes, EveryModeIsTheSameOnAnyThreadCount) {
    SceneDesc scene = test::sceneFromRepo("demo.f2");
    const Camera camera = Camera::fromDesc(scene.camera).resized(200, 150);
    for (ViewMode mode : kViewModes) {
        Renderer one(1), three(3);
        Image a, b;
        one.render(scene, 118, camera, a, {1, mode});
        three.render(scene, 118, camera, b, {1, mode});
        EXPECT_EQ(a, b) << viewModeName(mode);
    }
}

TEST(ViewModes, DepthAndCostCarryTheirLegend) {
    SceneDesc scene = test::sceneFromRepo("demo.f2");
    const Camera camera = Camera::fromDesc(scene.camera).resized(200, 150);
    Renderer renderer(1);
    Image image;
    renderer.render(scene, 118, camera, image, {1, ViewMode::Cost});
    // The panel's corner, inside the margin at the bottom left.
    const int panelTop = camera.height - kLegendMargin - kLegendHeight;
    EXPECT_EQ(image.at(kLegendMargin, panelTop), (Rgb8{24, 24, 24}));
    // The bar's 128 columns sample the ramp at their centres, 0.5/128 to 127.5/128.
    EXPECT_EQ(image.at(kLegendMargin + 4, panelTop + 4), costColor(1, 256));
    EXPECT_EQ(image.at(kLegendMargin + kLegendWidth - 5, panelTop + 4), costColor(255, 256));
    // No legend where it does not fit, nor for the unscaled modes.
    Image small;
    small.resize(kLegendWidth, 60);
    EXPECT_FALSE(drawViewLegend(small, ViewMode::Cost, {0, 10}));
    image.resize(200, 150);
    EXPECT_FALSE(drawViewLegend(image, ViewMode::Normals, {0, 10}));
    EXPECT_TRUE(drawViewLegend(image, ViewMode::Depth, {0, 10}));
}

}  // namespace
}  // namespace f2
