// The checker pattern (/checker) and mirror reflection (/material's sixth
// argument): parsing, the pattern's definition, pixel values against the
// formulas of docs/rendering.md, and the packet path against the reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/render/checker.h"
#include "core/render/pixel_report.h"
#include "core/render/reflection.h"
#include "core/render/renderer.h"
#include "core/scene/models.h"
#include "io/pov_export.h"
#include "robot_parts.h"
#include "test_scenes.h"

namespace f2 {

using test::RobotPart;
namespace {

/// A primitive's look, or that of a model part's main shape.
const Appearance& look(const SceneDesc& s, std::size_t object, int part = RobotPart::Body) {
    const SceneObject& o = s.objects[object];
    return o.appearance[o.model ? static_cast<std::size_t>(o.model->mainShapeOf(part)) : 0];
}

std::uint8_t byte(double v) { return std::uint8_t(std::floor(255 * std::clamp(v, 0.0, 1.0) + 0.5)); }

Image render(const SceneDesc& scene, int threads = 1) {
    Renderer renderer(threads);
    Image image;
    renderer.render(scene, 0, Camera::fromDesc(scene.camera), image);
    return image;
}

/// The packet path and the single-ray reference path give the same bytes.
void expectPacketPathIdentical(const SceneDesc& scene, const std::string& what) {
    Renderer renderer(2);
    Image fast, reference;
    const Camera camera = Camera::fromDesc(scene.camera);
    renderer.render(scene, 0, camera, fast);
    traceReference(renderer.frame(), camera, reference);
    ASSERT_EQ(fast.pixels.size(), reference.pixels.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < fast.pixels.size(); ++i) {
        if (fast.pixels[i] == reference.pixels[i]) continue;
        if (differing++ < 5)
            ADD_FAILURE() << what << ": pixel " << i % std::size_t(fast.width) << ","
                          << i / std::size_t(fast.width);
    }
    EXPECT_EQ(differing, 0u) << what;
}

// Parsing

TEST(CheckerCommand, SetsTheSecondColourAndSizeLikePaintInFileOrder) {
    const SceneDesc s = test::sceneFromText(
        "/box floor 100 10 100 0 0 0\n/robot r 0 0 0\n"
        "/checker floor 10 20 30 25\n"
        "/checker r.head 1 2 3 4\n"
        "/checker r 5 6 7 8\n"
        "/checker r.lhand 9 9 9 0.5\n"
        "/paint floor 200 0 0\n");
    EXPECT_EQ(look(s, 0).checker, (Checker{{10, 20, 30}, 25}));
    EXPECT_EQ(look(s, 0).color, (Color8{200, 0, 0}));  // /paint keeps the pattern
    EXPECT_EQ(look(s, 1, RobotPart::Head).checker, (Checker{{5, 6, 7}, 8}));
    EXPECT_EQ(look(s, 1, RobotPart::Body).checker, (Checker{{5, 6, 7}, 8}));
    EXPECT_EQ(look(s, 1, RobotPart::LHand).checker, (Checker{{9, 9, 9}, 0.5f}));
}

TEST(CheckerCommand, Errors) {
    const std::string base = "/sphere s 1 0 0 0\n";
    test::expectOnlyError(base + "/checker s 1 2 3\n", 2, 1, "'/checker' takes 5 arguments, got 4");
    test::expectOnlyError(base + "/checker s 1 2 3 0\n", 2, 18, "cell size must be > 0, got 0");
    test::expectOnlyError(base + "/checker s 1 2 256 5\n", 2, 16,
                          "blue must be a whole number from 0 to 255");
    test::expectOnlyError(base + "/checker t 1 2 3 5\n", 2, 10, "unknown name 't'");
    test::expectOnlyError(base + "/checker camera 1 2 3 5\n", 2, 10,
                          "'/checker' does not apply to the camera");
    test::expectOnlyError(base + "/checker s.head 1 2 3 5\n", 2, 12, "'/checker' on a part of a primitive");
}

TEST(MaterialReflection, IsTheOptionalSixthArgumentAndDefaultsToZero) {
    const SceneDesc s = test::sceneFromText(
        "/sphere a 1 0 0 0\n/sphere b 1 0 0 0\n/robot r 0 0 0\n"
        "/material a 1 1 0.3 32 0.75\n"
        "/material b 1 1 0.3 32\n"
        "/material r 0.5 0.5 0.5 5 0.25\n");
    EXPECT_EQ(look(s, 0).material.reflection, 0.75f);
    EXPECT_EQ(look(s, 1).material.reflection, 0.0f);
    EXPECT_EQ(look(s, 2, RobotPart::Head).material, (Material{0.5f, 0.5f, 0.5f, 5, 0.25f}));
    EXPECT_EQ(Material{}.reflection, 0.0f);
    const std::string base = "/sphere s 1 0 0 0\n";
    test::expectOnlyError(base + "/material s 1 1 1 1 -0.5\n", 2, 21, "reflection must be >= 0, got -0.5");
    test::expectOnlyError(base + "/material s 1 1 1 1 1 1\n", 2, 1,
                          "'/material' takes 5 or 6 arguments, got 7");
}

// The pattern

TEST(CheckerPattern, CellsOfTheSizeInThePrimitivesFrameAlternate) {
    Surface surface{{1, 0, 0}, Material{}, {0, 0, 1}, 10};
    // A box centred at (100, 0, 0), turned 90 degrees about y: local x is world -z.
    const Primitive box = makePrimitive(ShapeKind::Box, {50, 50, 50},
                                        Transform{rotationFromEulerDegrees({0, 90, 0}), {100, 0, 0}});
    auto at = [&](Vec3 local) {
        const Vec3 world = box.centre + Vec3{box.axes[0].x, box.axes[1].x, box.axes[2].x} * local.x +
                           Vec3{box.axes[0].y, box.axes[1].y, box.axes[2].y} * local.y +
                           Vec3{box.axes[0].z, box.axes[1].z, box.axes[2].z} * local.z;
        return surfaceColorAt(surface, box, world, {0, 1, 0}, 0.0f);
    };
    const Vec3 first = surface.color, second = surface.checkerColor;
    EXPECT_EQ(at({5, 5, 5}), first);      // cell (0, 0, 0)
    EXPECT_EQ(at({15, 5, 5}), second);    // (1, 0, 0)
    EXPECT_EQ(at({15, 15, 5}), first);    // (1, 1, 0)
    EXPECT_EQ(at({-5, 5, 5}), second);    // (-1, 0, 0): floor, not truncation
    EXPECT_EQ(at({-5, -5, -5}), second);  // (-1, -1, -1)
    EXPECT_EQ(at({-15, -5, 5}), second);  // (-2, -1, 0)
    EXPECT_EQ(at({-15, -15, 5}), first);  // (-2, -2, 0)
    EXPECT_EQ(at({25, 15, 5}), second);   // (2, 1, 0)
    // A plain surface ignores the pattern.
    surface.checkerSize = 0;
    EXPECT_EQ(at({15, 5, 5}), first);
}

TEST(CheckerPattern, AFaceOnAPlaneBetweenCellsTakesTheCellInside) {
    // The top face of this box is local y = 10, exactly a cell boundary for
    // size 10: read `inset` inside, it is all in cells y = 0 (not a speckle of y = 1).
    const Surface surface{{1, 0, 0}, Material{}, {0, 0, 1}, 10};
    const Primitive box = makePrimitive(ShapeKind::Box, {40, 20, 40}, Transform{Mat3{}, {0, 0, 0}});
    for (float x : {2.5f, 7.5f, 12.5f, -2.5f}) {
        const bool odd = int(std::floor(x / 10)) % 2 != 0;
        EXPECT_EQ(surfaceColorAt(surface, box, {x, 10, 5}, {0, 1, 0}, 1e-3f),
                  odd ? surface.checkerColor : surface.color)
            << x;
    }
    EXPECT_EQ(cellParity(1e30f), 0.0f);   // huge coordinates stay defined
    EXPECT_EQ(cellParity(-3.5f), 0.0f);   // cell -4
    EXPECT_EQ(cellParity(-0.25f), 1.0f);  // cell -1
}

TEST(CheckerRender, AFloorSeenFromAboveShowsTheCells) {
    // Looking straight down (rx 90) at a floor whose top is y = 0, cells of 20:
    // ambient light only, so each pixel is exactly its cell's colour.
    const SceneDesc scene = test::sceneFromText(
        "/camera 40 40 0.5 0 100 0 90 0 0\n/amb_light 1\n"
        "/box floor 400 20 400 0 -10 0\n/paint floor 200 100 50\n/checker floor 10 20 250 20\n");
    const Image image = render(scene);
    // Pixel (i, j) sees world x = (i + 0.5 - 20) * 5 and z = (20 - j - 0.5) * 5 (100 below the eye, 90
    // degrees).
    for (int j = 0; j < 40; j += 3)
        for (int i = 0; i < 40; i += 3) {
            const double x = (i + 0.5 - 20) * 5, z = (20 - (j + 0.5)) * 5;
            // The top face is local y = 10 (cell 0).
            const bool odd = (int(std::floor(x / 20)) + int(std::floor(z / 20))) % 2 != 0;
            const Rgb8 want = odd ? Rgb8{10, 20, 250} : Rgb8{200, 100, 50};
            ASSERT_EQ(image.at(i, j), want) << i << "," << j;
        }
}

// Reflection

TEST(MirrorRender, AMirrorAddsItsShareOfWhatItSees) {
    // A black mirror square to the eye: it sees the background straight back
    // (its mirrored ray passes the eye and escapes): colour = 0 + r * background.
    const SceneDesc scene = test::sceneFromText(
        "/camera 20 20 0.5\n/background 200 100 40\n/amb_light 1\n"
        "/box m 1000 1000 10 0 0 100\n/paint m 0 0 0\n/material m 1 1 0.3 32 0.5\n");
    const Image image = render(scene);
    EXPECT_EQ(image.at(10, 10),
              (Rgb8{byte(0.5 * 200 / 255.0), byte(0.5 * 100 / 255.0), byte(0.5 * 40 / 255.0)}));
}

TEST(MirrorRender, RaysAreReflectedToTheFifthTraceLevel) {
    // The eye between two parallel mirrors that face each other, each lit by
    // ambient only (colour L = 0.2) with reflection r = 0.5: the centre ray
    // bounces between them, and levels 1..5 add up to L (1 + r + r^2 + r^3 + r^4).
    const SceneDesc scene = test::sceneFromText(
        "/camera 21 21 0.5\n/background 255 255 255\n/amb_light 0.2\n"
        "/box front 1000 1000 10 0 0 100\n/box back 1000 1000 10 0 0 -100\n"
        "/paint front 255 255 255\n/paint back 255 255 255\n"
        "/material front 1 0 0 1 0.5\n/material back 1 0 0 1 0.5\n");
    const double levels = 0.2 * (1 + 0.5 + 0.25 + 0.125 + 0.0625);
    ASSERT_EQ(kMaxTraceLevel, 5);
    const Rgb8 centre = render(scene).at(10, 10);
    EXPECT_EQ(centre.r, byte(levels));
    EXPECT_NE(centre.r, byte(levels + 0.2 * 0.03125));  // a sixth level would show
}

// Packet path, threads

constexpr const char* kSurfaces =
    "/camera 203 149 0.7 30 120 -380 14 -4 0\n/background 30 40 60\n/amb_light 0.25\n"
    "/dir_light 0.7 0.5 -1 0.6\n/dir_light 0.3 -1 -0.4 0.2\n"
    "/box floor 1200 40 1200 0 -120 200 0 10 0\n/paint floor 220 220 210\n/checker floor 40 60 90 60\n"
    "/sphere mirror 60 -60 -40 200\n/paint mirror 30 30 30\n/material mirror 1 0.2 0 1 0.85\n"
    "/box wall 40 160 200 120 -20 180 10 -25 5\n/material wall 1 0.8 0 1 0.5\n/checker wall 250 220 60 25\n"
    "/robot f2 -150 0 320 0 150 0\n/checker f2.body 20 20 20 15\n/material f2.head 1 1 0 1 0.3\n"
    "/cylinder c 20 80 60 -60 60 20 0 40\n/material c 1 1 0 1 1\n";

TEST(SurfacePacketPath, IdenticalToTheReferenceWithCheckersAndMirrors) {
    SceneDesc scene = test::sceneFromText(kSurfaces);
    expectPacketPathIdentical(scene, "checkers and mirrors");
    // Inside a mirror sphere: every ray is reflected to the last level.
    expectPacketPathIdentical(test::sceneFromText("/camera 64 48 0.5\n/sphere room 500 0 0 0\n"
                                                  "/material room 1 1 0 1 0.9\n/checker room 90 160 220 70\n"
                                                  "/box b 50 50 50 0 0 200 0 45 0\n/material b 1 1 0 1 0.6\n"
                                                  "/amb_light 0.3\n/dir_light 0.7 0.2 -0.5 1\n"),
                              "inside a mirror sphere");
}

TEST(SurfacePacketPath, WithinOneLevelOfTheReferenceWithHighlights) {
    // Specular highlights use the packet path's pow(): within one level (design.md).
    const ParseResult parsed = parseSceneFile(test::sourcePath("tests/cli/data/mirror.f2"));
    ASSERT_TRUE(parsed.scene) << test::formatDiagnostics(parsed);
    const SceneDesc& scene = *parsed.scene;
    Renderer renderer(2);
    Image fast, reference;
    const Camera camera = Camera::fromDesc(scene.camera);
    renderer.render(scene, 0, camera, fast);
    traceReference(renderer.frame(), camera, reference);
    int worst = 0;
    for (std::size_t i = 0; i < fast.pixels.size(); ++i) {
        const Rgb8 a = fast.pixels[i], b = reference.pixels[i];
        worst = std::max({worst, std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
    }
    EXPECT_LE(worst, 1);
}

TEST(SurfaceRender, IdenticalForAnyThreadCountAndCountsMirroredRays) {
    const SceneDesc scene = test::sceneFromText(kSurfaces);
    const Image one = render(scene, 1);
    EXPECT_TRUE(one == render(scene, 2));
    EXPECT_TRUE(one == render(scene, 5));
    Renderer renderer(2);
    Image image;
    const FrameTimings timings = renderer.render(scene, 0, Camera::fromDesc(scene.camera), image);
    EXPECT_GT(timings.rays.reflected, 0u);
    EXPECT_EQ(timings.rays.total(), timings.rays.primary + timings.rays.shadow + timings.rays.reflected);
}

TEST(SurfaceRender, AScenePaintedWithoutTheNewCommandsCastsNoMirroredRays) {
    Renderer renderer(2);
    Image image;
    const SceneDesc scene = test::sceneFromRepo("seed_example.f2");
    EXPECT_EQ(renderer.render(scene, 10, Camera::fromDesc(scene.camera), image).rays.reflected, 0u);
}

TEST(SurfacePixelReport, TellsTheCheckerCellAndTheMirrorsShare) {
    const SceneDesc scene = test::sceneFromText(kSurfaces);
    Renderer renderer(1);
    Image image;
    const Camera camera = Camera::fromDesc(scene.camera);
    renderer.render(scene, 0, camera, image);
    int mirrors = 0, second = 0;
    for (int j = 0; j < camera.height; j += 7)
        for (int i = 0; i < camera.width; i += 7) {
            const PixelReport r = tracePixel(renderer.frame(), camera, i, j);
            // The story ends on the image's own pixel (within pow()'s rounding in highlights).
            const Rgb8 p = image.at(i, j);
            ASSERT_LE(
                std::max({std::abs(r.pixel.r - p.r), std::abs(r.pixel.g - p.g), std::abs(r.pixel.b - p.b)}),
                1)
                << i << "," << j;
            if (!r.hit) continue;
            const Surface& surface = renderer.frame().surfaces[r.chosen.primitive];
            if (r.material.reflection > 0 && !(r.color == r.ownColor)) ++mirrors;
            if (surface.checkerSize > 0 && r.surfaceColor == surface.checkerColor) ++second;
        }
    EXPECT_GT(mirrors, 10);
    EXPECT_GT(second, 10);
}

// Export

TEST(SurfacePovExport, WritesTheCheckerBeforeTheMatrixAndTheReflection) {
    const SceneDesc scene = test::sceneFromText(
        "/box floor 100 10 100 0 0 0\n/paint floor 1 2 3\n/checker floor 4 5 6 25\n"
        "/sphere m 10 0 50 0\n/material m 1 1 0.3 32 0.5\n/robot r 0 0 200\n/checker r.head 7 8 9 5\n");
    const std::string pov = povScene(scene, 0, Camera::fromDesc(scene.camera), "t.f2");
    EXPECT_NE(pov.find("pigment { checker rgb <1, 2, 3> / 255, rgb <4, 5, 6> / 255 scale 25 }\n  matrix"),
              std::string::npos)
        << pov;
    EXPECT_NE(pov.find("phong_size 32 reflection 0.5 }"), std::string::npos);
    EXPECT_NE(pov.find("max_trace_level 5 adc_bailout 0"), std::string::npos);
    EXPECT_NE(pov.find("checker rgb <200, 200, 200> / 255, rgb <7, 8, 9> / 255 scale 5"), std::string::npos);
    // The eyes keep their own plain colour; only the mirror reflects.
    EXPECT_NE(pov.find("// r.head.leye\nsphere { <0, 0, 0>, 6\n  pigment { rgb <20, 20, 20> / 255 }"),
              std::string::npos);
    std::size_t reflections = 0;
    for (std::size_t at = pov.find(" reflection "); at != std::string::npos;
         at = pov.find(" reflection ", at + 1))
        ++reflections;
    EXPECT_EQ(reflections, 1u);
}

}  // namespace
}  // namespace f2
