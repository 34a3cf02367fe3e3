// Scene language (SPEC 2-7): every command's happy path, every error kind with
// its exact place, the limits, and robustness against hostile input.
#include "core/parse/parser.h"

#include <gtest/gtest.h>

#include <chrono>
#include <clocale>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <locale>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/parse/lexer.h"
#include "core/parse/number.h"
#include "core/scene/models.h"
#include "robot_parts.h"
#include "test_scenes.h"

namespace f2 {

using test::RobotPart;
namespace {

namespace fs = std::filesystem;

constexpr const char* kFile = "t.f2";

std::string dump(const ParseResult& r) { return test::formatDiagnostics(r); }

/// Parses text that must be valid (warnings allowed) and returns the scene.
SceneDesc parseOk(std::string_view text) {
    ParseResult r = parseScene(text, kFile);
    EXPECT_TRUE(r.ok()) << dump(r);
    EXPECT_FALSE(hasErrors(r.diagnostics)) << dump(r);
    return r.scene.value_or(SceneDesc{});
}

/// Parses text with exactly one diagnostic, an error, and checks where it is
/// and that its message contains `what`.
void expectError(std::string_view text, int line, int column, std::string_view what) {
    test::expectOnlyError(text, line, column, what);
}

const SceneObject& object(const SceneDesc& s, std::string_view name) {
    for (const SceneObject& o : s.objects) {
        if (o.name == name) return o;
    }
    ADD_FAILURE() << "no object " << name;
    static const SceneObject kNone;
    return kNone;
}

/// The look of a part's main shape (the head's face, not its eyes).
const Appearance& part(const SceneObject& o, int p) {
    return o.appearance[static_cast<std::size_t>(o.model->mainShapeOf(static_cast<int>(p)))];
}
const Track& partTrack(const SceneObject& o, int p) { return o.partTracks[static_cast<std::size_t>(p)]; }

Pose makePose(float px, float py, float pz, float rx, float ry, float rz) {
    return {{px, py, pz}, {rx, ry, rz}};
}

std::vector<double> framesOf(const Track& t) {
    std::vector<double> frames;
    for (const Key& k : t.keys) frames.push_back(k.time);
    return frames;
}

/// The project's source tree (tests/CMakeLists.txt defines F2_SOURCE_DIR).
fs::path sourceRoot() {
#ifdef F2_SOURCE_DIR
    return fs::path(F2_SOURCE_DIR);
#else
    return fs::path(__FILE__).parent_path() / "../..";
#endif
}

// Diagnostic formatting

TEST(Diagnostic, FormatsLikeACompiler) {
    // Filled member by member: GCC 12 -O3 warns falsely (maybe-uninitialized) on the aggregate form.
    Diagnostic e;
    e.loc.file = "scene.f2";
    e.loc.line = 12;
    e.loc.column = 5;
    e.message = "unknown command '/cylnder'";
    EXPECT_EQ(e.format(), "scene.f2:12:5: error: unknown command '/cylnder'");
    Diagnostic w;
    w.loc.file = "a.f2";
    w.loc.line = 1;
    w.loc.column = 1;
    w.severity = Severity::Warning;
    w.message = "x";
    EXPECT_EQ(w.format(), "a.f2:1:1: warning: x");
    EXPECT_TRUE(hasErrors({w, e}));
    EXPECT_FALSE(hasErrors({w}));
    EXPECT_FALSE(hasErrors({}));
}

// Numbers

TEST(Number, AcceptsDecimalForms) {
    const std::pair<const char*, double> cases[] = {
        {"0", 0},  {"-130", -130}, {"0.75", 0.75}, {"1e3", 1000}, {"1E3", 1000},      {".5", 0.5},
        {"5.", 5}, {"+5", 5},      {"-0", 0},      {"007", 7},    {"2.5e-3", 0.0025}, {"3.4e38", 3.4e38},
    };
    for (auto [text, value] : cases) {
        const ParsedNumber n = parseNumber(text);
        EXPECT_EQ(n.status, NumberStatus::Ok) << text;
        EXPECT_DOUBLE_EQ(n.value, value) << text;
    }
    EXPECT_FALSE(std::signbit(parseNumber("-0").value));  // -0 is plain 0
}

TEST(Number, RejectsEverythingElse) {
    const std::pair<const char*, NumberStatus> cases[] = {
        {"", NumberStatus::NotANumber},        {"abc", NumberStatus::NotANumber},
        {"1.5x", NumberStatus::NotANumber},    {"1,5", NumberStatus::NotANumber},
        {"1e", NumberStatus::NotANumber},      {"+-1", NumberStatus::NotANumber},
        {"++1", NumberStatus::NotANumber},     {"+", NumberStatus::NotANumber},
        {"-", NumberStatus::NotANumber},       {"1 ", NumberStatus::NotANumber},
        {"--1", NumberStatus::NotANumber},     {"0x10", NumberStatus::Hexadecimal},
        {"-0X1p3", NumberStatus::Hexadecimal}, {"nan", NumberStatus::NotFinite},
        {"-nan", NumberStatus::NotFinite},     {"NaN", NumberStatus::NotFinite},
        {"inf", NumberStatus::NotFinite},      {"-infinity", NumberStatus::NotFinite},
        {"1e400", NumberStatus::OutOfRange},   {"-1e400", NumberStatus::OutOfRange},
        {"1e39", NumberStatus::OutOfRange},    {"1e-400", NumberStatus::OutOfRange},
    };
    for (auto [text, status] : cases) EXPECT_EQ(parseNumber(text).status, status) << "'" << text << "'";
}

// Lexer

TEST(Lexer, SplitsAtSpacesAndTabsUntilAComment) {
    LineTokens t;
    tokenizeLine("  /sphere\ts1  1 # comment 2 3", t);
    ASSERT_EQ(t.count, 3);
    EXPECT_EQ(t.tokens[0].text, "/sphere");
    EXPECT_EQ(t.tokens[0].column, 3);
    EXPECT_EQ(t.tokens[1].text, "s1");
    EXPECT_EQ(t.tokens[1].column, 11);
    EXPECT_EQ(t.tokens[2].text, "1");
    EXPECT_EQ(t.tokens[2].column, 15);
    tokenizeLine("a#b", t);  // '#' inside a token starts a comment too
    ASSERT_EQ(t.count, 1);
    EXPECT_EQ(t.tokens[0].text, "a");
}

TEST(Lexer, CountsTokensBeyondTheStoredOnes) {
    LineTokens t;
    std::string line;
    for (int i = 0; i < 40; ++i) line += "x ";
    tokenizeLine(line, t);
    EXPECT_EQ(t.count, 40);
}

TEST(Lexer, LinesHandleCrLfBomAndMissingFinalNewline) {
    LineReader reader(
        "\xEF\xBB\xBF"
        "a\r\nb\n\nc\r");
    std::vector<std::string> lines;
    SourceLine l;
    while (reader.next(l)) {
        lines.emplace_back(l.text);
        EXPECT_EQ(l.number, static_cast<int>(lines.size()));
    }
    EXPECT_EQ(lines, (std::vector<std::string>{"a", "b", "", "c"}));
}

TEST(Lexer, QuotedEscapesControlBytesAndInvalidUtf8AndCutsLongTokens) {
    EXPECT_EQ(quoteToken("abc"), "'abc'");
    EXPECT_EQ(quoteToken(std::string_view("a\0b", 3)), "'a\\x00b'");
    EXPECT_EQ(quoteToken("\xff\xfe"), "'\\xff\\xfe'");
    EXPECT_EQ(quoteToken("\xd1\x80\xd0\xbe"), "'\xd1\x80\xd0\xbe'");  // valid UTF-8 (Cyrillic) stays
    EXPECT_EQ(quoteToken("\xed\xa0\x80"), "'\\xed\\xa0\\x80'");       // a surrogate is not valid UTF-8
    EXPECT_EQ(quoteToken("\xc0\xaf"), "'\\xc0\\xaf'");                // overlong '/'
    const std::string longToken(1000, 'z');
    const std::string q = quoteToken(longToken);
    EXPECT_LT(q.size(), 100u);
    EXPECT_NE(q.find("..."), std::string::npos);
}

// Happy paths

TEST(Parser, EmptySceneHasSpecDefaults) {
    const SceneDesc s = parseOk("");
    EXPECT_EQ(s.camera.width, 800);
    EXPECT_EQ(s.camera.height, 600);
    EXPECT_DOUBLE_EQ(s.camera.distance, 0.5);
    EXPECT_EQ(s.camera.pose, Pose{});
    EXPECT_EQ(s.ambient, 0.0f);
    EXPECT_TRUE(s.lights.empty());
    EXPECT_EQ(s.background, (Color8{0, 0, 0}));
    EXPECT_EQ(s.fps, 24);
    EXPECT_TRUE(s.objects.empty());
}

TEST(Parser, BlankLinesCommentsAndIndentationAreIgnored) {
    const SceneDesc s =
        parseOk("\n   \n\t\n# a comment\n  # indented comment\n\t/fps 30   # trailing comment\n\n");
    EXPECT_EQ(s.fps, 30);
}

TEST(Parser, CameraWithThreeSixOrNineArguments) {
    SceneDesc s = parseOk("/camera 640 480 0.75\n");
    EXPECT_EQ(s.camera.width, 640);
    EXPECT_EQ(s.camera.height, 480);
    EXPECT_DOUBLE_EQ(s.camera.distance, 0.75);
    EXPECT_EQ(s.camera.pose, Pose{});

    s = parseOk("/camera 320 200 1 1 2 3\n");
    EXPECT_EQ(s.camera.pose, makePose(1, 2, 3, 0, 0, 0));

    s = parseOk("/camera 1e3 1E2 2 1 2 3 10 -20 30\n");
    EXPECT_EQ(s.camera.width, 1000);
    EXPECT_EQ(s.camera.height, 100);
    EXPECT_EQ(s.camera.pose, makePose(1, 2, 3, 10, -20, 30));
}

TEST(Parser, CameraAtTheLimits) {
    SceneDesc s = parseOk("/camera 16384 4096 1\n");  // exactly 2^26 pixels
    EXPECT_EQ(s.camera.width, 16384);
    EXPECT_EQ(s.camera.height, 4096);
    s = parseOk("/camera 1 16384 1\n");
    EXPECT_EQ(s.camera.height, 16384);
}

TEST(Parser, AmbientLightsAddUp) {
    const SceneDesc s = parseOk("/amb_light 0.25\n/amb_light 0.5\n/amb_light 0\n");
    EXPECT_FLOAT_EQ(s.ambient, 0.75f);
}

TEST(Parser, DirectionalLightsAreKeptAsWritten) {
    const SceneDesc s = parseOk("/dir_light 0.75 0 -0.2 1\n/dir_light 0 3 0 0\n");
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_FLOAT_EQ(s.lights[0].intensity, 0.75f);
    EXPECT_EQ(s.lights[0].direction, (Vec3{0, -0.2f, 1}));
    EXPECT_FLOAT_EQ(s.lights[1].intensity, 0.0f);
    EXPECT_EQ(s.lights[1].direction, (Vec3{3, 0, 0}));
}

TEST(Parser, Background) {
    EXPECT_EQ(parseOk("/background 1 2 255\n").background, (Color8{1, 2, 255}));
    EXPECT_EQ(parseOk("/background 0 -0 2.55e2\n").background, (Color8{0, 0, 255}));
}

TEST(Parser, Fps) {
    EXPECT_EQ(parseOk("/fps 1\n").fps, 1);
    EXPECT_EQ(parseOk("/fps 60.0\n").fps, 60);
}

TEST(Parser, PrimitivesWithAndWithoutRotation) {
    const SceneDesc s = parseOk(
        "/sphere s 2.5 1 2 3\n"
        "/sphere s_rot 1 0 0 0 10 20 30\n"
        "/cylinder c 4 5 -1 -2 -3\n"
        "/cylinder c_rot 4 5 0 0 0 0 90 0\n"
        "/box b 1 2 3 4 5 6\n"
        "/box B 1 2 3 4 5 6 7 8 9\n");
    ASSERT_EQ(s.objects.size(), 6u);
    const SceneObject& sphere = s.objects[0];
    EXPECT_EQ(sphere.name, "s");
    EXPECT_EQ(sphere.kind, ObjectKind::Sphere);
    EXPECT_FLOAT_EQ(sphere.size.x, 2.5f);
    EXPECT_EQ(sphere.rest, makePose(1, 2, 3, 0, 0, 0));
    EXPECT_EQ(s.objects[1].rest, makePose(0, 0, 0, 10, 20, 30));

    const SceneObject& cyl = s.objects[2];
    EXPECT_EQ(cyl.kind, ObjectKind::Cylinder);
    EXPECT_EQ(cyl.size, (Vec3{4, 5, 0}));
    EXPECT_EQ(cyl.rest, makePose(-1, -2, -3, 0, 0, 0));
    EXPECT_EQ(s.objects[3].rest.rotation, (Vec3{0, 90, 0}));

    const SceneObject& box = s.objects[4];
    EXPECT_EQ(box.kind, ObjectKind::Box);
    EXPECT_EQ(box.size, (Vec3{1, 2, 3}));
    EXPECT_EQ(box.rest, makePose(4, 5, 6, 0, 0, 0));
    EXPECT_EQ(s.objects[5].name, "B");  // names are case-sensitive
    EXPECT_EQ(s.objects[5].rest, makePose(4, 5, 6, 7, 8, 9));

    // Default appearance and no animation.
    for (const SceneObject& o : s.objects) {
        EXPECT_EQ(o.appearance[0].color, (Color8{200, 200, 200}));
        EXPECT_EQ(o.appearance[0].material, (Material{1, 1, 0.3f, 32}));
        EXPECT_TRUE(o.track.keys.empty());
        EXPECT_EQ(o.track.interpolation, Interpolation::Linear);
    }
}

TEST(Parser, RobotAndHuman) {
    const SceneDesc s = parseOk("/robot r1 0 0 200 0 180 0\n/human _h2 1 2 3\n");
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(typeNameOf(s.objects[0]), "robot");
    EXPECT_EQ(s.objects[0].rest, makePose(0, 0, 200, 0, 180, 0));
    EXPECT_EQ(typeNameOf(s.objects[1]), "human");
    EXPECT_EQ(s.objects[1].name, "_h2");
    EXPECT_EQ(s.objects[1].rest, makePose(1, 2, 3, 0, 0, 0));
    EXPECT_EQ(s.primitiveCount(), 10u);
}

TEST(Parser, PaintPrimitiveModelAndPart) {
    const SceneDesc s = parseOk(
        "/sphere s 1 0 0 0\n/robot r 0 0 0\n/human h 0 0 0\n"
        "/paint s 1 2 3\n/paint r 10 20 30\n/paint h.head 7 8 9\n");
    EXPECT_EQ(object(s, "s").appearance[0].color, (Color8{1, 2, 3}));
    // Every shape of the robot but its eyes, painted in the model (SPEC 10.1).
    const SceneObject& r = object(s, "r");
    for (std::size_t k = 0; k < r.appearance.size(); ++k)
        EXPECT_EQ(r.appearance[k].color,
                  (r.model->shapes[k].ownColor ? Color8{20, 20, 20} : Color8{10, 20, 30}));
    const SceneObject& h = object(s, "h");
    EXPECT_EQ(part(h, RobotPart::Head).color, (Color8{7, 8, 9}));
    EXPECT_EQ(part(h, RobotPart::Body).color, (Color8{200, 200, 200}));
    EXPECT_EQ(part(h, RobotPart::LHand).color, (Color8{200, 200, 200}));
}

TEST(Parser, PaintAppliesInFileOrder) {
    // A part painted before its robot is repainted by the robot's /paint...
    SceneDesc s = parseOk("/robot r 0 0 0\n/paint r.head 1 1 1\n/paint r 2 2 2\n");
    EXPECT_EQ(part(object(s, "r"), RobotPart::Head).color, (Color8{2, 2, 2}));
    // ...and a part painted after keeps its own colour.
    s = parseOk("/robot r 0 0 0\n/paint r 2 2 2\n/paint r.lhand 1 1 1\n");
    const SceneObject& r = object(s, "r");
    EXPECT_EQ(part(r, RobotPart::LHand).color, (Color8{1, 1, 1}));
    EXPECT_EQ(part(r, RobotPart::RHand).color, (Color8{2, 2, 2}));
    EXPECT_EQ(part(r, RobotPart::Head).color, (Color8{2, 2, 2}));
    EXPECT_EQ(part(r, RobotPart::Body).color, (Color8{2, 2, 2}));
}

TEST(Parser, MaterialPrimitiveModelAndPartInFileOrder) {
    const SceneDesc s = parseOk(
        "/box b 1 1 1 0 0 0\n/robot r 0 0 0\n"
        "/material b 0.5 0.25 0 1\n"
        "/material r.head 0 0 0 2\n"
        "/material r 0.1 0.2 0.3 4\n"
        "/material r.rhand 1 2 3 5\n");
    EXPECT_EQ(object(s, "b").appearance[0].material, (Material{0.5f, 0.25f, 0, 1}));
    const SceneObject& r = object(s, "r");
    EXPECT_EQ(part(r, RobotPart::Head).material, (Material{0.1f, 0.2f, 0.3f, 4}));
    EXPECT_EQ(part(r, RobotPart::Body).material, (Material{0.1f, 0.2f, 0.3f, 4}));
    EXPECT_EQ(part(r, RobotPart::LHand).material, (Material{0.1f, 0.2f, 0.3f, 4}));
    EXPECT_EQ(part(r, RobotPart::RHand).material, (Material{1, 2, 3, 5}));
    // Material and colour are independent.
    EXPECT_EQ(part(r, RobotPart::RHand).color, (Color8{200, 200, 200}));
}

TEST(Parser, AnimAcceptsBothFormsAndChangesNothing) {
    const std::string base = "/robot r1 0 0 0\n/sphere s 1 0 0 0\n";
    const SceneDesc plain = parseOk(base);
    const SceneDesc s = parseOk(base + "/anim r1\n/anim s\n/anim r1.lhand\n/anim r1 rhand\n/anim r1 body\n");
    ASSERT_EQ(s.objects.size(), plain.objects.size());
    EXPECT_TRUE(object(s, "r1").track.keys.empty());
    for (const Track& t : object(s, "r1").partTracks) EXPECT_TRUE(t.keys.empty());
    EXPECT_EQ(s.lastFrame(), 0);
}

TEST(Parser, KeyWithoutNumbersUsesRestState) {
    const SceneDesc s = parseOk(
        "/robot r1 1 2 3 4 5 6\n"
        "/key 7 r1\n"
        "/key 8 r1.head\n");
    const SceneObject& r = object(s, "r1");
    ASSERT_EQ(r.track.keys.size(), 1u);
    EXPECT_EQ(r.track.keys[0].time, 7);
    EXPECT_EQ(r.track.keys[0].pose, r.rest);  // the object as created
    const Track& head = partTrack(r, RobotPart::Head);
    ASSERT_EQ(head.keys.size(), 1u);
    EXPECT_EQ(head.keys[0].time, 8);
    EXPECT_EQ(head.keys[0].pose, Pose{});  // zero offset and rotation
    EXPECT_TRUE(partTrack(r, RobotPart::Body).keys.empty());
    EXPECT_EQ(s.lastFrame(), 8);
}

TEST(Parser, KeyWithSixNumbersOnObjectPrimitiveAndPart) {
    const SceneDesc s = parseOk(
        "/robot r1 0 0 0\n/box b 1 1 1 0 0 0\n"
        "/key 5 r1 1 2 3 4 5 6\n"
        "/key 1e1 b -1 -2 -3 -4 -5 -6\n"
        "/key 15 r1.lhand 0 0 0 120 45 0\n");
    EXPECT_EQ(object(s, "r1").track.keys[0].pose, makePose(1, 2, 3, 4, 5, 6));
    EXPECT_EQ(object(s, "b").track.keys[0].time, 10);
    EXPECT_EQ(object(s, "b").track.keys[0].pose, makePose(-1, -2, -3, -4, -5, -6));
    const Track& l = partTrack(object(s, "r1"), RobotPart::LHand);
    ASSERT_EQ(l.keys.size(), 1u);
    EXPECT_EQ(l.keys[0].pose, makePose(0, 0, 0, 120, 45, 0));
    EXPECT_EQ(s.lastFrame(), 15);
}

TEST(Parser, KeysAreSortedByFrame) {
    const SceneDesc s = parseOk(
        "/sphere s 1 0 0 0\n"
        "/key 30 s 3 0 0 0 0 0\n/key 10 s 1 0 0 0 0 0\n/key 20 s 2 0 0 0 0 0\n/key 0 s\n");
    const Track& t = object(s, "s").track;
    EXPECT_EQ(framesOf(t), (std::vector<double>{0, 10, 20, 30}));
    EXPECT_FLOAT_EQ(t.keys[1].pose.position.x, 1);
    EXPECT_FLOAT_EQ(t.keys[2].pose.position.x, 2);
    EXPECT_FLOAT_EQ(t.keys[3].pose.position.x, 3);
}

TEST(Parser, DuplicateKeyReplacesWithWarning) {
    ParseResult r = parseScene(
        "/sphere s 1 0 0 0\n"
        "/key 5 s 1 0 0 0 0 0\n"
        "/key 5 s 2 0 0 0 0 0\n"
        "/amb_light 1\n",
        kFile);
    ASSERT_TRUE(r.ok()) << dump(r);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].format(),
              "t.f2:3:6: warning: key frame 5 of 's' is given again; it replaces the key at 2:6");
    const Track& t = r.scene->objects[0].track;
    ASSERT_EQ(t.keys.size(), 1u);
    EXPECT_FLOAT_EQ(t.keys[0].pose.position.x, 2);  // the later key wins
}

