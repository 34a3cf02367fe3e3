// `/drive <target> <channel> (<expression>)` (SPEC 10.7): the compiled
// expression against the text evaluator, each error at its place, the values
// at fractional frames, what a drive replaces and what it leaves, the error
// of a frame without a finite value, and the pictures both paths make.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/anim/animation_program.h"
#include "core/anim/camera_motion.h"
#include "core/anim/frame_builder.h"
#include "core/anim/light_evaluation.h"
#include "core/parse/expression.h"
#include "core/render/camera.h"
#include "core/scene/models.h"
#include "io/bench_scenes.h"
#include "render_paths.h"
#include "robot_parts.h"
#include "test_scenes.h"

namespace f2 {

using test::RobotPart;
namespace {

/// The text evaluator with `frame` and `time` as variables of these values.
ExpressionResult evaluatedAt(const std::string& text, double frame, double fps) {
    Variables variables;
    variables.set("a", 3);
    variables.set("frame", frame);
    variables.set("time", frame / fps);
    return evaluateParenthesized(text, variables);
}

TEST(DriveExpressions, CompiledCodeGivesTheTextEvaluatorsBits) {
    Variables variables;
    variables.set("a", 3);
    const std::vector<std::string> texts = {
        "(100*sin(time*90))",
        "(frame)",
        "(-frame^2 + a*frame - 7 % 3)",
        "(cos(frame*7.5) * tan(frame) / (1 + abs(frame - 10)))",
        "(atan2(frame, a) + asin(time/100) + acos(-time/100) + atan(frame))",
        "(sqrt(frame) + exp(time) + log(frame + 1) + floor(time) + ceil(time) + round(frame/3))",
        "(min(frame, 10, a) + max(frame, 2*a) + frame % -4 + -frame % 3)",
        "(if(frame < 10, frame, 20 - frame) + (frame >= 5 && frame != 7) + (frame < 2 || time > 0.5))",
        "(!(frame == 12) + !frame + (a > 2 && frame) + (0 || frame) + if(1, frame, 1/0))",
        "(if(frame > 3, 1, 1/(frame - 2)) + (frame > 100 && 1/0) + (frame < 100 || sqrt(-1)))",
        "(2^(time) + (time - 1)^2 + frame^-1)",
        "(1/(frame - 12))",
        "(sqrt(frame - 6) + log(frame - 3) + tan(frame*90) + asin(frame - 10))",
        "(0 - frame*0)",
    };
    for (const std::string& text : texts) {
        const CompiledExpression compiled = compileParenthesized(text, variables, kDriveInputs);
        ASSERT_TRUE(compiled.result.ok) << text << ": " << compiled.result.message;
        EXPECT_FALSE(compiled.code.isConstant()) << text;
        for (double frame : {0.0, 0.5, 1.0, 2.0, 3.0, 6.0, 7.0, 11.75, 12.0, 12.25, 13.0, 24.0, 99.5}) {
            const ExpressionResult want = evaluatedAt(text, frame, 24);
            const std::array<double, 2> inputs = {frame, frame / 24};
            ExpressionFailure failure;
            const double got = compiled.code.evaluate(inputs, &failure);
            const std::string what = text + " at frame " + std::to_string(frame);
            if (!want.ok) {
                // The same problem at the same place, computed later.
                EXPECT_TRUE(std::isnan(got)) << what;
                EXPECT_EQ(failure.message, want.message) << what;
                EXPECT_EQ(failure.offset, want.errorOffset) << what;
                continue;
            }
            EXPECT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(want.value)) << what;
        }
    }
}

TEST(DriveExpressions, CodesSideBySideGiveEachCodesOwnBits) {
    // ExpressionCode::runLanes, as a frame runs the alike drives of a grid:
    // each lane's numbers, function and inputs, and a failing lane gives NaN
    // alone.
    Variables variables;
    variables.set("a", 3);
    const std::vector<std::string> texts = {
        "(a + 20*sin(time*180 + 40))", "(-40 + 15*cos(frame*7.5 + 17))", "(1 + 20*tan(frame*90 + 1))",
        "(7 + 3*sqrt(time*-1 + 1))",   "(2 + 5*log(frame*-1 + 13))",     "(a + 2*floor(time*2 + 0.5))",
    };
    std::vector<CompiledExpression> codes;
    for (const std::string& text : texts) {
        codes.push_back(compileParenthesized(text, variables, kDriveInputs));
        const ExpressionCode& code = codes.back().code;
        ASSERT_TRUE(codes.back().result.ok) << text;
        ASSERT_TRUE(ExpressionCode::runsInLanes(code.instructions(), code.stackSize())) << text;
        EXPECT_TRUE(ExpressionCode::sameShape(code.instructions(), codes[0].code.instructions())) << text;
    }
    const CompiledExpression other = compileParenthesized("(20*sin(time*180) + a)", variables, kDriveInputs);
    EXPECT_FALSE(ExpressionCode::sameShape(other.code.instructions(), codes[0].code.instructions()));
    const CompiledExpression jumps = compileParenthesized("(if(frame > 3, 1, 2))", variables, kDriveInputs);
    EXPECT_FALSE(ExpressionCode::runsInLanes(jumps.code.instructions(), jumps.code.stackSize()));

    for (double frame : {0.0, 0.5, 12.0, 13.0, 24.0, 99.5}) {
        const std::array<double, 2> inputs = {frame, frame / 24};
        std::vector<ExprLane> lanes;
        for (const CompiledExpression& c : codes) lanes.push_back({c.code.instructions().data(), inputs});
        std::vector<double> values(lanes.size());
        ExpressionCode::runLanes(lanes, codes[0].code.instructions().size(), values.data());
        bool someFailed = false;
        for (std::size_t l = 0; l < lanes.size(); ++l) {
            const double want = codes[l].code.evaluate(inputs);
            someFailed = someFailed || std::isnan(want);
            EXPECT_EQ(std::bit_cast<std::uint64_t>(values[l]), std::bit_cast<std::uint64_t>(want))
                << texts[l] << " at frame " << frame;
        }
        EXPECT_EQ(someFailed, frame >= 13) << "at frame " << frame;  // log(0) and below, sqrt(-1)
    }
}

TEST(DriveExpressions, AlikeDrivesOfAGridRunSideBySide) {
    // drives:N's two drives per sphere have the same shape (sin and cos,
    // time and frame, their numbers aside): all but the first run with the
    // one before them.
    const SceneDesc scene = test::sceneFromText(benchSceneText({BenchShape::Drives, 20}));
    const std::shared_ptr<const AnimationProgram> program = AnimationProgram::compile(scene);
    ASSERT_EQ(program->drives.size(), 40u);
    for (std::size_t d = 0; d < program->drives.size(); ++d)
        EXPECT_EQ(program->drives[d].withPrevious, d > 0) << "drive " << d;
    ASSERT_EQ(program->firstDrive.size(), 22u);  // the floor and 20 spheres, then the end
    EXPECT_EQ(program->firstDrive[1], 0u);
    EXPECT_EQ(program->firstDrive[21], 40u);
}

TEST(DriveExpressions, ConstantExpressionsAreFoldedToTheEvaluatorsValue) {
    Variables variables;
    variables.set("k", 7);
    for (const std::string text :
         {"(sin(37) * 3 + 2^0.5)", "(k % -3 + atan2(1, k))", "(if(k > 3, exp(1), 1/0))", "(-0)",
          "(min(k, 2, 9) * max(1, 2) - round(-2.5))"}) {
        const CompiledExpression compiled = compileParenthesized(text, variables, kDriveInputs);
        const ExpressionResult want = evaluateParenthesized(text, variables);
        ASSERT_TRUE(compiled.result.ok && want.ok) << text;
        EXPECT_TRUE(compiled.code.isConstant()) << text;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(compiled.code.evaluate({})),
                  std::bit_cast<std::uint64_t>(want.value))
            << text;
    }
    // What does not depend on frame or time fails now, at its place.
    const CompiledExpression broken = compileParenthesized("(frame + 1/0)", variables, kDriveInputs);
    EXPECT_FALSE(broken.result.ok);
    EXPECT_EQ(broken.result.message, "division by zero");
    EXPECT_EQ(broken.result.errorOffset, 10u);
}

