// Degenerate geometry through the public API: parse a scene text, render it
// small, and check that no sample is NaN or infinite and that flat-lit faces
// have no speckles (no isolated pixel differing from all four neighbours, and
// a uniformly lit face is uniform).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/render/camera.h"
#include "core/render/renderer.h"
#include "test_scenes.h"

namespace f2 {
namespace {

constexpr int kW = 64, kH = 48;

struct Rendered {
    Image image;
    int nonFinite = 0;
};

/// Renders `text` at 64x48 (the scene's own view) with `threads`, and counts
/// non-finite samples of the reference path renderSample at every pixel centre.
Rendered render(const std::string& text, int threads = 1, double t = 0) {
    const SceneDesc scene = test::sceneFromText(text);
    Renderer renderer(threads);
    const Camera camera = Camera::fromDesc(scene.camera).resized(kW, kH);
    Rendered r;
    renderer.render(scene, t, camera, r.image);
    for (int j = 0; j < kH; ++j)
        for (int i = 0; i < kW; ++i) {
            const Vec3 c = renderSample(renderer.frame(), camera, float(i) + 0.5f, float(j) + 0.5f);
            r.nonFinite += !(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
        }
    if (const char* dir = std::getenv("F2_DEGENERATE_DUMP")) {
        // Debugging aid: F2_DEGENERATE_DUMP=/tmp writes every image as a PPM.
        static int counter = 0;
        const std::string path = std::string(dir) + "/degenerate_" + std::to_string(counter++) + ".ppm";
        if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
            std::fprintf(f, "P6 %d %d 255\n", kW, kH);
            std::fwrite(r.image.pixels.data(), 3, r.image.pixels.size(), f);
            std::fclose(f);
            std::printf("%s: %s\n", path.c_str(), text.c_str());
        }
    }
    return r;
}

bool same(Rgb8 a, Rgb8 b) { return a == b; }

int luma(Rgb8 p) { return p.r + p.g + p.b; }

/// Isolated pixels inside [x0,x1)x[y0,y1) (1 pixel in from the image border):
/// brighter than all four neighbours, or darker than all four, by more than
/// `tolerance` (in r+g+b). A smooth gradient, even a steep one, has none; a
/// smooth highlight's peak differs from its neighbours by a few units only.
int speckles(const Image& im, int x0, int y0, int x1, int y1, int tolerance = 6) {
    int n = 0;
    for (int y = std::max(y0, 1); y < std::min(y1, im.height - 1); ++y)
        for (int x = std::max(x0, 1); x < std::min(x1, im.width - 1); ++x) {
            const int p = luma(im.at(x, y));
            const int nb[4] = {luma(im.at(x - 1, y)), luma(im.at(x + 1, y)), luma(im.at(x, y - 1)),
                               luma(im.at(x, y + 1))};
            bool above = true, below = true;
            for (int q : nb) {
                above = above && p > q + tolerance;
                below = below && p < q - tolerance;
            }
            n += above || below;
        }
    return n;
}

/// Number of pixels in the rectangle that are not exactly `value`.
int notEqual(const Image& im, int x0, int y0, int x1, int y1, Rgb8 value) {
    int n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) n += !same(im.at(x, y), value);
    return n;
}

std::string describe(Rgb8 p) {
    return std::to_string(p.r) + " " + std::to_string(p.g) + " " + std::to_string(p.b);
}

// byte(C * ka * ambient) for C = 100/255, ka = 1, ambient 0.5: floor(255 * 0.196 + 0.5) = 50.
constexpr Rgb8 kAmbientOnly{50, 50, 50};

// Camera inside a closed object: it sees the inside, no NaN, no speckles.
// The inside of each shape is flat-lit (no specular), so no pixel may stand
// out from all four neighbours.
constexpr const char* kInsideShapes[] = {
    "/sphere o 10 0 0 0",          "/box o 20 20 20 0 0 0",          "/box o 20 20 20 0 0 0 30 40 50",
    "/cylinder o 10 20 0 0 0",     "/cylinder o 10 20 0 0 0 90 0 0",
    "/sphere o 10 0 0 9.99",        // the eye very near the surface
    "/cylinder o 1e6 1e6 5e5 0 0",  // huge, the eye far from its axis
};

std::string insideScene(const char* shape) {
    return std::string("/camera 64 48 0.5\n") + shape +
           "\n/paint o 100 100 100\n/material o 1 1 0 1\n/amb_light 0.5\n/dir_light 1 0.3 -1 0.7\n";
}

TEST(Degenerate, CameraInsideASphereBoxOrCylinderIsFiniteAndSmooth) {
    for (const char* shape : kInsideShapes) {
        for (int threads : {1, 2}) {
            SCOPED_TRACE(std::string(shape) + " threads " + std::to_string(threads));
            const Rendered r = render(insideScene(shape), threads);
            EXPECT_EQ(r.nonFinite, 0);
            EXPECT_EQ(speckles(r.image, 0, 0, kW, kH), 0);
        }
    }
}

// Regression for core finding F2 (docs/robustness.md; fixed in 3d8ca4f).
// SPEC 3: s_j = 0 if a shadow ray from the hit point toward the light hits any
// object. From inside a closed sphere, box or cylinder the shadow ray always
// hits the object itself, so the inside is lit by ambient light only: one
// uniform colour. After fd01a06 shadeHit() skipped the hit primitive in every
// shadow ray, so the inside was lit by the directional light (a gradient).
// Input: kInsideShapes + insideScene() above, e.g.
//   /camera 64 48 0.5 / /sphere o 10 0 0 0 / /paint o 100 100 100 /
//   /material o 1 1 0 1 / /amb_light 0.5 / /dir_light 1 0.3 -1 0.7
TEST(Degenerate, CameraInsideAClosedObjectSeesOnlyAmbientLight) {
    for (const char* shape : kInsideShapes) {
        SCOPED_TRACE(shape);
        const Rendered r = render(insideScene(shape));
        EXPECT_EQ(notEqual(r.image, 0, 0, kW, kH, kAmbientOnly), 0)
            << "centre pixel " << describe(r.image.at(kW / 2, kH / 2)) << ", expected "
            << describe(kAmbientOnly);
    }
}

// Rays exactly along a surface: the centre row of pixels runs in the plane of a
// box face, along a box edge, or along a cylinder's side line.
TEST(Degenerate, RaysAlongAFaceAnEdgeOrACylinderSide) {
    // Eye at the origin; pixel centres with x = 0 do not exist at even widths,
    // so the camera is moved to put a face or edge exactly in the eye's planes.
    const char* scenes[] = {
        // Box face in the plane x = 0 (box from x = 0 to 2), eye in that plane.
        "/box o 2 2 2 1 0 10",
        // Box edge on the line x = 0, y = 0: every ray with y = 0 (none at even
        // heights) and the eye itself lie on the face planes.
        "/box o 2 2 2 1 1 10",
        // Cylinder, axis along z, touching the line x = 0, y = 0 along its side.
        "/cylinder o 1 4 1 0 10 90 0 0",
        // Cylinder, axis along y, its side line x = 0, z = 10 seen edge-on.
        "/cylinder o 1 4 1 0 11",
        // Looking straight down a cylinder's axis and along a box's edge at once.
        "/cylinder o 1 4 0 0 10 90 0 0\n/box p 1 1 1 0.5 0.5 20",
    };
    for (const char* shape : scenes) {
        SCOPED_TRACE(shape);
        const Rendered r = render(std::string("/camera 64 48 0.5\n") + shape +
                                  "\n/material o 1 1 0 1\n/amb_light 0.3\n/dir_light 0.7 0.2 -0.5 1\n");
        EXPECT_EQ(r.nonFinite, 0);
        EXPECT_EQ(speckles(r.image, 0, 0, kW, kH), 0);
    }
    // And the exact rays: a sample taken with a direction exactly on the face plane.
    const SceneDesc scene = test::sceneFromText("/camera 2 2 0.5\n/box o 2 2 2 1 1 10\n/amb_light 1\n");
    Renderer renderer(1);
    Image image;
    const Camera camera = Camera::fromDesc(scene.camera);
    renderer.render(scene, 0, camera, image);
    for (float px : {0.0f, 0.5f, 1.0f, 1.5f, 2.0f})
        for (float py : {0.0f, 0.5f, 1.0f, 1.5f, 2.0f}) {
            const Vec3 c = renderSample(renderer.frame(), camera, px, py);  // (1, 1) is x = y = 0 exactly
            EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z)) << px << "," << py;
        }
}