TEST(Parser, DuplicateKeyOutOfOrderReplacesWithWarningInFileOrder) {
    ParseResult r = parseScene(
        "/robot r 0 0 0\n"
        "/key 5 r.head 1 0 0 0 0 0\n"   // 2
        "/key 9 r.head\n"               // 3
        "/key 5 r.head 2 0 0 0 0 0\n"   // 4: replaces line 2
        "/key 0 r.head\n"               // 5
        "/fps 0\n"                      // 6: an error after the warning
        "/key 5 r.head 3 0 0 0 0 0\n",  // 7: replaces line 4
        kFile);
    ASSERT_EQ(r.diagnostics.size(), 3u) << dump(r);
    EXPECT_EQ(r.diagnostics[0].format(),
              "t.f2:4:6: warning: key frame 5 of 'r.head' is given again; it replaces the key at 2:6");
    EXPECT_EQ(r.diagnostics[1].loc.line, 6);
    EXPECT_EQ(r.diagnostics[1].severity, Severity::Error);
    EXPECT_EQ(r.diagnostics[2].format(),
              "t.f2:7:6: warning: key frame 5 of 'r.head' is given again; it replaces the key at 4:6");

    r = parseScene(
        "/robot r 0 0 0\n/key 5 r.head 1 0 0 0 0 0\n/key 9 r.head\n/key 5 r.head 2 0 0 0 0 0\n/key 0 "
        "r.head\n",
        kFile);
    ASSERT_TRUE(r.ok()) << dump(r);
    const Track& t = partTrack(r.scene->objects[0], RobotPart::Head);
    EXPECT_EQ(framesOf(t), (std::vector<double>{0, 5, 9}));
    EXPECT_FLOAT_EQ(t.keys[1].pose.position.x, 2);
}

