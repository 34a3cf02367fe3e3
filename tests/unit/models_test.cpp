// Models (SPEC 10.1): the robot written as text renders as /robot, every
// rule and error of the block at its place, looks on instances, parts and
// shapes, rest rotations and turned shapes.
#include "core/scene/models.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <sstream>

#include "core/anim/frame_builder.h"
#include "core/parse/parser.h"
#include "render_paths.h"
#include "robot_parts.h"
#include "test_scenes.h"

namespace f2 {
namespace {

using test::expectOnlyError;
using test::RobotPart;

std::string readSource(const std::string& relative) {
    std::ifstream in(test::sourcePath(relative));
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

/// `text` with every `/robot ` and `/human ` command made an instance of the
/// models written in tests/data/models/robot_as_model.f2.
std::string withWrittenModels(const std::string& text) {
    std::string out = readSource("tests/data/models/robot_as_model.f2");
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        if (line.starts_with("/robot ")) line = "/myrobot " + line.substr(7);
        if (line.starts_with("/human ")) line = "/myhuman " + line.substr(7);
        out += line + "\n";
    }
    return out;
}

TEST(Models, TheRobotWrittenAsAModelRendersPixelForPixelAsRobot) {
    const std::string demo = readSource("scenes/demo.f2");
    const std::string written = withWrittenModels(demo);
    ASSERT_NE(written.find("/myrobot f2"), std::string::npos);
    ASSERT_NE(written.find("/myhuman h1"), std::string::npos);
    for (double t : {0.0, 37.5, 100.0, 180.0}) {
        const Image builtIn = test::renderText(demo, t), own = test::renderText(written, t);
        ASSERT_EQ(builtIn.pixels.size(), own.pixels.size());
        std::size_t differing = 0, lit = 0;
        for (std::size_t i = 0; i < own.pixels.size(); ++i) {
            differing += !(builtIn.pixels[i] == own.pixels[i]);
            lit += !(own.pixels[i] == Rgb8{0, 0, 0});
        }
        EXPECT_EQ(differing, 0u) << "frame " << t;
        EXPECT_GT(lit, own.pixels.size() / 2) << "frame " << t;  // not a black picture
    }
}

TEST(Models, TheDocumentShowsTheRobotAsTheTestReadsIt) {
    // docs/scene-language.md quotes the file the test above renders.
    const std::string doc = readSource("docs/scene-language.md");
    const std::string model = readSource("tests/data/models/robot_as_model.f2");
    const std::string robot = model.substr(model.find("/model myrobot"),
                                           model.find("/model myhuman") - model.find("/model myrobot"));
    EXPECT_NE(doc.find(robot.substr(0, robot.find_last_of("d") + 1)), std::string::npos);
}

const char* kLamp =
    "/model lamp\n"                            // 1
    "/part base root 0 0 0\n"                  // 2
    "/part arm base 0 10 0 0 0 30\n"           // 3
    "/part head arm 0 100 0\n"                 // 4
    "/cylinder base.foot 40 10 0 5 0\n"        // 5
    "/cylinder arm.rod 4 100 0 50 0\n"         // 6
    "/box head.shade 20 10 30 0 5 0 0 90 0\n"  // 7
    "/sphere head.bulb 5 0 -5 0\n"             // 8
    "/paint head.bulb 250 250 200\n"           // 9
    "/end\n";                                  // 10

TEST(Models, APartHangsOnItsParentWithItsRestRotationUnderItsKeys) {
    const SceneDesc s = test::sceneFromText(std::string(kLamp) +
                                            "/lamp l 100 0 0\n/key 0 l.arm 0 0 0 0 0 -30\n/amb_light 1\n");
    const SceneObject& l = s.objects[0];
    ASSERT_EQ(typeNameOf(l), "lamp");
    ASSERT_EQ(l.model->parts.size(), 3u);
    EXPECT_EQ(l.model->parts[1].parent, 0);
    const std::vector<Transform> parts = modelPartFrames(l, objectFrame(l, 0), 0);
    // The arm's rest rotation (30 about z) and its key (-30) cancel: the head
    // is straight above the pivot, 10 + 100 up.
    EXPECT_NEAR(parts[2].translation.x, 100, 1e-4);
    EXPECT_NEAR(parts[2].translation.y, 110, 1e-4);
    // Without the key the arm leans by its rest rotation: the head at
    // (100 - 100 sin 30, 10 + 100 cos 30).
    const SceneDesc rest = test::sceneFromText(std::string(kLamp) + "/lamp l 100 0 0\n/amb_light 1\n");
    const std::vector<Transform> leaning =
        modelPartFrames(rest.objects[0], objectFrame(rest.objects[0], 0), 0);
    EXPECT_NEAR(leaning[2].translation.x, 50, 1e-4);
    EXPECT_NEAR(leaning[2].translation.y, 10 + 100 * std::sqrt(3.0) / 2, 1e-4);
    // The shade box is turned 90 about y about its own centre: its local x is world -z.
    const Transform shade = modelShapeFrame(rest.objects[0], 2, leaning);
    EXPECT_NEAR(shade.linear.column(0).z, -1, 1e-6);
}

TEST(Models, TheProgramAndTheReferencePathAgreeOnRestRotationsAndTurnedShapes) {
    test::expectIdenticalPaths(
        std::string(kLamp) +
            "/camera 160 120 0.5 0 60 -200\n/lamp l -40 0 0\n/lamp m 40 0 0 0 40 0\n"
            "/key 0 m.arm 0 0 0 0 0 10\n/key 0 m.head 0 0 0 20 0 0\n/material l 1 0 0 1\n"
            "/material m 1 0 0 1\n/amb_light 1\n",
        "lamps");
}

TEST(Models, LooksOnTheInstanceThePartAndTheShape) {
    const SceneDesc s = test::sceneFromText(std::string(kLamp) +
                                            "/lamp l 0 0 0\n/paint l 10 10 10\n/paint l.head 20 20 20\n"
                                            "/material l.head 1 2 3 4\n/paint l.head.shade 30 30 30\n"
                                            "/amb_light 1\n");
    const SceneObject& l = s.objects[0];
    EXPECT_EQ(l.appearance[0].color, (Color8{10, 10, 10}));       // base.foot
    EXPECT_EQ(l.appearance[1].color, (Color8{10, 10, 10}));       // arm.rod
    EXPECT_EQ(l.appearance[2].color, (Color8{30, 30, 30}));       // head.shade: its own /paint last
    EXPECT_EQ(l.appearance[3].color, (Color8{250, 250, 200}));    // head.bulb: painted in the model
    EXPECT_EQ(l.appearance[3].material, (Material{1, 2, 3, 4}));  // a /material reaches every shape
    EXPECT_EQ(l.appearance[0].material, Material{});
    // Only the shape itself repaints a shape painted in its model.
    const SceneDesc t =
        test::sceneFromText(std::string(kLamp) + "/lamp l 0 0 0\n/paint l.head.bulb 1 2 3\n/amb_light 1\n");
    EXPECT_EQ(t.objects[0].appearance[3].color, (Color8{1, 2, 3}));
}

TEST(Models, ColourAndVisibleKeysReachAShape) {
    const SceneDesc s = test::sceneFromText(std::string(kLamp) +
                                            "/lamp l 0 0 0\n/key 0 l.head.bulb colour 0 0 0\n"
                                            "/key 10 l.head.bulb colour 200 100 0\n/key 0 l colour 0 0 255\n"
                                            "/key 5 l.head.shade visible 0\n/amb_light 1\n");
    EvaluatedFrame frame;
    evaluateFrame(s, 5, frame);
    const std::uint32_t first = frame.firstPrimitive[0];
    EXPECT_NEAR(frame.surfaces[first + 3].color.x, 100 / 255.0f, 1e-6f);  // the bulb's own track
    EXPECT_NEAR(frame.surfaces[first + 0].color.z, 1.0f, 1e-6f);          // the instance's
    ASSERT_EQ(frame.rayMask.size(), frame.primitives.size());
    EXPECT_NE(frame.rayMask[first + 2] & ray_mask::kHidden, 0);
    EXPECT_EQ(frame.rayMask[first + 3] & ray_mask::kHidden, 0);
}

TEST(Models, LoopsVariablesAndIncludesStandInsideABlock) {
    const SceneDesc s = test::sceneFromText(
        "/let n 3\n/model chain\n/part p0 root 0 0 0\n/repeat i 1 (n - 1)\n/part p{i} p{i - 1} 0 10 0\n/end\n"
        "/repeat i 0 (n - 1)\n/sphere p{i}.ball 4 0 0 0\n/end\n/end\n/chain c 0 0 0\n/amb_light 1\n");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].model->parts.size(), 3u);
    EXPECT_EQ(s.objects[0].model->shapes.size(), 3u);
    EXPECT_EQ(s.objects[0].model->parts[2].parent, 1);
    EXPECT_EQ(s.primitiveCount(), 3u);
    // A model inside a loop is defined on the first pass; the second is an error there.
    expectOnlyError("/repeat i 0 1\n/model m\n/part a root 0 0 0\n/sphere a.b 1 0 0 0\n/end\n/end\n", 2, 8,
                    "model type 'm' is already defined (at 2:8)");
}

