// Animation output (docs/output.md): numbered file names, ffmpeg command
// lines and the pipe to it, and the POV-Ray / primitive-list exports.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "core/anim/frame_builder.h"
#include "core/render/camera.h"
#include "io/comment_text.h"
#include "io/frame_pattern.h"
#include "io/frame_primitives.h"
#include "io/pov_animation.h"
#include "io/pov_export.h"
#include "io/prims_export.h"
#include "io/video_encoder.h"
#include "missing_tool.h"
#include "test_scenes.h"

namespace f2 {
namespace {

namespace fs = std::filesystem;

bool contains(const std::vector<std::string>& args, const std::string& word) {
    return std::find(args.begin(), args.end(), word) != args.end();
}

int count(const std::string& text, const std::string& word) {
    int n = 0;
    for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
    return n;
}

std::vector<std::vector<std::string>> fieldsByLine(const std::string& text) {
    std::vector<std::vector<std::string>> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream words(line);
        lines.emplace_back();
        for (std::string w; words >> w;) lines.back().push_back(w);
    }
    return lines;
}

TEST(FramePattern, FormatsPaddedFrameNumbers) {
    std::string error;
    auto p = parseFramePattern("frames/f_%04d.png", error);
    ASSERT_TRUE(p) << error;
    EXPECT_EQ(p->format(7), "frames/f_0007.png");
    EXPECT_EQ(p->format(123456), "frames/f_123456.png");
    auto plain = parseFramePattern("%d.png", error);
    ASSERT_TRUE(plain);
    EXPECT_EQ(plain->format(42), "42.png");
    auto percent = parseFramePattern("100%%_%03d.png", error);
    ASSERT_TRUE(percent);
    EXPECT_EQ(percent->format(5), "100%_005.png");
}

TEST(FramePattern, RefusesSpacePaddingAndSuggestsZeros) {
    std::string error;
    EXPECT_FALSE(parseFramePattern("x_%4d.png", error));
    EXPECT_NE(error.find("%04d"), std::string::npos) << error;
}

TEST(FramePattern, RejectsAnythingButOneIntegerConversion) {
    std::string error;
    EXPECT_FALSE(parseFramePattern("f_%s.png", error));
    EXPECT_FALSE(parseFramePattern("f_%d_%d.png", error));
    EXPECT_FALSE(parseFramePattern("f_%n.png", error));
    EXPECT_FALSE(parseFramePattern("f_%010d.png", error));
    EXPECT_FALSE(parseFramePattern("f.png", error));
    EXPECT_FALSE(looksLikeFramePattern("100%%.png"));
    EXPECT_TRUE(looksLikeFramePattern("f_%04d.png"));
}

TEST(VideoEncoder, FormatFromExtension) {
    EXPECT_EQ(videoFormatForPath("out/Demo.MP4"), VideoFormat::Mp4);
    EXPECT_EQ(videoFormatForPath("a.webm"), VideoFormat::Webm);
    EXPECT_EQ(videoFormatForPath("a.gif"), VideoFormat::Gif);
    EXPECT_FALSE(videoFormatForPath("a.mp4.png"));
    EXPECT_FALSE(videoFormatForPath("dir.mp4/frame"));
    EXPECT_FALSE(videoFormatForPath("mp4"));
}

TEST(VideoEncoder, FfmpegReadsRawRgbAndWritesAnExplicitFormat) {
    VideoSettings mp4{VideoFormat::Mp4, 320, 240, 30, {}};
    auto args = ffmpegArguments(mp4, "x.mp4.tmp-1");
    EXPECT_TRUE(contains(args, "rawvideo") && contains(args, "rgb24") && contains(args, "320x240"));
    EXPECT_TRUE(contains(args, "libx264") && contains(args, "yuv420p") && contains(args, "mp4"));
    EXPECT_TRUE(contains(args, "30"));  // -framerate
    EXPECT_EQ(args.back(), "x.mp4.tmp-1");
    EXPECT_FALSE(videoNeedsPadding(mp4));
    EXPECT_FALSE(contains(args, "-vf"));

    VideoSettings odd{VideoFormat::Mp4, 321, 240, 24, {28, 32, 46}};
    EXPECT_TRUE(videoNeedsPadding(odd));
    auto oddArgs = ffmpegArguments(odd, "o");
    EXPECT_TRUE(contains(oddArgs, "pad=ceil(iw/2)*2:ceil(ih/2)*2:0:0:color=0x1C202E"));

    auto webm = ffmpegArguments({VideoFormat::Webm, 321, 241, 24, {}}, "w");
    EXPECT_TRUE(contains(webm, "libvpx-vp9") && contains(webm, "webm") && !contains(webm, "-vf"));
    auto gif = ffmpegArguments({VideoFormat::Gif, 100, 80, 12, {}}, "g");
    auto graph = std::find(gif.begin(), gif.end(), "-filter_complex");
    ASSERT_NE(graph, gif.end());
    EXPECT_NE(graph[1].find("palettegen"), std::string::npos);
    EXPECT_NE(graph[1].find("paletteuse"), std::string::npos);
}

TEST(VideoEncoder, FindsProgramsOnPath) {
    EXPECT_FALSE(findProgram("sh").empty());
    EXPECT_TRUE(findProgram("f2-no-such-program").empty());
}

TEST(VideoEncoder, WritesAVideoOrNothing) {
    if (findProgram("ffmpeg").empty()) F2_SKIP_MISSING("ffmpeg is not installed");
    fs::path dir = fs::temp_directory_path() / ("f2_output_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    Image frame;
    frame.resize(32, 24);
    std::string error;
    {
        VideoEncoder encoder;
        ASSERT_TRUE(encoder.open({VideoFormat::Mp4, 32, 24, 10, {}}, (dir / "ok.mp4").string(), error))
            << error;
        for (int i = 0; i < 3; ++i) ASSERT_TRUE(encoder.write(frame, error)) << error;
        Image wrong;
        wrong.resize(8, 8);
        EXPECT_FALSE(encoder.write(wrong, error));  // a size change is refused, the video goes on
        ASSERT_TRUE(encoder.finish(error)) << error;
    }
    EXPECT_GT(fs::file_size(dir / "ok.mp4"), 0u);
    {
        VideoEncoder encoder;
        ASSERT_TRUE(encoder.open({VideoFormat::Gif, 32, 24, 10, {}}, (dir / "gone.gif").string(), error));
        ASSERT_TRUE(encoder.write(frame, error));
        EXPECT_TRUE(fs::exists(encoder.tempPath()));
        encoder.abort();
    }
    {
        VideoEncoder dropped;  // destroyed without finish(): same as abort
        ASSERT_TRUE(
            dropped.open({VideoFormat::Webm, 32, 24, 10, {}}, (dir / "dropped.webm").string(), error));
    }
    std::vector<std::string> left;
    for (const auto& entry : fs::directory_iterator(dir)) left.push_back(entry.path().filename().string());
    EXPECT_EQ(left, std::vector<std::string>{"ok.mp4"});
    fs::remove_all(dir);
}

TEST(FramePrimitives, RobotExpandsInPeerOrderWithExactTransforms) {
    SceneDesc scene = test::sceneFromText(
        "/box b 10 20 30 1 2 3 0 90 0\n/robot r 0 0 100 0 180 0\n/paint r 1 2 3\n/human h 50 0 0\n");
    auto prims = framePrimitives(scene, 0);
    ASSERT_EQ(prims.size(), 11u);
    EXPECT_EQ(prims[0].kind, ShapeKind::Box);
    EXPECT_EQ(prims[0].size, (Vec3{10, 20, 30}));
    // ry = 90 turns +z toward +x (SPEC 1): the local z axis (column 2) is world +x.
    Vec3 z = prims[0].worldFromLocal.linear.column(2);
    EXPECT_NEAR(z.x, 1, 1e-6);
    EXPECT_EQ(prims[0].worldFromLocal.translation, (Vec3{1, 2, 3}));
    const char* robot[] = {"r.body.torso", "r.head.face", "r.head.leye",
                           "r.head.reye",  "r.lhand.arm", "r.rhand.arm"};
    for (int i = 0; i < 6; ++i) EXPECT_EQ(prims[1 + i].label, robot[i]);
    EXPECT_EQ(prims[3].color, (Color8{20, 20, 20}));  // eyes keep their colour
    EXPECT_EQ(prims[2].color, (Color8{1, 2, 3}));
    // The body cylinder's centre: root (0,0,100) + pivot (0,-105,0) + centre (0,75,0).
    Vec3 body = prims[1].worldFromLocal.translation;
    EXPECT_NEAR(body.y, -30, 1e-4);
    EXPECT_NEAR(body.z, 100, 1e-4);
    EXPECT_EQ(prims[7].label, "h.body.torso");
    EXPECT_EQ(prims[10].label, "h.rhand.arm");
}

TEST(FramePrimitives, NumbersReadBackExactly) {
    for (float v : {0.1f, -130.0f, 0.70710677f, 1e-7f, 12345.678f}) EXPECT_EQ(std::stof(formatNumber(v)), v);
    EXPECT_EQ(formatNumber(-0.0f), "0");
}

TEST(PovExport, CameraVectorsMatchTheSpecRay) {
    SceneDesc scene = test::sceneFromText(
        "/camera 800 600 0.5\n/background 1 2 3\n/amb_light 0.2\n"
        "/dir_light 0.75 0 -0.2 1\n/sphere s 10 0 0 100\n/material s 0.5 0.8 0.3 16\n");
    std::string pov = povScene(scene, 0, Camera::fromDesc(scene.camera), "t.f2");
    EXPECT_NE(pov.find("#version 3.7;"), std::string::npos);
    EXPECT_NE(pov.find("right <1, 0, 0>"), std::string::npos);
    EXPECT_NE(pov.find("up <0, 0.75, 0>"), std::string::npos);        // h / w
    EXPECT_NE(pov.find("direction <0, 0, 0.5>"), std::string::npos);  // d screen widths
    EXPECT_NE(pov.find("background { rgb <1, 2, 3> / 255 }"), std::string::npos);
    EXPECT_EQ(count(pov, "light_source"), 1);
    EXPECT_EQ(count(pov, "parallel"), 1);
    EXPECT_NE(pov.find("finish { ambient 0.1 diffuse 0.8 phong 0.3 phong_size 16 }"), std::string::npos);
    EXPECT_NE(pov.find("matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  0, 0, 100>"), std::string::npos);
}

// --pov --animation (docs/output.md): keys become SDL over their intervals,
// what never changes is written once as the single-frame export writes it,
// and only what POV-Ray cannot evaluate is read per frame.
TEST(PovAnimation, KeysAreEvaluatedInSdlAndOnlyAChangingRideIsReadPerFrame) {
    SceneDesc scene = test::sceneFromText(
        "/camera 80 60 0.8\n/fps 30\n/dir_light 0.75 0 -0.2 1\n/box floor 100 10 100 0 -20 0\n"
        "/sphere s 10 0 0 100\n/key 0 s 0 0 100 0 0 0 bounce\n/key 15 s 50 0 100 0 90 0 step\n"
        "/key 30 s 50 20 100 0 0 0\n/sphere moon 2 20 0 0\n/attach moon s\n"
        "/sphere comet 2 0 30 0\n/attach comet s at 10\n");
    const PovAnimation a = povAnimation(scene, 80, 60, "t.f2", "t");
    EXPECT_EQ(a.lastFrame, 30);
    EXPECT_EQ(a.evaluated, 2u);  // s, and the moon on it; the comet's ride changes: read per frame
    EXPECT_EQ(a.arrays, 1u);
    EXPECT_EQ(count(a.scene, "array[31]"), 1);
    EXPECT_NE(a.scene.find("#declare F2_Frame = clock * 30;"), std::string::npos);
    EXPECT_NE(a.scene.find("#elseif (F2_Frame < 15)"), std::string::npos);
    EXPECT_NE(a.scene.find("7.5625"), std::string::npos);  // bounce's parabolas
    EXPECT_NE(a.scene.find("rotate F2_Object1_Rotation translate F2_Object1_Position"), std::string::npos);
    // The moon: its own place, then s's pose (worldFromRef).
    EXPECT_NE(
        a.scene.find("{ translate <20, 0, 0> rotate F2_Object1_Rotation translate F2_Object1_Position }"),
        std::string::npos);
    // The floor never moves: its matrix as the single-frame export writes it.
    const std::string single = povScene(scene, 0, cameraAt(scene, 0).resized(80, 60), "t.f2");
    EXPECT_NE(single.find("matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  0, -20, 0>"), std::string::npos);
    EXPECT_NE(a.scene.find("matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  0, -20, 0>"), std::string::npos);
    EXPECT_NE(a.ini.find("\nFinal_Frame=30\nInitial_Clock=0\nFinal_Clock=1\n"), std::string::npos);
    EXPECT_NE(a.ini.find("\nInput_File_Name=t.pov\nOutput_File_Name=t_.png\n"), std::string::npos);
}

TEST(PovAnimation, OnlyPlainFileNamesGoIntoTheIni) {
    EXPECT_TRUE(povIniName("demo_v2.1-final+x"));
    for (const char* bad : {"", "a b", "a;b", "a\nPost_Frame_Command=x", "a\"b", "a$(x)", "a/b", "a=b"})
        EXPECT_FALSE(povIniName(bad)) << bad;
}

TEST(PovExport, EveryPrimitiveOnceWithItsShape) {
    SceneDesc scene = test::sceneFromRepo("seed_example.f2");
    std::string pov = povScene(scene, 10, Camera::fromDesc(scene.camera), "seed");
    EXPECT_EQ(count(pov, "matrix <"), int(scene.primitiveCount()));
    EXPECT_EQ(count(pov, "\nbox {"), 2);       // ground, robot head
    EXPECT_EQ(count(pov, "\nsphere {"), 3);    // two eyes, human head
    EXPECT_EQ(count(pov, "\ncylinder {"), 6);  // bodies and arms
    EXPECT_EQ(count(pov, " open"), 0);         // SPEC 4: closed cylinders
}

TEST(CommentText, EscapesEveryControlByteAndKeepsTheRest) {
    EXPECT_EQ(commentText("scenes/demo.f2"), "scenes/demo.f2");
    EXPECT_EQ(commentText("a\nb\rc\td"), "a\\nb\\rc\\td");
    EXPECT_EQ(commentText(std::string("x\0y\x1b\x7f", 5)), "x\\x00y\\x1b\\x7f");
    EXPECT_EQ(commentText("back\\slash"), "back\\\\slash");
    EXPECT_EQ(commentText("caf\xc3\xa9 \"#*/"), "caf\xc3\xa9 \"#*/");  // printable and UTF-8 pass
}

/// Lines of `text` that are not empty and not a `//` comment.
std::vector<std::string> liveLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty() && line.rfind("//", 0) != 0) lines.push_back(line);
    return lines;
}