TEST(Parser, InterpolationPerTarget) {
    const SceneDesc s = parseOk(
        "/robot r 0 0 0\n/sphere s 1 0 0 0\n"
        "/interp r ease\n/interp r.lhand spline\n/interp s linear\n/interp s spline\n");
    const SceneObject& r = object(s, "r");
    EXPECT_EQ(r.track.interpolation, Interpolation::Ease);
    EXPECT_EQ(partTrack(r, RobotPart::LHand).interpolation, Interpolation::Spline);
    EXPECT_EQ(partTrack(r, RobotPart::RHand).interpolation, Interpolation::Linear);
    EXPECT_EQ(object(s, "s").track.interpolation, Interpolation::Spline);  // the last one wins
}

TEST(Parser, NamesMayLookLikePartsOrCommands) {
    const SceneDesc s =
        parseOk("/sphere head 1 0 0 0\n/robot key 0 0 0\n/paint head 1 1 1\n/key 1 key.head\n");
    EXPECT_EQ(object(s, "head").appearance[0].color, (Color8{1, 1, 1}));
    EXPECT_EQ(partTrack(object(s, "key"), RobotPart::Head).keys.size(), 1u);
}

TEST(Parser, SeedExampleOfSpec8) {
    const char* kSeed =
        "/camera 800 600 0.5\n"
        "/box gr 2500 50 2500 0 -130 200 0 0 0\n"
        "/paint gr 0 200 0\n"
        "/robot r1 0 0 200 0 180 0\n"
        "/human h1 300 0 150 0 90 0\n"
        "/amb_light 0.2\n"
        "/dir_light 0.75 0 -0.2 1\n"
        "/anim r1\n"
        "/key 0 r1\n"
        "/key 5 r1 0 0 200 0 135 0\n"
        "/anim r1 lhand\n"
        "/key 0 r1.lhand\n"
        "/key 5 r1.lhand\n"
        "/key 15 r1.lhand 0 0 0 120 45 0\n"
        "/anim r1 rhand\n"
        "/key 0 r1.rhand\n"
        "/key 5 r1.rhand\n"
        "/key 15 r1.rhand 0 0 0 120 -45 0\n";
    ParseResult r = parseScene(kSeed, "seed_example.f2");
    ASSERT_TRUE(r.ok()) << dump(r);
    EXPECT_TRUE(r.diagnostics.empty()) << dump(r);
    const SceneDesc& s = *r.scene;
    EXPECT_EQ(s.camera.width, 800);
    EXPECT_EQ(s.camera.height, 600);
    EXPECT_DOUBLE_EQ(s.camera.distance, 0.5);
    EXPECT_FLOAT_EQ(s.ambient, 0.2f);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_FLOAT_EQ(s.lights[0].intensity, 0.75f);
    EXPECT_EQ(s.lights[0].direction, (Vec3{0, -0.2f, 1}));
    ASSERT_EQ(s.objects.size(), 3u);

    const SceneObject& gr = s.objects[0];
    EXPECT_EQ(gr.kind, ObjectKind::Box);
    EXPECT_EQ(gr.size, (Vec3{2500, 50, 2500}));
    EXPECT_EQ(gr.rest, makePose(0, -130, 200, 0, 0, 0));
    EXPECT_EQ(gr.appearance[0].color, (Color8{0, 200, 0}));

    const SceneObject& r1 = s.objects[1];
    EXPECT_EQ(typeNameOf(r1), "robot");
    EXPECT_EQ(r1.rest, makePose(0, 0, 200, 0, 180, 0));
    ASSERT_EQ(framesOf(r1.track), (std::vector<double>{0, 5}));
    EXPECT_EQ(r1.track.keys[0].pose, r1.rest);
    EXPECT_EQ(r1.track.keys[1].pose, makePose(0, 0, 200, 0, 135, 0));
    const Track& l = partTrack(r1, RobotPart::LHand);
    ASSERT_EQ(framesOf(l), (std::vector<double>{0, 5, 15}));
    EXPECT_EQ(l.keys[0].pose, Pose{});
    EXPECT_EQ(l.keys[1].pose, Pose{});
    EXPECT_EQ(l.keys[2].pose, makePose(0, 0, 0, 120, 45, 0));
    const Track& rh = partTrack(r1, RobotPart::RHand);
    ASSERT_EQ(framesOf(rh), (std::vector<double>{0, 5, 15}));
    EXPECT_EQ(rh.keys[2].pose, makePose(0, 0, 0, 120, -45, 0));
    EXPECT_TRUE(partTrack(r1, RobotPart::Head).keys.empty());

    const SceneObject& h1 = s.objects[2];
    EXPECT_EQ(typeNameOf(h1), "human");
    EXPECT_EQ(h1.rest, makePose(300, 0, 150, 0, 90, 0));
    EXPECT_EQ(s.lastFrame(), 15);

    // The project's copy must be exactly this scene.
    const fs::path file = sourceRoot() / "scenes/seed_example.f2";
    std::ifstream in(file, std::ios::binary);
    ASSERT_TRUE(in) << file;
    std::stringstream content;
    content << in.rdbuf();
    EXPECT_EQ(content.str(), kSeed);
}

