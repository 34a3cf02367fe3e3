// Span edits, numbers as a person writes them, and the write-back rules
// (source_edit.h, write_back.h): pure functions of the text, and the one
// editor function that applies edits as one undo step.
#include "source_edit.h"

#include <QDir>
#include <QPlainTextEdit>
#include <QTemporaryDir>
#include <QtTest>

#include "core/parse/parser.h"
#include "core/parse/symbol_index.h"
#include "dope_sheet_model.h"
#include "scene_locations.h"
#include "test_support.h"
#include "write_back.h"
#include "write_back_prompt.h"

using namespace f2;
using namespace f2::viewer;

namespace {

/// A text, its parse and the write-back of a request on it.
struct Parsed {
    QString text;
    std::string name;
    SceneDesc scene;
    SceneLocations locations;

    explicit Parsed(const QString& source, std::string file = "scene.f2")
        : text(source), name(std::move(file)) {
        SymbolIndex index;
        const QByteArray bytes = text.toUtf8();
        ParseResult result = parseScene(std::string_view(bytes.constData(), std::size_t(bytes.size())), name,
                                        ParseLimits{}, index);
        for (const Diagnostic& d : result.diagnostics)
            if (d.severity == Severity::Error) qWarning("%s", d.format().c_str());
        if (result.scene) scene = std::move(*result.scene);
        locations = SceneLocations::fromIndex(index);
    }
    WriteBack pose(const QString& target, int frame, const Pose& pose) const {
        return writePose({text, scene, locations, name}, target, frame, pose);
    }
    WriteBack property(const QString& target, KeyProperty property, int frame,
                       std::vector<double> values) const {
        return writeBack({text, scene, locations, name}, {target, property, frame, std::move(values)});
    }
};

Pose pose(float x, float y, float z, float rx = 0, float ry = 0, float rz = 0) {
    return {{x, y, z}, {rx, ry, rz}};
}

}  // namespace

class SourceEditTest : public QObject {
    Q_OBJECT
   private slots:
    void numbersAreWrittenInShortestForm();
    void spanEditsApplyBackToFront();
    void scannedLinesKnowTheirBlocks();
    void editorEditsAreOneUndoStep();
    void scrubbedNumberStepsByItsLastDigit();
    void keyAtTheFrameChangesOnlyItsNumbers();
    void newKeyGoesInTimeOrder();
    void unkeyedTargetChangesItsCreatingNumbers();
    void targetInALoopIsRefusedWithAnOffer();
    void targetInAnIncludedFileIsRefusedWithAnOffer();
    void propertyKeysAndFirstKeysOfParts();
    void dopeSheetRowsNameTheKeyLines();
    void movedKeysChangeOnlyTheirTimes();
    void deletedKeysAndModesAreLineEdits();
    void refusedWriteBackAsksBeforeItsOffer();
};

void SourceEditTest::numbersAreWrittenInShortestForm() {
    QCOMPARE(shortestNumber(1.25), QStringLiteral("1.25"));
    QCOMPARE(shortestNumber(40), QStringLiteral("40"));
    QCOMPARE(shortestNumber(0.1 + 0.2), QStringLiteral("0.3"));
    QCOMPARE(shortestNumber(double(0.1f)), QStringLiteral("0.1"));
    QCOMPARE(shortestNumber(-1e-7), QStringLiteral("0"));  // float noise, and no "-0"
    QCOMPARE(shortestNumber(-0.0), QStringLiteral("0"));
    QCOMPARE(shortestNumber(-12.5), QStringLiteral("-12.5"));
    QCOMPARE(shortestNumber(1e7), QStringLiteral("10000000"));
    QCOMPARE(shortestNumber(123456.7), QStringLiteral("123457"));     // 6 significant digits
    QCOMPARE(shortestNumber(0.0001234), QStringLiteral("0.000123"));  // at most 6 decimals
    QCOMPARE(shortestNumber(double(float(-89.99999f))), QStringLiteral("-90"));
}