// Objects near, touching or cutting through the eye (the rays' origin; the
// screen plane has no position in the world, only the eye has).
TEST(Degenerate, ObjectsNearOrCuttingTheEye) {
    const char* scenes[] = {
        // A wall 1e-3 in front of the eye, filling the view.
        "/box o 40 40 2 0 0 1.001",
        // A sphere whose surface passes 1e-3 in front of the eye.
        "/sphere o 1 0 0 1.001",
        // A box around the eye, cut open by nothing: the eye is well inside it.
        "/box o 1 1 1 0.3 0 0.2",
        // A thin box lying in the eye's horizontal plane, seen edge-on.
        "/box o 10 1e-3 10 0 0 5",
    };
    for (const char* shape : scenes) {
        for (int threads : {1, 2}) {
            SCOPED_TRACE(std::string(shape) + " threads " + std::to_string(threads));
            const Rendered r =
                render(std::string("/camera 64 48 0.5\n") + shape +
                           "\n/material o 1 1 0 1\n/amb_light 0.3\n/dir_light 0.7 0.1 -0.2 1\n",
                       threads);
            EXPECT_EQ(r.nonFinite, 0);
            EXPECT_EQ(speckles(r.image, 0, 0, kW, kH), 0);
        }
    }
}

// Regression for core finding F3 (docs/robustness.md; fixed in 3d8ca4f). The
// eye exactly on a surface: every primary ray starts on the object, and
// whether the root t ~ 0 counted as a hit (tMin = 0) depended on rounding, so
// the image was salt-and-pepper noise (~230 isolated pixels for the sphere).
// Input: /camera 64 48 0.5 / /sphere o 1 0 0 1 / /material o 1 1 0 1 /
//        /amb_light 0.3 / /dir_light 0.7 0.1 -0.2 1
TEST(Degenerate, SurfaceThroughTheEyeHasNoSpeckles) {
    const char* scenes[] = {
        "/sphere o 1 0 0 1",       // the eye on the sphere
        "/box o 40 40 2 0 0 1",    // the eye on the front face
        "/box o 1 1 1 0.3 0 0.5",  // the eye on a face of a small box
    };
    for (const char* shape : scenes) {
        SCOPED_TRACE(shape);
        const Rendered r = render(std::string("/camera 64 48 0.5\n") + shape +
                                  "\n/material o 1 1 0 1\n/amb_light 0.3\n/dir_light 0.7 0.1 -0.2 1\n");
        EXPECT_EQ(r.nonFinite, 0);
        EXPECT_EQ(speckles(r.image, 0, 0, kW, kH), 0);
    }
}

