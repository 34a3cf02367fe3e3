// Rendering against the SPEC 3 formula at chosen pixels, and determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "core/anim/frame_builder.h"
#include "core/render/renderer.h"
#include "io/bench_scenes.h"
#include "test_scenes.h"

namespace f2 {
namespace {

struct D3 {
    double x, y, z;
};
D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator*(D3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
D3 unit(D3 a) { return a * (1 / std::sqrt(dot(a, a))); }
int byte(double v) { return int(std::floor(255 * std::clamp(v, 0.0, 1.0) + 0.5)); }

/// SPEC 2 primary ray direction for an unrotated camera, in double.
D3 primaryDirection(int i, int j, int w, int h, double d) {
    return unit({(i + 0.5) / w - 0.5, (0.5 - (j + 0.5) / h) * h / w, d});
}

Image renderScene(const SceneDesc& scene, double t, int threads = 1, int aa = 1) {
    Renderer renderer(threads);
    Image image;
    renderer.render(scene, t, Camera::fromDesc(scene.camera), image, {aa});
    return image;
}

void expectPixelNear(const Image& image, int i, int j, int r, int g, int b) {
    Rgb8 p = image.at(i, j);
    EXPECT_NEAR(p.r, r, 1) << "pixel " << i << "," << j;
    EXPECT_NEAR(p.g, g, 1) << "pixel " << i << "," << j;
    EXPECT_NEAR(p.b, b, 1) << "pixel " << i << "," << j;
}

// A sphere of radius 30 at z = 100 in front of the eye, lit along +z (from
// behind the camera) and from the upper left, red, default material 1 1 0.3 32.
constexpr const char* kLitSphere =
    "/camera 64 48 0.5\n"
    "/background 10 20 30\n"
    "/sphere s 30 0 0 100\n"
    "/paint s 200 50 50\n"
    "/amb_light 0.2\n"
    "/dir_light 0.5 0 0 1\n"
    "/dir_light 0.4 1 -1 1\n";

TEST(Render, LitSpherePixelsMatchThePhongFormula) {
    SceneDesc scene = test::sceneFromText(kLitSphere);
    Image image = renderScene(scene, 0);
    const D3 centre{0, 0, 100};
    const D3 colour{200 / 255.0, 50 / 255.0, 50 / 255.0};
    const D3 lights[2] = {unit({0, 0, 1}), unit({1, -1, 1})};
    const double intensity[2] = {0.5, 0.4};
    int checked = 0;
    for (int j = 14; j < 34; j += 3) {
        for (int i = 22; i < 42; i += 3) {
            D3 d = primaryDirection(i, j, 64, 48, 0.5);
            // |t d - c|^2 = r^2 with the eye at the origin
            double b = dot(d, centre), disc = b * b - (dot(centre, centre) - 900);
            if (disc < 0) continue;
            D3 p = d * (b - std::sqrt(disc));
            D3 n = unit(p - centre), v = d * -1;
            double diffuse = 1 * 0.2, specular = 0;
            for (int l = 0; l < 2; ++l) {
                D3 L = lights[l] * -1;
                double nl = dot(n, L);
                if (nl <= 0) continue;  // nothing else in the scene casts shadows
                diffuse += intensity[l] * 1 * nl;
                D3 R = n * (2 * nl) - L;
                specular += intensity[l] * 0.3 * std::pow(std::max(0.0, dot(R, v)), 32);
            }
            expectPixelNear(image, i, j, byte(colour.x * diffuse + specular),
                            byte(colour.y * diffuse + specular), byte(colour.z * diffuse + specular));
            ++checked;
        }
    }
    EXPECT_GT(checked, 20);                    // the loop really sampled the sphere
    expectPixelNear(image, 0, 0, 10, 20, 30);  // background corner
}

TEST(Render, PixelInAShadowGetsOnlyAmbient) {
    // A ball hangs over a floor; light straight down. The floor point under the
    // ball is in its shadow; a point further away is lit.
    SceneDesc scene = test::sceneFromText(
        "/camera 80 60 0.5 0 100 -200 30 0 0\n"
        "/box floor 1000 10 1000 0 -5 0\n"
        "/paint floor 100 150 200\n"
        "/material floor 1 1 0 8\n"
        "/sphere ball 20 0 60 0\n"
        "/amb_light 0.3\n"
        "/dir_light 0.6 0 -1 0\n");
    Image image = renderScene(scene, 0);
    Camera camera = Camera::fromDesc(scene.camera);
    auto pixelOf = [&](Vec3 world) {
        Vec3 local = camera.worldFromCamera.transposed() * (world - camera.eye);
        float x = local.x / local.z * camera.distance, y = local.y / local.z * camera.distance;
        return std::pair<int, int>{int((x + 0.5f) * camera.width), int((0.5f - y / 0.75f) * camera.height)};
    };
    // Directly under the ball: shadow. The eye ray to it passes 53.7 from the
    // ball's centre, so the ball does not hide it.
    auto [si, sj] = pixelOf({0, 0, 0});
    expectPixelNear(image, si, sj, byte(100 / 255.0 * 0.3), byte(150 / 255.0 * 0.3), byte(200 / 255.0 * 0.3));
    auto [li, lj] = pixelOf({150, 0, 0});  // lit floor: ka*amb + kd*I*(N.L = 1)
    expectPixelNear(image, li, lj, byte(100 / 255.0 * 0.9), byte(150 / 255.0 * 0.9), byte(200 / 255.0 * 0.9));
}

TEST(Render, NoSelfShadowAcneOnTheFloor) {
    // Light grazing at 60 degrees: every floor pixel away from objects must be lit
    // to the same value; acne would show as scattered ambient-only pixels.
    SceneDesc scene = test::sceneFromText(
        "/camera 160 120 0.5 0 300 -800 20 0 0\n"
        "/box floor 5000 50 5000 0 -25 0\n"
        "/material floor 1 1 0 8\n"
        "/amb_light 0.2\n/dir_light 0.7 0.5 -0.8 0.3\n");
    Image image = renderScene(scene, 0);
    Rgb8 reference = image.at(80, 100);
    EXPECT_GT(reference.r, byte(200 / 255.0 * 0.2) + 20);  // really lit
    for (int j = 70; j < 120; ++j)
        for (int i = 0; i < 160; ++i) ASSERT_EQ(image.at(i, j), reference) << i << "," << j;
}

TEST(Render, ImagesAreIdenticalForAnyThreadCount) {
    SceneDesc scene = test::sceneFromRepo("demo.f2");
    scene.camera.width = 200;
    scene.camera.height = 150;
    for (double t : {0.0, 130.5, 240.0}) {
        Image one = renderScene(scene, t, 1);
        Image two = renderScene(scene, t, 2);
        Image five = renderScene(scene, t, 5);
        EXPECT_TRUE(one == two) << "frame " << t;
        EXPECT_TRUE(one == five) << "frame " << t;
    }
}

// A web page's workers each render a band of rows (RenderOptions::firstRow):
// the band's pixels are the whole frame's, whatever tiles the band cuts, and
// no pixel outside it is written.
TEST(Render, ABandOfRowsIsThatPartOfTheWholeFrame) {
    SceneDesc scene = test::sceneFromRepo("demo.f2");
    scene.camera.width = 200;
    scene.camera.height = 150;
    const Camera camera = Camera::fromDesc(scene.camera);
    const Image whole = renderScene(scene, 40);
    const Rgb8 unwritten{1, 2, 3};
    for (auto [first, end] : {std::pair{0, 150}, {0, 32}, {40, 77}, {77, 150}, {149, 150}, {100, 1000}}) {
        Renderer renderer(2);
        Image band;
        band.resize(200, 150);
        std::fill(band.pixels.begin(), band.pixels.end(), unwritten);
        RenderOptions options;
        options.firstRow = first;
        options.endRow = end;
        renderer.render(scene, 40, camera, band, options);
        for (int y = 0; y < 150; ++y) {
            const bool inside = y >= first && y < end;
            for (int x = 0; x < 200; ++x) {
                if (inside) {
                    ASSERT_EQ(band.at(x, y), whole.at(x, y))
                        << x << "," << y << " in rows " << first << ".." << end;
                } else {
                    // (Captions are drawn over the whole image; the demo has none.)
                    ASSERT_EQ(band.at(x, y), unwritten)
                        << x << "," << y << " outside rows " << first << ".." << end;
                }
            }
        }
    }
}

TEST(Render, DefaultSceneShowsTheRobotAndBothPeople) {
    SceneDesc scene = test::sceneFromRepo("demo.f2");
    scene.camera.width = 320;
    scene.camera.height = 240;
    PreparedFrame frame;
    evaluateFrame(scene, 0, frame);
    Image image = renderScene(scene, 0);
    Camera camera = Camera::fromDesc(scene.camera);
    std::set<std::uint32_t> colours;
    for (Rgb8 p : image.pixels) colours.insert(std::uint32_t(p.r) << 16 | std::uint32_t(p.g) << 8 | p.b);
    EXPECT_GT(colours.size(), 200u) << "a flat or black image";
    // The body of each model (primitive after the floor) is drawn where it projects:
    // not the background and roughly its own colour family.
    for (std::size_t prim : {1u, 7u, 11u}) {
        Vec3 local = camera.worldFromCamera.transposed() * (frame.primitives[prim].centre - camera.eye);
        int i = int((local.x / local.z * camera.distance + 0.5f) * camera.width);
        int j =
            int((0.5f - local.y / local.z * camera.distance * camera.width / camera.height) * camera.height);
        Rgb8 p = image.at(i, j);
        Vec3 c = frame.surfaces[prim].color;
        // Brightest channel of the pixel is the brightest channel of the paint.
        int paintMax = c.x >= c.y && c.x >= c.z ? 0 : (c.y >= c.z ? 1 : 2);
        int pixelMax = p.r >= p.g && p.r >= p.b ? 0 : (p.g >= p.b ? 1 : 2);
        EXPECT_EQ(pixelMax, paintMax) << "primitive " << prim << " at " << i << "," << j;
        EXPECT_FALSE(p == (Rgb8{28, 32, 46})) << "background where primitive " << prim << " should be";
    }
}

TEST(Render, AntialiasOneIsThePlainRender) {
    SceneDesc scene = test::sceneFromText(kLitSphere);
    EXPECT_TRUE(renderScene(scene, 0, 2, 1) == renderScene(scene, 0, 2));
}

TEST(Render, AntialiasChangesOnlyEdges) {
    SceneDesc scene = test::sceneFromText(
        "/camera 64 48 0.5\n/box b 40 40 1 0 0 100\n/paint b 255 255 255\n/amb_light 1\n");
    Image plain = renderScene(scene, 0), smooth = renderScene(scene, 0, 2, 4);
    int changed = 0;
    for (int j = 0; j < 48; ++j)
        for (int i = 0; i < 64; ++i) {
            // The front face (z = 99.5, half side 20) spans x = +-0.5*20/99.5 = +-0.1005 of
            // the screen width: columns 25.6..38.4, rows 17.1..30.9.
            bool interior = i >= 27 && i <= 36 && j >= 19 && j <= 28;
            bool exterior = i <= 23 || i >= 40 || j <= 15 || j >= 33;
            if (interior || exterior) {
                EXPECT_EQ(plain.at(i, j), smooth.at(i, j)) << i << "," << j;
            }
            changed += !(plain.at(i, j) == smooth.at(i, j));
        }
    EXPECT_GT(changed, 30);  // edge pixels blend (about 4 x 13 of them)
}

TEST(Render, CancelStopsEarly) {
    SceneDesc scene = test::sceneFromRepo("demo.f2");
    Renderer renderer(2);
    Image image;
    std::atomic<bool> cancel{true};
    PreparedFrame frame;
    evaluateFrame(scene, 0, frame);
    frame.bvh.build(frame.primitives);
    EXPECT_FALSE(renderer.trace(frame, Camera::fromDesc(scene.camera), image, {}, &cancel));
}

}  // namespace
}  // namespace f2

namespace f2 {
namespace {

/// Renders `scene` at time t by the packet path and by the single-ray reference
/// path; every channel of every pixel must agree within one level.
void expectPacketPathMatchesReference(const SceneDesc& scene, double t, const std::string& what) {
    Renderer renderer(2);
    Image fast, reference;
    Camera camera = Camera::fromDesc(scene.camera);
    renderer.render(scene, t, camera, fast);
    traceReference(renderer.frame(), camera, reference);
    ASSERT_EQ(fast.pixels.size(), reference.pixels.size());
    int worst = 0;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < fast.pixels.size(); ++i) {
        Rgb8 a = fast.pixels[i], b = reference.pixels[i];
        int d = std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
        worst = std::max(worst, d);
        differing += d > 0;
    }
    EXPECT_LE(worst, 1) << what;
    // The only difference allowed is pow() rounding in the specular term.
    EXPECT_LE(differing, fast.pixels.size() / 1000) << what;
}

TEST(PacketPath, MatchesReferenceOnTheDefaultScene) {
    SceneDesc scene = test::sceneFromRepo("demo.f2");
    scene.camera.width = 203;  // not a multiple of the block or tile size
    scene.camera.height = 149;
    for (double t : {0.0, 47.5, 118.0, 200.25, 240.0})
        expectPacketPathMatchesReference(scene, t, "demo frame " + std::to_string(t));
}

TEST(PacketPath, MatchesReferenceOnTheSeedExample) {
    expectPacketPathMatchesReference(test::sceneFromRepo("seed_example.f2"), 10, "seed example");
}

TEST(PacketPath, MatchesReferenceWithRotatedShapesAndSeveralLights) {
    SceneDesc scene = test::sceneFromText(
        "/camera 160 120 0.6 30 60 -300 10 -5 3\n"
        "/box floor 600 20 600 0 -60 100 0 10 0\n"
        "/box tilted 60 40 80 -60 0 100 20 35 -10\n"
        "/cylinder c 25 90 40 0 80 70 0 30\n"
        "/sphere s 30 90 20 150\n"
        "/robot r 0 0 220 0 200 0\n"
        "/key 0 r.lhand 0 0 0 -60 20 0\n"
        "/material s 0.5 0.8 0.9 7\n"
        "/amb_light 0.1\n/dir_light 0.5 1 -1 1\n/dir_light 0.4 -1 -0.5 0.2\n/dir_light 0.3 0 -1 0\n");
    expectPacketPathMatchesReference(scene, 0, "rotated shapes");
}

TEST(PacketPath, MatchesReferenceWithMoreLightsThanTileBeams) {
    // A tile's shadow rays start from beam entry nodes for its first four
    // lights and from the root for the rest; lights along the axes give the
    // beam test zero direction components.
    SceneDesc scene = test::sceneFromText(
        "/camera 120 90 0.6 0 150 -250 25 0 0\n"
        "/box floor 500 20 500 0 -20 0\n"
        "/robot r 0 0 0 0 160 0\n/human h 80 0 40 0 200 0\n/sphere s 25 -90 20 30\n"
        "/amb_light 0.1\n/dir_light 0.3 1 -1 1\n/dir_light 0.2 0 -1 0\n/dir_light 0.2 -1 -1 0\n"
        "/dir_light 0.2 0 -1 1\n/dir_light 0.2 1 -0.5 -1\n/dir_light 0.2 -0.3 -1 -0.2\n");
    expectPacketPathMatchesReference(scene, 0, "six lights");
}

TEST(PacketPath, MatchesReferenceOnAGridOfRobots) {
    // Hundreds of robots a few pixels wide: a deep tree whose shadow beams
    // start well below the root.
    BenchSceneSpec spec;
    spec.shape = BenchShape::Robots;
    spec.count = 400;
    SceneDesc scene = test::sceneFromText(benchSceneText(spec, 200, 150));
    for (double t : {0.0, 13.0})
        expectPacketPathMatchesReference(scene, t, "400 robots at " + std::to_string(t));
}

TEST(PacketPath, MatchesReferenceWithTheCameraInsideASphere) {
    SceneDesc scene = test::sceneFromText(
        "/camera 64 48 0.5\n/sphere room 500 0 0 0\n/paint room 90 160 220\n"
        "/box b 50 50 50 0 0 200 0 45 0\n/amb_light 0.3\n/dir_light 0.7 0.2 -0.5 1\n");
    expectPacketPathMatchesReference(scene, 0, "camera inside a sphere");
}

}  // namespace
}  // namespace f2