void SourceEditTest::spanEditsApplyBackToFront() {
    const QString text = QStringLiteral("/sphere ball 1 2 3 4  # é comment\n");
    // Offsets in the original text, given in any order.
    QCOMPARE(withEdits(text, {{17, 18, QStringLiteral("30")}, {15, 16, QStringLiteral("20")}}),
             QStringLiteral("/sphere ball 1 20 30 4  # é comment\n"));
    QCOMPARE(withEdits(text, {{0, 0, QStringLiteral("a")}, {0, 0, QStringLiteral("b")}}),
             QStringLiteral("ab") + text);
    // Tokens carry UTF-16 offsets, also after non-ASCII text on earlier lines.
    const QString twoLines = QStringLiteral("# ünïcode\n/key 4 ball 1 2 3 0 0 0 ease # ü\n");
    const std::vector<SourceLine> lines = scanSource(twoLines);
    QCOMPARE(lines.size(), std::size_t(3));
    QVERIFY(lines[0].tokens.empty());
    QCOMPARE(lines[1].tokens.size(), std::size_t(10));
    QCOMPARE(twoLines.mid(lines[1].tokens[3].begin, 1), QStringLiteral("1"));
    QCOMPARE(lines[1].tokens[9].text, QStringLiteral("ease"));
}

void SourceEditTest::scannedLinesKnowTheirBlocks() {
    const QString text = QStringLiteral(
        "/model m\n"                           // 0
        "/part p root 0 0 0\n"                 // 1
        "/repeat i 0 1\n"                      // 2: a loop inside a block
        "/sphere p.s{ i } 1 0 0 0\n"           // 3
        "/end\n"                               // 4
        "/end\n"                               // 5
        "/repeat i 0 1\n"                      // 6
        "  /repeat j 0 1   # nested\n"         // 7
        "  /sphere b{ i }{ j } 1 (i) (j) 0\n"  // 8
        "  /end\n"                             // 9
        "/end\n"                               // 10
        "/sphere solo 1 0 0 0\r\n"             // 11: CRLF
        "/repeat k 0 1\n"                      // 12: without its /end
        "/sphere late{ k } 1 0 0 0");          // 13
    const std::vector<SourceLine> lines = scanSource(text);
    QCOMPARE(lines.size(), std::size_t(14));
    QVERIFY(lines[1].inModel && lines[3].inModel && !lines[6].inModel);
    QCOMPARE(lines[3].loopStart, 2);
    QCOMPARE(lines[3].loopEnd, 4);
    QCOMPARE(lines[1].loopEnd, -1);
    // Inner loops count as the outermost's: a key goes after line 10.
    QCOMPARE(lines[8].loopStart, 6);
    QCOMPARE(lines[8].loopEnd, 10);
    QCOMPARE(lines[8].tokens[4].text, QStringLiteral("(j)"));
    QCOMPARE(lines[11].loopEnd, -1);
    QCOMPARE(lines[11].tokens.back().text, QStringLiteral("0"));  // no '\r' in it
    QCOMPARE(lines[13].loopStart, 12);
    QCOMPARE(lines[13].loopEnd, 13);
}

void SourceEditTest::editorEditsAreOneUndoStep() {
    const QString text = QStringLiteral("/sphere ball 1 2 3 4  # kept\n/key 0 ball\n");
    QPlainTextEdit editor;
    editor.setPlainText(text);
    const std::vector<SpanEdit> edits{{13, 14, QStringLiteral("2.5")}, {29, 29, QStringLiteral("/fps 25\n")}};
    applySourceEdits(&editor, edits);
    QCOMPARE(editor.toPlainText(), withEdits(text, edits));
    editor.undo();
    QCOMPARE(editor.toPlainText(), text);  // byte-identical after one undo
    editor.redo();
    QCOMPARE(editor.toPlainText(), withEdits(text, edits));
}