TEST(ModelErrors, TypeNames) {
    const std::string body = "/part a root 0 0 0\n/sphere a.b 1 0 0 0\n/end\n";
    expectOnlyError("/model 9x\n" + body, 1, 8, "invalid model type '9x'");
    expectOnlyError("/model box\n" + body, 1, 8, "'box' cannot name a model type: '/box' is a command");
    expectOnlyError("/model root\n" + body, 1, 8, "'root' cannot name a model type: it is a reserved word");
    expectOnlyError("/model camera\n" + body, 1, 8, "'camera' cannot name a model type");
    expectOnlyError("/model robot\n" + body, 1, 8, "'robot' is a built-in model type");
    expectOnlyError("/model m\n" + body + "/model m\n" + body, 5, 8,
                    "model type 'm' is already defined (at 1:8)");
    expectOnlyError("/model\n" + body, 1, 1, "'/model' takes 1 argument, got 0");
}

TEST(ModelErrors, PartsAndShapes) {
    expectOnlyError("/model m\n/part a b 0 0 0\n/sphere a.s 1 0 0 0\n/end\n", 2, 9,
                    "unknown parent 'b' (expected 'root' or a part declared before this one)");
    expectOnlyError("/model m\n/part a root 0 0 0\n/part a root 0 0 0\n/sphere a.s 1 0 0 0\n/end\n", 3, 7,
                    "duplicate part 'a' in 'm'");
    expectOnlyError("/model m\n/part root root 0 0 0\n/end\n", 2, 7, "'root' is the model's own frame");
    expectOnlyError("/model m\n/part a root 0 0 0\n/sphere b.s 1 0 0 0\n/end\n", 3, 9,
                    "unknown part 'b' of 'm' (expected a)");
    expectOnlyError("/model m\n/part a root 0 0 0\n/sphere a.s 1 0 0 0\n/box a.s 1 1 1 0 0 0\n/end\n", 4, 6,
                    "duplicate shape 'a.s' in 'm'");
    expectOnlyError("/model m\n/part a root 0 0 0\n/sphere as 1 0 0 0\n/end\n", 3, 9,
                    "a shape of a model is named '<part>.<shape>', got 'as'");
    expectOnlyError("/model m\n/part a root 0 0 0\n/end\n", 1, 1, "model 'm' has no shapes");
    expectOnlyError("/model m\n/part a root 0 0 0\n/sphere a.s -1 0 0 0\n/end\n", 3, 13,
                    "radius must be > 0");
    expectOnlyError("/model m\n/part a root 0 0 0\n/sphere a.s 1 0 0 0\n/paint a 1 2 3\n/end\n", 4, 8,
                    "inside '/model' '/paint' takes a shape of the model, '<part>.<shape>', got 'a'");
    expectOnlyError("/model m\n/part a root 0 0 0\n/sphere a.s 1 0 0 0\n/paint a.t 1 2 3\n/end\n", 4, 10,
                    "unknown shape 't' on the part 'a' of 'm'");
    expectOnlyError("/part a root 0 0 0\n", 1, 1, "'/part' stands only inside a '/model' block");
}

