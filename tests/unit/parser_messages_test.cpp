// Scene language messages that help a user find what is wrong (issue 12):
// no follow-on errors after a broken creating command, invisible characters
// named, "did you mean" for names and parts, and warnings about scenes that
// parse but are almost certainly not what was meant.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/parse/parser.h"
#include "core/parse/unusual_char.h"

namespace f2 {
namespace {

constexpr const char* kFile = "t.f2";

/// Every diagnostic of `text`, formatted, without the file name.
std::vector<std::string> messages(std::string_view text, const ParseLimits& limits = {}) {
    const ParseResult r = parseScene(text, kFile, limits);
    std::vector<std::string> out;
    for (const Diagnostic& d : r.diagnostics) out.push_back(d.format().substr(std::string(kFile).size() + 1));
    EXPECT_EQ(r.ok(), !hasErrors(r.diagnostics));
    return out;
}

using Lines = std::vector<std::string>;

// A creating command with an error still registers its name

TEST(CreatingCommandErrors, AWrongArgumentCountStillRegistersTheNameWithItsKind) {
    // Six numbers: the rotation is incomplete. Q is still a robot afterwards.
    EXPECT_EQ(messages("/robot Q 0 0 200 0 180\n"
                       "/amb_light 0.2\n"
                       "/key 0 Q.lhand\n"
                       "/paint Q 10 20 30\n"
                       "/interp Q.head ease\n"),
              (Lines{"1:1: error: '/robot' takes 4 or 7 arguments, got 6"}));
    // A sphere registered after a count error has no parts.
    EXPECT_EQ(
        messages("/sphere s 1 0 0\n/key 0 s.head\n"),
        (Lines{"1:1: error: '/sphere' takes 5 or 8 arguments, got 4",
               "2:10: error: '/key' on a part of a primitive: 's' is a sphere; only models have parts"}));
    EXPECT_EQ(
        messages("/box b 1 2\n/cylinder c 1\n/human h\n/paint b 1 1 1\n/paint c 1 1 1\n/key 1 h.rhand\n"),
        (Lines{"1:1: error: '/box' takes 7 or 10 arguments, got 3",
               "2:1: error: '/cylinder' takes 6 or 9 arguments, got 2",
               "3:1: error: '/human' takes 4 or 7 arguments, got 1"}));
}

TEST(CreatingCommandErrors, EveryKindOfErrorStillRegistersTheName) {
    // Bad numbers, bad sizes.
    EXPECT_EQ(messages("/sphere s -1 0 x 0\n/paint s 1 1 1\n"),
              (Lines{"1:11: error: radius must be > 0, got -1", "1:16: error: expected a number, got 'x'"}));
    // Errors in expressions (second edition) and non-finite numbers.
    EXPECT_EQ(messages("/robot Q 0 0 (1/0)\n/key 0 Q.head\n/sphere b (n) 0 0 0\n/paint b 1 1 1\n"
                       "/box c 1 1 1 0 0 0 1 nan 0\n/paint c 1 1 1\n"),
              (Lines{"1:16: error: division by zero", "3:12: error: unknown variable 'n'",
                     "5:22: error: expected a finite number, got 'nan'"}));
    // Beyond the object limit.
    ParseLimits one;
    one.maxObjects = 1;
    EXPECT_EQ(messages("/sphere a 1 0 0 0\n/robot b 0 0 0\n/key 0 b.head\n/key 0 a\n", one),
              (Lines{"2:1: error: too many objects: at most 1 allowed (a robot or human counts as one)"}));
}

TEST(CreatingCommandErrors, TheSceneStillFailsAndNamesAreNotTakenTwice) {
    const ParseResult r = parseScene("/robot Q 0 0 200 0 180\n/dir_light 1 0 0 1\n", kFile);
    EXPECT_FALSE(r.ok());
    EXPECT_FALSE(r.scene.has_value());
    // A count error on a name that exists does not replace the first object.
    EXPECT_EQ(messages("/robot r 0 0 0\n/sphere r 1\n/key 0 r.head\n"),
              (Lines{"2:1: error: '/sphere' takes 5 or 8 arguments, got 2"}));
    // Without a valid name there is nothing to register.
    EXPECT_EQ(messages("/sphere 1 0 0\n"), (Lines{"1:1: error: '/sphere' takes 5 or 8 arguments, got 3"}));
}

// Invisible and unusual characters

TEST(UnusualCharacters, ANoBreakSpaceInACommandIsNamed) {
    EXPECT_EQ(
        messages("/sphere\u00A0t 10 0 0 0\n"),
        (Lines{"1:1: error: unknown command '/sphere\u00A0t' (it contains U+00A0 NO-BREAK SPACE at column 8, "
               "which does not separate tokens: only spaces and tabs do)"}));
}

TEST(UnusualCharacters, ANoBreakSpaceBetweenArgumentsIsNamedInTheCountError) {
    EXPECT_EQ(
        messages("/sphere t\u00A010 0 0 0   # comment \u00A0 ignored\n"),
        (Lines{"1:1: error: '/sphere' takes 5 or 8 arguments, got 4 (it contains U+00A0 NO-BREAK SPACE at "
               "column 10, which does not separate tokens: only spaces and tabs do)"}));
    EXPECT_EQ(
        messages("/sphere s 1 0 0 0\n/key 0\u202Fs\n"),
        (Lines{
            "2:1: error: '/key' takes 2 or 8 arguments (a time, a target and 0 or 6 numbers), got 1 (it "
            "contains U+202F NARROW NO-BREAK SPACE at column 7, which does not separate tokens: only spaces "
            "and tabs do)"}));
}

TEST(UnusualCharacters, InExpressionsAndTheCountsOfLetAndRepeat) {
    EXPECT_EQ(
        messages("/amb_light 1\n/let n\u00A08\n/repeat i 0\u00A03\n/end\n"),
        (Lines{"2:1: error: '/let' takes 2 arguments (a variable and a number), got 1 (it contains U+00A0 "
               "NO-BREAK SPACE at column 7, which does not separate tokens: only spaces and tabs do)",
               "3:1: error: '/repeat' takes 3 or 4 arguments (a variable, from, to and an optional step), "
               "got 2 (it contains U+00A0 NO-BREAK SPACE at column 12, which does not separate tokens: "
               "only spaces and tabs do)"}));
    EXPECT_EQ(
        messages("/amb_light 1\n/sphere s 1 0 0 (1 +\u00A02)\n/sphere t 1 0 0 (2 \u2212 1)\n"
                 "/sphere u 1 0 0 (\u201C1)\n/sphere v 1 0 0 (1 \xE9)\n"),
        (Lines{"2:21: error: unexpected U+00A0 NO-BREAK SPACE in the expression (which does not separate "
               "tokens: only spaces and tabs do)",
               "3:20: error: unexpected U+2212 MINUS SIGN in the expression (which is not a minus: write "
               "'-')",
               "4:18: error: unexpected U+201C LEFT DOUBLE QUOTATION MARK in the expression",
               "5:20: error: unexpected byte 0xE9 in the expression (which is not UTF-8 text)"}));
}

TEST(UnusualCharacters, DashesAndMinusSignsInNumbers) {
    EXPECT_EQ(
        messages("/sphere s 10 \u22125 0 0\n"),
        (Lines{"1:14: error: expected a number, got '\u22125' (it contains U+2212 MINUS SIGN at column 14, "
               "which is not a minus: write '-')"}));
    EXPECT_EQ(
        messages("/amb_light \u20130.5\n"),
        (Lines{"1:12: error: expected a number, got '\u20130.5' (it contains U+2013 EN DASH at column 12, "
               "which is not a minus: write '-')"}));
}

TEST(UnusualCharacters, InvisibleCharactersInNamesAndTargets) {
    EXPECT_EQ(
        messages("/sphere s\u200B 1 0 0 0\n"),
        (Lines{
            "1:9: error: invalid name 's\u200B' (expected a letter or '_', then letters, digits or '_'; it "
            "contains U+200B ZERO WIDTH SPACE at column 10, an invisible character: delete it)"}));
    EXPECT_EQ(
        messages("/robot r 0 0 0\n/key 0 r.\u00ADhead\n"),
        (Lines{"2:10: error: unknown part '\u00ADhead' (did you mean 'head'? it contains U+00AD SOFT HYPHEN "
               "at column 10, an invisible character: delete it)"}));
    EXPECT_EQ(messages("/robot r 0 0 0\n/interp r ease\u200D\n"),
              (Lines{"2:11: error: unknown interpolation 'ease\u200D' (expected linear, ease, ease_in, "
                     "ease_out, step, "
                     "spline, back, elastic, bounce or bezier; it contains "
                     "U+200D ZERO WIDTH JOINER at column 15, an invisible character: delete it)"}));
}

TEST(UnusualCharacters, AByteOrderMarkInTheMiddle) {
    // Two files joined with cat: the second one's BOM lands in the middle.
    EXPECT_EQ(
        messages("/fps 24\n\xEF\xBB\xBF/amb_light 1\n"),
        (Lines{"2:1: error: expected a command starting with '/', got '\xEF\xBB\xBF/amb_light' (it contains "
               "U+FEFF ZERO WIDTH NO-BREAK SPACE at column 1, a byte order mark, allowed only at the very "
               "start of the file)"}));
}

TEST(UnusualCharacters, OtherCharactersGetTheirCode) {
    EXPECT_EQ(
        messages("/sphere caf\u00E9 1 0 0 0\n"),
        (Lines{"1:9: error: invalid name 'caf\u00E9' (expected a letter or '_', then letters, digits or '_'; "
               "it contains U+00E9 at column 12, but commands, names and numbers are plain ASCII)"}));
    // Latin-1, not UTF-8.
    EXPECT_EQ(
        messages("/sphere caf\xE9 1 0 0 0\n"),
        (Lines{"1:9: error: invalid name 'caf\\xe9' (expected a letter or '_', then letters, digits or '_'; "
               "it contains the byte 0xE9 at column 12, which is not UTF-8 text)"}));
}

TEST(UnusualCharacters, NoteNamesOnlyTheFirstAndIgnoresTabs) {
    EXPECT_EQ(unusualCharacterNote("a\tb", 1), "");
    EXPECT_EQ(
        unusualCharacterNote("ab\x0B\u00A0", 5),
        "it contains U+000B LINE TABULATION (vertical tab) at column 7, which does not separate tokens: "
        "only spaces and tabs do");
    EXPECT_EQ(
        unusualCharacterNote("1\r2", 1),
        "it contains U+000D CARRIAGE RETURN at column 2, which ends a line only just before a line feed");
    EXPECT_EQ(unusualCharacterNote(std::string_view("x\0", 2), 1),
              "it contains U+0000 NULL at column 2, an invisible character: delete it");
    EXPECT_EQ(unusualCharacterNote("\u2014", 3),
              "it contains U+2014 EM DASH at column 3, which is not a minus: write '-'");
    EXPECT_EQ(unusualCharacterNote("\u201Cr1\u201D", 1),
              "it contains U+201C LEFT DOUBLE QUOTATION MARK at column 1");
    EXPECT_EQ(
        unusualCharacterNote("\xFE\xFF\x00/", 1),
        "it contains the bytes 0xFE 0xFF at column 1, a UTF-16 byte order mark: save the file as UTF-8");
    EXPECT_EQ(unusualCharacterNote("a\x1B", 1), "it contains U+001B at column 2, a control character");
}

TEST(UnusualCharacters, TabsAreOrdinarySeparators) {
    EXPECT_EQ(messages("/sphere\ts\t1 0 0 0\n/amb_light 1\n"), Lines{});
}

// Duplicate names point at names

TEST(DuplicateNames, BothPositionsPointAtTheName) {
    EXPECT_EQ(messages("  /robot r1 0 0 0\n/sphere   r1 1 0 0 0\n"),
              (Lines{"2:11: error: duplicate name 'r1' (first defined at 1:10)"}));
}

// Did you mean

TEST(DidYouMean, NamesDifferingInCaseOrByATypo) {
    EXPECT_EQ(messages("/robot Robo 0 0 0\n/key 0 robo\n"),
              (Lines{"2:8: error: unknown name 'robo' (did you mean 'Robo'?)"}));
    EXPECT_EQ(messages("/sphere ground 1 0 0 0\n/paint gruond 1 1 1\n"),
              (Lines{"2:8: error: unknown name 'gruond' (did you mean 'ground'?)"}));
    EXPECT_EQ(messages("/robot r1 0 0 0\n/key 0 r2.head\n"),
              (Lines{"2:8: error: unknown name 'r2' (did you mean 'r1'?)"}));
    // A case-only difference wins over a nearer typo; ties go to the first defined.
    EXPECT_EQ(messages("/sphere lamp1 1 0 0 0\n/sphere LAMP 1 0 0 0\n/paint lamp 1 1 1\n"),
              (Lines{"3:8: error: unknown name 'lamp' (did you mean 'LAMP'?)"}));
    EXPECT_EQ(messages("/sphere ab 1 0 0 0\n/sphere ac 1 0 0 0\n/paint ad 1 1 1\n"),
              (Lines{"3:8: error: unknown name 'ad' (did you mean 'ab'?)"}));
    // Nothing close: no hint.
    EXPECT_EQ(
        messages(
            "/sphere ball 1 0 0 0\n/sphere s 1 0 0 0\n/paint xyz 1 1 1\n/paint r1 1 1 1\n/paint q 1 1 1\n"),
        (Lines{"3:8: error: unknown name 'xyz'", "4:8: error: unknown name 'r1'",
               "5:8: error: unknown name 'q'"}));
}

TEST(DidYouMean, TheCameraWhereTheCommandTakesIt) {
    EXPECT_EQ(
        messages("/sphere s 1 0 0 5\n/amb_light 1\n/key 0 Camera\n/interp camra ease\n/attach Camera s\n"),
        (Lines{"3:8: error: unknown name 'Camera' (did you mean 'camera'?)",
               "4:9: error: unknown name 'camra' (did you mean 'camera'?)",
               "5:9: error: unknown name 'Camera' (did you mean 'camera'?)"}));
    // /paint does not take the camera: no such hint; an object's name still wins a tie.
    EXPECT_EQ(messages("/sphere camera1 1 0 0 5\n/amb_light 1\n/paint Camera 1 1 1\n/key 0 camera2\n"),
              (Lines{"3:8: error: unknown name 'Camera' (did you mean 'camera1'?)",
                     "4:8: error: unknown name 'camera2' (did you mean 'camera1'?)"}));
}

TEST(DidYouMean, Parts) {
    const std::string robot = "/robot r1 0 0 0\n";
    EXPECT_EQ(messages(robot + "/key 0 r1.Head\n"),
              (Lines{"2:11: error: unknown part 'Head' (did you mean 'head'?)"}));
    EXPECT_EQ(messages(robot + "/anim r1 lhnd\n"),
              (Lines{"2:10: error: unknown part 'lhnd' (did you mean 'lhand'?)"}));
    EXPECT_EQ(messages(robot + "/key 0 r1.left_arm\n"),
              (Lines{"2:11: error: unknown part 'left_arm' (did you mean 'lhand'?)"}));
    EXPECT_EQ(messages(robot + "/paint r1.torso 1 1 1\n"),
              (Lines{"2:11: error: unknown part 'torso' (did you mean 'body'?)"}));
    EXPECT_EQ(messages(robot + "/key 0 r1.leg\n"),
              (Lines{"2:11: error: unknown part 'leg' (expected body, head, lhand or rhand)"}));
}

// Warnings about scenes that are almost certainly not what was meant

TEST(SceneWarnings, NoLightMeansEveryObjectIsBlack) {
    const Lines black{
        "1:9: warning: the scene has no light (no '/amb_light', '/dir_light', '/point_light' or "
        "'/spot_light' with an intensity > 0): every object renders black"};
    EXPECT_EQ(messages("/sphere s 1 0 0 5\n/sphere t 1 0 0 9\n"), black);
    EXPECT_EQ(messages("/sphere s 1 0 0 5\n/amb_light 0\n/dir_light 0 0 0 1\n"), black);
    EXPECT_EQ(messages("/sphere s 1 0 0 5\n/amb_light 0.1\n"), Lines{});
    EXPECT_EQ(messages("/sphere s 1 0 0 5\n/dir_light 1 0 0 1\n"), Lines{});
    // Point and spot lights light a scene too; at intensity 0 they do not.
    EXPECT_EQ(messages("/sphere s 1 0 0 5\n/point_light 0.5 0 9 0\n"), Lines{});
    EXPECT_EQ(messages("/sphere s 1 0 0 5\n/spot_light 0.8 0 9 0 0 -1 0 20 30\n"), Lines{});
    EXPECT_EQ(messages("/sphere s 1 0 0 5\n/point_light 0 0 9 0\n/spot_light 0 0 9 0 0 -1 0 20 30\n"), black);
    // The scene is still used.
    EXPECT_TRUE(parseScene("/sphere s 1 0 0 5\n", kFile).ok());
}

TEST(SceneWarnings, AnEmptyScene) {
    EXPECT_EQ(messages(""),
              (Lines{"1:1: warning: the scene has no objects: every frame shows only the background"}));
    EXPECT_EQ(messages("# nothing\n/camera 10 10 1\n/amb_light 1\n"),
              (Lines{"1:1: warning: the scene has no objects: every frame shows only the background"}));
    EXPECT_TRUE(parseScene("", kFile).ok());
}

TEST(SceneWarnings, NotAddedToAnErroneousScene) {
    EXPECT_EQ(messages("/fps 0\n"), (Lines{"1:6: error: fps must be a whole number from 1 to 1000, got 0"}));
    EXPECT_EQ(messages("/sphere s 1 0 0 5\n/fps 0\n"),
              (Lines{"2:6: error: fps must be a whole number from 1 to 1000, got 0"}));
}

TEST(SceneWarnings, ASecondInterpForTheSameTarget) {
    const std::string text =
        "/robot r1 0 0 0\n/amb_light 1\n/interp r1 ease\n/interp r1.lhand spline\n/interp  r1 linear\n"
        "/interp r1.rhand ease\n";
    EXPECT_EQ(messages(text),
              (Lines{"5:10: warning: interpolation of 'r1' is given again; it replaces the one at 3:9"}));
    const ParseResult r = parseScene(text, kFile);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.scene->objects[0].track.interpolation, Interpolation::Linear);  // the last one wins
    EXPECT_EQ(r.scene->objects[0].partTracks[2].interpolation /* lhand */, Interpolation::Spline);
    // The camera is a target like any other.
    EXPECT_EQ(messages("/sphere s 1 0 0 5\n/amb_light 1\n/interp camera ease\n/interp camera spline\n"),
              (Lines{"4:9: warning: interpolation of 'camera' is given again; it replaces the one at 3:9"}));
    // A broken /interp does not count as the first.
    EXPECT_EQ(messages("/robot r1 0 0 0\n/amb_light 1\n/interp r1 cubic\n/interp r1 ease\n"),
              (Lines{"3:12: error: unknown interpolation 'cubic' (expected linear, ease, ease_in, ease_out, "
                     "step, spline, back, elastic, bounce or bezier)"}));
}

}  // namespace
}  // namespace f2