void SourceEditTest::scrubbedNumberStepsByItsLastDigit() {
    QCOMPARE(numberStep(u"1.25"), 0.01);
    QCOMPARE(numberStep(u"40"), 1.0);
    QCOMPARE(numberStep(u"-0.5"), 0.1);
    QCOMPARE(*scrubNumber(u"1.25", 5), QStringLiteral("1.30"));
    QCOMPARE(*scrubNumber(u"40", -5), QStringLiteral("35"));
    QCOMPARE(*scrubNumber(u"0.1", -1), QStringLiteral("0.0"));
    QCOMPARE(*scrubNumber(u"0.1", -2), QStringLiteral("-0.1"));
    QCOMPARE(*scrubNumber(u"2e3", 5), QStringLiteral("7000"));  // its last digit is the thousands
    QVERIFY(!scrubNumber(u"(n * 2)", 1));
    QVERIFY(!scrubNumber(u"2.5s", 1));
}

void SourceEditTest::keyAtTheFrameChangesOnlyItsNumbers() {
    const QString text = QStringLiteral(
        "/sphere ball 1 0 0 0\n"
        "/key 0 ball\n"
        "/key  40   ball 1   2.5 3 0 0 0   ease_out  # the bounce\n"
        "/key 3s ball 9 9 9 0 0 0\n");
    const Parsed parsed(text);
    // Frame 40: only the numbers whose written value changes.
    WriteBack write = parsed.pose(QStringLiteral("ball"), 40, pose(1, 2.75f, 3, 0, 90.0f + 1e-5f, 0));
    QVERIFY(!write.refused());
    QCOMPARE(withEdits(text, write.edits),
             QString(text).replace(QStringLiteral("2.5 3 0 0 0"), QStringLiteral("2.75 3 0 90 0")));
    // A time in seconds matches its frame (3s at 24 fps is 72).
    write = parsed.pose(QStringLiteral("ball"), 72, pose(9, 9, 8));
    QCOMPARE(withEdits(text, write.edits),
             QString(text).replace(QStringLiteral("9 9 9"), QStringLiteral("9 9 8")));
    // A key without numbers gets them after its target.
    write = parsed.pose(QStringLiteral("ball"), 0, pose(0.5f, 0, 0));
    QCOMPARE(withEdits(text, write.edits),
             QString(text).replace(QStringLiteral("/key 0 ball\n"),
                                   QStringLiteral("/key 0 ball 0.5 0 0 0 0 0\n")));
    // Nothing changes: no edit.
    QVERIFY(parsed.pose(QStringLiteral("ball"), 40, pose(1, 2.5f, 3)).edits.empty());
}

void SourceEditTest::newKeyGoesInTimeOrder() {
    const QString text = QStringLiteral(
        "/sphere ball 1 0 0 0\n"
        "  /key 10 ball 1 0 0 0 0 0\n"
        "/key 30 ball 3 0 0 0 0 0\n"
        "/fps 24\n");
    const Parsed parsed(text);
    QCOMPARE(withEdits(text, parsed.pose(QStringLiteral("ball"), 20, pose(2, 0, 0)).edits),
             QString(text).replace(
                 QStringLiteral("/key 30"),
                 QStringLiteral("  /key 20 ball 2 0 0 0 0 0\n/key 30")));  // indented as the key before
    // Before the first key: before it, with its indentation.
    QCOMPARE(withEdits(text, parsed.pose(QStringLiteral("ball"), 5, pose(0.5, 0, 0)).edits),
             QString(text).replace(QStringLiteral("  /key 10"),
                                   QStringLiteral("  /key 5 ball 0.5 0 0 0 0 0\n  /key 10")));
    // After the last: after it.
    QCOMPARE(withEdits(text, parsed.pose(QStringLiteral("ball"), 40, pose(4, 0, 0)).edits),
             QString(text).replace(QStringLiteral("/fps"), QStringLiteral("/key 40 ball 4 0 0 0 0 0\n/fps")));
}