TEST(ModelErrors, Limits) {
    std::string parts = "/model m\n";
    for (int i = 0; i <= kMaxModelParts; ++i) parts += "/part p" + std::to_string(i) + " root 0 0 0\n";
    parts += "/sphere p0.s 1 0 0 0\n/end\n";
    expectOnlyError(parts, 2 + kMaxModelParts, 1, "too many parts: at most 64 in a model");
    std::string shapes = "/model m\n/part a root 0 0 0\n";
    for (int i = 0; i <= kMaxModelShapes; ++i) shapes += "/sphere a.s" + std::to_string(i) + " 1 0 0 0\n";
    shapes += "/end\n";
    expectOnlyError(shapes, 3 + kMaxModelShapes, 1, "too many shapes: at most 256 in a model");
    std::string types;
    for (int i = 0; i < kMaxModelTypes - 1; ++i)
        types += "/model m" + std::to_string(i) + "\n/part a root 0 0 0\n/sphere a.s 1 0 0 0\n/end\n";
    expectOnlyError(types, 1 + 4 * (kMaxModelTypes - 2), 8,
                    "too many model types: at most 1000 allowed (the robot and the human count)");
}

TEST(ModelErrors, WhatStandsInsideABlock) {
    const std::string open = "/model m\n/part a root 0 0 0\n/sphere a.s 1 0 0 0\n";
    expectOnlyError(open + "/key 0 a 0 0 0 0 0 0\n/end\n", 4, 1,
                    "'/key' cannot stand inside a '/model' block");
    expectOnlyError(open + "/model n\n/part b root 0 0 0\n/end\n/end\n", 4, 1,
                    "a '/model' cannot stand inside another (the block of 'm' is open until its '/end')");
    expectOnlyError(open + "/fly\n/end\n", 4, 1, "unknown command '/fly'");
    expectOnlyError(open, 1, 1, "'/model' without '/end' in the same file");
    expectOnlyError(open + "/end x\n", 4, 6, "'/end' takes no arguments");
}