TEST(Parser, ProjectScenesParseCleanly) {
    for (const char* name : {"seed_example.f2", "demo.f2"}) {
        const fs::path file = sourceRoot() / "scenes" / name;
        if (!fs::exists(file)) continue;  // written by another part of the project
        ParseResult r = parseSceneFile(file.string());
        EXPECT_TRUE(r.ok()) << name << "\n" << dump(r);
        EXPECT_TRUE(r.diagnostics.empty()) << name << "\n" << dump(r);
    }
}

// Line ends, BOM, locale

TEST(Parser, AcceptsBomAndCrLf) {
    const std::string text = "\xEF\xBB\xBF/camera 64 48 1\r\n/sphere s 1 0 0 0\r\n\r\n# c\r\n/fps 12\r";
    const SceneDesc s = parseOk(text);
    EXPECT_EQ(s.camera.width, 64);
    EXPECT_EQ(s.fps, 12);
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].name, "s");
    // Columns on line 1 count from after the BOM.
    expectError("\xEF\xBB\xBF/fps 0\r\n", 1, 6, "fps must be a whole number from 1 to 1000, got 0");
    expectError("/fps 1\r\n/fps 2\r\n", 2, 1, "second '/fps'");
}

TEST(Parser, ABomAfterTheStartIsNotWhitespace) {
    expectError("/fps 1\n\xEF\xBB\xBF/fps 2\n", 2, 1, "expected a command starting with '/'");
}

/// Tries to switch to a locale whose decimal separator is ','.
bool useCommaLocale() {
    for (const char* name : {"de_DE.UTF-8", "de_DE.utf8", "de_DE", "ru_RU.UTF-8", "ru_RU.utf8", "fr_FR.UTF-8",
                             "fr_FR.utf8", "nl_NL.UTF-8", "es_ES.UTF-8", "it_IT.UTF-8"}) {
        if (std::setlocale(LC_ALL, name) != nullptr && std::localeconv()->decimal_point[0] == ',') {
            try {
                std::locale::global(std::locale(name));
            } catch (const std::exception&) {
                // The C locale alone is enough to break strtod-style parsing.
            }
            return true;
        }
    }
    std::setlocale(LC_ALL, "C");
    return false;
}

TEST(Parser, NumbersIgnoreTheProcessLocale) {
    const bool comma = useCommaLocale();
    if (!comma) {
        std::printf(
            "note: no comma-decimal locale installed (CI generates de_DE.UTF-8 with localedef); "
            "checking under the C locale only\n");
    } else {
        // Prove the locale is active: the C library now formats with ','.
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.2f", 0.75);
        EXPECT_STREQ(buf, "0,75");
    }
    ParseResult r = parseScene("/camera 10 10 0.75\n/amb_light 1.5e-1\n/dir_light 0.5 0 -0.25 1\n", kFile);
    ParseResult bad = parseScene("/amb_light 0,5\n", kFile);
    std::setlocale(LC_ALL, "C");
    std::locale::global(std::locale::classic());

    ASSERT_TRUE(r.ok()) << dump(r);
    EXPECT_DOUBLE_EQ(r.scene->camera.distance, 0.75);
    EXPECT_FLOAT_EQ(r.scene->ambient, 0.15f);
    EXPECT_FLOAT_EQ(r.scene->lights[0].direction.y, -0.25f);
    ASSERT_EQ(bad.diagnostics.size(), 1u);
    EXPECT_EQ(bad.diagnostics[0].format(),
              "t.f2:1:12: error: expected a number, got '0,5' (the decimal separator is '.')");
}