void SourceEditTest::unkeyedTargetChangesItsCreatingNumbers() {
    const QString text = QStringLiteral(
        "/camera 64 48 0.5  0 0 -10   # the eye\n"
        "/box crate 1 2 3 4 5 6\n"
        "/cylinder pole 0.5 3 1 1 1 0 45 0  # tilted\n"
        "/robot r1 0 0 5\n");
    const Parsed parsed(text);
    QCOMPARE(withEdits(text, parsed.pose(QStringLiteral("crate"), 12, pose(4, 5.5f, 6)).edits),
             QString(text).replace(QStringLiteral("4 5 6"), QStringLiteral("4 5.5 6")));
    QCOMPARE(withEdits(text, parsed.pose(QStringLiteral("pole"), 0, pose(1, 1, 1, 0, 30, 0)).edits),
             QString(text).replace(QStringLiteral("0 45 0"), QStringLiteral("0 30 0")));
    // A rotation the command left out is appended.
    QCOMPARE(withEdits(text, parsed.pose(QStringLiteral("r1"), 0, pose(0, 0, 5, 0, 180, 0)).edits),
             QString(text).replace(QStringLiteral("r1 0 0 5"), QStringLiteral("r1 0 0 5 0 180 0")));
    // The camera's /camera line, its comment and spacing kept.
    QCOMPARE(withEdits(text, parsed.pose(QStringLiteral("camera"), 7, pose(0, 1, -10, 5)).edits),
             QString(text).replace(QStringLiteral("0 0 -10  "), QStringLiteral("0 1 -10 5 0 0  ")));
    QCOMPARE(withEdits(text, parsed.property(QStringLiteral("camera"), KeyProperty::Zoom, 7, {0.75}).edits),
             QString(text).replace(QStringLiteral("0.5  0"), QStringLiteral("0.75  0")));
    // Text changed since the parse (a line typed above): no edit of whatever line is there now.
    const QString typed = QStringLiteral("/fps 30\n") + text;
    const WriteBack stale = writePose({typed, parsed.scene, parsed.locations, parsed.name},
                                      QStringLiteral("crate"), 0, pose(4, 5.5f, 6));
    QVERIFY(stale.refused());
    QVERIFY(stale.edits.empty() && stale.offer.empty());
    QVERIFY2(stale.refusal.startsWith(QStringLiteral("The text has changed at the line that makes crate")),
             qPrintable(stale.refusal));
}

void SourceEditTest::targetInALoopIsRefusedWithAnOffer() {
    const QString text = QStringLiteral(
        "/camera 64 48 0.5 0 0 -10\n"
        "/repeat i 0 2\n"
        "  /sphere b{ i } 1 (i * 3) 0 5\n"
        "/end\n"
        "/sphere solo 1 0 0 0\n");
    const Parsed parsed(text);
    const WriteBack write = parsed.pose(QStringLiteral("b1"), 12, pose(3, 1, 5));
    QVERIFY(write.refused());
    QVERIFY(write.edits.empty());
    QCOMPARE(write.refusal,
             QStringLiteral("b1 is made inside the /repeat loop of lines 2–4: changing its numbers "
                            "there would change every object the loop makes."));
    QCOMPARE(write.offerLabel, QStringLiteral("Add a key after the loop (line 5) instead"));
    QCOMPARE(
        withEdits(text, write.offer),
        QString(text).replace(QStringLiteral("/end\n"), QStringLiteral("/end\n/key 12 b1 3 1 5 0 0 0\n")));
    // The offered key then takes it over (it is keyed from then on).
    const Parsed offered(withEdits(text, write.offer));
    const WriteBack next = offered.pose(QStringLiteral("b1"), 12, pose(3, 2, 5));
    QVERIFY(!next.refused());
    QCOMPARE(withEdits(offered.text, next.edits),
             QString(offered.text).replace(QStringLiteral("b1 3 1 5"), QStringLiteral("b1 3 2 5")));
    // A key at the frame written inside a loop is refused too.
    const QString keyed = QStringLiteral(
        "/sphere ball 1 0 0 0\n"
        "/repeat i 0 0\n"
        "/key 5 ball 1 1 1 0 0 0\n"
        "/end\n");
    const WriteBack inLoop = Parsed(keyed).pose(QStringLiteral("ball"), 5, pose(2, 2, 2));
    QVERIFY(inLoop.refused());
    QVERIFY(inLoop.refusal.contains(QStringLiteral("inside the /repeat loop of lines 2–4")));
    QCOMPARE(withEdits(keyed, inLoop.offer), keyed + QStringLiteral("/key 5 ball 2 2 2 0 0 0\n"));
}