TEST(ModelErrors, InstancesAndShapesAsTargets) {
    const std::string lamp = std::string(kLamp) + "/lamp l 0 0 0\n/amb_light 1\n";  // lines 11, 12
    expectOnlyError("/lamp l 0 0 0\n" + std::string(kLamp), 1, 1, "unknown command '/lamp'");
    expectOnlyError(lamp + "/key 0 l.head.bulb 1 2 3 4 5 6\n", 13, 15, "'/key' does not apply to a shape");
    expectOnlyError(lamp + "/attach l.head.bulb l\n", 13, 9,
                    "only a whole object or the camera can be attached");
    expectOnlyError(lamp + "/sphere s 1 0 0 0\n/attach s l.head.bulb\n", 14, 18,
                    "'/attach' does not apply to a shape");
    expectOnlyError(lamp + "/interp l.head.bulb ease\n", 13, 16, "'/interp' does not apply to a shape");
    expectOnlyError(lamp + "/look_at l.head.bulb\n", 13, 17, "'/look_at' does not apply to a shape");
    expectOnlyError(lamp + "/paint l.leg 1 2 3\n", 13, 10, "unknown part 'leg' (expected base, arm or head)");
    expectOnlyError(lamp + "/paint l.head.lid 1 2 3\n", 13, 15,
                    "unknown shape 'lid' on the part 'head' of 'lamp' (expected shade, bulb)");
    expectOnlyError(lamp + "/lamp l 1 2 3\n", 13, 7, "duplicate name 'l'");
    expectOnlyError(lamp + "/lamp k 1 2\n", 13, 1, "'/lamp' takes 4 or 7 arguments, got 3");
}

}  // namespace
}  // namespace f2

