// The language server's parts: framing, UTF-16 positions, incremental
// changes, and the features whose replies the protocol test does not cover
// (symbols, folding, key alignment, command completion, robustness).
#include <gtest/gtest.h>
#include <unistd.h>

#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <random>
#include <set>
#include <string>
#include <utility>

#include "core/parse/language.h"
#include "core/parse/parser.h"
#include "core/parse/symbol_index.h"
#include "lsp/features.h"
#include "lsp/language_files.h"
#include "lsp/message_reader.h"
#include "lsp/scene_sources.h"
#include "lsp/server.h"
#include "lsp/source_scan.h"
#include "lsp/stdio_transport.h"

namespace f2::lsp {
namespace {

std::vector<MessageReader::Item> readAll(MessageReader& reader) {
    std::vector<MessageReader::Item> items;
    MessageReader::Item item;
    while (reader.next(item)) items.push_back(item);
    return items;
}

Analysis analysed(std::string text) { return analyze("file:///t/a.f2", TextDocument(std::move(text), 1)); }

/// A fresh directory under the system's temporary one, removed at the end.
struct TempDir {
    std::filesystem::path path;
    explicit TempDir(const std::string& name)
        : path(std::filesystem::temp_directory_path() / (name + std::to_string(::getpid()))) {
        std::filesystem::create_directories(path);
    }
    ~TempDir() { std::filesystem::remove_all(path); }
    std::string write(const std::string& file, const std::string& text) const {
        std::ofstream(path / file) << text;
        return (path / file).string();
    }
};

TEST(MessageReader, SplitsFramesFedByteByByte) {
    const std::string stream = frameMessage("{\"a\":1}") + "content-length:  2\r\nX-Other: y\r\n\r\n{}";
    MessageReader reader;
    std::vector<MessageReader::Item> items;
    for (char c : stream) {
        reader.feed(std::string_view(&c, 1));
        for (auto& i : readAll(reader)) items.push_back(i);
    }
    ASSERT_EQ(items.size(), 2u);
    EXPECT_EQ(items[0].kind, MessageReader::Item::Kind::Body);
    EXPECT_EQ(items[0].text, "{\"a\":1}");
    EXPECT_EQ(items[1].text, "{}");
}

TEST(MessageReader, ReportsBadHeadersAndResynchronises) {
    MessageReader reader;
    reader.feed("Content-Type: x\r\n\r\nContent-Length: abc\r\n\r\n" + frameMessage("[1]"));
    const auto items = readAll(reader);
    ASSERT_EQ(items.size(), 3u);
    EXPECT_EQ(items[0].text, "a message header without Content-Length");
    EXPECT_EQ(items[1].text, "bad Content-Length 'abc'");
    EXPECT_EQ(items[2].text, "[1]");
}

TEST(MessageReader, SkipsAnOversizedBodyWithoutKeepingIt) {
    MessageReader reader;
    const std::size_t size = MessageReader::kMaxBodyBytes + 10;
    reader.feed("Content-Length: " + std::to_string(size) + "\r\n\r\n");
    auto items = readAll(reader);
    ASSERT_EQ(items.size(), 1u);
    EXPECT_EQ(items[0].kind, MessageReader::Item::Kind::Problem);
    // The body arrives in chunks and is dropped; the next message is read.
    const std::string chunk(1 << 20, 'x');
    std::size_t sent = 0;
    while (sent + chunk.size() <= size) {
        reader.feed(chunk);
        sent += chunk.size();
        EXPECT_TRUE(readAll(reader).empty());
    }
    reader.feed(std::string(size - sent, 'x') + frameMessage("{}"));
    items = readAll(reader);
    ASSERT_EQ(items.size(), 1u);
    EXPECT_EQ(items[0].text, "{}");
}

TEST(MessageReader, DropsEndlessGarbage) {
    MessageReader reader;
    reader.feed(std::string(3 * MessageReader::kMaxHeaderBytes, 'g'));
    const auto items = readAll(reader);
    ASSERT_EQ(items.size(), 1u);
    EXPECT_EQ(items[0].kind, MessageReader::Item::Kind::Problem);
    reader.feed("\r\n\r\n" + frameMessage("1"));  // the rest of a garbage header, then a message
    const auto after = readAll(reader);
    ASSERT_FALSE(after.empty());
    EXPECT_EQ(after.back().text, "1");
}

TEST(MessageReader, DropsStrayBytesBeforeAHeaderFedByteByByte) {
    // A stray byte glued to the next header, blank lines, a junk line, and a
    // junk word that begins like a field name ("Cont", "content-lengthy").
    const std::string stream = frameMessage("1") + "x" + frameMessage("2") + "\n\r\n" + frameMessage("3") +
                               "junk: line\r\n\r\nCont" + frameMessage("4") + "content-lengthy" +
                               "CONTENT-LENGTH: 1\r\n\r\n5";
    for (const std::size_t chunk : {std::size_t{1}, std::size_t{3}, stream.size()}) {
        MessageReader reader;
        std::vector<std::string> bodies, problems;
        for (std::size_t i = 0; i < stream.size(); i += chunk) {
            reader.feed(std::string_view(stream).substr(i, chunk));
            for (const auto& item : readAll(reader))
                (item.kind == MessageReader::Item::Kind::Body ? bodies : problems).push_back(item.text);
        }
        EXPECT_EQ(bodies, (std::vector<std::string>{"1", "2", "3", "4", "5"})) << "chunk " << chunk;
        EXPECT_EQ(problems, (std::vector<std::string>{"dropped 1 stray byte (not a message header)",
                                                      "dropped 3 stray bytes (not a message header)",
                                                      "dropped 18 stray bytes (not a message header)",
                                                      "dropped 15 stray bytes (not a message header)"}))
            << "chunk " << chunk;
    }
}

TEST(MessageReader, AHeaderThatDoesNotEndIsGarbage) {
    MessageReader reader;
    reader.feed("Content-Length: 5" + std::string(2 * MessageReader::kMaxHeaderBytes, 'g') +
                frameMessage("ok"));
    const auto items = readAll(reader);
    ASSERT_FALSE(items.empty());
    EXPECT_EQ(items.front().kind, MessageReader::Item::Kind::Problem);
    EXPECT_EQ(items.back().kind, MessageReader::Item::Kind::Body);
    EXPECT_EQ(items.back().text, "ok");
}

TEST(Positions, CountUtf16Units) {
    EXPECT_EQ(utf16Length("abc"), 3);
    EXPECT_EQ(utf16Length("\xD0\xBF"), 1);          // п: 2 bytes, 1 unit
    EXPECT_EQ(utf16Length("\xE2\x82\xAC"), 1);      // €: 3 bytes, 1 unit
    EXPECT_EQ(utf16Length("\xF0\x9F\x98\x80"), 2);  // 😀: 4 bytes, a surrogate pair
    EXPECT_EQ(utf16Length("\xFF\x80"), 2);          // invalid bytes: one unit each
    const std::string line =
        "a\xF0\x9F\x98\x80"
        "b";
    EXPECT_EQ(byteOffsetOfUtf16(line, 1), 1u);
    EXPECT_EQ(byteOffsetOfUtf16(line, 2), 1u);  // inside the pair: its start
    EXPECT_EQ(byteOffsetOfUtf16(line, 3), 5u);
    EXPECT_EQ(byteOffsetOfUtf16(line, 99), line.size());
}

TEST(Positions, TokenRangesFromParserPlaces) {
    const TextDocument doc("\xEF\xBB\xBF/fps x\r\n/paint \xD0\xBF 1 2\n", 1);
    // Line 1 columns count from after the byte order mark, which is one UTF-16 unit.
    EXPECT_EQ(doc.tokenRange(1, 6), (Range{{0, 6}, {0, 7}}));
    EXPECT_EQ(doc.tokenRange(2, 8), (Range{{1, 7}, {1, 8}}));
    EXPECT_EQ(doc.tokenRange(2, 11), (Range{{1, 9}, {1, 10}}));
    // Past the end of the line and past the last line: clamped, never outside the text.
    EXPECT_EQ(doc.tokenRange(2, 500), (Range{{1, 12}, {1, 12}}));
    EXPECT_EQ(doc.tokenRange(99, 1), (Range{{2, 0}, {2, 0}}));
    EXPECT_EQ(doc.lineCount(), 3);
}

TEST(Positions, ShortDocumentsSurviveCopiesAndMoves) {
    // Short texts live inside the string object (small-string optimisation):
    // lines kept as views would point into the old object after a move.
    TextDocument a("/fps 1\n/x", 1);
    TextDocument b = a;
    TextDocument c = std::move(a);
    a = TextDocument("zzzzzzzzzz", 2);
    EXPECT_EQ(b.line(0), "/fps 1");
    EXPECT_EQ(c.line(1), "/x");
    EXPECT_EQ(a.line(0), "zzzzzzzzzz");
}

TEST(Server, HandlesALargeDocument) {
    // 100,000 objects and keys: every request answers (no size-dependent failure).
    std::string text = "/amb_light 1\n";
    for (int i = 0; i < 50'000; ++i) {
        text += "/sphere s" + std::to_string(i) + " 1 " + std::to_string(i) + " 0 0\n/key 1 s" +
                std::to_string(i) + "\n";
    }
    const Analysis a = analysed(text);
    EXPECT_TRUE(a.result.ok());
    const Json refs = references(a, {100'000, 8}, true);  // "/key 1 s49999"
    ASSERT_TRUE(refs.is_array());
    EXPECT_EQ(refs.size(), 2u);
    EXPECT_EQ(documentSymbols(a).size(), 50'001u);
    // Names as typed, at most 1000 of them, marked incomplete beyond that.
    const Json some = completion(a, {100'000, 8});  // after "/key 1 s"
    ASSERT_TRUE(some.is_object());
    EXPECT_EQ(some["isIncomplete"], true);
    EXPECT_EQ(some["items"].size(), 1000u);
    const Json few = completion(a, {100'000, 12});  // after "/key 1 s4999"
    ASSERT_TRUE(few.is_array());
    EXPECT_EQ(few.size(), 11u);  // s4999, s49990 … s49999
}

TEST(Uris, PathsArePercentEncodedByteByByte) {
    // Only RFC 3986's unreserved ASCII characters and '/' stay as they are.
    EXPECT_EQ(uriFromPath("/t/\xC3\xA9 d~x_1-2.f2"), "file:///t/%C3%A9%20d~x_1-2.f2");
    EXPECT_EQ(uriFromPath("/t/a#b%c"), "file:///t/a%23b%25c");
}

TEST(Changes, ApplyRangesInUtf16Units) {
    const std::string text = "/paint \xF0\x9F\x98\x80 1\n/fps 24\n";
    const Json change = {
        {"range", {{"start", {{"line", 0}, {"character", 7}}}, {"end", {{"line", 0}, {"character", 9}}}}},
        {"text", "s"}};
    EXPECT_EQ(applyChange(text, change), "/paint s 1\n/fps 24\n");
    const Json whole = {{"text", "/fps 1"}};
    EXPECT_EQ(applyChange(text, whole), "/fps 1");
    const Json reversed = {
        {"range", {{"start", {{"line", 1}, {"character", 0}}}, {"end", {{"line", 0}, {"character", 0}}}}},
        {"text", ""}};
    EXPECT_THROW(applyChange(text, reversed), RequestError);
}

TEST(Diagnostics, WarningsAndErrorsWithTokenRanges) {
    const Analysis a = analysed("/amb_light 1\n/sphere ball 10 0 0 0\n/key 5 ball\n/key 5 ball\n/fps 24x\n");
    const Json published = publishDiagnostics(a);
    ASSERT_EQ(published.size(), 1u);
    EXPECT_EQ(published[0]["uri"], "file:///t/a.f2");
    const Json& list = published[0]["diagnostics"];
    ASSERT_EQ(list.size(), 2u) << list.dump();
    EXPECT_EQ(list[0]["severity"], kSeverityWarning);
    EXPECT_EQ(list[0]["range"], toJson(Range{{3, 5}, {3, 6}}));  // the frame of the later key
    EXPECT_EQ(list[1]["severity"], kSeverityError);
    EXPECT_EQ(list[1]["range"], toJson(Range{{4, 5}, {4, 8}}));
}

TEST(Diagnostics, RangesCoverWhatTheParserSaysAsTheViewerUnderlinesIt) {
    // An expression argument with spaces, and a name inside one: the parser's
    // extent (core markedBytes), not "up to the next space".
    const Analysis a = analysed("/sphere b2 (1 - 3) 0 0 0\n/sphere b3 (1 + nope) 0 0 0\n");
    const Json published = publishDiagnostics(a);
    const Json& list = published[0]["diagnostics"];
    ASSERT_EQ(list.size(), 2u) << list.dump();
    EXPECT_EQ(list[0]["range"], toJson(Range{{0, 11}, {0, 18}}));  // (1 - 3)
    EXPECT_EQ(list[1]["range"], toJson(Range{{1, 16}, {1, 20}}));  // nope
}

// The same lines, the same marks: tests/viewer/editor_test.cpp
// (sameMarksAsTheLanguageServer) underlines these columns in the viewer.
TEST(Diagnostics, MarksOnBracketsGluedCommentsTabsAndNonAscii) {
    struct Case {
        const char* line;
        int begin, end;  // UTF-16 columns, 0-based, [begin, end)
    };
    const Case cases[] = {
        {"/fps 24x#c", 5, 8},                    // '#' glued to the token: "24x"
        {"/fps\t24x", 5, 8},                     // a tab is one column
        {"/sphere \xc3\xa9 1 0 0 0", 8, 9},      // 'é': two bytes, one UTF-16 unit
        {"/sphere b (1 + nope) 0 0 0", 15, 19},  // a name inside brackets
    };
    for (const Case& c : cases) {
        const Json published = publishDiagnostics(analysed(std::string(c.line) + "\n"));
        const Json& list = published[0]["diagnostics"];
        ASSERT_EQ(list.size(), 1u) << c.line << ": " << list.dump();
        EXPECT_EQ(list[0]["range"], toJson(Range{{0, c.begin}, {0, c.end}})) << c.line;
    }
}

TEST(Diagnostics, ThirdEditionLinesAsTheParserReadsThem) {
    // A caption's quoted text with spaces and '#', seconds and a bezier key: no diagnostics;
    // a caption whose quote is left open: the parser's one error, at the quote.
    const Analysis good = analysed(
        "/amb_light 1\n/sphere b 1 0 0 0\n/key 0.5s b bezier 0.25 0.1 0.25 1\n/key 2s b 1 0 0 0 0 0\n"
        "/caption 0 1s 0.1 0.9 0.1 \"a # b \\\" c\" colour 1 2 3\n");
    EXPECT_TRUE(publishDiagnostics(good)[0]["diagnostics"].empty()) << publishDiagnostics(good).dump();
    const Analysis open = analysed("/sphere b 1 0 0 0\n/caption 0 1 0 0 0.1 \"a # b\n");
    const Json published = publishDiagnostics(open);
    const Json& list = published[0]["diagnostics"];
    ASSERT_EQ(list.size(), 1u) << list.dump();
    EXPECT_EQ(list[0]["message"], "this '\"' has no closing '\"'");
    EXPECT_EQ(list[0]["range"]["start"], toJson(Range{{1, 21}, {1, 21}})["start"]);
}

TEST(Outline, SymbolsListObjectsPartsCameraAndLights) {
    const Analysis a = analysed(
        "/camera 320 240 0.5\n/sphere ball 10 0 0 0\n/robot r1 0 0 0\n/dir_light 1 0 -1 0\n"
        "/key 0 r1.head\n/key 5 r1.head 0 0 0 0 30 0\n/key 5 ball\n");
    const Json symbols = documentSymbols(a);
    ASSERT_EQ(symbols.size(), 4u);
    EXPECT_EQ(symbols[0]["name"], "camera");
    EXPECT_EQ(symbols[0]["detail"], "320 240 0.5");
    EXPECT_EQ(symbols[1]["name"], "ball");
    EXPECT_EQ(symbols[1]["detail"], "sphere, 1 key");
    EXPECT_EQ(symbols[2]["name"], "r1");
    EXPECT_EQ(symbols[2]["detail"], "robot, 0 keys");
    ASSERT_EQ(symbols[2]["children"].size(), 4u);
    EXPECT_EQ(symbols[2]["children"][1]["name"], "head");
    EXPECT_EQ(symbols[2]["children"][1]["detail"], "2 keys");
    EXPECT_EQ(symbols[3]["name"], "dir_light");
    EXPECT_EQ(symbols[3]["kind"], kSymbolEvent);
}

TEST(Outline, FoldsRepeatBlocksKeepingEndVisible) {
    const Analysis a =
        analysed("/repeat i 1 3\n  /sphere s{i} 1 (i) 0 0\n  /repeat j 1 2\n    /fps 1\n  /end\n/end\n");
    EXPECT_EQ(foldingRanges(a), Json::parse(R"([{"startLine":2,"endLine":3,"kind":"region"},
                                                {"startLine":0,"endLine":4,"kind":"region"}])"));
}

TEST(KeyFormat, AlignsRunsOfKeysIntoColumns) {
    const Analysis a = analysed(
        "/robot r1 0 0 0\n"
        "  /key 0 r1.lhand   # rest\n"
        "  /key 15 r1.lhand 0 0 0 120 45 0\n"
        "  /key 5 r1 0 0 200 0 -135.5 0  # turn\n"
        "/fps 24\n"
        "/key 1 r1\n");
    const Json edits = formatKeys(a);
    ASSERT_EQ(edits.size(), 3u);
    EXPECT_EQ(edits[0]["newText"], "  /key  0 r1.lhand" + std::string(23, ' ') + "# rest");
    EXPECT_EQ(edits[1]["newText"], "  /key 15 r1.lhand 0 0   0 120     45 0");
    EXPECT_EQ(edits[2]["newText"], "  /key  5 r1       0 0 200   0 -135.5 0  # turn");
    EXPECT_EQ(edits[1]["range"], toJson(Range{{2, 0}, {2, 33}}));
    // Aligned text is left alone.
    std::string text = "/robot r1 0 0 0\n";
    for (const Json& e : edits) text += e["newText"].get<std::string>() + "\n";
    EXPECT_TRUE(formatKeys(analysed(text)).empty());
}

TEST(Hover, PrimitiveSizeCommandSyntaxAndBrokenScenes) {
    const Analysis a =
        analysed("/amb_light 1\n/box crate 10 20 30 1 2 3\n/key 4 crate 0 0 0 0 90 0\n/fps x\n");
    const Json onName = hover(a, {2, 9});
    ASSERT_TRUE(onName.is_object());
    const std::string text = onName["contents"]["value"];
    EXPECT_NE(text.find("**box** `crate`, created at line 2"), std::string::npos) << text;
    EXPECT_NE(text.find("- box 10 × 20 × 30\n- keys: 1\n"), std::string::npos) << text;
    // The scene has an error (line 4): the pose shown is the one it was created with.
    EXPECT_NE(text.find("as created: position (1, 2, 3), rotation (0, 0, 0)"), std::string::npos) << text;
    const Json onCommand = hover(a, {1, 2});
    EXPECT_EQ(onCommand["range"], toJson(Range{{1, 0}, {1, 4}}));
    EXPECT_EQ(onCommand["contents"]["value"].get<std::string>().rfind("```f2\n/box <name> <sx>", 0), 0u);
    EXPECT_TRUE(hover(a, {1, 17}).is_null());  // a number
}

TEST(Drives, CompletionOfChannelsAndInputsAndHoverWithTheValueAtFrameZero) {
    // SPEC 10.7: the channels a target has, then frame and time inside the expression.
    const std::string scene =
        "/sphere ball 1 0 0 0\n"                       // 0
        "/point_light 2 0 3 0 name lamp\n"             // 1
        "/let k 3\n"                                   // 2
        "/drive ball px (k + 10*sin(time*90 + 90))\n"  // 3
        "/drive lamp intensity (1/frame)\n";           // 4
    const Analysis typing =
        analysed(scene + "/drive ball \n/drive camera \n/drive lamp \n/drive ball px (fr\n/key 0 ball (\n");
    const auto labels = [&](Position p) {
        std::vector<std::string> out;
        for (const Json& i : completion(typing, p)) out.push_back(i["label"]);
        return out;
    };
    EXPECT_EQ(labels({5, 12}), (std::vector<std::string>{"px", "py", "pz", "rx", "ry", "rz", "r", "g", "b"}));
    EXPECT_EQ(labels({6, 14}), (std::vector<std::string>{"px", "py", "pz", "rx", "ry", "rz", "d"}));
    EXPECT_EQ(labels({7, 12}), (std::vector<std::string>{"px", "py", "pz", "rx", "ry", "rz", "intensity"}));
    const auto inDrive = labels({8, 17});
    EXPECT_NE(std::find(inDrive.begin(), inDrive.end(), "frame"), inDrive.end());
    EXPECT_NE(std::find(inDrive.begin(), inDrive.end(), "time"), inDrive.end());
    EXPECT_NE(std::find(inDrive.begin(), inDrive.end(), "k"), inDrive.end());
    // Elsewhere frame and time are no variables.
    const auto inKey = labels({9, 13});
    EXPECT_NE(std::find(inKey.begin(), inKey.end(), "pi"), inKey.end());
    EXPECT_EQ(std::find(inKey.begin(), inKey.end(), "frame"), inKey.end());

    // Hover on /drive: its value at frame 0 (the server has no current frame), or why it has none.
    const Analysis a = analysed(scene);
    ASSERT_TRUE(a.result.ok());
    const std::string ball = hover(a, {3, 2})["contents"]["value"];
    EXPECT_EQ(ball.rfind("```f2\n/drive <target> <channel> (<expression>)\n```\n", 0), 0u) << ball;
    EXPECT_NE(ball.find("\n\n`ball px` at frame 0: 13"), std::string::npos) << ball;
    const std::string lamp = hover(a, {4, 2})["contents"]["value"];
    EXPECT_NE(lamp.find("`lamp intensity` at frame 0: no finite value (division by zero)"), std::string::npos)
        << lamp;
    const std::string inside = hover(a, {3, 28})["contents"]["value"];
    EXPECT_NE(inside.find("frame / fps"), std::string::npos) << inside;
}

// Second edition (SPEC 9.4, 9.5): variables and includes, as the parser's one pass finds them.
constexpr const char* kLoops =
    "/let n 3\n"                                 // 0
    "/repeat i 1 (n)  # (ignored) \n"            // 1
    "  /sphere s{i} 10 (i * 30 + sin(n)) 0 0\n"  // 2
    "/end\n"                                     // 3
    "/let n (n + 1)\n"                           // 4
    "/fps (n)\n";                                // 5

TEST(Variables, FoundByTheParsersOnePass) {
    const Analysis a = analysed(kLoops);
    const auto& all = a.sources.variables;
    std::vector<std::string> seen;
    for (const VariableOccurrence& v : all) {
        seen.push_back(std::to_string(v.line) + ":" + v.name + (v.definition ? "=" : ""));
    }
    // The loop's body is read three times and listed once.
    EXPECT_EQ(seen,
              (std::vector<std::string>{"0:n=", "1:i=", "1:n", "2:i", "2:i", "2:n", "4:n=", "4:n", "5:n"}));
    EXPECT_EQ(definitionOf(all, "n", a.sources.orderOf(0, 5))->line, 4);
    EXPECT_EQ(definitionOf(all, "n", a.sources.orderOf(0, 2))->line, 0);
    EXPECT_TRUE(definitionOf(all, "i", a.sources.orderOf(0, 2))->loop);
    EXPECT_FALSE(definitionOf(all, "zz", a.sources.orderOf(0, 2)));
}

TEST(Variables, ALoopBodyReadManyTimesHasOneReferencePerWrittenPlace) {
    const Analysis a = analysed(
        "/let k 2\n"                            // 0
        "/repeat i 1 1000\n"                    // 1
        "  /sphere s{i} (k) (i * k) 0 0\n"      // 2
        "/end\n"                                // 3
        "/repeat j 1 0\n"                       // 4: no pass, never read
        "  /sphere t{j} (k) 0 0 0\n"            // 5
        "/end\n");                              // 6
    EXPECT_EQ(a.sources.variables.size(), 7u);  // k= i= i k i k j=
    EXPECT_EQ(references(a, {0, 5}, true).size(), 3u);
    EXPECT_EQ(references(a, {2, 12}, false).size(), 2u);
    EXPECT_EQ(rename(a, {1, 8}, "m")["changes"][a.uri].size(), 3u);
    // The body of a loop of no pass is not read: its names are not known there.
    EXPECT_TRUE(definition(a, {5, 12}).is_null());
    EXPECT_EQ(references(a, {4, 8}, true).size(), 1u);
}

TEST(Variables, DefinitionReferencesRenameHoverCompletion) {
    const Analysis a = analysed(kLoops);
    // From the use of n in "(i * 30 + sin(n))" (line 2, column 32) to "/let n 3".
    EXPECT_EQ(definition(a, {2, 32}), location(a.uri, Range{{0, 5}, {0, 6}}));
    EXPECT_EQ(definition(a, {5, 6}), location(a.uri, Range{{4, 5}, {4, 6}}));
    EXPECT_EQ(references(a, {2, 32}, false).size(), 4u);
    EXPECT_EQ(references(a, {2, 32}, true).size(), 6u);
    const Json edit = rename(a, {2, 13}, "k");
    ASSERT_EQ(edit["changes"][a.uri].size(), 3u);  // the /repeat's i and two uses
    EXPECT_EQ(edit["changes"][a.uri][0]["range"], toJson(Range{{1, 8}, {1, 9}}));
    EXPECT_THROW(rename(a, {2, 13}, "pi"), RequestError);
    EXPECT_THROW(rename(a, {2, 13}, "n"), RequestError);
    EXPECT_EQ(prepareRename(a, {5, 6})["placeholder"], "n");
    const std::string text = hover(a, {2, 13})["contents"]["value"];
    EXPECT_EQ(text,
              "**loop variable** `i` = 1 on the first pass, defined at line 2:\n```f2\n/repeat i 1 (n)  # "
              "(ignored) "
              "\n```");
    // The value where it is used: /let n (n + 1) after /let n 3.
    EXPECT_EQ(hover(a, {5, 6})["contents"]["value"],
              "**variable** `n` = 4, defined at line 5:\n```f2\n/let n (n + 1)\n```");
    // In an expression: the variables defined so far, pi and the functions.
    const Json items = completion(a, {2, 20});
    ASSERT_GE(items.size(), 3u);
    EXPECT_EQ(items[0]["label"], "n");
    EXPECT_EQ(items[1]["label"], "i");
    EXPECT_EQ(items[2]["label"], "pi");
    EXPECT_EQ(items[3]["label"], "sin");
    EXPECT_EQ(items[3]["textEdit"]["newText"], "sin($1)");
    // The name s{i} is the objects s1, s2, s3; the parser sees it written as `s{i}`.
    const std::string object = hover(a, {2, 10})["contents"]["value"];
    EXPECT_EQ(object.rfind("**sphere** `s1`, created at line 3", 0), 0u) << object;
    EXPECT_EQ(hover(a, {2, 10})["range"], toJson(Range{{2, 10}, {2, 14}}));
    EXPECT_THROW(rename(a, {2, 10}, "t"), RequestError);  // written as an expression
}

TEST(Includes, DefinitionHoverAndPathCompletion) {
    const TempDir dir("f2_lsp_include_");
    std::filesystem::create_directories(dir.path / "parts");
    const std::string floor = dir.write("parts/floor.f2", "/box floor 10 10 10 0 0 0\n");
    dir.write("parts/notes.txt", "x");
    const std::string main = (dir.path / "main.f2").string();
    const Analysis a =
        analyze(uriFromPath(main), TextDocument("/include \"parts/floor.f2\"\n/include parts/\n", 1));
    EXPECT_EQ(definition(a, {0, 12}), location(uriFromPath(floor), Range{}));
    EXPECT_EQ(hover(a, {0, 12})["contents"]["value"], "**include** `" + floor + "`");
    const Json items = completion(a, {1, 15});
    ASSERT_EQ(items.size(), 1u);  // floor.f2; not the .txt
    EXPECT_EQ(items[0]["label"], "floor.f2");
    EXPECT_EQ(items[0]["textEdit"]["range"], toJson(Range{{1, 15}, {1, 15}}));
}

TEST(Includes, DiagnosticsInAnIncludedFileAreItsOwn) {
    const TempDir dir("f2_lsp_diag_");
    const std::string part = dir.write("part.f2", "# \xD0\xBF\n/sphere ball 1 0 0 0\n/key 0 bal\n");
    const Analysis a = analyze(uriFromPath((dir.path / "main.f2").string()),
                               TextDocument("/amb_light 1\n/include part.f2\n/key 1 ball\n", 1));
    const Json published = publishDiagnostics(a);
    ASSERT_EQ(published.size(), 2u) << published.dump();
    // On the include line of the open file: a summary pointing at the place.
    ASSERT_EQ(published[0]["diagnostics"].size(), 1u);
    const Json& summary = published[0]["diagnostics"][0];
    EXPECT_EQ(summary["range"], toJson(Range{{1, 9}, {1, 16}}));
    EXPECT_EQ(summary["message"],
              "in the included file part.f2:3:8: unknown name 'bal' (did you mean 'ball'?)");
    EXPECT_EQ(summary["relatedInformation"][0]["location"],
              location(uriFromPath(part), Range{{2, 7}, {2, 10}}));
    EXPECT_EQ(published[1]["uri"], uriFromPath(part));
    ASSERT_EQ(published[1]["diagnostics"].size(), 1u);
    EXPECT_EQ(published[1]["diagnostics"][0]["range"], toJson(Range{{2, 7}, {2, 10}}));
    // The object created in the included file: definition goes there.
    EXPECT_EQ(definition(a, {2, 8}), location(uriFromPath(part), Range{{1, 8}, {1, 12}}));
}

TEST(Includes, FixedIncludeErrorsAreClearedOnSave) {
    const TempDir dir("f2_lsp_clear_");
    const std::string part = dir.write("part.f2", "/fps x\n");
    const std::string mainUri = uriFromPath((dir.path / "main.f2").string());
    const std::string partUri = uriFromPath(part);
    Server server;
    server.handle(R"({"id":1,"method":"initialize"})");
    auto diagnosticsOf = [](const std::vector<std::string>& out, const std::string& uri) {
        Json found;
        for (const std::string& m : out) {
            const Json j = Json::parse(m);
            if (j["params"]["uri"] == uri) found = j["params"]["diagnostics"];
        }
        return found;
    };
    const auto opened = server.handle(
        Json({{"method", "textDocument/didOpen"},
              {"params",
               {{"textDocument", {{"uri", mainUri}, {"version", 1}, {"text", "/include part.f2\n"}}}}}})
            .dump());
    EXPECT_EQ(diagnosticsOf(opened, partUri).size(), 1u);
    dir.write("part.f2", "/fps 24\n");
    const auto saved = server.handle(
        Json({{"method", "textDocument/didSave"}, {"params", {{"textDocument", {{"uri", partUri}}}}}})
            .dump());
    EXPECT_EQ(diagnosticsOf(saved, partUri), Json::array());
}

/// A scene in a temporary directory: main.f2 includes parts/stage.f2, which
/// defines a variable and an object main.f2 uses, and uses one of main.f2's.
struct IncludedScene {
    TempDir dir;
    std::string main, stage;
    static constexpr const char* kMain =
        "/let w 40\n"                       // 0
        "/include \"parts/stage.f2\"\n"     // 1
        "/sphere ball (w) 0 (h) 0\n"        // 2
        "/key 0 prop\n"                     // 3
        "/key 10 prop 0 (h * 2) 0 0 0 0\n"  // 4
        "/look_at prop\n"                   // 5
        "/key 0 camera\n";                  // 6
    static constexpr const char* kStage =
        "/amb_light 1\n"                     // 0
        "/let h 25\n"                        // 1
        "/box prop 10 (w) 10 0 0 0\n"        // 2
        "/camera 320 240 0.5 0 100 -500\n";  // 3

    explicit IncludedScene(const std::string& name) : dir(name) {
        std::filesystem::create_directories(dir.path / "parts");
        main = dir.write("main.f2", kMain);
        stage = dir.write("parts/stage.f2", kStage);
    }
};

TEST(Includes, VariablesAndObjectsFollowedBothWays) {
    const IncludedScene scene("f2_lsp_both_");
    const Analysis m = analyze(uriFromPath(scene.main), TextDocument(IncludedScene::kMain, 1));
    const std::string mainUri = uriFromPath(scene.main), stageUri = uriFromPath(scene.stage);
    EXPECT_TRUE(m.result.ok());
    // From main.f2 into the included file: the variable h and the object prop.
    EXPECT_EQ(definition(m, {2, 20}), location(stageUri, Range{{1, 5}, {1, 6}}));
    EXPECT_EQ(definition(m, {3, 8}), location(stageUri, Range{{2, 5}, {2, 9}}));
    EXPECT_EQ(references(m, {4, 16}, true).size(), 3u);
    const Json edit = rename(m, {2, 20}, "height");
    EXPECT_EQ(edit["changes"][stageUri].size(), 1u);
    EXPECT_EQ(edit["changes"][mainUri].size(), 2u);
    EXPECT_THROW(rename(m, {2, 20}, "w"), RequestError);      // taken
    EXPECT_THROW(rename(m, {3, 8}, "camera"), RequestError);  // reserved
    EXPECT_THROW(rename(m, {3, 8}, "ball"), RequestError);    // taken
    // Back: stage.f2 open, analysed as part of main.f2 (its buffer replaces the file).
    const SourceOverlay open{{scene.main, IncludedScene::kMain},
                             {scene.stage, std::string(IncludedScene::kStage) + "# edited\n"}};
    const Analysis s = analyze(stageUri, TextDocument(open.at(scene.stage), 2), open, scene.main);
    EXPECT_EQ(s.root, scene.main);
    EXPECT_TRUE(s.result.ok()) << publishDiagnostics(s).dump();
    EXPECT_EQ(s.document.lineCount(), 6);
    EXPECT_EQ(definition(s, {2, 14}), location(mainUri, Range{{0, 5}, {0, 6}}));
    EXPECT_EQ(references(s, {2, 6}, false).size(), 3u);  // the uses in main.f2
    const std::string hoverW = hover(s, {2, 14})["contents"]["value"];
    EXPECT_EQ(hoverW,
              "**variable** `w` = 40, defined at line 1 of " + scene.main + ":\n```f2\n/let w 40\n```");
    // Alone, stage.f2 does not know w.
    const Analysis alone = analyze(stageUri, TextDocument(IncludedScene::kStage, 1));
    EXPECT_FALSE(alone.result.ok());
    EXPECT_TRUE(definition(alone, {2, 14}).is_null());
}

TEST(Includes, AUseInAnIncludedFileResolvesAndRenamesAcrossTheInclude) {
    const TempDir dir("f2_lsp_across_");
    // The included file is read on each of three passes; its names are listed once.
    const std::string main = dir.write("main.f2", "/let w 2\n/repeat i 1 3\n  /include part.f2\n/end\n");
    const std::string part = dir.write("part.f2", "/sphere s{i} (w) 0 0 0\n");
    const std::string mainUri = uriFromPath(main), partUri = uriFromPath(part);
    const SourceOverlay open{{main, "/let w 2\n/repeat i 1 3\n  /include part.f2\n/end\n"},
                             {part, "/sphere s{i} (w) 0 0 0\n"}};
    const Analysis p = analyze(partUri, TextDocument(open.at(part), 1), open, main);
    ASSERT_EQ(p.root, main);
    EXPECT_TRUE(p.result.ok()) << publishDiagnostics(p).dump();
    EXPECT_EQ(definition(p, {0, 14}), location(mainUri, Range{{0, 5}, {0, 6}}));
    EXPECT_EQ(definition(p, {0, 10}), location(mainUri, Range{{1, 8}, {1, 9}}));
    EXPECT_EQ(references(p, {0, 14}, true).size(), 2u);
    const Json w = rename(p, {0, 14}, "width");
    ASSERT_EQ(w["changes"][mainUri].size(), 1u);
    ASSERT_EQ(w["changes"][partUri].size(), 1u);
    EXPECT_EQ(w["changes"][partUri][0]["range"], toJson(Range{{0, 14}, {0, 15}}));
    const Json i = rename(p, {0, 10}, "k");
    EXPECT_EQ(i["changes"][mainUri].size(), 1u);
    EXPECT_EQ(i["changes"][partUri].size(), 1u);
    // From the including file: the include's path leads to the file.
    const Analysis m = analyze(mainUri, TextDocument(open.at(main), 1), open);
    EXPECT_EQ(definition(m, {2, 12}), location(partUri, Range{}));
    EXPECT_EQ(references(m, {1, 8}, false).size(), 1u);  // the use in part.f2
}

TEST(Includes, ParserReadsOpenTextsBeforeTheDisk) {
    const TempDir dir("f2_lsp_overlay_");
    const std::string part = dir.write("part.f2", "/fps x\n");  // broken on disk, fixed in the editor
    const std::string main = dir.write("main.f2", "");
    const std::string ghost = (dir.path / "ghost.f2").string();  // open, never saved
    const SourceOverlay open{{part, "/fps 30\n"}, {ghost, "/amb_light 1\n/include ghost.f2\n"}};
    SymbolIndex index;
    const ParseResult fixed =
        parseScene("/include part.f2\n/amb_light 1\n", main, ParseLimits{}, index, open);
    EXPECT_TRUE(fixed.ok());
    EXPECT_EQ(fixed.scene->fps, 30);
    // An unsaved file that includes itself: a cycle, not an endless read.
    const ParseResult cycle = parseScene("/include ghost.f2\n", main, ParseLimits{}, index, open);
    ASSERT_EQ(cycle.diagnostics.size(), 1u);
    EXPECT_EQ(cycle.diagnostics[0].loc.file, ghost);
    EXPECT_EQ(cycle.diagnostics[0].message.rfind("include cycle: ", 0), 0u) << cycle.diagnostics[0].message;
    // The text stands for its file: including that file is a cycle at once.
    const ParseResult self = parseScene("/include main.f2\n", main, ParseLimits{}, index, open);
    ASSERT_EQ(self.diagnostics.size(), 1u);
    EXPECT_EQ(self.diagnostics[0].loc.file, main);
    EXPECT_EQ(self.diagnostics[0].loc.line, 1);
}

TEST(Includes, IndexSurvivesCyclesMissingFilesAndDiamonds) {
    const TempDir dir("f2_lsp_scan_");
    const std::string a =
        dir.write("a.f2", "/let a 1\n/include b.f2\n/include missing.f2\n/include \"{x}.f2\"\n");
    dir.write("b.f2", "/let b 2\n/include a.f2\n");
    // 17 levels, each including the next twice: 2^17 readings without the line budget.
    for (int i = 0; i < 17; ++i) {
        const std::string next = "d" + std::to_string(i + 1) + ".f2";
        dir.write("d" + std::to_string(i) + ".f2", "/include " + next + "\n/include " + next + "\n");
    }
    dir.write("d17.f2", "/let deep 1\n");
    const SceneSources cyc =
        analyze(uriFromPath(a), TextDocument("/let a 1\n/include b.f2\n/include missing.f2\n", 1)).sources;
    ASSERT_EQ(cyc.files.size(), 2u);
    EXPECT_TRUE(cyc.reaches(0, 1));
    EXPECT_TRUE(cyc.reaches(1, 0));
    EXPECT_EQ(cyc.variables.size(), 2u);  // b.f2's include of a.f2 is a cycle, not read again
    ASSERT_EQ(cyc.includes.size(), 3u);
    EXPECT_EQ(cyc.includes[2].target, -1);  // missing.f2
    const SceneSources deep = analyze(uriFromPath((dir.path / "d0.f2").string()),
                                      TextDocument("/include d1.f2\n/include d1.f2\n", 1))
                                  .sources;
    EXPECT_EQ(deep.files.size(), 17u);    // d0 … d16 read; d17 would be 17 deep, beyond 16 (SPEC 9.5)
    EXPECT_TRUE(deep.variables.empty());  // so its /let is not seen
}

TEST(Includes, OpenDocumentsThatIncludeEachOtherOrThemselves) {
    // Files that exist only as open documents: their texts are what includes read.
    Server server;
    server.handle(R"({"id":1,"method":"initialize"})");
    auto open = [&](const std::string& uri, const std::string& text) {
        return server.handle(
            Json({{"method", "textDocument/didOpen"},
                  {"params", {{"textDocument", {{"uri", uri}, {"version", 1}, {"text", text}}}}}})
                .dump());
    };
    const std::string a = "file:///nowhere/a.f2", b = "file:///nowhere/b.f2";
    open(a, "/amb_light 1\n/include b.f2\n/sphere s (n) 0 0 0\n");
    const auto both = open(b, "/let n 3\n/include b.f2\n");
    // b.f2 is read as part of a.f2: its self-include is a cycle, reported once on b.f2.
    std::map<std::string, Json> published;
    for (const std::string& m : both) {
        const Json j = Json::parse(m);
        published[j["params"]["uri"]] = j["params"]["diagnostics"];
    }
    ASSERT_EQ(published.size(), 2u);
    ASSERT_EQ(published[b].size(), 1u);
    EXPECT_EQ(published[b][0]["message"].get<std::string>().rfind("include cycle: ", 0), 0u);
    EXPECT_EQ(published[a].size(), 1u);  // the summary on a.f2's include line
    // The variable n of the open b.f2 is known in a.f2, both ways.
    const Json def = Json::parse(server.handle(
        Json({{"id", 2},
              {"method", "textDocument/definition"},
              {"params", {{"textDocument", {{"uri", a}}}, {"position", {{"line", 2}, {"character", 11}}}}}})
            .dump())[0]);
    EXPECT_EQ(def["result"], location(b, Range{{0, 5}, {0, 6}}));
    // a.f2 now includes itself and b.f2 includes a.f2: every request still answers.
    open(a, "/include a.f2\n/include b.f2\n");
    open(b, "/include a.f2\n");
    const auto reply = server.handle(
        Json({{"id", 3},
              {"method", "textDocument/hover"},
              {"params", {{"textDocument", {{"uri", b}}}, {"position", {{"line", 0}, {"character", 10}}}}}})
            .dump());
    ASSERT_EQ(reply.size(), 1u);
    EXPECT_TRUE(Json::parse(reply[0]).contains("result"));
}

/// A server fed didOpen/didChange/didClose, counting the publishDiagnostics
/// notifications each change sends, by URI.
struct Editor {
    Server server;
    Editor() { server.handle(R"({"id":1,"method":"initialize"})"); }
    std::map<std::string, std::vector<Json>> send(const Json& message) {
        std::map<std::string, std::vector<Json>> published;
        for (const std::string& m : server.handle(message.dump())) {
            const Json j = Json::parse(m);
            if (j.value("method", "") == "textDocument/publishDiagnostics")
                published[j["params"]["uri"]].push_back(j["params"]["diagnostics"]);
        }
        return published;
    }
    std::map<std::string, std::vector<Json>> open(const std::string& uri, const std::string& text) {
        return send({{"method", "textDocument/didOpen"},
                     {"params", {{"textDocument", {{"uri", uri}, {"version", 1}, {"text", text}}}}}});
    }
    std::map<std::string, std::vector<Json>> change(const std::string& uri, const std::string& text) {
        return send({{"method", "textDocument/didChange"},
                     {"params",
                      {{"textDocument", {{"uri", uri}, {"version", 2}}},
                       {"contentChanges", Json::array({{{"text", text}}})}}}});
    }
    std::map<std::string, std::vector<Json>> close(const std::string& uri) {
        return send({{"method", "textDocument/didClose"}, {"params", {{"textDocument", {{"uri", uri}}}}}});
    }
    Json hover(const std::string& uri, int line, int character) {
        return Json::parse(server.handle(Json({{"id", 2},
                                               {"method", "textDocument/hover"},
                                               {"params",
                                                {{"textDocument", {{"uri", uri}}},
                                                 {"position", {{"line", line}, {"character", character}}}}}})
                                             .dump())[0]);
    }
};

/// The URIs published, each once.
std::vector<std::string> urisOf(const std::map<std::string, std::vector<Json>>& published) {
    std::vector<std::string> uris;
    for (const auto& [uri, each] : published) {
        EXPECT_EQ(each.size(), 1u) << uri << " published " << each.size() << " times";
        uris.push_back(uri);
    }
    return uris;
}

TEST(Includes, AChangeRepublishesItsIncludersAndNothingElse) {
    // Files that exist only as open documents, so every include reads an open text.
    const std::string part = "file:///nowhere/part.f2", a = "file:///nowhere/a.f2",
                      b = "file:///nowhere/b.f2", other = "file:///nowhere/other.f2",
                      top = "file:///nowhere/top.f2";
    Editor e;
    EXPECT_EQ(urisOf(e.open(part, "/let n 3\n")), std::vector<std::string>{part});
    // part.f2 moves into a.f2's scene, and stays there when b.f2 includes it too.
    EXPECT_EQ(urisOf(e.open(a, "/amb_light 1\n/include part.f2\n/sphere s (n) 0 0 0\n")),
              (std::vector{a, part}));
    EXPECT_EQ(urisOf(e.open(b, "/amb_light 1\n/include part.f2\n/box c (n) 1 1 0 0 0\n")), std::vector{b});
    EXPECT_EQ(urisOf(e.open(other, "/amb_light 1\n/sphere o 1 0 0 0\n")), std::vector{other});
    // An error typed into part.f2: part.f2 and both includers, each once; other.f2 not.
    auto published = e.change(part, "/let n x\n");
    EXPECT_EQ(urisOf(published), (std::vector{a, b, part}));
    ASSERT_EQ(published[a].size(), 1u);
    ASSERT_EQ(published[a][0].size(), 1u);  // the summary on a.f2's include line: a.f2 read the new text
    EXPECT_EQ(published[a][0][0]["range"]["start"]["line"], 1);
    EXPECT_EQ(published[part][0].size(), 1u);
    // A change of the unrelated document: itself alone.
    EXPECT_EQ(urisOf(e.change(other, "/amb_light 0.5\n/sphere o 2 0 0 0\n")), std::vector{other});
    // top.f2 includes a.f2: a.f2 moves into top.f2's scene, part.f2 into b.f2's
    // (the topmost includer that no other includes); b.f2 and other.f2 stay.
    EXPECT_EQ(urisOf(e.open(top, "/include a.f2\n")), (std::vector{a, part, top}));
    // The error fixed: part.f2, a.f2 (in top.f2's scene), b.f2, and top.f2, which reads part.f2 through a.f2.
    published = e.change(part, "/let n 4\n");
    EXPECT_EQ(urisOf(published), (std::vector{a, b, part, top}));
    for (const auto& [uri, each] : published) EXPECT_EQ(each[0], Json::array()) << uri;
    EXPECT_EQ(e.hover(a, 2, 12)["result"]["contents"]["value"],
              "**variable** `n` = 4, defined at line 1 of /nowhere/part.f2:\n```f2\n/let n 4\n```");
    // part.f2 closed: its own diagnostics cleared; its includers read the disk (no such file).
    published = e.close(part);
    EXPECT_EQ(urisOf(published), (std::vector{a, b, part, top}));
    EXPECT_EQ(published[part][0], Json::array());
    EXPECT_FALSE(published[b][0].empty());
}

TEST(Server, TenThousandOpenDocumentsOpenAndAnswer) {
    // Before, every didOpen copied every open text, stored every open URI in
    // every document and compared every document's includes with every
    // other's: 2,000 documents took 37 s and 407 MB, 10,000 never finished.
    // (f2_lsp_bench prints the times and memory.)
    constexpr int kDocuments = 10'000;
    Editor e;
    std::size_t published = 0;
    for (int i = 0; i < kDocuments; ++i) {
        const std::string name = "s" + std::to_string(i);
        published += e.open("file:///many/d" + std::to_string(i) + ".f2",
                            "/sphere " + name + " 1 0 0 0\n/paint " + name + " 9 9 9\n")
                         .size();
    }
    EXPECT_EQ(published, std::size_t{kDocuments});
    const Json reply = e.hover("file:///many/d5000.f2", 0, 9);
    EXPECT_EQ(reply["result"]["contents"]["value"].get<std::string>().rfind("**sphere** `s5000`", 0), 0u)
        << reply;
    EXPECT_EQ(urisOf(e.change("file:///many/d7.f2", "/fps x\n")),
              std::vector<std::string>{"file:///many/d7.f2"});
}

TEST(Hover, CameraLineKeysLookAtAttachmentAndPose) {
    const IncludedScene scene("f2_lsp_camera_");
    const Analysis m = analyze(uriFromPath(scene.main), TextDocument(IncludedScene::kMain, 1));
    const Json h = hover(m, {6, 9});
    EXPECT_EQ(h["range"], toJson(Range{{6, 7}, {6, 13}}));
    EXPECT_EQ(h["contents"]["value"],
              "**camera**, the scene camera, set at line 4 of " + scene.stage +
                  ":\n```f2\n/camera 320 240 0.5 0 100 -500\n```\n- image 320 × 240, d 0.5\n- keys: 1\n"
                  "- looks at: `prop` (line 6)\n- rides on: nothing\n"
                  "- at frame 0: eye (0, 100, -500), looking along (0, -0.196116, 0.980581)\n");
    const Analysis attached = analysed(
        "/amb_light 1\n/camera 320 240 0.5 0 0 -10 0 90 0\n/robot r1 0 0 0\n/attach camera r1.head\n");
    const std::string text = hover(attached, {3, 10})["contents"]["value"];
    EXPECT_NE(
        text.find("- keys: 0\n- looks at: nothing (its keys turn it)\n- rides on: `r1.head` (line 4)\n"),
        std::string::npos)
        << text;
    const Analysis plain = analysed("/amb_light 1\n/key 0 camera 0 0 -10 0 90 0\n");
    const std::string plainText = hover(plain, {1, 9})["contents"]["value"];
    EXPECT_NE(plainText.find("no `/camera` line"), std::string::npos) << plainText;
    EXPECT_NE(plainText.find("eye (0, 0, -10), rotation (0, 90, 0)"), std::string::npos) << plainText;
}

TEST(LanguageFiles, FillsAlternationsLongestFirstAndDictionaryLines) {
    std::string problem;
    EXPECT_EQ(fillLanguageTemplate("(@f2:modes@) and @f2:camera@\n", problem),
              "(ease_out|ease_in|elastic|linear|spline|bounce|bezier|ease|step|back) and camera\n");
    EXPECT_EQ(problem, "");
    EXPECT_EQ(fillLanguageTemplate("# parts\n@f2:parts:dict@\nend\n", problem),
              "# parts\n\"body\"\n\"head\"\n\"lhand\"\n\"rhand\"\nend\n");
    // Every command of the table, and only those, in the commands list.
    const std::vector<std::string> words = languageList("slashed-commands").value();
    EXPECT_EQ(words.size(), commands().size());
    EXPECT_NE(std::find(words.begin(), words.end(), "/checker"), words.end());
}

TEST(LanguageFiles, AnUnknownOrUnclosedListIsAnErrorWithItsPlace) {
    std::string problem;
    EXPECT_EQ(fillLanguageTemplate("ok\n  x @f2:colours@\n", problem), "");
    EXPECT_EQ(problem, "2:5: error: unknown list 'colours' (f2 language --lists names them)");
    EXPECT_EQ(fillLanguageTemplate("@f2:modes\n@\n", problem), "");
    EXPECT_EQ(problem, "1:1: error: '@f2:' without its closing '@'");
}

TEST(Variables, ConditionsInExpressions) {
    // SPEC 10.7: if(c, a, b) is a function, not a use of a variable called if.
    const Analysis a = analysed("/let k 2\n/let m (if(k == 2 && !0, 10, 1/0))\n/sphere s (m) 0 0 0\n");
    ASSERT_TRUE(a.result.ok());
    EXPECT_EQ(hover(a, {1, 6})["contents"]["value"],
              "**variable** `m` = 10, defined at line 2:\n```f2\n/let m (if(k == 2 && !0, 10, 1/0))\n```");
    EXPECT_EQ(references(a, {0, 5}, true).size(), 2u);  // /let k and the k inside if( … )
    const Json items = completion(a, {1, 8});
    const auto it =
        std::find_if(items.begin(), items.end(), [](const Json& i) { return i["label"] == "if"; });
    ASSERT_NE(it, items.end());
    EXPECT_EQ((*it)["detail"], "if(condition, a, b): a if condition is not 0, else b");
    EXPECT_EQ((*it)["textEdit"]["newText"], "if($1)");
}

TEST(Completion, OffersTheParsersCommandsAsSnippets) {
    const Analysis a = analysed("/ro\n");
    const Json items = completion(a, {0, 3});
    std::vector<std::string> labels;
    for (const Json& i : items) labels.push_back(i["label"]);
    // Exactly the commands the parser knows (the client filters by prefix).
    std::vector<std::string> known;
    for (std::string_view c : commandNames()) known.push_back(std::string(c));
    std::vector<std::string> sortedLabels = labels, sortedKnown = known;
    std::sort(sortedLabels.begin(), sortedLabels.end());
    std::sort(sortedKnown.begin(), sortedKnown.end());
    EXPECT_EQ(sortedLabels, sortedKnown);
    const auto robot = std::find(labels.begin(), labels.end(), "/robot") - labels.begin();
    EXPECT_EQ(items[static_cast<std::size_t>(robot)]["textEdit"]["range"], toJson(Range{{0, 0}, {0, 3}}));
    EXPECT_EQ(items[static_cast<std::size_t>(robot)]["insertTextFormat"], kInsertSnippet);
}

TEST(Completion, ModesObjectsAndNothingInComments) {
    const Analysis a = analysed("/sphere ball 1 0 0 0\n/interp ball \n/paint  # b\n/paint \n");
    const Json modes = completion(a, {1, 13});
    ASSERT_GE(modes.size(), 3u);
    EXPECT_EQ(modes[0]["label"], "linear");
    // `bezier` comes as a snippet with its four numbers (SPEC 10.4).
    const auto bezier =
        std::find_if(modes.begin(), modes.end(), [](const Json& m) { return m["label"] == "bezier"; });
    ASSERT_NE(bezier, modes.end());
    EXPECT_EQ((*bezier)["textEdit"]["newText"], "bezier ${1:0.25} ${2:0.1} ${3:0.25} ${4:1}");
    EXPECT_EQ((*bezier)["insertTextFormat"], 2);
    EXPECT_TRUE(completion(a, {2, 11}).empty());
    const Json names = completion(a, {3, 7});
    ASSERT_EQ(names.size(), 1u);  // not `camera`: /paint cannot take it
    EXPECT_EQ(names[0]["label"], "ball");
    EXPECT_EQ(names[0]["detail"], "sphere");
}

TEST(NamedLights, CompletionHoverDefinitionReferencesAndRename) {
    // SPEC 10.2: a lamp riding on a ball, keyed; a named ambient light.
    const std::string scene =
        "/sphere ball 1 0 0 0\n"            // 0
        "/point_light 2 0 3 0 name lamp\n"  // 1
        "/attach lamp ball\n"               // 2
        "/key 10 lamp intensity 4\n"        // 3
        "/amb_light 0.2 name sky\n";        // 4
    // Completion after `/key 0`: objects, lights and the camera; `/paint` takes no light.
    const Analysis typing = analysed(scene + "/key 0 \n/paint \n");
    std::vector<std::string> labels;
    for (const Json& i : completion(typing, {5, 7})) labels.push_back(i["label"]);
    EXPECT_EQ(labels, (std::vector<std::string>{"ball", "lamp", "sky", "camera"}));
    labels.clear();
    for (const Json& i : completion(typing, {6, 7})) labels.push_back(i["label"]);
    EXPECT_EQ(labels, (std::vector<std::string>{"ball"}));

    const Analysis a = analysed(scene);
    ASSERT_TRUE(a.result.ok());
    // From the uses in `/key` and `/attach` to the word after `name`.
    const Json lampName = location(a.uri, Range{{1, 26}, {1, 30}});
    EXPECT_EQ(definition(a, {3, 9}), lampName);
    EXPECT_EQ(definition(a, {2, 9}), lampName);
    EXPECT_EQ(references(a, {1, 27}, true).size(), 3u);
    EXPECT_EQ(references(a, {1, 27}, false).size(), 2u);
    EXPECT_EQ(prepareRename(a, {3, 9})["placeholder"], "lamp");
    const Json edit = rename(a, {3, 9}, "bulb");
    ASSERT_EQ(edit["changes"][a.uri].size(), 3u);
    EXPECT_EQ(edit["changes"][a.uri][2]["range"], toJson(Range{{3, 8}, {3, 12}}));
    // One set of names for objects and lights.
    EXPECT_THROW(rename(a, {3, 9}, "ball"), RequestError);
    EXPECT_THROW(rename(a, {0, 9}, "sky"), RequestError);
    // Hover: its line, mount, keys, and where it is at frame 0 (the key at 10 holds before it).
    EXPECT_EQ(hover(a, {3, 9})["contents"]["value"],
              "**light** `lamp` (`/point_light`), created at line 2:\n```f2\n/point_light 2 0 3 0 name "
              "lamp\n```\n- rides on: `ball`\n- pose keys: 0\n- intensity keys: 1\n"
              "- at frame 0: position (0, 3, 0), intensity 4\n");
    EXPECT_EQ(hover(a, {4, 21})["contents"]["value"],
              "**light** `sky` (`/amb_light`), created at line 5:\n```f2\n/amb_light 0.2 name sky\n```\n"
              "- intensity keys: 0\n- at frame 0: intensity 0.2\n");
}

// SPEC 10.1: a model type of the scene, an instance, its parts and shapes.
constexpr const char* kLamp =
    "/model lamp\n"                        // 0
    "/part base root 0 0 0\n"              // 1
    "/part arm base 0 10 0 0 0 30\n"       // 2
    "/cylinder base.foot 40 10 0 5 0\n"    // 3
    "/sphere arm.bulb 8 0 -5 0\n"          // 4
    "/paint arm.bulb 255 255 180\n"        // 5
    "/end\n"                               // 6
    "/lamp l1 0 0 0\n"                     // 7
    "/key 0 l1.arm\n"                      // 8
    "/key 4 l1.arm.bulb colour 0 0 255\n"  // 9
    "/robot r 0 0 0\n"                     // 10
    "/key 0 r.head\n";                     // 11

std::vector<std::string> labelsOf(const Json& items) {
    std::vector<std::string> labels;
    for (const Json& i : items) labels.push_back(i["label"]);
    return labels;
}

const Json* itemLabelled(const Json& items, std::string_view label) {
    for (const Json& i : items) {
        if (i["label"] == label) return &i;
    }
    return nullptr;
}

TEST(Models, CompletionOfTypesPartsShapesAndProperties) {
    // After `/`: the scene's types defined above, as commands that make an instance.
    const Analysis a = analysed(std::string("/\n") + kLamp +
                                "/\n/key 0 l1.\n/key 0 l1.arm.\n/key 0 l1.arm.bulb \n"
                                "/key 0 l1 \n");
    EXPECT_EQ(itemLabelled(completion(a, {0, 1}), "/lamp"), nullptr);
    const Json commandsBelow = completion(a, {13, 1});
    const Json* lamp = itemLabelled(commandsBelow, "/lamp");
    ASSERT_NE(lamp, nullptr);
    EXPECT_EQ((*lamp)["kind"], kCompletionClass);
    EXPECT_EQ((*lamp)["detail"], "/lamp <name> <px> <py> <pz> [<rx> <ry> <rz>]");
    EXPECT_EQ((*lamp)["textEdit"]["newText"], "/lamp ${1:name} ${2:0} ${3:0} ${4:0}");
    EXPECT_EQ((*lamp)["textEdit"]["range"], toJson(Range{{13, 0}, {13, 1}}));
    EXPECT_EQ((*lamp)["documentation"]["value"], "An instance of the model `lamp` (parts base, arm).");
    EXPECT_EQ(commandsBelow.size(), commands().size() + 1);
    // `name.`: the parts; `name.part.`: that part's shapes.
    EXPECT_EQ(labelsOf(completion(a, {14, 10})), (std::vector<std::string>{"l1.base", "l1.arm"}));
    const Json shapes = completion(a, {15, 14});
    ASSERT_EQ(shapes.size(), 1u);
    EXPECT_EQ(shapes[0]["label"], "l1.arm.bulb");
    EXPECT_EQ(shapes[0]["detail"], "sphere of lamp l1");
    EXPECT_EQ(shapes[0]["textEdit"]["range"], toJson(Range{{15, 7}, {15, 14}}));
    // After a shape only its properties (no pose, so no mode); after an instance modes too.
    EXPECT_EQ(labelsOf(completion(a, {16, 19})), (std::vector<std::string>{"colour", "visible"}));
    const auto instance = labelsOf(completion(a, {17, 10}));
    EXPECT_EQ(instance.front(), "linear");
    EXPECT_EQ(std::vector<std::string>(instance.end() - 2, instance.end()),
              (std::vector<std::string>{"colour", "visible"}));
}

TEST(Models, CompletionInsideAModelBlock) {
    const Analysis a = analysed(
        "/model desk\n"           // 0
        "/part top root 0 0 0\n"  // 1
        "/box top.plate 9 1 9 0 0 0\n"
        "/\n"              // 3
        "/part leg \n"     // 4
        "/sphere \n"       // 5
        "/paint \n"        // 6
        "/repeat i 1 2\n"  // 7
        "/end\n"           // 8
        "/\n"              // 9: still in the block
        "/end\n"           // 10
        "/\n");            // 11
    const std::vector<std::string> inBlock{"/part",  "/sphere",   "/cylinder", "/box",
                                           "/paint", "/material", "/checker",  "/end",
                                           "/let",   "/repeat",   "/include"};
    const Json commandsIn = completion(a, {3, 1});
    EXPECT_EQ(labelsOf(commandsIn), inBlock);
    EXPECT_EQ((*itemLabelled(commandsIn, "/sphere"))["textEdit"]["newText"],
              "/sphere ${1:part.shape} ${2:r} ${3:0} ${4:0} ${5:0}");
    EXPECT_EQ((*itemLabelled(commandsIn, "/paint"))["textEdit"]["newText"],
              "/paint ${1:part.shape} ${2:200} ${3:200} ${4:200}");
    EXPECT_EQ(labelsOf(completion(a, {9, 1})), inBlock);
    EXPECT_GT(completion(a, {11, 1}).size(), inBlock.size());  // after the block: every command
    // A part's parent: root and the parts declared above.
    const Json parents = completion(a, {4, 10});
    EXPECT_EQ(labelsOf(parents), (std::vector<std::string>{"root", "top"}));
    EXPECT_EQ(parents[1]["detail"], "part of desk");
    // The parts as the text declares them, finished or not.
    EXPECT_EQ(labelsOf(completion(a, {5, 8})), (std::vector<std::string>{"top.", "leg."}));
    EXPECT_EQ(labelsOf(completion(a, {6, 7})), (std::vector<std::string>{"top.plate"}));
}

TEST(Models, HoverShowsThePartTree) {
    const Analysis a = analysed(kLamp);
    ASSERT_TRUE(a.result.ok()) << a.result.diagnostics.front().message;
    const std::string tree =
        "  - `base` on the root, pivot (0, 0, 0)\n"
        "    - `base.foot`: cylinder r 40, h 10 centred at (0, 5, 0)\n"
        "    - `arm`, pivot (0, 10, 0), rest rotation (0, 0, 30)\n"
        "      - `arm.bulb`: sphere r 8 centred at (0, -5, 0) (keeps its colour)\n";
    const std::string model = "**model** `lamp`, defined at line 1\n- 2 parts, 2 shapes:\n" + tree;
    // On the instance's command word and on the type after `/model`.
    EXPECT_EQ(hover(a, {7, 2})["contents"]["value"], model);
    EXPECT_EQ(hover(a, {7, 2})["range"], toJson(Range{{7, 0}, {7, 5}}));
    EXPECT_EQ(hover(a, {0, 8})["contents"]["value"], model);
    EXPECT_EQ(hover(a, {0, 8})["range"], toJson(Range{{0, 7}, {0, 11}}));
    // On the instance: its keys and the tree.
    const std::string instance = hover(a, {8, 8})["contents"]["value"];
    EXPECT_NE(instance.find("**lamp** `l1`, created at line 8"), std::string::npos) << instance;
    EXPECT_NE(instance.find("- keys: 0 (own), base 0, arm 1\n- parts of lamp:\n" + tree), std::string::npos)
        << instance;
    // On a part and on a shape.
    EXPECT_EQ(
        hover(a, {8, 11})["contents"]["value"],
        "**part** `l1.arm` of lamp `l1`\n- pivot (0, 10, 0) in base's frame, rest rotation (0, 0, 30)\n"
        "- `bulb`: sphere r 8 centred at (0, -5, 0) (keeps its colour)\n- keys: 1\n- declared at line 3\n");
    const Json shape = hover(a, {9, 16});
    EXPECT_EQ(
        shape["contents"]["value"],
        "**shape** `l1.arm.bulb` of lamp `l1`\n- sphere r 8 centred at (0, -5, 0) (keeps its colour) in "
        "arm's frame\n- created at line 5\n");
    EXPECT_EQ(shape["range"], toJson(Range{{9, 14}, {9, 18}}));
    // The robot is a model too: its tree, and no line defines it.
    const std::string robot = hover(a, {11, 9})["contents"]["value"];
    EXPECT_EQ(robot.rfind("**part** `r.head` of robot `r`\n", 0), 0u) << robot;
    EXPECT_EQ(robot.find("declared at"), std::string::npos) << robot;
    const std::string robotCommand = hover(a, {10, 2})["contents"]["value"];
    EXPECT_NE(robotCommand.find("\n\n**model** `robot`, built in (SPEC 5)\n- 4 parts, 6 shapes:\n"
                                "  - `body` on the root, pivot (0, -105, 0)\n"),
              std::string::npos)
        << robotCommand;
}

TEST(Models, DefinitionReferencesAndRenameOfTypes) {
    const Analysis a = analysed(kLamp);
    // From `/lamp` to the type's name after `/model`; from a part and a shape to their lines.
    EXPECT_EQ(definition(a, {7, 2}), location(a.uri, Range{{0, 7}, {0, 11}}));
    EXPECT_EQ(definition(a, {8, 11}), location(a.uri, Range{{2, 6}, {2, 9}}));
    EXPECT_EQ(definition(a, {9, 16}), location(a.uri, Range{{4, 8}, {4, 16}}));
    EXPECT_EQ(definition(a, {8, 8}), location(a.uri, Range{{7, 6}, {7, 8}}));  // the instance's name
    // The robot's parts have no line.
    EXPECT_TRUE(definition(a, {11, 9}).is_null());
    EXPECT_EQ(references(a, {0, 8}, true),
              Json::array({location(a.uri, Range{{0, 7}, {0, 11}}), location(a.uri, Range{{7, 1}, {7, 5}})}));
    EXPECT_EQ(references(a, {7, 2}, false), Json::array({location(a.uri, Range{{7, 1}, {7, 5}})}));
    EXPECT_EQ(prepareRename(a, {7, 2}),
              Json({{"range", toJson(Range{{7, 1}, {7, 5}})}, {"placeholder", "lamp"}}));
    const Json edit = rename(a, {7, 2}, "light");
    ASSERT_EQ(edit["changes"][a.uri].size(), 2u);
    EXPECT_EQ(edit["changes"][a.uri][1],
              Json({{"range", toJson(Range{{7, 1}, {7, 5}})}, {"newText", "light"}}));
    EXPECT_THROW(rename(a, {7, 2}, "box"), RequestError);    // a command
    EXPECT_THROW(rename(a, {7, 2}, "robot"), RequestError);  // a type already
    EXPECT_TRUE(prepareRename(a, {10, 2}).is_null());        // `/robot` is a command
}

TEST(Models, PartsAndShapesInsideTheirBlock) {
    const Analysis a = analysed(kLamp);
    // A parent, the part of `part.shape` and its shape lead to their lines.
    EXPECT_EQ(definition(a, {2, 11}), location(a.uri, Range{{1, 6}, {1, 10}}));
    EXPECT_EQ(definition(a, {5, 8}), location(a.uri, Range{{2, 6}, {2, 9}}));
    EXPECT_EQ(definition(a, {5, 12}), location(a.uri, Range{{4, 8}, {4, 16}}));
    EXPECT_EQ(definition(a, {4, 13}), location(a.uri, Range{{4, 8}, {4, 16}}));
    const Json part = hover(a, {2, 7});
    EXPECT_EQ(part["contents"]["value"],
              "**part** `arm` of the model `lamp`\n- pivot (0, 10, 0) in base's frame, rest rotation (0, 0, "
              "30)\n- `bulb`: sphere r 8 centred at (0, -5, 0) (keeps its colour)\n- declared at line 3\n");
    EXPECT_EQ(part["range"], toJson(Range{{2, 6}, {2, 9}}));
    const Json shape = hover(a, {5, 12});
    EXPECT_EQ(
        shape["contents"]["value"],
        "**shape** `arm.bulb` of the model `lamp`\n- sphere r 8 centred at (0, -5, 0) (keeps its colour) "
        "in arm's frame\n- created at line 5\n");
    EXPECT_EQ(shape["range"], toJson(Range{{5, 11}, {5, 15}}));
    EXPECT_TRUE(hover(a, {1, 11}).is_null());  // `root` is no part
}

TEST(Models, OutlineAndFolding) {
    const Analysis a = analysed(kLamp);
    const Json symbols = documentSymbols(a);
    ASSERT_EQ(symbols.size(), 3u);
    EXPECT_EQ(symbols[0]["name"], "lamp");
    EXPECT_EQ(symbols[0]["detail"], "model, 2 parts, 2 shapes");
    EXPECT_EQ(symbols[0]["kind"], kSymbolClass);
    EXPECT_EQ(symbols[0]["range"], toJson(Range{{0, 0}, {6, 4}}));
    EXPECT_EQ(symbols[0]["selectionRange"], toJson(Range{{0, 7}, {0, 11}}));
    ASSERT_EQ(symbols[0]["children"].size(), 2u);
    EXPECT_EQ(symbols[0]["children"][1]["name"], "arm");
    EXPECT_EQ(symbols[0]["children"][1]["detail"], "on base, bulb");
    EXPECT_EQ(symbols[0]["children"][1]["selectionRange"], toJson(Range{{2, 6}, {2, 9}}));
    EXPECT_EQ(symbols[1]["name"], "l1");
    EXPECT_EQ(symbols[1]["detail"], "lamp, 0 keys");
    EXPECT_EQ(foldingRanges(a), Json::parse(R"([{"startLine":0,"endLine":5,"kind":"region"}])"));
}

std::string body(const Json& j) { return j.dump(); }

TEST(Server, AnswersGarbageWithErrorsAndNeverThrows) {
    std::vector<std::string> logged;
    Server server([&](std::string_view line) { logged.emplace_back(line); });
    EXPECT_EQ(Json::parse(server.handle("[]")[0])["error"]["code"], kInvalidRequest);
    EXPECT_EQ(Json::parse(server.handle("{\"id\":1,\"method\":\"initialize\"}")[0])["id"], 1);
    EXPECT_EQ(Json::parse(server.handle("{\"id\":{},\"method\":\"x\"}")[0])["error"]["code"],
              kInvalidRequest);
    const auto noDoc = server.handle(body({{"id", 2},
                                           {"method", "textDocument/hover"},
                                           {"params", {{"textDocument", {{"uri", "file:///x"}}}}}}));
    EXPECT_EQ(Json::parse(noDoc[0])["error"]["code"], kInvalidParams);
    EXPECT_TRUE(server.handle(body({{"method", "textDocument/didChange"}, {"params", 5}})).empty());
    EXPECT_FALSE(logged.empty());
    // Invalid UTF-8 inside a JSON string is not JSON.
    const auto open = server.handle(
        "{\"method\":\"textDocument/didOpen\",\"params\":{\"textDocument\":"
        "{\"uri\":\"u\",\"version\":1,\"text\":\"/fps \xFF\xFE\"}}}");
    ASSERT_EQ(open.size(), 1u);
    EXPECT_EQ(Json::parse(open[0])["error"]["code"], kParseError);
    const auto control = server.handle(
        body({{"method", "textDocument/didOpen"},
              {"params", {{"textDocument", {{"uri", "u"}, {"version", 1}, {"text", "/fps \x01"}}}}}}));
    ASSERT_EQ(control.size(), 1u);
    EXPECT_NE(control[0].find("expected a number, got '\\\\x01'"), std::string::npos) << control[0];
    const auto huge = server.handle(
        body({{"id", 3},
              {"method", "textDocument/completion"},
              {"params",
               {{"textDocument", {{"uri", "u"}}}, {"position", {{"line", 1e300}, {"character", -1}}}}}}));
    EXPECT_EQ(Json::parse(huge[0])["error"]["code"], kInvalidParams);
    const auto negative = server.handle(body(
        {{"id", 4},
         {"method", "textDocument/hover"},
         {"params", {{"textDocument", {{"uri", "u"}}}, {"position", {{"line", -5}, {"character", -1}}}}}}));
    EXPECT_TRUE(Json::parse(negative[0])["result"].is_null());
    // Random bytes: every reply is valid JSON.
    std::mt19937 rng(7);
    for (int n = 0; n < 2000; ++n) {
        std::string junk(static_cast<std::size_t>(rng() % 64), '\0');
        for (char& c : junk) c = "{}[]\":,0123 abcnull-\\u"[rng() % 22];
        for (const std::string& reply : server.handle(junk))
            EXPECT_FALSE(Json::parse(reply, nullptr, false).is_discarded());
    }
}

TEST(Server, ExitCodeFollowsShutdown) {
    Server a;
    a.handle(body({{"method", "exit"}}));
    EXPECT_TRUE(a.exited());
    EXPECT_EQ(a.exitCode(), 1);
    Server b;
    b.handle(body({{"id", 1}, {"method", "initialize"}}));
    EXPECT_EQ(Json::parse(b.handle(body({{"id", 2}, {"method", "shutdown"}}))[0])["result"], nullptr);
    EXPECT_EQ(Json::parse(b.handle(body({{"id", 3}, {"method", "shutdown"}}))[0])["error"]["code"],
              kInvalidRequest);
    b.handle(body({{"method", "exit"}}));
    EXPECT_EQ(b.exitCode(), 0);
}

/// What `f2 lsp` does with a whole input stream: runServer reads it from a
/// file as its standard input and writes to another as its standard output.
struct Transcript {
    int exitCode = -1;
    std::vector<Json> replies;
    std::string log;
};

std::string readWhole(std::FILE* f) {
    std::rewind(f);
    std::string text;
    char buffer[65536];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, f)) > 0;) text.append(buffer, n);
    return text;
}

Transcript runStream(const std::string& input) {
    std::FILE* in = std::tmpfile();
    std::FILE* out = std::tmpfile();
    std::FILE* log = std::tmpfile();
    std::fwrite(input.data(), 1, input.size(), in);
    std::fflush(in);
    std::rewind(in);
    Transcript t;
    t.exitCode = runServer(fileno(in), fileno(out), log);
    MessageReader reader;
    reader.feed(readWhole(out));
    for (const auto& item : readAll(reader)) t.replies.push_back(Json::parse(item.text));
    t.log = readWhole(log);
    for (std::FILE* f : {in, out, log}) std::fclose(f);
    return t;
}

/// initialize (id 1), a hover on an open document (id 2), shutdown (id 3) and
/// exit, with `between` before each message after the first.
std::string session(const std::string& between) {
    const std::string uri = "file:///t/stream.f2";
    return frameMessage(body({{"jsonrpc", "2.0"}, {"id", 1}, {"method", "initialize"}})) + between +
           frameMessage(body(
               {{"jsonrpc", "2.0"},
                {"method", "textDocument/didOpen"},
                {"params",
                 {{"textDocument", {{"uri", uri}, {"version", 1}, {"text", "/sphere s 1 0 0 0\n"}}}}}})) +
           between +
           frameMessage(
               body({{"jsonrpc", "2.0"},
                     {"id", 2},
                     {"method", "textDocument/hover"},
                     {"params",
                      {{"textDocument", {{"uri", uri}}}, {"position", {{"line", 0}, {"character", 9}}}}}})) +
           between + frameMessage(body({{"jsonrpc", "2.0"}, {"id", 3}, {"method", "shutdown"}})) + between +
           frameMessage(body({{"jsonrpc", "2.0"}, {"method", "exit"}}));
}

/// The ids of the responses, in order (null for an error without an id).
std::vector<Json> responseIds(const Transcript& t) {
    std::vector<Json> ids;
    for (const Json& r : t.replies) {
        if (!r.contains("method")) ids.push_back(r["id"]);
    }
    return ids;
}

TEST(Transport, StrayBytesBetweenMessagesLoseNothing) {
    std::mt19937 rng(11);
    std::vector<std::string> junk = {"x", "\n", "\r\n", "\r\n\r\n", "junk\r\nmore junk: 1\n\n"};
    for (int n = 0; n < 5; ++n) {
        std::string lines;
        for (int k = 0; k < 1 + n; ++k) {
            std::string line(1 + rng() % 40, ' ');
            for (char& c : line) c = " abxyz:{}[]\t0123456789\"-"[rng() % 24];
            lines += line + (k % 2 ? "\n" : "\r\n");
        }
        junk.push_back(lines);
    }
    for (const std::string& between : junk) {
        const Transcript t = runStream(session(between));
        EXPECT_EQ(t.exitCode, 0) << Json(between) << "\n" << t.log;
        EXPECT_EQ(responseIds(t), (std::vector<Json>{1, 2, 3})) << Json(between) << "\n" << t.log;
        for (const Json& r : t.replies) EXPECT_FALSE(r.contains("error")) << r;
        const bool hovered = std::any_of(t.replies.begin(), t.replies.end(), [](const Json& r) {
            return r.value("id", 0) == 2 && r["result"].contains("contents");
        });
        EXPECT_TRUE(hovered) << Json(between);
        EXPECT_NE(t.log.find("f2 lsp: dropped "), std::string::npos) << t.log;
    }
}

TEST(Transport, DeeplyNestedJsonIsAParseErrorAndTheSessionGoesOn) {
    constexpr int kDeep = 1'000'000;
    const std::string deepArray = std::string(kDeep, '[') + std::string(kDeep, ']');
    // As parameters of a request: copying them overflowed the stack (SIGSEGV).
    const std::string deepParams =
        R"({"jsonrpc":"2.0","id":9,"method":"initialize","params":)" + deepArray + "}";
    const std::string unclosed = std::string(kDeep, '{');
    // At the limit: accepted (brackets in strings do not count).
    const int limit = Server::kMaxJsonDepth;
    const std::string atLimit = R"({"jsonrpc":"2.0","id":8,"method":"initialize","params":{"x":")" +
                                std::string(1000, '[') + R"(\"[","y":)" + std::string(limit - 2, '[') +
                                std::string(limit - 2, ']') + "}}";
    const std::string overLimit = R"({"jsonrpc":"2.0","id":7,"method":"initialize","params":)" +
                                  std::string(limit, '[') + std::string(limit, ']') + "}";
    const Transcript t =
        runStream(frameMessage(deepArray) + frameMessage(deepParams) + frameMessage(unclosed) +
                  frameMessage(overLimit) + frameMessage(atLimit) + session(""));
    EXPECT_EQ(t.exitCode, 0) << t.log;
    ASSERT_EQ(responseIds(t), (std::vector<Json>{nullptr, nullptr, nullptr, nullptr, 8, 1, 2, 3}));
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(t.replies[static_cast<std::size_t>(i)]["error"]["code"], kParseError);
        EXPECT_EQ(t.replies[static_cast<std::size_t>(i)]["error"]["message"],
                  "the message nests arrays and objects deeper than 256 levels");
    }
    EXPECT_TRUE(t.replies[4]["result"].contains("capabilities")) << t.replies[4];
}

/// A server as `f2 lsp` runs it: notifications sent by its worker as
/// analyses finish. Through the test seam (Server::Options::beforeAnalysis) a
/// test holds the analysis of chosen (URI, version) pairs until release():
/// everything here waits for events, never for time.
struct AsyncEditor {
    using Analysed = std::pair<std::string, int>;
    std::mutex mutex;
    std::condition_variable cv;
    std::vector<Json> sent;          ///< the worker's notifications, in order
    std::vector<Analysed> analysed;  ///< every analysis started, in order
    std::set<Analysed> held, entered;
    bool released = false;
    std::unique_ptr<Server> server;

    AsyncEditor() {
        Server::Options options;
        options.notify = [this](std::vector<std::string> round) {
            const std::lock_guard lock(mutex);
            for (const std::string& m : round) sent.push_back(Json::parse(m));
            cv.notify_all();
        };
        options.beforeAnalysis = [this](const std::string& uri, int version) {
            std::unique_lock lock(mutex);
            analysed.emplace_back(uri, version);
            if (!held.contains({uri, version})) return;
            entered.insert({uri, version});
            cv.notify_all();
            cv.wait(lock, [&] { return released; });
        };
        server = std::make_unique<Server>(std::function<void(std::string_view)>{}, std::move(options));
        server->handle(R"({"id":1,"method":"initialize"})");
    }
    ~AsyncEditor() {
        release();
        server.reset();  // joins the worker before the members it calls back are gone
    }
    void hold(const std::string& uri, int version) {
        const std::lock_guard lock(mutex);
        held.insert({uri, version});
    }
    /// Waits until the worker is inside the held analysis.
    void waitEntered(const std::string& uri, int version) {
        std::unique_lock lock(mutex);
        cv.wait(lock, [&] { return entered.contains({uri, version}); });
    }
    void release() {
        const std::lock_guard lock(mutex);
        released = true;
        cv.notify_all();
    }
    bool isReleased() {
        const std::lock_guard lock(mutex);
        return released;
    }
    /// The publishDiagnostics params sent so far for `uri`.
    std::vector<Json> published(const std::string& uri) {
        const std::lock_guard lock(mutex);
        std::vector<Json> found;
        for (const Json& m : sent) {
            if (m.value("method", "") == "textDocument/publishDiagnostics" && m["params"]["uri"] == uri)
                found.push_back(m["params"]);
        }
        return found;
    }
    /// Waits for the first publishDiagnostics of `uri`.
    void waitPublished(const std::string& uri) {
        std::unique_lock lock(mutex);
        cv.wait(lock, [&] {
            return std::any_of(sent.begin(), sent.end(), [&](const Json& m) {
                return m.value("method", "") == "textDocument/publishDiagnostics" &&
                       m["params"]["uri"] == uri;
            });
        });
    }
    std::vector<std::string> open(const std::string& uri, int version, const std::string& text) {
        return server->handle(
            Json({{"method", "textDocument/didOpen"},
                  {"params", {{"textDocument", {{"uri", uri}, {"version", version}, {"text", text}}}}}})
                .dump());
    }
    std::vector<std::string> change(const std::string& uri, int version, const std::string& text) {
        return server->handle(Json({{"method", "textDocument/didChange"},
                                    {"params",
                                     {{"textDocument", {{"uri", uri}, {"version", version}}},
                                      {"contentChanges", Json::array({{{"text", text}}})}}}})
                                  .dump());
    }
    /// A hover's reply: handle() returns it, so it came while whatever is held still is.
    Json hover(const std::string& uri, int line, int character) {
        const auto replies =
            server->handle(Json({{"id", 7},
                                 {"method", "textDocument/hover"},
                                 {"params",
                                  {{"textDocument", {{"uri", uri}}},
                                   {"position", {{"line", line}, {"character", character}}}}}})
                               .dump());
        EXPECT_EQ(replies.size(), 1u);
        return replies.empty() ? Json() : Json::parse(replies[0]);
    }
};

std::string hoverText(const Json& reply) {
    return reply.contains("result") && reply["result"].is_object()
               ? reply["result"]["contents"]["value"].get<std::string>()
               : reply.dump();
}

TEST(Async, AHoverIsAnsweredWhileAnIncludeIsParsed) {
    // The parse of a document that includes a (say 10,000,000-line) file is
    // held inside the worker; hovers are answered meanwhile, before it is let go.
    const std::string a = "file:///nowhere/a.f2", big = "file:///nowhere/reads-big.f2";
    AsyncEditor e;
    EXPECT_TRUE(e.open(a, 1, "/amb_light 1\n/sphere s 1 0 0 0\n").empty());  // published by the worker
    e.waitPublished(a);
    e.hold(big, 1);
    EXPECT_TRUE(e.open(big, 1, "/include huge.f2\n/sphere t 1 0 0 0\n").empty());
    e.waitEntered(big, 1);
    // Another document: answered from its analysis.
    EXPECT_EQ(hoverText(e.hover(a, 1, 9)).rfind("**sphere** `s`", 0), 0u);
    // A change of it queues behind the held parse; until it is analysed, a
    // hover is answered from the last good analysis (the text before the change).
    EXPECT_TRUE(e.change(a, 2, "/amb_light 1\n/box q 1 1 1 0 0 0\n").empty());
    EXPECT_EQ(hoverText(e.hover(a, 1, 9)).rfind("**sphere** `s`", 0), 0u);
    EXPECT_FALSE(e.isReleased());
    EXPECT_TRUE(e.published(big).empty());
    EXPECT_EQ(e.published(a).size(), 1u);  // version 1's only
    e.release();
    e.server->waitUntilIdle();
    const std::vector<Json> bigs = e.published(big), as = e.published(a);
    ASSERT_EQ(bigs.size(), 1u);
    EXPECT_EQ(bigs[0]["version"], 1);
    EXPECT_FALSE(bigs[0]["diagnostics"].empty());  // huge.f2 does not exist here
    ASSERT_EQ(as.size(), 2u);
    EXPECT_EQ(as[1]["version"], 2);
    EXPECT_EQ(hoverText(e.hover(a, 1, 6)).rfind("**box** `q`", 0), 0u);
}

TEST(Async, AStaleVersionIsNeverPublished) {
    const std::string a = "file:///nowhere/stale.f2";
    AsyncEditor e;
    const std::string scene = "/amb_light 1\n/sphere s 1 0 0 0\n";
    e.hold(a, 1);
    e.open(a, 1, scene + "/fps x\n");  // an error
    e.waitEntered(a, 1);
    // Two changes while version 1 is parsed: the second replaces the first,
    // which is never analysed; version 1's result is dropped.
    e.change(a, 2, scene + "/fps y\n");
    e.change(a, 3, scene + "/fps 24\n");
    e.release();
    e.server->waitUntilIdle();
    const std::vector<Json> published = e.published(a);
    ASSERT_EQ(published.size(), 1u);
    EXPECT_EQ(published[0]["version"], 3);
    EXPECT_EQ(published[0]["diagnostics"], Json::array());
    const std::lock_guard lock(e.mutex);
    EXPECT_EQ(e.analysed, (std::vector<AsyncEditor::Analysed>{{a, 1}, {a, 3}}));
}

TEST(Async, ADocumentClosedWhileParsedIsOnlyCleared) {
    const std::string a = "file:///nowhere/closed.f2";
    AsyncEditor e;
    e.hold(a, 1);
    e.open(a, 1, "/fps x\n");
    e.waitEntered(a, 1);
    e.server->handle(
        Json({{"method", "textDocument/didClose"}, {"params", {{"textDocument", {{"uri", a}}}}}}).dump());
    EXPECT_EQ(e.hover(a, 0, 1)["error"]["code"], kInvalidParams);  // not open
    e.release();
    e.server->waitUntilIdle();
    const std::vector<Json> published = e.published(a);
    ASSERT_EQ(published.size(), 1u);  // the clearing, not version 1's error
    EXPECT_EQ(published[0]["diagnostics"], Json::array());
}

TEST(Async, AChangeRepublishesItsIncludersOnce) {
    // The include machinery behind the worker: as Includes.AChangeRepublishes… but asynchronous.
    const std::string part = "file:///nowhere/part.f2", a = "file:///nowhere/a.f2",
                      b = "file:///nowhere/b.f2";
    AsyncEditor e;
    e.open(part, 1, "/let n 3\n");
    e.open(a, 1, "/amb_light 1\n/include part.f2\n/sphere s (n) 0 0 0\n");
    e.open(b, 1, "/amb_light 1\n/include part.f2\n/box c (n) 1 1 0 0 0\n");
    e.server->waitUntilIdle();
    const std::size_t before = e.published(a).size() + e.published(b).size() + e.published(part).size();
    e.change(part, 2, "/let n x\n");
    e.server->waitUntilIdle();
    for (const std::string& uri : {a, b, part}) {
        const std::vector<Json> each = e.published(uri);
        ASSERT_FALSE(each.empty()) << uri;
        EXPECT_EQ(each.back()["diagnostics"].size(), 1u) << uri << ": " << each.back();
    }
    EXPECT_EQ(e.published(a).size() + e.published(b).size() + e.published(part).size(), before + 3);
    EXPECT_EQ(e.published(part).back()["version"], 2);
}

TEST(Async, DestroyedWithWorkQueuedJoinsWithoutHanging) {
    // Many documents queued, then the server goes (as on `exit`): the worker
    // finishes the round it is in and is joined; nothing is sent afterwards.
    auto e = std::make_unique<AsyncEditor>();
    for (int i = 0; i < 200; ++i) e->open("file:///many/q" + std::to_string(i) + ".f2", 1, "/fps 24\n");
    e->server.reset();
    const std::size_t sent = e->sent.size();
    EXPECT_LE(sent, 200u);
    e.reset();
}

TEST(Uris, DecodeAndEncodePaths) {
    EXPECT_EQ(pathFromUri("file:///a/b%20c.f2"), "/a/b c.f2");
    EXPECT_EQ(pathFromUri("file:///a/%zz%2"), "/a/%zz%2");
    EXPECT_EQ(pathFromUri("untitled:Untitled-1"), "untitled:Untitled-1");
    EXPECT_EQ(uriFromPath("/a/b c.f2"), "file:///a/b%20c.f2");
}

}  // namespace
}  // namespace f2::lsp

namespace f2::lsp {
namespace {

TEST(ModelParams, CompletionOfATypesParametersAfterAnInstancesPose) {
    // SPEC 10.6: after the position, the parameters not yet given, with their defaults.
    const Analysis a = analysed(
        "/model lamp arm 120 shade 20\n/part b root 0 0 0\n/sphere b.s (shade) 0 0 0\n/end\n"  // 0-3
        "/lamp l1 0 0 0 \n"                                                                    // 4
        "/lamp l2 0 0 0 0 90 0 arm 60 \n"                                                      // 5
        "/lamp l3 0 0 \n"                                                                      // 6
        "/lamp l4 0 0 0 sh\n");                                                                // 7
    const auto labels = [&](Position p) {
        std::vector<std::string> out;
        for (const Json& i : completion(a, p)) out.push_back(i["label"]);
        return out;
    };
    EXPECT_EQ(labels({4, 15}), (std::vector<std::string>{"arm", "shade"}));
    EXPECT_EQ(labels({5, 29}), (std::vector<std::string>{"shade"}));
    EXPECT_TRUE(labels({6, 13}).empty());  // still in the position
    EXPECT_EQ(labels({7, 17}), (std::vector<std::string>{"shade"}));
    const Json first = completion(a, {4, 15})[0];
    EXPECT_EQ(first["detail"], "parameter of lamp (default 120)");
    EXPECT_EQ(first["textEdit"]["newText"], "arm ${1:120}");
}

}  // namespace
}  // namespace f2::lsp