void SourceEditTest::targetInAnIncludedFileIsRefusedWithAnOffer() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    test::writeFile(dir.filePath(QStringLiteral("props.f2")), "/sphere prop 1 2 0 5\n");
    const QString text = QStringLiteral("/camera 64 48 0.5 0 0 -10\n/include props.f2\n/fps 24\n");
    const Parsed parsed(text, QDir::cleanPath(dir.filePath(QStringLiteral("main.f2"))).toStdString());
    const WriteBack write = parsed.pose(QStringLiteral("prop"), 0, pose(2, 1, 5));
    QVERIFY(write.refused());
    QVERIFY2(write.refusal.startsWith(QStringLiteral("prop is made in the included file ")),
             qPrintable(write.refusal));
    QCOMPARE(write.offerLabel, QStringLiteral("Add a key after its /include (line 3) instead"));
    QCOMPARE(withEdits(text, write.offer),
             QString(text).replace(QStringLiteral("/fps"), QStringLiteral("/key 0 prop 2 1 5 0 0 0\n/fps")));
}

void SourceEditTest::propertyKeysAndFirstKeysOfParts() {
    const QString text = QStringLiteral(
        "/point_light 0.8 0 5 0 name lamp\n"
        "/sphere ball 1 0 0 0\n"
        "/key 0 ball colour 255 0 0 ease # red\n"
        "/robot r1 0 0 5\n"
        "/key 0 ball 0 0 0 0 0 0\n");
    const Parsed parsed(text);
    // The colour key at the frame: its numbers, not the pose key's.
    QCOMPARE(
        withEdits(text, parsed.property(QStringLiteral("ball"), KeyProperty::Colour, 0, {255, 128, 0}).edits),
        QString(text).replace(QStringLiteral("255 0 0 ease"), QStringLiteral("255 128 0 ease")));
    // A light's intensity without keys: the light's own number.
    QCOMPARE(withEdits(text, parsed.property(QStringLiteral("lamp"), KeyProperty::Intensity, 3, {0.5}).edits),
             QString(text).replace(QStringLiteral("0.8"), QStringLiteral("0.5")));
    // A part without keys: its first key, after its object's line.
    QCOMPARE(withEdits(text, parsed.pose(QStringLiteral("r1.head"), 10, pose(0, 0, 0, 0, 30, 0)).edits),
             QString(text).replace(QStringLiteral("0 0 5\n"),
                                   QStringLiteral("0 0 5\n/key 10 r1.head 0 0 0 0 30 0\n")));
    // visible has no creating number: a first key after the object's line.
    QCOMPARE(
        withEdits(text, parsed.property(QStringLiteral("r1"), KeyProperty::Visible, 4, {0}).edits),
        QString(text).replace(QStringLiteral("0 0 5\n"), QStringLiteral("0 0 5\n/key 4 r1 visible 0\n")));
    QCOMPARE(parsed.pose(QStringLiteral("nobody"), 0, pose(0, 0, 0)).refusal,
             QStringLiteral("nobody is not in the scene as it was last read (renamed or deleted since?)"));
    QCOMPARE(parsed.property(QStringLiteral("ball"), KeyProperty::Intensity, 0, {1}).refusal,
             QStringLiteral("ball has no intensity to key."));
    // An instance's parameters stay after its pose; a missing rotation goes before them.
    const QString lamps = QStringLiteral(
        "/model lamp arm 120\n/part head root 0 (arm) 0\n/sphere head.bulb 5 0 0 0\n/end\n"
        "/lamp b 200 0 0 arm 60\n");
    const Parsed lamp(lamps);
    QCOMPARE(withEdits(lamps, lamp.pose(QStringLiteral("b"), 0, pose(200, 0, 0, 0, 90, 0)).edits),
             QString(lamps).replace(QStringLiteral("200 0 0 arm"), QStringLiteral("200 0 0 0 90 0 arm")));
}