TEST(PovExport, NothingFromOutsideTheNumbersReachesLiveCode) {
    // Issue 29: a newline in the scene's path ended the header comment and the
    // rest ran in povray. Names cannot hold one today, but the label is escaped
    // as well, so a future name rule cannot reopen the hole.
    SceneDesc scene = test::sceneFromText("/camera 80 60 0.8\n/sphere s 10 0 0 100\n");
    const std::string clean = povScene(scene, 0, Camera::fromDesc(scene.camera), "t.f2");
    const std::string hostile = "dir\n#fopen F \"x\" write\r#write (F, 1) */ \"q\"\n/* #";
    scene.objects.front().name = "s\n#declare X = 1;";
    const std::string pov = povScene(scene, 0, Camera::fromDesc(scene.camera), hostile);
    EXPECT_EQ(liveLines(pov), liveLines(clean));
    EXPECT_NE(pov.find("// dir\\n#fopen F \"x\" write\\r#write (F, 1) */ \"q\"\\n/* # at frame 0"),
              std::string::npos);
    EXPECT_NE(pov.find("// s\\n#declare X = 1;"), std::string::npos);
    EXPECT_EQ(pov.find('\r'), std::string::npos);
}

TEST(PrimsExport, TheHeaderCommentStaysOneLine) {
    SceneDesc scene = test::sceneFromText("/camera 80 60 0.8\n/sphere s 10 0 0 100\n");
    const std::string prims = primsScene(scene, 0, Camera::fromDesc(scene.camera), "a\ncamera 1 2 3\n#");
    EXPECT_EQ(prims.rfind("# a\\ncamera 1 2 3\\n# at frame 0", 0), 0u);
    EXPECT_EQ(count(prims, "\ncamera "), 1);
}