namespace f2 {
namespace {

using test::expectOnlyError;

const char* kParamLamp =
    "/model lamp arm 100 shade 20\n"           // 1
    "/let half (arm / 2)\n"                    // 2
    "/part base root 0 0 0\n"                  // 3
    "/part head base 0 (arm) 0\n"              // 4
    "/cylinder base.rod 4 (arm) 0 (half) 0\n"  // 5
    "/sphere head.shade (shade) 0 0 0\n"       // 6
    "/end\n";                                  // 7

TEST(ModelParams, EachInstanceReadsTheBlockWithItsValues) {
    const SceneDesc s = test::sceneFromText(std::string(kParamLamp) +
                                            "/lamp a 0 0 0\n/lamp b 0 0 0 shade 5 arm 40\n"
                                            "/lamp c 0 0 0 0 90 0 arm 60\n/amb_light 1\n");
    ASSERT_EQ(s.objects.size(), 3u);
    const ModelType& a = *s.objects[0].model;
    const ModelType& b = *s.objects[1].model;
    const ModelType& c = *s.objects[2].model;
    EXPECT_EQ(a.shapes[0].size.y, 100);  // the defaults
    EXPECT_EQ(a.shapes[1].size.x, 20);
    EXPECT_EQ(b.shapes[0].size.y, 40);    // any order
    EXPECT_EQ(b.shapes[0].centre.y, 20);  // its /let from its own value
    EXPECT_EQ(b.shapes[1].size.x, 5);
    EXPECT_EQ(b.parts[1].pivot.y, 40);
    EXPECT_EQ(c.shapes[0].size.y, 60);
    EXPECT_EQ(c.shapes[1].size.x, 20);  // the default where none is given
    EXPECT_EQ(s.objects[2].rest.rotation.y, 90);
    EXPECT_EQ(b.name, "lamp");
    EXPECT_EQ(s.objects[0].model, s.models[0]);  // without values the type as defined
    // Keys and looks reach the parts and shapes by the type's names.
    const SceneDesc keyed = test::sceneFromText(std::string(kParamLamp) +
                                                "/lamp b 0 0 0 arm 40\n/key 0 b.head 0 0 0 10 0 0\n"
                                                "/paint b.head.shade 1 2 3\n/amb_light 1\n");
    EXPECT_EQ(keyed.objects[0].partTracks[1].keys.size(), 1u);
    EXPECT_EQ(keyed.objects[0].appearance[1].color, (Color8{1, 2, 3}));
}

TEST(ModelParams, TheBlocksVariablesStayInside) {
    // `half` and the parameters are the block's: outside, `arm` is the file's own.
    const SceneDesc s = test::sceneFromText("/let arm 7\n" + std::string(kParamLamp) +
                                            "/lamp b 0 0 0 arm 40\n/sphere s (arm) 0 0 0\n/amb_light 1\n");
    EXPECT_EQ(s.objects[1].size.x, 7);
    expectOnlyError(std::string(kParamLamp) + "/sphere s (half) 0 0 0\n", 8, 12, "unknown variable 'half'");
    expectOnlyError(std::string(kParamLamp) + "/lamp b 0 0 0 arm 40\n/sphere s (shade) 0 0 0\n", 9, 12,
                    "unknown variable 'shade'");
}

TEST(ModelParams, Errors) {
    const std::string lamp = kParamLamp;
    expectOnlyError(lamp + "/lamp b 0 0 0 leg 3\n", 8, 15,
                    "unknown parameter 'leg' of 'lamp' (its parameters: arm and shade)");
    expectOnlyError(lamp + "/lamp b 0 0 0 arm 3 arm 4\n", 8, 21, "the parameter 'arm' is given twice");
    expectOnlyError(lamp + "/lamp b 0 0 0 arm\n", 8, 15, "the parameter 'arm' needs a value");
    expectOnlyError(lamp + "/lamp b 0 0 0 arm x\n", 8, 19, "expected a number, got 'x'");
    expectOnlyError("/model m a\n/part p root 0 0 0\n/sphere p.s 1 0 0 0\n/end\n", 1, 10,
                    "the parameter 'a' needs a default value");
    expectOnlyError("/model m a 1 a 2\n/part p root 0 0 0\n/sphere p.s 1 0 0 0\n/end\n", 1, 14,
                    "the parameter 'a' is given twice");
    expectOnlyError("/model m pi 1\n/part p root 0 0 0\n/sphere p.s 1 0 0 0\n/end\n", 1, 10,
                    "'pi' is a constant; a parameter cannot take its name");
    expectOnlyError("/robot r 0 0 0 arm 3\n", 1, 16,
                    "unknown parameter 'arm' of 'robot' (it has no parameters)");
    // An error in the block for one instance is at the block's line, and says which instance.
    expectOnlyError(lamp + "/lamp b 0 0 0 shade -1\n", 6, 20, "radius must be > 0, got -1 (in /lamp b)");
    // Names may not depend on a parameter.
    expectOnlyError(
        "/model m n 1\n/part p root 0 0 0\n/repeat i 1 (n)\n/sphere p.s{i} 1 0 0 0\n/end\n/end\n"
        "/m a 0 0 0 n 2\n",
        1, 8, "the parts and shapes of 'm' must not depend on its parameters");
}

}  // namespace
}  // namespace f2