TEST(DriveErrors, EachAtItsPlace) {
    const std::string ball = "/sphere ball 1 0 0 0\n";
    // frame and time are variables of a drive's expression only.
    test::expectOnlyError(ball + "/key 0 ball (frame) 0 0 0 0 0\n", 2, 14, "unknown variable 'frame'");
    test::expectOnlyError("/let x (time)\n", 1, 9, "unknown variable 'time'");
    test::expectOnlyError(ball + "/drive ball rxx (frame)\n", 2, 13,
                          "unknown channel 'rxx' (did you mean 'rx'?); the channels are px py pz rx ry rz "
                          "intensity d r g b");
    test::expectOnlyError(ball + "/drive ball pos (frame)\n", 2, 13,
                          "unknown channel 'pos'; the channels are px py pz rx ry rz intensity d r g b");
    test::expectOnlyError(
        ball + "/drive ball intensity (frame)\n", 2, 13,
        "'intensity' is not a channel of the sphere 'ball' ('intensity' drives a named light)");
    test::expectOnlyError("/point_light 1 0 0 0 name lamp\n/drive lamp r (frame)\n", 2, 13,
                          "'r' is not a channel of the light 'lamp'");
    test::expectOnlyError("/amb_light 1 name sky\n/drive sky px (frame)\n", 2, 12,
                          "'px' is not a channel of the ambient light 'sky'");
    test::expectOnlyError(ball + "/drive camera d (0.5)\n/drive ball d (frame)\n", 3, 13,
                          "'d' is not a channel of the sphere 'ball' ('d' drives the camera)");
    test::expectOnlyError(ball + "/drive ball px (frame)\n/key 0 ball\n/drive ball px (2)\n", 4, 1,
                          "second '/drive' of 'px' of the sphere 'ball' (the first is at 2:1)");
    test::expectOnlyError(ball + "/drive ball px frame*2\n", 2, 16,
                          "a drive's expression stands in parentheses: write '(frame*2)'");
    test::expectOnlyError(ball + "/drive ball px\n", 2, 1, "'/drive' takes 3 arguments, got 2");
    test::expectOnlyError(ball + "/drive ball px (frame*)\n", 2, 23, "unexpected ')' in the expression");
    test::expectOnlyError(ball + "/drive ball px (frme)\n", 2, 17, "unknown variable 'frme'");
    test::expectOnlyError(ball + "/drive bal px (frame)\n", 2, 8,
                          "unknown name 'bal' (did you mean 'ball'?)");
    test::expectOnlyError("/robot f2 0 0 0\n/drive f2.hed rx (frame)\n", 2, 11, "unknown part 'hed'");
}