TEST(PrimsExport, FollowsThePeerFormat) {
    SceneDesc scene = test::sceneFromRepo("demo.f2");
    Camera camera = Camera::fromDesc(scene.camera);
    auto lines = fieldsByLine(primsScene(scene, 120, camera, "demo"));
    ASSERT_EQ(lines.size(), 3 + scene.lights.size() + scene.primitiveCount());
    ASSERT_EQ(lines[0].size(), 16u);
    EXPECT_EQ(lines[0][0], "camera");
    EXPECT_EQ(lines[0][1], "800");
    // Column 3 of [R | eye] is the eye (SPEC demo camera at 0 180 -620).
    EXPECT_EQ(lines[0][7], "0");
    EXPECT_EQ(lines[0][11], "180");
    EXPECT_EQ(lines[0][15], "-620");
    EXPECT_EQ(lines[1], (std::vector<std::string>{"background", "28", "32", "46"}));
    EXPECT_EQ(lines[2][0], "amb");
    EXPECT_EQ(lines[3][0], "dir");
    auto prims = framePrimitives(scene, 120);
    for (std::size_t i = 0; i < prims.size(); ++i) {
        const auto& f = lines[3 + scene.lights.size() + i];
        ASSERT_EQ(f.size(), 25u) << "primitive " << i;
        EXPECT_EQ(f[0], prims[i].kind == ShapeKind::Box      ? "box"
                        : prims[i].kind == ShapeKind::Sphere ? "sphere"
                                                             : "cylinder");
        EXPECT_EQ(std::stof(f[9]), prims[i].worldFromLocal.translation.x);
        EXPECT_EQ(std::stoi(f[18]), prims[i].color.r);
    }
}

}  // namespace
}  // namespace f2