// A face seen head-on, lit only by ambient and a light parallel to it: N.L = 0,
// so the face is exactly ambient everywhere, whatever rounding the rotation has.
TEST(Degenerate, LightParallelToAFaceLeavesItUniform) {
    struct Case {
        const char* box;
        const char* light;
    };
    const Case cases[] = {
        {"/box o 40 30 1 0 0 50", "/dir_light 1 1 0 0"},           // light along +x, face normal -z
        {"/box o 40 30 1 0 0 50", "/dir_light 1 0 1 0"},           // along +y
        {"/box o 40 30 1 0 0 50 0 0 30", "/dir_light 1 1 1 0"},    // rotated in its plane
        {"/box o 40 30 1 0 0 50 0 0 30", "/dir_light 1 -1 -1 0"},  // the other way
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(std::string(c.box) + " " + c.light);
        const Rendered r = render(std::string("/camera 64 48 2\n") + c.box +
                                  "\n/paint o 100 100 100\n/amb_light 0.5\n" + c.light + "\n");
        EXPECT_EQ(r.nonFinite, 0);
        // The face covers the whole view: d = 2 sees 49.5 / 2 = 24.75 wide at the face.
        EXPECT_EQ(notEqual(r.image, 0, 0, kW, kH, kAmbientOnly), 0) << describe(r.image.at(kW / 2, kH / 2));
    }
}

// A face lit head-on with no specular is one colour: ka*amb + kd*(N.L), the same
// at every pixel; and a Phong-lit sphere has no isolated pixels.
TEST(Degenerate, FlatLitFacesAreUniformAndCurvedOnesSmooth) {
    const Rendered face = render(
        "/camera 64 48 2\n/box o 40 30 1 0 0 50\n/paint o 100 100 100\n/material o 1 1 0 1\n"
        "/amb_light 0.25\n/dir_light 0.5 0 0 1\n",
        2);
    EXPECT_EQ(face.nonFinite, 0);
    // 100/255 * (0.25 + 0.5) * 255 = 75.
    EXPECT_EQ(notEqual(face.image, 0, 0, kW, kH, Rgb8{75, 75, 75}), 0) << describe(face.image.at(0, 0));

    const Rendered sphere = render(
        "/camera 64 48 0.5\n/sphere s 30 0 0 60\n/material s 1 1 0 1\n/amb_light 0.2\n"
        "/dir_light 0.6 0.3 -0.4 1\n",
        2);
    EXPECT_EQ(sphere.nonFinite, 0);
    EXPECT_EQ(speckles(sphere.image, 0, 0, kW, kH), 0);
}

