// The one animation loop (io/render_animation.h), its sinks, the timeline rule
// (core/anim/frame_time.h), and the output guarantees of docs/robustness.md
// that a unit test can show: unique temporary names, devices, links, helper
// programs that fail.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <climits>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <thread>

#include "core/anim/frame_time.h"
#include "core/render/camera.h"
#include "core/render/renderer.h"
#include "io/atomic_file.h"
#include "io/child_process.h"
#include "io/image_sink.h"
#include "io/png_writer.h"
#include "io/render_animation.h"
#include "io/sequence_sink.h"
#include "io/video_encoder.h"
#include "io/video_sink.h"
#include "test_scenes.h"

namespace f2 {
namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------
// Which frame is time t: one rule.

TEST(FrameTime, FrameAtIsTheWholeFrameTheTimeFallsIn) {
    EXPECT_EQ(frameAt(0), 0);
    EXPECT_EQ(frameAt(3.5), 3);
    EXPECT_EQ(frameAt(3.999), 3);
    EXPECT_EQ(frameAt(4), 4);
    EXPECT_EQ(frameAt(0.1 * 3 * 10), 3);  // 2.9999999999999996 is frame 3
    EXPECT_EQ(frameAt(1e7), 10'000'000);
    EXPECT_EQ(frameAt(1e10 + 0.5), 10'000'000'000);
}

TEST(FrameTime, OutputFramesRoundTripThroughSceneTime) {
    // At every pair of rates, the output frame that shows output frame i's time is i.
    for (int sceneFps : {1, 12, 24, 25, 30, 60})
        for (int outputFps : {1, 7, 10, 12, 24, 29, 30, 60, 1000})
            for (std::int64_t i : {0LL, 1LL, 2LL, 3LL, 239LL, 1000LL, 123456LL, 9'999'999LL})
                ASSERT_EQ(outputFrameAt(sceneTimeOfOutputFrame(i, sceneFps, outputFps), sceneFps, outputFps),
                          i)
                    << i << " at " << sceneFps << " -> " << outputFps;
    EXPECT_EQ(outputFrameAt(240, 24, 60), 600);  // the demo's last frame at 60 fps
    EXPECT_EQ(outputFrameAt(11, 12, 24), 22);
}

// ---------------------------------------------------------------------------
// renderAnimation drives any sink the same way.

/// Records what the loop does; fails or cancels on request.
class RecordingSink : public FrameSink {
   public:
    std::set<std::int64_t> done;  ///< frames "already in the output"
    std::int64_t failAt = -1, cancelAt = -1;
    std::atomic<bool>* cancelFlag = nullptr;

    FrameFormat format;
    std::map<std::int64_t, Image> written;
    std::vector<std::string> calls;

    bool begin(const FrameFormat& f, std::string&) override {
        format = f;
        calls.push_back("begin");
        return true;
    }
    bool alreadyDone(std::int64_t frame) override { return done.count(frame) != 0; }
    bool write(const Image& image, std::int64_t frame, std::string& error,
               const std::atomic<bool>*) override {
        calls.push_back("write " + std::to_string(frame));
        if (frame == cancelAt) cancelFlag->store(true);
        if (frame == failAt) {
            error = "the disk is on fire";
            return false;
        }
        written[frame] = image;
        return true;
    }
    bool finish(std::string&, const std::atomic<bool>*) override {
        calls.push_back("finish");
        return true;
    }
    void abandon() override { calls.push_back("abandon"); }
    std::int64_t framesCompleted() const override { return std::int64_t(written.size() + done.size()); }
};

const char* const kMovingBall = R"(/camera 32 24 0.6 0 0 -10
/background 20 30 40
/amb_light 0.3
/dir_light 0.8 0.3 -0.5 1
/sphere ball 1.5 -3 0 8
/key 0 ball
/key 10 ball 3 0 8 0 0 0
)";

TEST(RenderAnimation, RendersEachFrameInOrderAtItsTime) {
    const SceneDesc scene = test::sceneFromText(kMovingBall);
    const Camera camera = Camera::fromDesc(scene.camera);
    AnimationRange range{1, 5, 24, 60};  // 60 fps output of a 24 fps scene: frame i at t = 0.4 i
    RecordingSink sink;
    std::vector<std::int64_t> progress;
    const AnimationResult result =
        renderAnimation(scene, range, FrameView::fixedCamera(camera), sink, nullptr,
                        [&](const AnimationProgress& p) { progress.push_back(p.done); });
    EXPECT_EQ(result.outcome, AnimationResult::Outcome::Finished) << result.error;
    EXPECT_EQ(result.done, 5);
    EXPECT_EQ(result.total, 5);
    EXPECT_EQ(sink.format.frameCount, 5);
    EXPECT_EQ(sink.format.fps, 60);
    EXPECT_EQ(sink.format.width, 32);
    EXPECT_EQ(sink.calls, (std::vector<std::string>{"begin", "write 1", "write 2", "write 3", "write 4",
                                                    "write 5", "finish"}));
    EXPECT_EQ(progress, (std::vector<std::int64_t>{1, 2, 3, 4, 5, 5}));
    Renderer renderer(1);
    for (auto& [frame, image] : sink.written) {
        Image expected;
        renderer.render(scene, 0.4 * double(frame), camera, expected);
        EXPECT_TRUE(image == expected) << "frame " << frame;
    }
    EXPECT_FALSE(sink.written.at(1) == sink.written.at(5));  // the ball moved
}

TEST(RenderAnimation, AShardRendersEveryNthFrameAndSkipsFinishedOnes) {
    const SceneDesc scene = test::sceneFromText(kMovingBall);
    AnimationRange range{3, 13, 24, 24, 0, 1, 3};  // worker 1 of 3: 4, 7, 10, 13
    EXPECT_EQ(range.count(), 4);
    RecordingSink sink;
    sink.done = {7};
    const AnimationResult result =
        renderAnimation(scene, range, FrameView::fixedCamera(Camera::fromDesc(scene.camera)), sink, nullptr);
    EXPECT_EQ(result.outcome, AnimationResult::Outcome::Finished);
    EXPECT_EQ(sink.calls, (std::vector<std::string>{"begin", "write 4", "write 10", "write 13", "finish"}));
    EXPECT_EQ(result.skipped, 1);
    EXPECT_EQ(result.rendered(), 3);
    EXPECT_EQ((AnimationRange{0, 7, 24, 24, 0, 0, 3}.count()), 3);  // 0, 3, 6
    EXPECT_EQ((AnimationRange{5, 5, 24, 24, 0, 2, 3}.count()), 1);
    EXPECT_EQ((AnimationRange{5, 5, 24, 24, 0, 1, 3}.count()), 0);
}

TEST(RenderAnimation, AStepRendersEveryStepthFrameAlsoInAShard) {
    const SceneDesc scene = test::sceneFromText(kMovingBall);
    AnimationRange range{2, 20, 24, 24, 0, 1, 2, 3};  // 2, 5, 8, 11, 14, 17, 20; odd ones: 5, 11, 17
    EXPECT_EQ(range.count(), 3);
    EXPECT_EQ(range.lastRendered(), 20);
    RecordingSink sink;
    renderAnimation(scene, range, FrameView::fixedCamera(Camera::fromDesc(scene.camera)), sink, nullptr);
    EXPECT_EQ(sink.calls, (std::vector<std::string>{"begin", "write 5", "write 11", "write 17", "finish"}));
    // Counting by periods agrees with counting one by one, for many ranges, steps and shards.
    for (std::int64_t first : {0, 1, 7})
        for (std::int64_t last : {first, first + 1, first + 30, first + 97})
            for (std::int64_t step : {1, 2, 3, 4, 6, 9})
                for (int n : {1, 2, 3, 4, 6}) {
                    const AnimationRange r{first, last, 24, 24, 0, n - 1, n, step};
                    std::int64_t expected = 0;
                    for (std::int64_t f = first; f <= last; f += step) expected += r.inShard(f);
                    EXPECT_EQ(r.count(), expected)
                        << first << "-" << last << ":" << step << " shard " << n - 1 << "/" << n;
                }
    EXPECT_EQ((AnimationRange{0, 10, 24, 24, 0, 0, 1, 4}.lastRendered()), 8);
}

TEST(RenderAnimation, CancelAndErrorsAbandonTheSink) {
    const SceneDesc scene = test::sceneFromText(kMovingBall);
    const Camera camera = Camera::fromDesc(scene.camera);
    std::atomic<bool> cancel{false};
    RecordingSink cancelled;
    cancelled.cancelFlag = &cancel;
    cancelled.cancelAt = 1;
    AnimationResult result =
        renderAnimation(scene, {0, 9, 24, 24}, FrameView::fixedCamera(camera), cancelled, &cancel);
    EXPECT_EQ(result.outcome, AnimationResult::Outcome::Cancelled);
    EXPECT_TRUE(result.error.empty());
    EXPECT_EQ(cancelled.calls, (std::vector<std::string>{"begin", "write 0", "write 1", "abandon"}));

    RecordingSink failing;
    failing.failAt = 2;
    result = renderAnimation(scene, {0, 9, 24, 24}, FrameView::fixedCamera(camera), failing, nullptr);
    EXPECT_EQ(result.outcome, AnimationResult::Outcome::Failed);
    EXPECT_EQ(result.error, "the disk is on fire");
    EXPECT_EQ(failing.calls.back(), "abandon");
    EXPECT_EQ(result.done, 2);
}

TEST(RenderAnimation, AStillIsOneFrameAtAFractionalTime) {
    const SceneDesc scene = test::sceneFromText(kMovingBall);
    const Camera camera = Camera::fromDesc(scene.camera);
    RecordingSink sink;
    const AnimationResult result = renderAnimation(scene, AnimationRange::still(2.75, 24),
                                                   FrameView::fixedCamera(camera), sink, nullptr);
    ASSERT_EQ(result.outcome, AnimationResult::Outcome::Finished);
    ASSERT_EQ(sink.written.size(), 1u);
    Image expected;
    Renderer(1).render(scene, 2.75, camera, expected);
    EXPECT_TRUE(sink.written.begin()->second == expected);
}

class OutputDir : public ::testing::Test {
   protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("f2_anim_output_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::vector<std::string> names(const fs::path& dir) const {
        std::vector<std::string> out;
        for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
        std::sort(out.begin(), out.end());
        return out;
    }
    static std::string slurp(const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        return {(std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()};
    }
    fs::path dir_;
};

TEST_F(OutputDir, SequenceMakesTheDirectoryOfEveryFrame) {
    const SceneDesc scene = test::sceneFromText(kMovingBall);
    std::string error;
    auto pattern = parseFramePattern((dir_ / "out_%d/f.png").string(), error);
    ASSERT_TRUE(pattern) << error;
    PngSequenceSink sink(*pattern);
    const AnimationResult result = renderAnimation(
        scene, {0, 3, 24, 24}, FrameView::fixedCamera(Camera::fromDesc(scene.camera)), sink, nullptr);
    ASSERT_EQ(result.outcome, AnimationResult::Outcome::Finished) << result.error;
    EXPECT_EQ(result.done, 4);
    for (int f = 0; f <= 3; ++f) {
        Image image;
        EXPECT_TRUE(readPng((dir_ / ("out_" + std::to_string(f)) / "f.png").string(), image, error)) << error;
    }
}

// ---------------------------------------------------------------------------
// Temporary names: unique, in the target's directory, within NAME_MAX.

TEST_F(OutputDir, TwoWritersOfOneFileNeverShareATemporary) {
    // Two writers in one process have the same PID, as two containers' workers
    // can: `<name>.tmp-<pid>` made them write into one file.
    const std::string out = (dir_ / "f.png").string();
    AtomicFile a(out), b(out);
    ASSERT_TRUE(a.ok()) << a.error();
    ASSERT_TRUE(b.ok()) << b.error();
    EXPECT_NE(a.tempPath(), b.tempPath());
    EXPECT_EQ(fs::path(a.tempPath()).parent_path(), dir_);
    EXPECT_TRUE(isTemporaryOf(fs::path(a.tempPath()).filename().string(), "f.png"));
    std::fputs("from a", a.handle());
    std::fputs("from b, longer", b.handle());
    ASSERT_TRUE(b.commit()) << b.error();
    ASSERT_TRUE(a.commit()) << a.error();
    EXPECT_EQ(slurp(out), "from a");  // whole: the last rename wins, nothing mixed
    EXPECT_EQ(names(dir_), std::vector<std::string>{"f.png"});
}

TEST_F(OutputDir, ALongestLegalFileNameIsWritten) {
    // 255 bytes, the 2-byte é where the temporary name has to cut it.
    const std::string legal = std::string(243, 'n') + "é" + std::string(6, 'm') + ".png";
    ASSERT_EQ(legal.size(), std::size_t(NAME_MAX));
    Image image;
    image.resize(4, 3);
    std::string error;
    ASSERT_TRUE(writePng(image, (dir_ / legal).string(), error)) << error;
    EXPECT_EQ(names(dir_), std::vector<std::string>{legal});
    AtomicFile f((dir_ / legal).string());
    ASSERT_TRUE(f.ok()) << f.error();
    const std::string temp = fs::path(f.tempPath()).filename().string();
    EXPECT_LE(temp.size(), std::size_t(NAME_MAX));
    EXPECT_TRUE(temp.starts_with(std::string(243, 'n') + ".tmp-")) << temp;  // not half an é
    EXPECT_TRUE(isTemporaryOf(temp, legal));
    // And the issue's 254-byte name, through the command line's own path.
    const std::string name254 = std::string(250, 'a') + ".png";
    ASSERT_TRUE(writePng(image, (dir_ / name254).string(), error)) << error;
}

TEST_F(OutputDir, ANewFileGetsTheUsualPermissionsAndAReplacedOneKeepsItsOwn) {
    Image image;
    image.resize(4, 3);
    std::string error;
    const fs::path fresh = dir_ / "fresh.png", kept = dir_ / "kept.png";
    ASSERT_TRUE(writePng(image, fresh.string(), error)) << error;
    const mode_t mask = ::umask(0);
    ::umask(mask);
    EXPECT_EQ(fs::status(fresh).permissions(), fs::perms(0666 & ~mask));  // not mkstemp's 0600
    std::ofstream(kept) << "old";
    fs::permissions(kept, fs::perms(0640));
    ASSERT_TRUE(writePng(image, kept.string(), error)) << error;
    EXPECT_EQ(fs::status(kept).permissions(), fs::perms(0640));
}

// ---------------------------------------------------------------------------
// Devices and links.

TEST_F(OutputDir, DevicesAreWrittenDirectlyNeverReplaced) {
    const fs::path null = dir_ / "null", full = dir_ / "full";
    if (::mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0 ||
        ::mknod(full.c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0)
        GTEST_SKIP() << "cannot create device nodes here (mknod needs root): " << std::strerror(errno);
    Image image;
    image.resize(64, 48);
    std::string error;
    EXPECT_TRUE(writePng(image, null.string(), error)) << error;
    EXPECT_TRUE(fs::is_character_file(null));
    EXPECT_FALSE(writePng(image, full.string(), error));
    EXPECT_NE(error.find("No space left on device"), std::string::npos) << error;
    EXPECT_TRUE(fs::is_character_file(full));
    EXPECT_EQ(names(dir_), (std::vector<std::string>{"full", "null"}));

    VideoEncoder encoder;
    EXPECT_FALSE(encoder.open({VideoFormat::Gif, 8, 8, 10, {}}, null.string(), error));
    EXPECT_NE(error.find("is a character device"), std::string::npos) << error;
}

TEST_F(OutputDir, ALinkIsFollowedAndTheFileItNamesReplaced) {
    fs::create_directory(dir_ / "real");
    std::ofstream(dir_ / "real" / "f.txt") << "old";
    fs::create_symlink("real/f.txt", dir_ / "link.txt");
    fs::create_symlink("link.txt", dir_ / "link2.txt");         // a chain
    fs::create_symlink("real/new.txt", dir_ / "dangling.txt");  // names a file not there yet
    for (const char* name : {"link2.txt", "dangling.txt"}) {
        AtomicFile f((dir_ / name).string());
        ASSERT_TRUE(f.ok()) << f.error();
        EXPECT_EQ(fs::path(f.tempPath()).parent_path(), dir_ / "real");  // the rename stays in one directory
        std::fputs(name, f.handle());
        ASSERT_TRUE(f.commit()) << f.error();
    }
    EXPECT_TRUE(fs::is_symlink(dir_ / "link.txt"));
    EXPECT_TRUE(fs::is_symlink(dir_ / "link2.txt"));
    EXPECT_TRUE(fs::is_symlink(dir_ / "dangling.txt"));
    EXPECT_EQ(slurp(dir_ / "real" / "f.txt"), "link2.txt");
    EXPECT_EQ(slurp(dir_ / "real" / "new.txt"), "dangling.txt");
    EXPECT_EQ(names(dir_ / "real"), (std::vector<std::string>{"f.txt", "new.txt"}));

    fs::create_symlink("loop2", dir_ / "loop1");
    fs::create_symlink("loop1", dir_ / "loop2");
    AtomicFile loop((dir_ / "loop1").string());
    EXPECT_FALSE(loop.ok());
    EXPECT_NE(loop.error().find("symbolic links"), std::string::npos) << loop.error();
    AtomicFile directory(dir_.string());
    EXPECT_FALSE(directory.ok());
    EXPECT_NE(directory.error().find("is a directory"), std::string::npos) << directory.error();
}

TEST_F(OutputDir, SinkErrorsSpeakOfFilesNotOfACommandLine) {
    // The viewer shows these messages too: they state what is wrong with the
    // file, and never advise a front end's options (-o, --frames, ...).
    std::vector<std::string> errors;
    auto collect = [&](FrameSink& sink, std::int64_t frames) {
        std::string error;
        Image image;
        image.resize(8, 6);
        std::atomic<bool> cancel{false};
        bool ok = sink.begin({8, 6, 24, frames}, error) && sink.write(image, 0, error, &cancel) &&
                  sink.finish(error, &cancel);
        EXPECT_FALSE(ok) << "no error to look at";
        sink.abandon();
        errors.push_back(error);
    };
    std::ofstream(dir_ / "file").put('x');
    std::string patternError;
    auto underAFile = parseFramePattern((dir_ / "file" / "f_%04d.png").string(), patternError);
    ASSERT_TRUE(underAFile) << patternError;
    PngSequenceSink sequence(*underAFile);
    collect(sequence, 1);
    PngImageSink image((dir_ / "one.png").string());
    collect(image, 3);
    PngImageSink intoADirectory(dir_.string());
    collect(intoADirectory, 1);
    VideoSink video(dir_.string(), VideoFormat::Mp4);
    collect(video, 1);
    // Without ffmpeg on PATH (the error that used to suggest -o frames/f_%04d.png).
    const char* path = std::getenv("PATH");
    const std::string savedPath = path ? path : "";
    ::setenv("PATH", (dir_ / "nothing_here").c_str(), 1);
    VideoSink noFfmpeg((dir_ / "out.mp4").string(), VideoFormat::Mp4);
    collect(noFfmpeg, 1);
    ::setenv("PATH", savedPath.c_str(), 1);
    ASSERT_EQ(errors.size(), 5u);
    EXPECT_NE(errors[4].find("ffmpeg"), std::string::npos) << errors[4];
    for (const std::string& e : errors) {
        EXPECT_FALSE(e.empty());
        EXPECT_EQ(e.find("-o "), std::string::npos) << e;
        EXPECT_EQ(e.find("--"), std::string::npos) << e;
        EXPECT_EQ(e.find("f2 "), std::string::npos) << e;
    }
}

// ---------------------------------------------------------------------------
// ffmpeg's file names and the helper programs.

TEST(VideoEncoder, FfmpegGetsAFileNameNoProtocol) {
    const std::string cwd = fs::current_path().string();
    EXPECT_EQ(ffmpegFileName("pipe:x.gif"), "file:" + cwd + "/pipe:x.gif");
    EXPECT_EQ(ffmpegFileName("file:y.gif"), "file:" + cwd + "/file:y.gif");
    EXPECT_EQ(ffmpegFileName("/abs/http://z.mp4"), "file:/abs/http://z.mp4");
}

TEST(ChildProcess, AClosedPipeIsAnErrorAndTheProcessKeepsItsSignals) {
    struct sigaction before {};
    ::sigaction(SIGPIPE, nullptr, &before);
    ChildProcess child;
    std::string error;
    ASSERT_TRUE(child.start(findProgram("sh"), {"-c", "exec 0<&-; echo bye >&2; exit 3"}, error)) << error;
    const std::string frame(1 << 20, 'x');  // more than a pipe holds
    EXPECT_EQ(child.writeInput(frame.data(), frame.size(), nullptr), ChildProcess::Io::Closed);
    EXPECT_EQ(child.wait(nullptr), ChildProcess::Io::Done);
    EXPECT_EQ(child.describeExit(), "exit status 3");
    EXPECT_EQ(child.standardError(), "bye\n");
    // Still here (no SIGPIPE killed us), no SIGPIPE left pending, and its disposition untouched.
    struct sigaction after {};
    ::sigaction(SIGPIPE, nullptr, &after);
    EXPECT_EQ(after.sa_handler, before.sa_handler);
    sigset_t pending;
    sigpending(&pending);
    EXPECT_FALSE(sigismember(&pending, SIGPIPE));
}

TEST(ChildProcess, ACancelStopsAWriteThatNobodyReads) {
    ChildProcess child;
    std::string error;
    // The child never reads: the pipe fills and the write would block for ever.
    ASSERT_TRUE(child.start(findProgram("sh"), {"-c", "kill -STOP $$"}, error)) << error;
    std::atomic<bool> cancel{false};
    std::thread stopper([&] {
        // Raised once the child has stopped, which it does without reading.
        for (int i = 0; i < 100000; ++i) {
            std::ifstream status("/proc/" + std::to_string(child.pid()) + "/status");
            std::string text((std::istreambuf_iterator<char>(status)), std::istreambuf_iterator<char>());
            if (text.find("(stopped)") != std::string::npos) break;
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        cancel.store(true);
    });
    const std::string data(8 << 20, 'x');
    EXPECT_EQ(child.writeInput(data.data(), data.size(), &cancel), ChildProcess::Io::Cancelled);
    stopper.join();
    const pid_t pid = child.pid();
    child.kill();  // a stopped child is killed and reaped
    EXPECT_FALSE(child.running());
    EXPECT_EQ(::waitpid(pid, nullptr, WNOHANG), -1);  // already reaped
}

}  // namespace
}  // namespace f2