// Errors: commands and argument counts

TEST(ParserError, UnknownCommand) {
    expectError("/cylnder c 1 1 0 0 0\n", 1, 1, "unknown command '/cylnder' (did you mean '/cylinder'?)");
    expectError("  /teapot t\n", 1, 3, "unknown command '/teapot'");
    expectError("/Sphere s 1 0 0 0\n", 1, 1, "unknown command '/Sphere' (did you mean '/sphere'?)");
    expectError("/\n", 1, 1, "unknown command '/'");
}

TEST(ParserError, LineWithoutSlash) {
    expectError("sphere s 1 0 0 0\n", 1, 1,
                "expected a command starting with '/', got 'sphere' (did you mean '/sphere'?)");
    expectError("\n\t 42\n", 2, 3, "expected a command starting with '/', got '42'");
}

TEST(ParserError, WrongArgumentCountPointsAtTheCommand) {
    expectError("/sphere s 1 2 3\n", 1, 1, "'/sphere' takes 5 or 8 arguments, got 4");
    expectError("/sphere s 1 2 3 4 5\n", 1, 1, "'/sphere' takes 5 or 8 arguments, got 6");
    expectError(" /camera 1 2\n", 1, 2, "'/camera' takes 3, 6 or 9 arguments, got 2");
    expectError("/camera 1 2 3 4 5 6 7 8 9 10\n", 1, 1, "'/camera' takes 3, 6 or 9 arguments, got 10");
    expectError("/cylinder c 1 1 0 0\n", 1, 1, "'/cylinder' takes 6 or 9 arguments, got 5");
    expectError("/box b 1 1 1 0 0 0 0\n", 1, 1, "'/box' takes 7 or 10 arguments, got 8");
    expectError("/robot r 0 0\n", 1, 1, "'/robot' takes 4 or 7 arguments, got 3");
    expectError("/human h\n", 1, 1, "'/human' takes 4 or 7 arguments, got 1");
    expectError("/amb_light\n", 1, 1, "'/amb_light' takes 1 or 3 arguments, got 0");
    expectError("/dir_light 1 0 0\n", 1, 1, "'/dir_light' takes 4 arguments, got 3");
    expectError("/background 1 2\n", 1, 1, "'/background' takes 3 arguments, got 2");
    expectError("/fps 1 2\n", 1, 1, "'/fps' takes 1 argument, got 2");
    expectError("/sphere s 1 0 0 0\n/paint s 1 2\n", 2, 1, "'/paint' takes 4 arguments, got 3");
    expectError("/sphere s 1 0 0 0\n/material s 1 1 1\n", 2, 1, "'/material' takes 5 or 6 arguments, got 4");
    expectError("/anim\n", 1, 1, "'/anim' takes 1 or 2 arguments, got 0");
    expectError("/interp s\n", 1, 1, "'/interp' takes 2 or 6 arguments, got 1");
    // Many tokens are counted even beyond the ones the lexer keeps.
    std::string many = "/fps";
    for (int i = 0; i < 50; ++i) many += " 1";
    expectError(many, 1, 1, "'/fps' takes 1 argument, got 50");
}

TEST(ParserError, KeyNeedsZeroOrSixNumbers) {
    const std::string base = "/robot r 0 0 0\n";
    expectError(base + "/key 1 r 1 2 3\n", 2, 1, "'/key' takes 0 or 6 numbers after the target, got 3");
    expectError(base + "/key 1 r 1 2 3 4 5 6 7\n", 2, 1,
                "'/key' takes 0 or 6 numbers after the target, got 7");
    expectError(base + "/key 1\n", 2, 1, "'/key' takes 2 or 8 arguments");
    expectError(base + "/key\n", 2, 1, "got 0");
}

TEST(ParserError, SecondCameraBackgroundOrFps) {
    expectError("/camera 10 10 1\n\n/camera 10 10 1\n", 3, 1, "second '/camera' (the first is at 1:1)");
    expectError("  /background 0 0 0\n/background 0 0 0\n", 2, 1,
                "second '/background' (the first is at 1:3)");
    expectError("/fps 24\n/fps 25\n", 2, 1, "second '/fps' (the first is at 1:1)");
}

// Errors: numbers

TEST(ParserError, NotANumberPointsAtTheArgument) {
    expectError("/sphere s abc 0 0 0\n", 1, 11, "expected a number, got 'abc'");
    expectError("/sphere s 1.5x 0 0 0\n", 1, 11, "expected a number, got '1.5x'");
    expectError("/sphere s 1 0 0 1e\n", 1, 17, "expected a number, got '1e'");
    expectError("/amb_light 0x1p3\n", 1, 12,
                "expected a decimal number, got '0x1p3' (hexadecimal is not accepted)");
}

TEST(ParserError, NanAndInfinity) {
    expectError("/sphere s 1 nan 0 0\n", 1, 13, "expected a finite number, got 'nan'");
    expectError("/sphere s 1 0 -inf 0\n", 1, 15, "expected a finite number, got '-inf'");
    expectError("/dir_light 1 0 0 infinity\n", 1, 18, "expected a finite number, got 'infinity'");
}

TEST(ParserError, OutOfRange) {
    expectError("/sphere s 1e400 0 0 0\n", 1, 11, "number '1e400' is out of range");
    expectError("/sphere s 1 1e39 0 0\n", 1, 13, "number '1e39' is out of range");
    expectError("/sphere s 1 1e-400 0 0\n", 1, 13, "number '1e-400' is out of range (too close to zero");
}

TEST(ParserError, EveryBadArgumentOnALineIsReported) {
    ParseResult r = parseScene("/sphere s x y z w\n", kFile);
    ASSERT_EQ(r.diagnostics.size(), 4u) << dump(r);
    EXPECT_EQ(r.diagnostics[0].loc.column, 11);
    EXPECT_EQ(r.diagnostics[1].loc.column, 13);
    EXPECT_EQ(r.diagnostics[2].loc.column, 15);
    EXPECT_EQ(r.diagnostics[3].loc.column, 17);
}

// Errors: values out of range

TEST(ParserError, SizesMustBePositive) {
    expectError("/sphere s -1 0 0 0\n", 1, 11, "radius must be > 0, got -1");
    expectError("/sphere s 0 0 0 0\n", 1, 11, "radius must be > 0, got 0");
    expectError("/sphere s 1e-50 0 0 0\n", 1, 11, "radius must be > 0, got 1e-50");  // 0 as a float
    expectError("/cylinder c 1 -2 0 0 0\n", 1, 15, "height must be > 0, got -2");
    expectError("/cylinder c -0 2 0 0 0\n", 1, 13, "radius must be > 0, got -0");
    expectError("/box b 1 1 0 0 0 0\n", 1, 12, "side sz must be > 0, got 0");
    expectError("/box b 1 -1 1 0 0 0\n", 1, 10, "side sy must be > 0, got -1");
}

TEST(ParserError, CameraValues) {
    expectError("/camera 0 10 1\n", 1, 9, "image width must be a whole number from 1 to 16384, got 0");
    expectError("/camera 10 16385 1\n", 1, 12,
                "image height must be a whole number from 1 to 16384, got 16385");
    expectError("/camera 10.5 10 1\n", 1, 9, "image width must be a whole number from 1 to 16384, got 10.5");
    expectError("/camera -10 10 1\n", 1, 9, "image width must be a whole number");
    expectError("/camera 10 10 0\n", 1, 15, "screen distance must be > 0, got 0");
    expectError("/camera 10 10 -1\n", 1, 15, "screen distance must be > 0, got -1");
    expectError("/camera 10 10 1 0 0 x\n", 1, 21, "expected a number, got 'x'");
}