void SourceEditTest::dopeSheetRowsNameTheKeyLines() {
    const QString text = QStringLiteral(
        "/robot r1 0 0 5\n"
        "/key 0 r1\n"
        "/key 1s r1 1 0 5 0 0 0 ease\n"
        "/repeat i 0 0\n"
        "/key 48 r1 2 0 5 0 0 0\n"
        "/end\n"
        "/key 10 r1.head 0 0 0 0 30 0\n"
        "/key 5 r1 colour 255 0 0\n");
    const Parsed parsed(text);
    const auto rows = dopeSheetRows(text, parsed.scene, Selection{"r1", std::nullopt, {}});
    // The pose, the one keyed part, the colour; not the unkeyed parts.
    QCOMPARE(rows.size(), std::size_t(3));
    QCOMPARE(rows[0].target, QStringLiteral("r1"));
    QCOMPARE(rows[0].keys.size(), std::size_t(3));
    QCOMPARE(rows[0].keys[0].line, 1);
    QCOMPARE(rows[0].keys[1].time, 24.0);  // 1s at 24 fps
    QCOMPARE(rows[0].keys[1].line, 2);
    QVERIFY(rows[0].keys[1].mode && rows[0].keys[1].mode->mode == Interpolation::Ease);
    QCOMPARE(rows[0].keys[2].line, -1);  // inside a loop: shown, not editable
    QCOMPARE(rows[1].target, QStringLiteral("r1.head"));
    QCOMPARE(rows[1].keys[0].line, 6);
    QCOMPARE(rows[2].property, std::optional(KeyProperty::Colour));
    QCOMPARE(rows[2].keys[0].line, 7);
    // Without a selection: the camera.
    const auto camera = dopeSheetRows(text, parsed.scene, std::nullopt);
    QCOMPARE(camera.size(), std::size_t(1));
    QCOMPARE(camera[0].target, QStringLiteral("camera"));
}

void SourceEditTest::movedKeysChangeOnlyTheirTimes() {
    const QString text = QStringLiteral(
        "/sphere ball 1 0 0 0\n"
        "/key 0 ball\n"
        "/key  40  ball 1 2 3 0 0 0 ease  # hop\n"
        "/key 2s ball 2 2 2 0 0 0\n"
        "/key 60 ball colour 1 2 3\n"
        "/key 80 ball 4 4 4 0 0 0\n");
    // 40 → 60: exactly that line's time.
    QCOMPARE(withEdits(text, moveKeyEdits(text, 24, {2}, 20, false)),
             QString(text).replace(QStringLiteral("/key  40  ball"), QStringLiteral("/key  60  ball")));
    // A time in seconds stays in seconds; two keys move together.
    QCOMPARE(withEdits(text, moveKeyEdits(text, 24, {2, 3}, 12, false)),
             QString(text)
                 .replace(QStringLiteral("/key  40  ball"), QStringLiteral("/key  52  ball"))
                 .replace(QStringLiteral("2s ball"), QStringLiteral("2.5s ball")));
    // Not before frame 0: the move stops there for all.
    QCOMPARE(
        withEdits(text, moveKeyEdits(text, 24, {2, 3}, -100, false)),
        QString(text)
            .replace(QStringLiteral("/key  40  ball"), QStringLiteral("/key  0  ball"))
            .replace(QStringLiteral("2s ball"), QStringLiteral("8 ball"))  // 1/3 s is no short number: frames
            .replace(QStringLiteral("/key 0 ball\n"), QString()));         // the key at 0 it lands on goes
    // A copy: the original stays, the copy follows it; a key of the same
    // track at the new time goes, not the colour key there.
    QCOMPARE(withEdits(text, moveKeyEdits(text, 24, {3}, 20, true)),
             QString(text).replace(QStringLiteral("/key 2s ball 2 2 2 0 0 0\n"),
                                   QStringLiteral("/key 2s ball 2 2 2 0 0 0\n/key 68 ball 2 2 2 0 0 0\n")));
    QCOMPARE(withEdits(text, moveKeyEdits(text, 24, {2}, 40, true)),
             QString(text)
                 .replace(QStringLiteral("# hop\n"),
                          QStringLiteral("# hop\n/key  80  ball 1 2 3 0 0 0 ease  # hop\n"))
                 .replace(QStringLiteral("/key 80 ball 4 4 4 0 0 0\n"), QString()));
}

