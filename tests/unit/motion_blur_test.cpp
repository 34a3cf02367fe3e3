// Motion blur: sub-frame times, the mean of sub-frames, determinism.
#include "core/render/motion_blur.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include "core/render/renderer.h"
#include "io/render_animation.h"
#include "test_scenes.h"

namespace f2 {
namespace {

// A ball crossing the picture left to right over frames 0..10, over a floor,
// and a camera dollying sideways: both blur.
constexpr const char* kMovingScene = R"(/camera 96 72 0.6 0 2 -12
/background 20 30 40
/amb_light 0.3
/dir_light 0.8 0.3 -0.5 1
/box floor 40 1 40 0 -2 10
/sphere ball 1.5 -4 0 8
/paint ball 230 120 40
/key 0 ball
/key 10 ball 4 0 8 0 0 0
/key 0 camera
/key 10 camera 1 2 -12 0 0 0
)";

// Nothing moves.
constexpr const char* kStillScene = R"(/camera 96 72 0.6 0 2 -12
/background 20 30 40
/amb_light 0.3
/dir_light 0.8 0.3 -0.5 1
/box floor 40 1 40 0 -2 10
/sphere ball 1.5 0 0 8
)";

int channelDiff(Rgb8 a, Rgb8 b) {
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

Image blurred(const SceneDesc& scene, double t, MotionBlur blur, int threads, int aa = 1) {
    Renderer renderer(threads);
    Image image;
    const FrameView view = FrameView::sceneCamera(96, 72);
    EXPECT_TRUE(renderer.renderAveraged(scene, t, blur.subFrames(scene, view, t, 1.0), image, {aa}).complete);
    return image;
}

TEST(MotionBlur, SubFramesSliceTheShutterCentredOnTheFrame) {
    const MotionBlur blur{0.5, 4};
    // Centres of 4 slices of [t - 0.25, t + 0.25] frames.
    EXPECT_DOUBLE_EQ(blur.subFrameTime(10, 1, 0), 10 - 0.1875);
    EXPECT_DOUBLE_EQ(blur.subFrameTime(10, 1, 1), 10 - 0.0625);
    EXPECT_DOUBLE_EQ(blur.subFrameTime(10, 1, 2), 10 + 0.0625);
    EXPECT_DOUBLE_EQ(blur.subFrameTime(10, 1, 3), 10 + 0.1875);
    // An output frame of 0.4 scene frames (24 fps scene at 60 fps): the shutter shrinks with it.
    EXPECT_DOUBLE_EQ(blur.subFrameTime(10, 0.4, 3), 10 + 0.1875 * 0.4);
    // A full shutter reaches the frames' midpoints; one sample is the frame itself.
    EXPECT_DOUBLE_EQ((MotionBlur{1, 2}.subFrameTime(3, 1, 0)), 2.75);
    EXPECT_DOUBLE_EQ((MotionBlur{1, 1}.subFrameTime(3, 1, 0)), 3);
}

TEST(MotionBlur, EachSubFrameIsSeenByTheCameraAtItsTime) {
    const SceneDesc scene = test::sceneFromText(kMovingScene);
    const MotionBlur blur{1, 4};
    const auto subs = blur.subFrames(scene, FrameView::sceneCamera(48, 36), 5, 1);
    ASSERT_EQ(subs.size(), 4u);
    for (const SubFrame& sub : subs) {
        const Camera expected = cameraAt(scene, sub.time);
        EXPECT_EQ(sub.camera.eye, expected.eye) << "time " << sub.time;
        EXPECT_EQ(sub.camera.width, 48);
    }
    EXPECT_NE(subs.front().camera.eye, subs.back().camera.eye);  // the dolly moves during the shutter
    // Off: the frame itself.
    const auto sharp = MotionBlur{}.subFrames(scene, FrameView::sceneCamera(48, 36), 5, 1);
    ASSERT_EQ(sharp.size(), 1u);
    EXPECT_EQ(sharp[0].time, 5);
}

TEST(MotionBlur, OneSubFrameIsTheSharpFrameByteForByte) {
    const SceneDesc scene = test::sceneFromText(kMovingScene);
    for (int aa : {1, 3}) {
        Renderer renderer(2);
        Image sharp;
        renderer.render(scene, 4.5, cameraAt(scene, 4.5).resized(96, 72), sharp, {aa});
        EXPECT_TRUE(blurred(scene, 4.5, {0.5, 1}, 2, aa) == sharp) << "aa " << aa;
    }
}

TEST(MotionBlur, IsTheMeanOfTheSubFramesWithinRounding) {
    const SceneDesc scene = test::sceneFromText(kMovingScene);
    const MotionBlur blur{1, 5};
    const Image image = blurred(scene, 5, blur, 2);
    const FrameView view = FrameView::sceneCamera(96, 72);
    std::vector<Image> subs;
    Renderer renderer(2);
    for (const SubFrame& sub : blur.subFrames(scene, view, 5, 1)) {
        subs.emplace_back();
        renderer.render(scene, sub.time, sub.camera, subs.back());
    }
    int changed = 0;
    for (int y = 0; y < 72; ++y)
        for (int x = 0; x < 96; ++x) {
            // Each 8-bit sub-frame is within half a level of its float value, so their mean is
            // within half a level of the float mean, whose rounding adds another half.
            double mean[3] = {0, 0, 0};
            for (const Image& s : subs) {
                mean[0] += s.at(x, y).r / 5.0;
                mean[1] += s.at(x, y).g / 5.0;
                mean[2] += s.at(x, y).b / 5.0;
            }
            const Rgb8 p = image.at(x, y);
            ASSERT_NEAR(p.r, mean[0], 1.0) << x << "," << y;
            ASSERT_NEAR(p.g, mean[1], 1.0) << x << "," << y;
            ASSERT_NEAR(p.b, mean[2], 1.0) << x << "," << y;
            changed += channelDiff(p, subs[2].at(x, y)) > 2;
        }
    // The middle sub-frame is the sharp frame: the ball's streak and the moved camera differ from it.
    EXPECT_GT(changed, 30);  // 54 when written
}

TEST(MotionBlur, StillSceneStaysSharp) {
    const SceneDesc scene = test::sceneFromText(kStillScene);
    Renderer renderer(1);
    Image sharp;
    renderer.render(scene, 3, cameraAt(scene, 3).resized(96, 72), sharp);
    const Image image = blurred(scene, 3, {1, 7}, 1);
    // The mean of 7 equal floats may round differently by one level, nothing more.
    for (std::size_t i = 0; i < sharp.pixels.size(); ++i)
        ASSERT_LE(channelDiff(image.pixels[i], sharp.pixels[i]), 1) << "pixel " << i;
}

TEST(MotionBlur, SameBytesForAnyThreadCountAndHistory) {
    const SceneDesc scene = test::sceneFromText(kMovingScene);
    const MotionBlur blur{0.75, 6};
    const Image one = blurred(scene, 6.25, blur, 1, 2);
    // A renderer that has shown other frames first (its BVH refitted from them).
    Renderer renderer(3);
    Image image;
    for (double t : {9.0, 0.0, 6.5}) renderer.render(scene, t, cameraAt(scene, t).resized(96, 72), image);
    renderer.renderAveraged(scene, 6.25, blur.subFrames(scene, FrameView::sceneCamera(96, 72), 6.25, 1),
                            image, {2});
    EXPECT_TRUE(image == one);
    EXPECT_TRUE(blurred(scene, 6.25, blur, 2, 2) == one);
}

TEST(MotionBlur, CancelStopsBetweenSubFrames) {
    const SceneDesc scene = test::sceneFromText(kMovingScene);
    const MotionBlur blur{1, 4};
    std::atomic<bool> cancel{false};
    Renderer renderer(1);
    Image image;
    std::vector<int> reported;
    const FrameTimings timings =
        renderer.renderAveraged(scene, 5, blur.subFrames(scene, FrameView::sceneCamera(96, 72), 5, 1), image,
                                {}, &cancel, [&](int done) {
                                    reported.push_back(done);
                                    if (done == 2) cancel = true;
                                });
    EXPECT_FALSE(timings.complete);
    EXPECT_EQ(reported, (std::vector<int>{1, 2}));
}

TEST(MotionBlur, DiagnosticViewShowsTheMiddleSubFrame) {
    const SceneDesc scene = test::sceneFromText(kMovingScene);
    const auto subs = MotionBlur{1, 4}.subFrames(scene, FrameView::sceneCamera(96, 72), 5, 1);
    RenderOptions depth;
    depth.view = ViewMode::Depth;
    Renderer renderer(2);
    Image averaged, middle;
    renderer.renderAveraged(scene, 5, subs, averaged, depth);
    renderer.render(scene, subs[2].time, subs[2].camera, middle, depth);
    EXPECT_TRUE(averaged == middle);
}

/// Collects the frames a renderAnimation writes.
class MemorySink : public FrameSink {
   public:
    bool begin(const FrameFormat&, std::string&) override { return true; }
    bool write(const Image& image, std::int64_t, std::string&, const std::atomic<bool>*) override {
        frames.push_back(image);
        return true;
    }
    bool finish(std::string&, const std::atomic<bool>*) override { return true; }
    void abandon() override {}
    std::int64_t framesCompleted() const override { return std::int64_t(frames.size()); }
    std::vector<Image> frames;
};

TEST(MotionBlur, AnimationBlursEveryFrameAndReportsSubFrames) {
    const SceneDesc scene = test::sceneFromText(kMovingScene);
    AnimationRange range{2, 3, 24, 48};  // output frames 2 and 3 at 48 fps: scene times 1 and 1.5
    AnimationOptions options;
    options.threads = 2;
    options.motionBlur = {0.5, 3};
    MemorySink sink;
    std::vector<std::pair<std::int64_t, int>> progress;
    const AnimationResult result = renderAnimation(
        scene, range, FrameView::sceneCamera(96, 72), sink, nullptr,
        [&](const AnimationProgress& p) {
            EXPECT_EQ(p.subFramesPerFrame, 3);
            progress.emplace_back(p.done, p.subFramesDone);
        },
        options);
    ASSERT_EQ(result.outcome, AnimationResult::Outcome::Finished);
    ASSERT_EQ(sink.frames.size(), 2u);
    const std::vector<std::pair<std::int64_t, int>> expected{{0, 1}, {0, 2}, {1, 0}, {1, 1},
                                                             {1, 2}, {2, 0}, {2, 0}};
    EXPECT_EQ(progress, expected);
    // An output frame is half a scene frame long: the shutter is a quarter of a scene frame.
    EXPECT_TRUE(sink.frames[1] == blurred(scene, 1.5, {0.25, 3}, 1));
}

}  // namespace
}  // namespace f2