TEST(ParserError, ImagePixelLimit) {
    expectError("/camera 16384 16384 1\n", 1, 9,
                "image of 16384x16384 = 268435456 pixels is larger than the limit of 67108864 pixels");
    expectError("/camera 8193 8192 1\n", 1, 9, "larger than the limit of 67108864 pixels");
}

TEST(ParserError, LightValues) {
    expectError("/amb_light -0.1\n", 1, 12, "ambient intensity must be >= 0, got -0.1");
    expectError("/dir_light -1 0 0 1\n", 1, 12, "light intensity must be >= 0, got -1");
    expectError("/dir_light 1 0 -0 0\n", 1, 14, "light direction must not be 0 0 0");
    expectError("/dir_light 1 1e-30 0 0\n", 1, 14, "light direction cannot be normalised");
    expectError("/dir_light 1 3e38 3e38 0\n", 1, 14, "light direction cannot be normalised");
    expectError("/amb_light 3e38\n/amb_light 3e38\n", 2, 12, "total ambient intensity is out of range");
}

TEST(ParserError, ColourValues) {
    expectError("/background 0 256 0\n", 1, 15, "green must be a whole number from 0 to 255, got 256");
    expectError("/background -1 0 0\n", 1, 13, "red must be a whole number from 0 to 255, got -1");
    expectError("/background 0 0 0.5\n", 1, 17, "blue must be a whole number from 0 to 255, got 0.5");
    expectError("/sphere s 1 0 0 0\n/paint s 1 2 300\n", 2, 14,
                "blue must be a whole number from 0 to 255, got 300");
}

TEST(ParserError, MaterialValues) {
    const std::string base = "/sphere s 1 0 0 0\n";
    expectError(base + "/material s -1 1 1 1\n", 2, 13, "ka must be >= 0, got -1");
    expectError(base + "/material s 1 -1 1 1\n", 2, 15, "kd must be >= 0, got -1");
    expectError(base + "/material s 1 1 -1 1\n", 2, 17, "ks must be >= 0, got -1");
    expectError(base + "/material s 1 1 1 0\n", 2, 19, "n must be > 0, got 0");
}

TEST(ParserError, FpsValues) {
    expectError("/fps 0\n", 1, 6, "fps must be a whole number from 1 to 1000, got 0");
    expectError("/fps 23.976\n", 1, 6, "fps must be a whole number from 1 to 1000, got 23.976");
    expectError("/fps 1001\n", 1, 6, "fps must be a whole number from 1 to 1000, got 1001");
}

TEST(ParserError, KeyFrameValues) {
    const std::string base = "/sphere s 1 0 0 0\n";
    expectError(base + "/key -1 s\n", 2, 6, "a key time must be >= 0, got -1");
    expectError(base + "/key -0.5s s\n", 2, 6, "a key time must be >= 0, got -0.5s");
    expectError(base + "/key 10000001 s\n", 2, 6, "a key time must be at most 10000000 frames, got 10000001");
    expectError(base + "/key 1e8 s\n", 2, 6, "got 1e8");
    expectError(base + "/key 1.5x s\n", 2, 6, "expected a number, got '1.5x'");
    expectError(base + "/key s s\n", 2, 6, "expected a number, got 's'");
    // Seconds at the scene's fps, wherever /fps stands (here 25 fps: 400,001 s is over the limit).
    expectError(base + "/key 400001s s\n/fps 25\n", 2, 6,
                "a key time must be at most 10000000 frames, got 400001 s = 10000025 frames at 25 fps");
    const SceneDesc s = parseOk(base + "/key 1e7 s\n");  // the limit itself is fine
    EXPECT_EQ(s.lastFrame(), 10'000'000);
}

TEST(ParserError, UnknownInterpolation) {
    expectError("/sphere s 1 0 0 0\n/interp s cubic\n", 2, 11,
                "unknown interpolation 'cubic' (expected linear, ease, ease_in, ease_out, step, spline, "
                "back, elastic, bounce or bezier)");
    expectError("/sphere s 1 0 0 0\n/interp s Linear\n", 2, 11, "unknown interpolation 'Linear'");
}

// Errors: names and targets

TEST(ParserError, InvalidName) {
    expectError("/sphere 1s 1 0 0 0\n", 1, 9, "invalid name '1s' (expected a letter or '_'");
    expectError("/sphere a-b 1 0 0 0\n", 1, 9, "invalid name 'a-b'");
    expectError("/robot r.head 0 0 0\n", 1, 8, "invalid name 'r.head'");
}

TEST(ParserError, DuplicateName) {
    expectError("/sphere r1 1 0 0 0\n\n  /robot r1 0 0 0\n", 3, 10,
                "duplicate name 'r1' (first defined at 1:9)");
    const SceneDesc s = parseOk("/sphere r1 1 0 0 0\n/sphere R1 1 0 0 0\n");  // case-sensitive
    EXPECT_EQ(s.objects.size(), 2u);
}

TEST(ParserError, UnknownName) {
    expectError("/paint r2 1 1 1\n", 1, 8, "unknown name 'r2'");
    expectError("/robot r1 0 0 0\n/key 0 r2.head\n", 2, 8, "unknown name 'r2'");
    expectError("/robot r1 0 0 0\n/anim R1\n", 2, 7, "unknown name 'R1'");
    expectError("/robot r1 0 0 0\n/anim r2 head\n", 2, 7, "unknown name 'r2'");
    expectError("/robot r1 0 0 0\n/interp r2 ease\n", 2, 9, "unknown name 'r2'");
    expectError("/robot r1 0 0 0\n/material r2 1 1 1 1\n", 2, 11, "unknown name 'r2'");
    // Use before creation is an error even if the name comes later.
    ParseResult r = parseScene("/paint s 1 1 1\n/sphere s 1 0 0 0\n", kFile);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].format(), "t.f2:1:8: error: unknown name 's'");
}

TEST(ParserError, UnknownPartPointsAtThePart) {
    const std::string base = "/robot r1 0 0 0\n";
    expectError(base + "/key 0 r1.leg\n", 2, 11, "unknown part 'leg' (expected body, head, lhand or rhand)");
    expectError(base + "/anim r1 leg\n", 2, 10, "unknown part 'leg'");
    expectError(base + "/paint r1.Head 1 1 1\n", 2, 11, "unknown part 'Head'");
    expectError(base + "/paint r1. 1 1 1\n", 2, 11, "unknown part ''");
    // A third word is a shape of the part (SPEC 10.1).
    expectError(base + "/paint r1.head.x 1 1 1\n", 2, 16,
                "unknown shape 'x' on the part 'head' of 'robot' (expected face, leye, reye)");
}

TEST(ParserError, PartOfAPrimitive) {
    const std::string base = "/sphere s1 1 0 0 0\n";
    expectError(base + "/key 0 s1.head\n", 2, 11, "'/key' on a part of a primitive: 's1' is a sphere");
    expectError(base + "/paint s1.body 1 1 1\n", 2, 11, "'/paint' on a part of a primitive");
    expectError(base + "/material s1.lhand 1 1 1 1\n", 2, 14, "'/material' on a part of a primitive");
    expectError(base + "/anim s1 rhand\n", 2, 10, "'/anim' on a part of a primitive");
    expectError("/box b 1 1 1 0 0 0\n/interp b.head ease\n", 2, 11,
                "'/interp' on a part of a primitive: 'b' is a box");
}

TEST(ParserError, BadTargets) {
    const std::string base = "/robot r1 0 0 0\n";
    expectError(base + "/anim r1.head lhand\n", 2, 7,
                "'/anim' with two arguments takes a name and a part, got 'r1.head'");
    expectError(base + "/paint .head 1 1 1\n", 2, 8, "invalid target '.head' (expected a name or name.part)");
    expectError(base + "/key 0 9r\n", 2, 8, "invalid target '9r'");
}