// Tiny (1e-3) and huge (1e6) objects, near and far: finite, no speckles, no
// self-shadowing acne on a huge floor lit at a slant.
TEST(Degenerate, TinyAndHugeObjects) {
    {
        // A 1e-3 sphere filling most of the view from 3e-3 away.
        const Rendered r = render(
            "/camera 64 48 0.5\n/sphere s 1e-3 0 0 3e-3\n/paint s 100 100 100\n/material s 1 1 0 "
            "1\n/amb_light 0.3\n"
            "/dir_light 0.7 0 0 1\n");
        EXPECT_EQ(r.nonFinite, 0);
        EXPECT_EQ(speckles(r.image, 0, 0, kW, kH), 0);
        EXPECT_NE(r.image.at(kW / 2, kH / 2), (Rgb8{0, 0, 0}));  // it is seen
    }
    {
        // A 1e-3 box far away: smaller than a pixel, nothing breaks.
        const Rendered r = render("/camera 64 48 0.5\n/box b 1e-3 1e-3 1e-3 0 0 1e3\n/amb_light 1\n");
        EXPECT_EQ(r.nonFinite, 0);
    }
    {
        // A 1e6 floor under the eye, lit at a slant: a flat face, uniform in
        // colour (no acne from the shadow ray starting on or under the surface).
        const Rendered r = render(
            "/camera 64 48 0.5 0 100 0 20 0 0\n/box floor 1e6 10 1e6 0 -5 0\n/paint floor 100 100 100\n"
            "/material floor 1 1 0 1\n/amb_light 0.2\n/dir_light 0.6 0.5 -1 0.3\n");
        EXPECT_EQ(r.nonFinite, 0);
        // The lower half of the image sees only the floor: one colour.
        const Rgb8 ref = r.image.at(kW / 2, kH - 2);
        EXPECT_EQ(notEqual(r.image, 0, kH / 2 + 2, kW, kH, ref), 0) << describe(ref);
        EXPECT_EQ(speckles(r.image, 0, 0, kW, kH), 0);
    }
    {
        // A 1e6 sphere seen from near its surface: locally a flat wall, smooth.
        const Rendered r = render(
            "/camera 64 48 0.5\n/sphere s 1e6 0 0 1000010\n/paint s 100 100 100\n/material s 1 1 0 1\n"
            "/amb_light 0.2\n/dir_light 0.6 0 0 1\n");
        EXPECT_EQ(r.nonFinite, 0);
        EXPECT_EQ(speckles(r.image, 0, 0, kW, kH), 0);
    }
}

// Threads change nothing, even in these scenes.
// Regression (issue 13.10): a material and light at the float limit made
// 0 * inf = NaN (a black channel times an infinite diffuse sum, an infinite
// ks * intensity times a highlight that underflows to 0): the pixel went black
// instead of saturating.
TEST(Degenerate, HugeMaterialsSaturateInsteadOfTurningBlack) {
    const std::string view = "/camera 64 48 0.5 0 0 -100\n/background 10 20 30\n/sphere s 60 0 0 0\n";
    // Black paint, ka * ambient = inf: only the highlight (n tiny: everywhere lit, pow = 1) remains.
    Rendered black =
        render(view + "/paint s 0 0 0\n/material s 3e38 1 1 1e-30\n/amb_light 10\n/dir_light 1 0 0 1\n");
    EXPECT_EQ(black.nonFinite, 0);
    EXPECT_EQ(describe(black.image.at(kW / 2, kH / 2)), "255 255 255");
    // ks * intensity = inf, n huge: pow() underflows off the highlight's centre.
    Rendered white = render(view +
                            "/paint s 255 255 255\n/material s 1 1 3e38 3e38\n/amb_light 0.5\n"
                            "/dir_light 3e38 0 0 1\n");
    EXPECT_EQ(white.nonFinite, 0);
    EXPECT_EQ(notEqual(white.image, kW / 2 - 8, kH / 2 - 8, kW / 2 + 8, kH / 2 + 8, Rgb8{255, 255, 255}), 0);
}

TEST(Degenerate, OneAndTwoThreadsGiveTheSameImage) {
    const std::string text =
        "/camera 64 48 0.5\n/box o 2 2 2 1 1 10\n/cylinder c 1 4 1 0 10 90 0 0\n/sphere s 1 0 0 1\n"
        "/amb_light 0.3\n/dir_light 0.7 0.2 -0.5 1\n";
    EXPECT_TRUE(render(text, 1).image == render(text, 2).image);
}

}  // namespace
}  // namespace f2