TEST(Drives, ValuesAtFractionalFramesReplaceTheirChannelOnly) {
    const SceneDesc scene = test::sceneFromText(
        "/sphere ball 1 5 6 7 10 20 30\n"
        "/drive ball px (100*sin(time*90))\n"
        "/key 0 ball 0 0 0 0 0 0\n"
        "/key 48 ball 48 96 -48 0 0 48\n"
        "/sphere still 1 5 6 7 10 20 30\n"
        "/let k 2\n"
        "/drive still rz (frame*k)\n"
        "/let k 100\n");
    // Frame 12 at 24 fps: time 0.5, sin(45°) · 100; the keys still give py, pz and rz.
    const Transform at12 = objectFrame(scene.objects[0], 12);
    EXPECT_FLOAT_EQ(at12.translation.x, float(100 * std::sin(std::numbers::pi / 4)));
    EXPECT_FLOAT_EQ(at12.translation.y, 24.0f);
    EXPECT_FLOAT_EQ(at12.translation.z, -12.0f);
    // Fractional frames (motion blur, playback): time = frame / fps.
    const Pose at = evaluateTrack(scene.objects[0].track, 12.5, scene.objects[0].rest);
    EXPECT_FLOAT_EQ(at.position.x, float(100 * std::sin(12.5 / 24 * 90 * std::numbers::pi / 180)));
    EXPECT_FLOAT_EQ(at.position.y, 25.0f);
    EXPECT_FLOAT_EQ(at.rotation.z, 12.5f);
    // Without keys the other channels keep the rest pose; k is 2 at the /drive line.
    const Pose still = evaluateTrack(scene.objects[1].track, 7.25, scene.objects[1].rest);
    EXPECT_EQ(still.position, (Vec3{5, 6, 7}));
    EXPECT_EQ(still.rotation, (Vec3{10, 20, 14.5f}));
}

TEST(Drives, PartsLightsCameraAndColours) {
    const SceneDesc scene = test::sceneFromText(
        "/fps 10\n"
        "/camera 80 60 0.5 0 0 -300\n"
        "/robot f2 0 0 0\n"
        "/drive f2.head ry (frame*3)\n"
        "/point_light 2 0 300 0 name lamp\n"
        "/drive lamp intensity (time)\n"
        "/drive lamp py (100 + frame)\n"
        "/drive camera d (0.5 + time/10)\n"
        "/sphere ball 1 0 0 0\n"
        "/paint ball 10 20 30\n"
        "/drive ball g (frame*100)\n");
    const SceneObject& robot = scene.objects[0];
    const Pose head = evaluateTrack(robot.partTracks[std::size_t(RobotPart::Head)], 5, Pose{});
    EXPECT_EQ(head.rotation, (Vec3{0, 15, 0}));
    EXPECT_FLOAT_EQ(lightIntensityAt(scene, 0, 2, 5), 0.5f);  // time 0.5 s at 10 fps
    EXPECT_FLOAT_EQ(float(cameraDistanceAt(scene, 5)), 0.55f);
    EvaluatedFrame frame;
    evaluateFrame(scene, 1.5, frame);
    ASSERT_EQ(frame.localLights.size(), 1u);
    EXPECT_EQ(frame.localLights[0].position, (Vec3{0, 401.5f, 0}));
    // Green driven (and kept within 0..255), red and blue from /paint.
    const Vec3 ball = frame.surfaces[frame.firstPrimitive[1]].color * 255.0f;
    EXPECT_VEC_NEAR(ball, (Vec3{10, 150, 30}), 1e-4);
    evaluateFrame(scene, 9, frame);
    EXPECT_VEC_NEAR(frame.surfaces[frame.firstPrimitive[1]].color * 255.0f, (Vec3{10, 255, 30}), 1e-4);
}