void SourceEditTest::deletedKeysAndModesAreLineEdits() {
    const QString text = QStringLiteral(
        "/sphere ball 1 0 0 0\n"
        "/key 0 ball\n"
        "/key 40 ball 1 2 3 0 0 0 bezier 0.1 0.2 0.3 1  # hop\n"
        "/key 60 ball colour 1 2 3\n"
        "/key 70 ball visible 0\n"
        "/key 80 ball 4 4 4 0 0 0");
    QCOMPARE(withEdits(text, deleteKeyEdits(text, {1, 5})),
             QStringLiteral("/sphere ball 1 0 0 0\n"
                            "/key 40 ball 1 2 3 0 0 0 bezier 0.1 0.2 0.3 1  # hop\n"
                            "/key 60 ball colour 1 2 3\n"
                            "/key 70 ball visible 0"));
    // The mode word and its numbers are replaced, the comment stays; a key
    // without a mode gets one; visible keys take none.
    QCOMPARE(withEdits(text, keyModeEdits(text, {1, 2, 3, 4}, Easing(Interpolation::EaseIn))),
             QString(text)
                 .replace(QStringLiteral("/key 0 ball\n"), QStringLiteral("/key 0 ball ease_in\n"))
                 .replace(QStringLiteral("bezier 0.1 0.2 0.3 1"), QStringLiteral("ease_in"))
                 .replace(QStringLiteral("colour 1 2 3"), QStringLiteral("colour 1 2 3 ease_in")));
    QCOMPARE(withEdits(text, keyModeEdits(text, {2}, std::nullopt)),
             QString(text).replace(QStringLiteral(" bezier 0.1 0.2 0.3 1"), QString()));
}

void SourceEditTest::refusedWriteBackAsksBeforeItsOffer() {
    const QString text = QStringLiteral(
        "/repeat i 0 1\n"
        "/sphere b{ i } 1 (i * 3) 0 5  # a row\n"
        "/end\n");
    const Parsed parsed(text);
    const WriteBack write = parsed.pose(QStringLiteral("b0"), 4, pose(1, 0, 5));
    QVERIFY(write.refused());
    QPlainTextEdit editor;
    editor.setPlainText(text);
    QString asked;
    // Declined: the text is byte-identical and there is nothing to undo.
    QCOMPARE(applyWriteBack(&editor, write,
                            [&](const QString& why, const QString&) {
                                asked = why;
                                return false;
                            }),
             WriteBackOutcome::Declined);
    QCOMPARE(asked, write.refusal);
    QCOMPARE(editor.toPlainText(), text);
    QVERIFY(!editor.document()->isUndoAvailable());
    // Taken: the key after the loop, one undo step.
    QCOMPARE(applyWriteBack(&editor, write, [](const QString&, const QString&) { return true; }),
             WriteBackOutcome::Offered);
    QCOMPARE(editor.toPlainText(), text + QStringLiteral("/key 4 b0 1 0 5 0 0 0\n"));
    QCOMPARE(editor.textCursor().selectedText(), QStringLiteral("/key 4 b0 1 0 5 0 0 0"));
    // Keyed now: written in place, that line selected.
    const Parsed keyed(editor.toPlainText());
    QCOMPARE(applyWriteBack(&editor, keyed.pose(QStringLiteral("b0"), 4, pose(1, 2, 5)), {}),
             WriteBackOutcome::Written);
    QCOMPARE(editor.textCursor().selectedText(), QStringLiteral("/key 4 b0 1 2 5 0 0 0"));
    QCOMPARE(applyWriteBack(&editor,
                            Parsed(editor.toPlainText()).pose(QStringLiteral("b0"), 4, pose(1, 2, 5)), {}),
             WriteBackOutcome::Unchanged);
    editor.undo();
    editor.undo();
    QCOMPARE(editor.toPlainText(), text);
    // Line edits of the capture commands are one span.
    QCOMPARE(changedSpan(QStringLiteral("a b c"), QStringLiteral("a bb c")),
             (SpanEdit{3, 3, QStringLiteral("b")}));
    QCOMPARE(changedSpan(QStringLiteral("abc"), QStringLiteral("abc")), (SpanEdit{3, 3, QString()}));
}

QTEST_MAIN(SourceEditTest)
#include "source_edit_test.moc"