namespace f2 {
namespace {

TEST(ModelParams, ThreeLampsFromOneModelInTwelveLinesOrFewer) {
    // The trial's desk lamps (issue 28): one model, three instances with
    // their own values, a light riding on each head, one lamp nodding.
    const std::string text = readSource("tests/data/models/three_lamps.f2");
    const std::string lamps = text.substr(text.find("# The three lamps"));
    int lines = 0;
    std::istringstream in(lamps);
    for (std::string line; std::getline(in, line);) lines += !line.empty() && line[0] != '#';
    EXPECT_LE(lines, 12);
    const SceneDesc s = test::sceneFromText(text);
    ASSERT_EQ(s.models.size(), 1u);
    EXPECT_EQ(s.objects.size(), 4u);  // the desk and three lamps
    EXPECT_EQ(s.lightMotions.size(), 3u);
    EXPECT_EQ(s.objects[2].model->parts[1].pivot.y, 12);
    EXPECT_EQ(s.objects[2].model->shapes[1].size.y, 70);                  // b's arm
    EXPECT_EQ(s.objects[3].model->parts[2].restRotation.z, -80);          // c's nod
    EXPECT_EQ(s.objects[2].appearance[3].color, (Color8{255, 120, 70}));  // b's bulb, painted by its values
    // Lit by the three bulbs, and the nodding lamp moves.
    const Image first = test::renderText(text, 0), later = test::renderText(text, 36);
    std::size_t bright = 0, moved = 0;
    for (std::size_t i = 0; i < first.pixels.size(); ++i) {
        bright += first.pixels[i].r > 150;
        moved += !(first.pixels[i] == later.pixels[i]);
    }
    EXPECT_GT(bright, 100u);
    EXPECT_GT(moved, 100u);
}

}  // namespace
}  // namespace f2

namespace f2 {
namespace {

TEST(Models, OnePartsFrameIsThatOfAllThePartsBitForBit) {
    // modelPartFrame (attachments to a part, every frame) against modelPartFrames.
    const SceneDesc s =
        test::sceneFromText(std::string(kLamp) +
                            "/lamp l 10 20 30 0 40 0\n/key 0 l.arm 1 2 3 10 20 30\n"
                            "/key 10 l.arm 0 0 0 -30 0 5\n/key 0 l.head 0 4 0 0 0 90\n/amb_light 1\n");
    const SceneObject& l = s.objects[0];
    for (double t : {0.0, 3.25, 10.0}) {
        const Transform root = objectFrame(l, t);
        const std::vector<Transform> all = modelPartFrames(l, root, t);
        for (int part = 0; part < int(all.size()); ++part) {
            const Transform one = modelPartFrame(l, part, root, t);
            EXPECT_EQ(std::memcmp(&one, &all[std::size_t(part)], sizeof one), 0)
                << "part " << part << " t " << t;
        }
    }
}

}  // namespace
}  // namespace f2