TEST(Drives, AFrameWithoutAFiniteValueIsAnErrorNamingItAndTheDrive) {
    const SceneDesc scene = test::sceneFromText(
        "/sphere ball 1 0 0 0\n"
        "/key 24 ball\n"
        "  /drive ball py (100/(frame - 12))\n");
    EXPECT_FALSE(firstDriveProblem(scene, 11.0));
    EXPECT_FALSE(firstDriveProblem(scene, 12.5));
    const std::optional<std::string> problem = firstDriveProblem(scene, 12.0);
    ASSERT_TRUE(problem);
    EXPECT_EQ(*problem,
              "test.f2:3:3: error: at frame 12, '/drive ball py (100/(frame - 12))' has no finite value: "
              "division by "
              "zero");
    // A motion-blurred frame's sub-frames: the one that fails is named.
    const std::array<double, 3> times = {11.5, 12.0, 12.5};
    EXPECT_TRUE(firstDriveProblem(scene, times));
    // The picture never gets the NaN: the channel keeps its keyed value.
    EXPECT_EQ(objectFrame(scene.objects[0], 12).translation, (Vec3{0, 0, 0}));
    // Past the float range is no finite scene number either.
    const SceneDesc huge = test::sceneFromText("/sphere ball 1 0 0 0\n/drive ball px (frame*1e30*1e30)\n");
    EXPECT_FALSE(firstDriveProblem(huge, 0));
    EXPECT_NE(firstDriveProblem(huge, 1).value_or("").find("beyond the largest number"), std::string::npos);
}

constexpr const char* kDrivenScene =
    "/camera 120 90 0.5 0 40 -350\n"
    "/dir_light 1 1 -1 1\n"
    "/amb_light 0.2\n"
    "/sphere ball 30 0 0 0\n"
    "/material ball 1 1 0 1\n"
    "/drive ball px (60*sin(frame*40 + 20))\n"
    "/drive ball py (30*cos(time*500))\n"
    "/robot f2 -80 0 50 0 180 0\n"
    "/material f2 1 1 0 1\n"
    "/drive f2.head ry (35 + frame)\n"
    "/drive f2.lhand rx (if(frame < 5, -40, 40))\n"
    "/key 0 f2.lhand 0 0 0 0 0 10\n"
    "/key 10 f2.lhand 0 0 0 0 0 -10\n"
    "/drive f2 r (128 + 100*sin(frame*30))\n"
    "/drive camera rz (2)\n";

TEST(Drives, PacketAndReferencePathsGiveTheSameImage) {
    test::expectIdenticalPaths(kDrivenScene, "drives at frame 0");
}

TEST(Drives, TheAnimationProgramGivesTheObjectByObjectFramesBits) {
    const SceneDesc scene = test::sceneFromText(kDrivenScene);
    for (double t : {0.0, 2.5, 7.0, 12.25}) {
        EvaluatedFrame program;
        evaluateFrame(scene, t, program);
        // The objects one by one, as picking and the exports see them.
        std::vector<Transform> roots;
        attachedRootFrames(scene, t, roots);
        std::size_t k = 0;
        for (std::size_t i = 0; i < scene.objects.size(); ++i) {
            const SceneObject& o = scene.objects[i];
            const Transform root = worldFromRoot(scene, i, t, roots);
            if (!isModel(o.kind)) {
                const Primitive want = makePrimitive(shapeKindOf(o.kind), o.size, root);
                EXPECT_EQ(std::memcmp(&want, &program.primitives[k++], sizeof want), 0) << "t = " << t;
                continue;
            }
            const auto parts = modelPartFrames(o, root, t);
            for (std::size_t shape = 0; shape < o.model->shapes.size(); ++shape) {
                const ModelShape& s = o.model->shapes[shape];
                const Primitive want = makePrimitive(s.kind, s.size, modelShapeFrame(o, shape, parts));
                EXPECT_EQ(std::memcmp(&want, &program.primitives[k++], sizeof want), 0) << "t = " << t;
            }
        }
    }
}

}  // namespace
}  // namespace f2