// Recovery, and no partial scenes

TEST(ParserError, ReportsEveryErrorAndKeepsNoScene) {
    ParseResult r = parseScene(
        "/camera 800 600 0.5\n"
        "/cylnder c 1 1 0 0 0\n"
        "/sphere s -1 0 0 0\n"
        "/paint s 1 1 1\n"  // fine: s was created despite its bad radius
        "/paint q 1 1 1\n"
        "/key 0 s.head\n"
        "/fps 24\n",
        kFile);
    EXPECT_FALSE(r.ok());
    EXPECT_FALSE(r.scene.has_value());
    std::vector<std::string> got;
    for (const Diagnostic& d : r.diagnostics) got.push_back(d.format());
    EXPECT_EQ(
        got, (std::vector<std::string>{
                 "t.f2:2:1: error: unknown command '/cylnder' (did you mean '/cylinder'?)",
                 "t.f2:3:11: error: radius must be > 0, got -1",
                 "t.f2:5:8: error: unknown name 'q'",
                 "t.f2:6:10: error: '/key' on a part of a primitive: 's' is a sphere; only models have parts",
             }));
}

TEST(ParserError, AModelWithARefusedNameAndNoShapesSaysSoPlainly) {
    // A refused type name and an empty block: two errors, the second without
    // a name to show ("the model has no shapes", not "model the model ...").
    ParseResult r = parseScene("/model robot\n/end\n/model lamp\n/end\n", kFile);
    std::vector<std::string> got;
    for (const Diagnostic& d : r.diagnostics) got.push_back(d.format());
    ASSERT_EQ(got.size(), 3u) << dump(r);
    EXPECT_EQ(got[0].rfind("t.f2:1:1: error: the model has no shapes (put a", 0), 0u) << got[0];
    EXPECT_EQ(got[1].rfind("t.f2:1:8: error: 'robot' is a built-in model type", 0), 0u) << got[1];
    EXPECT_EQ(got[2].rfind("t.f2:3:1: error: model 'lamp' has no shapes (put a", 0), 0u) << got[2];
}

TEST(ParserError, WarningsAloneKeepTheScene) {
    ParseResult r = parseScene("/sphere s 1 0 0 0\n/key 1 s\n/key 1 s\n", kFile);
    EXPECT_TRUE(r.ok());
    EXPECT_FALSE(hasErrors(r.diagnostics));
    EXPECT_EQ(r.diagnostics.size(), 2u) << dump(r);  // the repeated key, and no light
}

// Hostile input

TEST(ParserError, LineTooLong) {
    std::string text = "/fps 1\n# " + std::string(2 << 20, 'x') + "\n/fps 2\n";
    ParseResult r = parseScene(text, kFile);
    ASSERT_EQ(r.diagnostics.size(), 2u) << dump(r);
    EXPECT_EQ(r.diagnostics[0].format(),
              "t.f2:2:1: error: line is 2097154 bytes long, more than the limit of "
              "1048576 bytes");
    EXPECT_EQ(r.diagnostics[1].loc.line, 3);  // parsing goes on after it
}

TEST(ParserError, BinaryGarbageGivesEscapedErrors) {
    static constexpr char kBytes[] = "/sphere \xff\xfe\x00\x01 1 0 0 0\n\x00\x00\x00\n\x89PNG\r\n\x1a\n";
    const std::string text(kBytes, sizeof kBytes - 1);
    ParseResult r = parseScene(text, kFile);
    EXPECT_FALSE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), 4u) << dump(r);
    EXPECT_EQ(
        r.diagnostics[0].format(),
        "t.f2:1:9: error: invalid name '\\xff\\xfe\\x00\\x01' (expected a letter "
        "or '_', then letters, digits or '_'; it contains the bytes 0xFF 0xFE at column 9, a UTF-16 byte "
        "order mark: save the file as UTF-8)");
    EXPECT_EQ(
        r.diagnostics[1].format(),
        "t.f2:2:1: error: expected a command starting with '/', got '\\x00\\x00\\x00' (it contains U+0000 "
        "NULL at column 1, an invisible character: delete it)");
    EXPECT_EQ(
        r.diagnostics[2].format(),
        "t.f2:3:1: error: expected a command starting with '/', got '\\x89PNG' (it contains the byte 0x89 "
        "at column 1, which is not UTF-8 text)");
    EXPECT_EQ(
        r.diagnostics[3].format(),
        "t.f2:4:1: error: expected a command starting with '/', got '\\x1a' (it contains U+001A at column "
        "1, a control character)");
    // Messages are printable ASCII or valid UTF-8 only.
    for (const Diagnostic& d : r.diagnostics) {
        for (char c : d.message) EXPECT_TRUE(static_cast<unsigned char>(c) >= 0x20) << d.message;
    }
}

TEST(ParserError, RandomBytesNeverCrash) {
    std::mt19937 rng(12345);
    const std::string alphabet = "/ \t\n\r#.-+e0123456789abcdefxyz_\xff\x80";
    for (int round = 0; round < 300; ++round) {
        std::string text;
        const int n = static_cast<int>(rng() % 400);
        for (int i = 0; i < n; ++i) {
            text += rng() % 4 == 0 ? static_cast<char>(rng() % 256) : alphabet[rng() % alphabet.size()];
        }
        ParseResult r = parseScene(text, kFile);
        EXPECT_EQ(r.ok(), !hasErrors(r.diagnostics)) << round;
    }
}

TEST(ParserError, MutatedValidScenesNeverCrash) {
    const std::string seed =
        "/camera 64 48 0.5 0 0 0 0 0 0\n/box gr 2500 50 2500 0 -130 200\n/robot r1 0 0 200 0 180 0\n"
        "/paint r1.head 1 2 3\n/material r1 1 1 0.3 32\n/key 5 r1.lhand 0 0 0 120 45 0\n/interp r1 spline\n";
    std::mt19937 rng(777);
    for (int round = 0; round < 2000; ++round) {
        std::string text = seed;
        for (int m = 0; m < 3; ++m) {
            const std::size_t at = rng() % text.size();
            switch (rng() % 3) {
                case 0:
                    text[at] = static_cast<char>(rng() % 128);
                    break;
                case 1:
                    text.erase(at, 1);
                    break;
                default:
                    text.insert(at, 1, " .-e9#\n"[rng() % 7]);
                    break;
            }
        }
        ParseResult r = parseScene(text, kFile);
        EXPECT_EQ(r.ok(), !hasErrors(r.diagnostics)) << text;
    }
}

// Limits

TEST(ParserLimits, DefaultsAreTheSpecs) {
    const ParseLimits l;
    EXPECT_EQ(l.maxImageSide, 16384);
    EXPECT_EQ(l.maxImagePixels, 1LL << 26);
    EXPECT_EQ(l.maxObjects, 1'000'000u);
    EXPECT_EQ(l.maxKeyFrame, 10'000'000);
    EXPECT_EQ(l.maxKeyLines, 10'000'000u);
}

TEST(ParserLimits, ObjectCountAndModelsCountAsOne) {
    ParseLimits l;
    l.maxObjects = 3;
    ParseResult r =
        parseScene("/robot a 0 0 0\n/human b 0 0 0\n/sphere c 1 0 0 0\n/box d 1 1 1 0 0 0\n", kFile, l);
    ASSERT_EQ(r.diagnostics.size(), 1u) << dump(r);
    EXPECT_EQ(r.diagnostics[0].format(),
              "t.f2:4:1: error: too many objects: at most 3 allowed (a robot or human counts as one)");
    r = parseScene("/robot a 0 0 0\n/human b 0 0 0\n/sphere c 1 0 0 0\n", kFile, l);
    EXPECT_TRUE(r.ok()) << dump(r);
}

