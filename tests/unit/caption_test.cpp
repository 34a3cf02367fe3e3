// Captions (SPEC 10.5): what /caption reads and where each error points, and
// how the text lands in the picture: only while shown, only in the shaded
// view, its ink exact where a glyph covers a pixel, the same bytes for any
// thread count, and blurred frames' captions sharp.
#include <gtest/gtest.h>

#include <string>

#include "core/render/camera.h"
#include "core/render/captions.h"
#include "core/render/motion_blur.h"
#include "core/render/renderer.h"
#include "test_scenes.h"

namespace f2 {
namespace {

using test::expectOnlyError;
using test::sceneFromText;

// A flat background and nothing else: every pixel a caption does not touch is 10 20 30.
const std::string kEmpty = "/camera 160 90 0.5\n/background 10 20 30\n";
// U+2588 FULL BLOCK: a glyph that covers its middle completely.
const std::string kBlock = "\xE2\x96\x88";

Image rendered(const SceneDesc& scene, double t, ViewMode view = ViewMode::Shaded, int threads = 2) {
    Renderer renderer(threads);
    Image image;
    RenderOptions options;
    options.view = view;
    renderer.render(scene, t, cameraAt(scene, t), image, options);
    return image;
}

TEST(CaptionParse, TimesPlaceSizeTextAndColour) {
    // 1 s at 10 fps is frame 10, (n)s with n = 3 is frame 30; escapes undone, braces expanded, '#' kept.
    const SceneDesc s = sceneFromText(
        kEmpty +
        "/let n 3\n/fps 10\n/caption 1s (n)s 0.1 0.5 0.25 \"a \\\"b\\\" \\\\ {n} # c\" colour 1 2 3\n"
        "/caption 2.5 4 0 1 1 \"\"\n");
    ASSERT_EQ(s.captions.size(), 2u);
    const Caption& c = s.captions[0];
    EXPECT_EQ(c.from, 10.0);
    EXPECT_EQ(c.to, 30.0);
    EXPECT_FLOAT_EQ(c.x, 0.1f);
    EXPECT_FLOAT_EQ(c.y, 0.5f);
    EXPECT_FLOAT_EQ(c.size, 0.25f);
    EXPECT_EQ(c.text, "a \"b\" \\ 3 # c");
    EXPECT_EQ(c.colour, (Color8{1, 2, 3}));
    EXPECT_EQ(s.captions[1].colour, (Color8{255, 255, 255}));  // white without `colour`
    EXPECT_EQ(s.captions[1].text, "");
    EXPECT_EQ(s.lastFrame(), 30);  // a caption's times are key times
    EXPECT_TRUE(c.shownAt(10) && c.shownAt(29.99) && !c.shownAt(9.99) && !c.shownAt(30));
    // Other backslashes stay as written; non-ASCII text passes through.
    EXPECT_EQ(sceneFromText(kEmpty + "/caption 0 1 0 0 0.1 \"C:\\scenes \xC3\x84\"\n").captions[0].text,
              "C:\\scenes \xC3\x84");
}

TEST(CaptionParse, EveryErrorAtItsPlace) {
    expectOnlyError(kEmpty + "/caption 0 1 0 0 0.1\n", 3, 1, "'/caption' takes 6 or 10 arguments");
    expectOnlyError(kEmpty + "/caption 0 1 0 0 0.1 \"a\" colour 1 2\n", 3, 1, "got 9");
    expectOnlyError(kEmpty + "/caption 0 1 0 0 0 \"a\"\n", 3, 18, "caption size must be > 0, got 0");
    expectOnlyError(kEmpty + "/caption 0 1 0 0 2 \"a\"\n", 3, 18,
                    "caption size is a fraction of the image height, at most 1, got 2");
    expectOnlyError(kEmpty + "/caption 0 1 0 0 0.1 a\n", 3, 22, "expected a text in double quotes, got 'a'");
    expectOnlyError(kEmpty + "/caption 0 1 0 0 0.1 \"abc # d\n", 3, 22, "this '\"' has no closing '\"'");
    expectOnlyError(kEmpty + "/caption 0 1 0 0 0.1 \"ab\"c\n", 3, 26,
                    "unexpected text after the closing '\"'");
    expectOnlyError(kEmpty + "/caption 0 1 0 0 0.1 \"a\xFF\"\n", 3, 24, "the text is not valid UTF-8 here");
    expectOnlyError(kEmpty + "/caption 0 1 0 0 0.1 \"a\" color 1 2 3\n", 3, 26,
                    "expected 'colour' after the caption's text, got 'color'");
    expectOnlyError(kEmpty + "/caption 0 1 0 0 0.1 \"a\" colour 1 2 300\n", 3, 37,
                    "blue must be a whole number");
    expectOnlyError(kEmpty + "/caption -1 1 0 0 0.1 \"a\"\n", 3, 10, "a key time must be >= 0, got -1");
    expectOnlyError(kEmpty + "/caption 5 3 0 0 0.1 \"a\"\n", 3, 12,
                    "a caption must end after it starts: it starts at frame 5 and ends at frame 3");
    // Seconds become frames at /fps wherever it stands: 2 s at 20 fps is frame 40, after 30.
    expectOnlyError(kEmpty + "/caption 2s 30 0 0 0.1 \"a\"\n/fps 20\n", 3, 13,
                    "it starts at frame 40 and ends at frame 30");
}

TEST(CaptionDraw, ShownFromItsStartUntilItsEnd) {
    const SceneDesc plain = sceneFromText(kEmpty + "/key 20 camera\n");
    const SceneDesc captioned = sceneFromText(kEmpty + "/key 20 camera\n/caption 5 10 0.1 0.6 0.4 \"F-2\"\n");
    const Image background = rendered(plain, 0);
    EXPECT_TRUE(rendered(captioned, 4.99) == background);
    EXPECT_FALSE(rendered(captioned, 5) == background);
    EXPECT_FALSE(rendered(captioned, 9.99) == background);
    EXPECT_TRUE(rendered(captioned, 10) == background);
}

TEST(CaptionDraw, InkExactWhereTheGlyphCoversAndNothingOutsideItsBox) {
    // The block's em is 0.5 · 90 = 45 px, its baseline at y = 54, its pen at x = 40.
    const SceneDesc s =
        sceneFromText(kEmpty + "/caption 0 1 0.25 0.6 0.5 \"" + kBlock + "\" colour 250 128 3\n");
    const Image image = rendered(s, 0);
    EXPECT_EQ(image.at(50, 40), (Rgb8{250, 128, 3}));  // inside the block: all ink
    int inked = 0, partly = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const Rgb8 p = image.at(x, y);
            if (p == Rgb8{10, 20, 30}) continue;
            ++inked;
            if (p != Rgb8{250, 128, 3}) ++partly;  // an anti-aliased edge
            EXPECT_GE(x, 39) << y;                 // nothing left of the pen
            EXPECT_LE(x, 40 + 45) << y;            // nor beyond one em to its right
            EXPECT_GE(y, 54 - 45) << x;            // nor above one em over the baseline
        }
    }
    EXPECT_GT(inked, 20 * 30);
    EXPECT_GT(partly, 0);
}

TEST(CaptionDraw, TheSameBytesForAnyThreadCountAndNoneInDiagnosticViews) {
    const std::string scene =
        "/camera 200 120 0.5 0 40 -300\n/amb_light 0.3\n/dir_light 0.8 0.3 -1 0.6\n/robot r 0 0 0 0 180 0\n";
    const SceneDesc plain = sceneFromText(scene);
    const SceneDesc captioned = sceneFromText(scene +
                                              "/caption 0 1 0.05 0.2 0.15 \"Hello, F-2! \xC3\x84\xCE\xA9\"\n"
                                              "/caption 0 1 0.5 0.95 0.1 \"second\" colour 255 200 0\n");
    const Image one = rendered(captioned, 0, ViewMode::Shaded, 1);
    EXPECT_TRUE(rendered(captioned, 0, ViewMode::Shaded, 2) == one);
    EXPECT_TRUE(rendered(captioned, 0, ViewMode::Shaded, 3) == one);
    EXPECT_FALSE(rendered(plain, 0) == one);
    for (ViewMode view : {ViewMode::Normals, ViewMode::Depth, ViewMode::Cost}) {
        EXPECT_TRUE(rendered(captioned, 0, view) == rendered(plain, 0, view));
    }
}

TEST(CaptionDraw, ABlurredFrameHasItsCaptionSharp) {
    const std::string moving = kEmpty + "/sphere b 10 -40 0 60\n/key 0 b\n/key 10 b 40 0 60 0 0 0\n";
    const SceneDesc s =
        sceneFromText(moving + "/caption 0 10 0.25 0.6 0.5 \"" + kBlock + "\" colour 250 128 3\n");
    const MotionBlur blur{1, 4};
    Renderer renderer(2);
    Image image;
    renderer.renderAveraged(s, 5, blur.subFrames(s, FrameView::sceneCamera(160, 90), 5, 1), image);
    EXPECT_EQ(image.at(50, 40), (Rgb8{250, 128, 3}));
}

TEST(CaptionDraw, CaptionsOffThePictureOrLargerThanItDrawSafely) {
    Image image;
    image.resize(64, 48);
    const Rgb8 ink{255, 255, 255};
    std::string longText(100000, 'W');
    // Far left, far right, above, a glyph as tall as the picture, a very long line.
    for (const Caption& c : {Caption{0, 1, -5, 0.5f, 1, longText}, Caption{0, 1, 2, 0.5f, 0.5f, "abc"},
                             Caption{0, 1, 0, -1, 0.5f, "abc"}, Caption{0, 1, -0.2f, 1.1f, 1, kBlock},
                             Caption{0, 1, 0, 0.5f, 0.01f, longText}}) {
        drawCaption(image, c);
    }
    int white = 0;
    for (const Rgb8& p : image.pixels) white += p == ink;
    EXPECT_GT(white, 0);  // the tall block and the long lines reach the picture
    Image empty;
    drawCaption(empty, Caption{0, 1, 0, 0.5f, 0.5f, "abc"});  // no pixels: nothing to do
    EXPECT_TRUE(empty.pixels.empty());
}

}  // namespace
}  // namespace f2