TEST(ParserLimits, KeyLineCount) {
    ParseLimits l;
    l.maxKeyLines = 3;
    // Every /key line counts, even a replaced or a broken one.
    ParseResult r = parseScene("/sphere s 1 0 0 0\n/key 0 s\n/key 0 s\n/key x s\n/key 1 s\n", kFile, l);
    ASSERT_EQ(r.diagnostics.size(), 3u) << dump(r);
    EXPECT_EQ(r.diagnostics[2].format(), "t.f2:5:1: error: too many '/key' lines: at most 3 allowed");
}

TEST(ParserLimits, SmallerImageLimitsAreHonoured) {
    ParseLimits l;
    l.maxImageSide = 100;
    l.maxImagePixels = 5000;
    ParseResult r = parseScene("/camera 101 10 1\n", kFile, l);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_NE(r.diagnostics[0].message.find("from 1 to 100"), std::string::npos);
    r = parseScene("/camera 100 51 1\n", kFile, l);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_NE(r.diagnostics[0].message.find("5100 pixels is larger than the limit of 5000"),
              std::string::npos);
}

TEST(ParserLimits, ErrorsStopAtTheCap) {
    ParseLimits l;
    l.maxErrors = 5;
    std::string text;
    for (int i = 0; i < 100; ++i) text += "junk\n";
    ParseResult r = parseScene(text, kFile, l);
    ASSERT_EQ(r.diagnostics.size(), 6u);
    EXPECT_EQ(r.diagnostics[5].format(), "t.f2:5:1: error: too many errors (5); parsing stopped here");
}

TEST(ParserLimits, WarningsAreCountedBeyondTheCap) {
    ParseLimits l;
    l.maxWarnings = 2;
    std::string text = "/sphere s 1 0 0 0\n";
    for (int i = 0; i < 10; ++i) text += "/key 3 s\n";  // lines 2..11: 9 replacements
    text += "/amb_light 1\n";
    ParseResult r = parseScene(text, kFile, l);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), 3u) << dump(r);
    EXPECT_EQ(r.diagnostics[2].format(), "t.f2:5:6: warning: 7 more warnings from here on are not shown");
}

TEST(ParserLimits, SceneSize) {
    ParseLimits l;
    l.maxSceneBytes = 10;
    ParseResult r = parseScene("/fps 24   # long\n", kFile, l);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].format(),
              "t.f2:1:1: error: the scene is 17 bytes, more than the limit of 10 bytes");
}

TEST(ParserLimits, AMillionLinesWithOutOfOrderKeysParse) {
    // 1,000,000 lines: 1000 spheres with 999 keys each, half of them out of order.
    std::string text;
    text.reserve(40u << 20);
    for (int o = 0; o < 1000; ++o) {
        text += "/sphere s" + std::to_string(o) + " 1 0 0 0\n";
        for (int k = 1; k < 1000; ++k) {
            const int frame = o % 2 == 0 ? k : 1000 - k;
            text += "/key " + std::to_string(frame) + " s" + std::to_string(o) + " 1 2 3 4.5 5 6\n";
        }
    }
    const auto start = std::chrono::steady_clock::now();
    ParseResult r = parseScene(text, kFile);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("parsed 1,000,000 lines in %.3f s\n", seconds);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.scene->objects.size(), 1000u);
    EXPECT_EQ(r.scene->objects[1].track.keys.size(), 999u);
    EXPECT_EQ(r.scene->objects[1].track.keys.front().time, 1);
    EXPECT_EQ(r.scene->lastFrame(), 999);
    // No bound on the time, only printed: a unit test must not depend on the
    // machine's speed or load (0.7 s optimised, 119 s under ASan on a loaded machine).
}

// Files

class ParserFile : public ::testing::Test {
   protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("f2_parser_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    std::string write(const std::string& name, const std::string& content) {
        const fs::path p = dir_ / name;
        std::ofstream(p, std::ios::binary) << content;
        return p.string();
    }
    fs::path dir_;
};

TEST_F(ParserFile, ReadsAFileInBinaryMode) {
    const std::string path = write("s.f2", "/camera 10 20 1\r\n/sphere s 1 0 0 0\r\n/fps 0\r\n");
    ParseResult r = parseSceneFile(path);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].format(),
              path + ":3:6: error: fps must be a whole number from 1 to 1000, got 0");
    r = parseSceneFile(write("ok.f2", "/camera 10 20 1\r\n"));
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.scene->camera.height, 20);
}

TEST_F(ParserFile, MissingFile) {
    const std::string path = (dir_ / "nope.f2").string();
    ParseResult r = parseSceneFile(path);
    EXPECT_FALSE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].format(),
              path + ":1:1: error: cannot read '" + path + "': No such file or directory");
}

TEST_F(ParserFile, Directory) {
    ParseResult r = parseSceneFile(dir_.string());
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].format(),
              dir_.string() + ":1:1: error: cannot read '" + dir_.string() + "': it is a directory");
}

TEST_F(ParserFile, UnreadableFile) {
    const std::string path = write("secret.f2", "/fps 1\n");
    fs::permissions(path, fs::perms::none);
    std::FILE* probe = std::fopen(path.c_str(), "rb");
    if (probe) {
        // Running as root: permissions do not stop reading, so there is nothing to test here.
        std::fclose(probe);
        EXPECT_TRUE(parseSceneFile(path).ok());
        return;
    }
    ParseResult r = parseSceneFile(path);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].format(), path + ":1:1: error: cannot read '" + path + "': Permission denied");
}

TEST_F(ParserFile, NotARegularFile) {
    ParseResult r = parseSceneFile("/dev/null");
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].format(),
              "/dev/null:1:1: error: cannot read '/dev/null': it is not a regular file");
}

TEST_F(ParserFile, TooLarge) {
    ParseLimits l;
    l.maxSceneBytes = 8;
    const std::string path = write("big.f2", "/fps 24\n/fps 25\n");
    ParseResult r = parseSceneFile(path, l);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].format(), path + ":1:1: error: cannot read '" + path +
                                             "': the file is 16 bytes, more than the limit of 8 bytes");
}

TEST_F(ParserFile, DashReadsStandardInput) {
    const std::string path = write("in.f2", "/fps 30\n/paint nobody 1 1 1\n");
    ASSERT_NE(std::freopen(path.c_str(), "rb", stdin), nullptr);
    ParseResult r = parseSceneFile("-");
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].format(), "<stdin>:2:8: error: unknown name 'nobody'");

    ParseLimits l;
    l.maxSceneBytes = 4;
    ASSERT_NE(std::freopen(path.c_str(), "rb", stdin), nullptr);
    r = parseSceneFile("-", l);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(
        r.diagnostics[0].format(),
        "<stdin>:1:1: error: cannot read standard input: the input is larger than the limit of 4 bytes");
}

/// Each tests/data/parse_errors/*.f2 lists its expected diagnostics in lines
/// `#> LINE:COL: error: message`, in order; the whole output must match.
TEST(ParserGolden, ParseErrorFiles) {
    const fs::path dir = sourceRoot() / "tests/data/parse_errors";
    ASSERT_TRUE(fs::is_directory(dir)) << dir;
    int files = 0;
    for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
        if (e.path().extension() != ".f2") continue;
        ++files;
        SCOPED_TRACE(e.path().filename().string());
        std::ifstream in(e.path(), std::ios::binary);
        std::vector<std::string> expected;
        std::string line;
        while (std::getline(in, line)) {
            if (line.starts_with("#> ")) expected.push_back(line.substr(3));
        }
        const ParseResult r = parseSceneFile(e.path().string());
        std::vector<std::string> got;
        const std::string prefix = e.path().string() + ":";
        for (const Diagnostic& d : r.diagnostics) {
            const std::string f = d.format();
            EXPECT_TRUE(f.starts_with(prefix)) << f;
            got.push_back(f.substr(prefix.size()));
        }
        EXPECT_EQ(got, expected);
        EXPECT_EQ(r.ok(), !hasErrors(r.diagnostics));
    }
    EXPECT_GE(files, 3);
}

}  // namespace
}  // namespace f2
