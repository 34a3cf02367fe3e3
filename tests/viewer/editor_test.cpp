// QtTest suite of the viewer's scene editor, on the offscreen platform: live
// parse and render while typing, problems in the text, saving, autosave and
// crash recovery, changes on disk, and the editing commands.
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QLineEdit>
#include <QListWidget>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <memory>

#include "autosave.h"
#include "capture_pose.h"
#include "core/anim/camera_motion.h"
#include "core/anim/frame_builder.h"
#include "core/parse/parser.h"
#include "editor_dock.h"
#include "image_convert.h"
#include "main_window.h"
#include "number_scrubber.h"
#include "opening_indicator.h"
#include "playback.h"
#include "render_controller.h"
#include "scene_document.h"
#include "scene_editor.h"
#include "scene_highlighter.h"
#include "selection.h"
#include "test_support.h"
#include "text_capture.h"
#include "viewport_widget.h"

using namespace f2;
using namespace f2::viewer;
using namespace f2::viewer::test;

namespace {

using Question = MainWindow::Question;

/// Records the questions a window asks and answers them from a script.
struct ScriptedAnswers {
    std::vector<Question> asked;
    QMessageBox::StandardButton answer = QMessageBox::Cancel;

    MainWindow::Asker asker() {
        return [this](Question q, const QString&) {
            asked.push_back(q);
            return answer;
        };
    }
};

bool hasObject(const SceneDesc& scene, const std::string& name) {
    return std::any_of(scene.objects.begin(), scene.objects.end(),
                       [&](const auto& object) { return object.name == name; });
}

/// While alive, every file and text counts as large: it opens in the
/// background (the thresholds are sizes, so the test needs no 20 MB file).
struct EverythingOpensInTheBackground {
    qint64 bytes = SceneDocument::kBackgroundBytes;
    qsizetype chars = EditorDock::kBackgroundChars;
    EverythingOpensInTheBackground() {
        SceneDocument::kBackgroundBytes = 0;
        EditorDock::kBackgroundChars = 0;
    }
    ~EverythingOpensInTheBackground() {
        SceneDocument::kBackgroundBytes = bytes;
        EditorDock::kBackgroundChars = chars;
    }
};

/// Replaces `length` characters at `line`:`column` (1-based) by typing, as a user would.
void typeOver(SceneEditor* editor, int line, int column, int length, const QString& typed) {
    editor->goTo(line, column);
    for (int i = 0; i < length; ++i) QTest::keyClick(editor, Qt::Key_Delete);
    QTest::keyClicks(editor, typed);
}

/// The highlighter's format at `pos` of `block` (an invalid one if unformatted).
QTextCharFormat formatAt(const QTextBlock& block, int pos) {
    for (const QTextLayout::FormatRange& r : block.layout()->formats())
        if (pos >= r.start && pos < r.start + r.length) return r.format;
    return {};
}

}  // namespace

class EditorTest : public QObject {
    Q_OBJECT
   private slots:
    void initTestCase();
    void init();

    void editorShowsFileAndHighlights();
    void typingRendersLive();
    void errorKeepsImageAndUnderlinesColumn();
    void sameMarksAsTheLanguageServer();
    void saveWritesTextAtomically();
    void autosaveRestoresAfterCrash();
    void diskChangeWithUnsavedEditsAsks();
    void openAndCloseAskAboutUnsavedEdits();
    void commentFindAndGoToLine();
    void missingOrBrokenFileShowsItself();
    void largeSceneTypesSmoothly();
    void largeFileOpensInTheBackground();
    void newerFileWinsOverOneStillOpening();
    void captureWritesLinesInOneUndoStep();
    void captureLinesGoNextToTheirTarget();
    void keyCameraHereWritesTheView();
    void cameraKeyOfAnAttachedCamera();
    void ctrlDragScrubsANumber();
    void altWheelScrubsANumber();
};

void EditorTest::initTestCase() {
    QCoreApplication::setOrganizationName("F2StageTest");
    QCoreApplication::setApplicationName("f2-viewer-editor-test");
}

void EditorTest::init() {
    // Each test starts without autosaved copies from an earlier one.
    QDir(Autosave::directory()).removeRecursively();
}

void EditorTest::editorShowsFileAndHighlights() {
    QTemporaryDir dir;
    const QString path = smallSceneFile(dir);
    auto w = windowOn(path, 0);
    QVERIFY(w);
    QVERIFY(w->editorDock()->isVisible());
    QCOMPARE(w->editor()->toPlainText(), QString::fromUtf8(kSmallScene));
    QVERIFY(!w->editorDock()->isModified());
    QVERIFY(w->windowTitle().startsWith("scene.f2"));
    QVERIFY(!w->isWindowModified());

    // Each kind of word has its own format.
    QTextDocument doc;
    SceneHighlighter highlighter(&doc);
    doc.setPlainText(
        "/key 10 r1.head 0 (x*2) 0 0 0 0 ease  # turn\n"
        "/sphere ball{i} 1 2 3 4\n"
        "/caption 2.5s 3s 0 0 0.1 \"a \\\" # b\" colour 1 2 3\n");
    highlighter.rehighlight();
    using Kind = SceneHighlighter::Kind;
    const QTextBlock key = doc.firstBlock();
    auto is = [&](const QTextBlock& b, int pos, Kind kind) {
        return formatAt(b, pos).foreground() == highlighter.format(kind).foreground();
    };
    QVERIFY(is(key, 0, Kind::Command));      // /key
    QVERIFY(is(key, 5, Kind::Number));       // 10
    QVERIFY(is(key, 8, Kind::Name));         // r1
    QVERIFY(is(key, 11, Kind::Part));        // head
    QVERIFY(is(key, 18, Kind::Expression));  // (x*2)
    QVERIFY(is(key, 34, Kind::Mode));        // ease
    QVERIFY(is(key, 40, Kind::Comment));     // # turn
    const QTextBlock sphere = key.next();
    QVERIFY(is(sphere, 8, Kind::Name));         // ball
    QVERIFY(is(sphere, 12, Kind::Expression));  // {i}
    // A caption's text is one piece, its '#' and escaped quote inside; seconds are numbers.
    const QTextBlock caption = sphere.next();
    QVERIFY(is(caption, 9, Kind::Number));   // 2.5s
    QVERIFY(is(caption, 26, Kind::Text));    // "a
    QVERIFY(is(caption, 31, Kind::Text));    // #
    QVERIFY(is(caption, 34, Kind::Text));    // b"
    QVERIFY(is(caption, 37, Kind::Name));    // colour
    QVERIFY(is(caption, 43, Kind::Number));  // 1
}

void EditorTest::typingRendersLive() {
    QTemporaryDir dir;
    const QString path = smallSceneFile(dir);
    auto w = windowOn(path, 5);
    QVERIFY(w);
    const QImage before = w->viewport()->image();
    const auto beforeScene = w->document()->scene();

    // "/background 20 30 40" -> "/background 90 30 40", typed.
    w->editor()->setFocus();
    typeOver(w->editor(), 2, 13, 2, "90");
    QVERIFY(!w->playback()->isPlaying());  // Space and letters type; they are not shortcuts here
    QTRY_VERIFY_WITH_TIMEOUT(w->document()->scene() != beforeScene, kWaitMs);
    QCOMPARE(int(w->document()->scene()->background.r), 90);
    QVERIFY(waitForShownFrame(*w, 5));
    QVERIFY(w->viewport()->image() != before);
    expectViewportMatchesCore(*w, 5);
    // The time and the file are untouched; the title says there are edits.
    QCOMPARE(w->playback()->time(), 5.0);
    QCOMPARE(readFile(path), QByteArray(kSmallScene));
    QVERIFY(w->isWindowModified());

    // A space typed in the editor is text, not Play.
    QTest::keyClick(w->editor(), Qt::Key_Space);
    QVERIFY(!w->playback()->isPlaying());
}

void EditorTest::sameMarksAsTheLanguageServer() {
    // The lines and columns of lsp.Diagnostics.MarksOnBracketsGluedCommentsTabsAndNonAscii:
    // the viewer underlines what the language server ranges.
    struct Case {
        QString line;
        int begin, end;  // UTF-16 columns, 0-based, [begin, end)
    };
    const Case cases[] = {
        {"/fps 24x#c", 5, 8},
        {"/fps\t24x", 5, 8},
        {QString::fromUtf8("/sphere \xc3\xa9 1 0 0 0"), 8, 9},
        {"/sphere b (1 + nope) 0 0 0", 15, 19},
    };
    QTemporaryDir dir;
    auto w = windowOn(smallSceneFile(dir), 0);
    QVERIFY(w);
    SceneEditor* editor = w->editor();
    const QString good = editor->toPlainText();
    for (const Case& c : cases) {
        editor->selectAll();
        editor->insertPlainText(good + c.line + "\n");
        QTRY_VERIFY_WITH_TIMEOUT(w->document()->hasErrors() && editor->problems().size() == 1, kWaitMs);
        const int lineStart = editor->document()->findBlockByNumber(good.count('\n')).position();
        QCOMPARE(editor->problemRange(editor->problems().front()),
                 std::make_pair(lineStart + c.begin, c.end - c.begin));
        editor->selectAll();
        editor->insertPlainText(good);
        QTRY_VERIFY_WITH_TIMEOUT(!w->document()->hasErrors(), kWaitMs);
    }
}

void EditorTest::errorKeepsImageAndUnderlinesColumn() {
    QTemporaryDir dir;
    const QString path = smallSceneFile(dir);
    auto w = windowOn(path, 5);
    QVERIFY(w);
    const QImage good = w->viewport()->image();
    const auto goodScene = w->document()->scene();

    // "/amb_light 0.3" -> "/amb_light abc": an error at line 3, column 12.
    typeOver(w->editor(), 3, 12, 3, "abc");
    QTRY_VERIFY_WITH_TIMEOUT(w->document()->hasErrors(), kWaitMs);
    QCOMPARE(w->document()->scene(), goodScene);  // the last good scene keeps playing
    QVERIFY2(problemsText(*w).contains(path + ":3:12: error:"), qPrintable(problemsText(*w)));
    QVERIFY(w->diagnosticsDock()->isVisible());

    // Underlined from that column to the end of the word, with the message as tooltip.
    SceneEditor* editor = w->editor();
    QCOMPARE(int(editor->problems().size()), 1);
    const EditorProblem& problem = editor->problems().front();
    QCOMPARE(problem.line, 3);
    QCOMPARE(problem.column, 12);
    const int lineStart = editor->document()->findBlockByNumber(2).position();
    QCOMPARE(editor->problemRange(problem), std::make_pair(lineStart + 11, 3));
    QVERIFY(editor->problemAt(lineStart + 12).contains("number"));
    QVERIFY(editor->problemAt(lineStart + 5).isEmpty());
    bool underlined = false;
    for (const QTextEdit::ExtraSelection& s : editor->extraSelections())
        underlined |= s.format.underlineStyle() == QTextCharFormat::SpellCheckUnderline &&
                      s.cursor.selectionStart() == lineStart + 11 &&
                      s.cursor.selectionEnd() == lineStart + 14;
    QVERIFY(underlined);

    // A new frame of the same time still shows the last good scene.
    w->playback()->seek(5.0);
    w->scheduleFrame();
    QVERIFY(waitForShownFrame(*w, 5));
    QCOMPARE(w->viewport()->image(), good);

    // A click on the problem puts the cursor there.
    editor->goTo(1, 1);
    QListWidgetItem* item = w->problemsList()->item(0);
    emit w->problemsList()->itemClicked(item);
    QCOMPARE(editor->textCursor().blockNumber(), 2);
    QCOMPARE(editor->textCursor().positionInBlock(), 11);

    // Undoing the typing brings the good scene back and clears the marks.
    while (editor->document()->isUndoAvailable()) editor->undo();
    QTRY_VERIFY_WITH_TIMEOUT(!w->document()->hasErrors(), kWaitMs);
    QVERIFY(editor->problems().empty());
    QCOMPARE(problemsText(*w), QStringLiteral("No problems."));

    // An expression argument is underlined whole, spaces and all (the
    // parser's extent, as the language server ranges it), and after a
    // two-byte character the columns still meet the right characters.
    typeOver(editor, 3, 12, 3, "(0.1 - 0.5)");
    QTRY_VERIFY_WITH_TIMEOUT(editor->problems().size() == 1, kWaitMs);
    QCOMPARE(editor->problemRange(editor->problems().front()), std::make_pair(lineStart + 11, 11));
    while (editor->document()->isUndoAvailable()) editor->undo();
    QTRY_VERIFY_WITH_TIMEOUT(editor->problems().empty(), kWaitMs);
    // "\u00e9/amb_light": 2 bytes before the command (QTest types only ASCII: a cursor edit).
    QTextCursor(editor->document()->findBlockByNumber(2)).insertText(QString::fromUtf8("\u00e9"));
    QTRY_VERIFY_WITH_TIMEOUT(editor->problems().size() == 1, kWaitMs);
    QCOMPARE(editor->problemRange(editor->problems().front()), std::make_pair(lineStart, 11));  // 12 bytes
}

void EditorTest::saveWritesTextAtomically() {
    QTemporaryDir dir;
    const QString path = smallSceneFile(dir);
    auto w = windowOn(path, 0);
    QVERIFY(w);
    typeOver(w->editor(), 2, 13, 2, "90");
    QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(Autosave::copyPath(path)), kWaitMs);
    QVERIFY(w->isWindowModified());

    QVERIFY(w->saveScene());
    const QByteArray expected = QByteArray(kSmallScene).replace("/background 20", "/background 90");
    QCOMPARE(readFile(path), expected);
    QVERIFY(!w->isWindowModified());
    QVERIFY(!QFile::exists(Autosave::copyPath(path)));  // nothing left to recover
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"scene.f2"});

    // The viewer's own write is no change on disk: the text and its undo history stay.
    QTest::qWait(2 * SceneDocument::kReloadDelayMs);
    QCOMPARE(w->editor()->toPlainText(), QString::fromUtf8(expected));
    QVERIFY(w->editor()->document()->isUndoAvailable());
}

void EditorTest::autosaveRestoresAfterCrash() {
    QTemporaryDir dir;
    const QString path = smallSceneFile(dir);
    QString typed;
    {
        auto w = windowOn(path, 0);
        QVERIFY(w);
        w->editor()->moveCursor(QTextCursor::End);
        QTest::keyClicks(w->editor(), "/fps 30");
        QTest::keyClick(w->editor(), Qt::Key_Return);
        typed = w->editor()->toPlainText();
        QTRY_COMPARE_WITH_TIMEOUT(Autosave::read(path).value_or(QString()), typed, kWaitMs);
        // The window goes away without closing: what a crash leaves behind.
    }
    QCOMPARE(readFile(path), QByteArray(kSmallScene));
    QVERIFY(QFile::exists(Autosave::copyPath(path)));

    ScriptedAnswers answers;
    answers.answer = QMessageBox::Yes;
    MainWindow w;
    w.setAsker(answers.asker());
    QVERIFY(w.openFile(path));
    QCOMPARE(answers.asked, std::vector<Question>{Question::RestoreAutosave});
    QCOMPARE(w.editor()->toPlainText(), typed);
    QVERIFY(w.isWindowModified());
    QTRY_COMPARE_WITH_TIMEOUT(w.document()->scene()->fps, 30, kWaitMs);
    // One undo goes back to the file's text.
    w.editor()->undo();
    QCOMPARE(w.editor()->toPlainText(), QString::fromUtf8(kSmallScene));

    // Discarding the edits removes the copy.
    w.editor()->redo();
    answers.answer = QMessageBox::Discard;  // discard the edits when opening again
    QVERIFY(w.openFile(path));
    QVERIFY(!QFile::exists(Autosave::copyPath(path)));
    QCOMPARE(w.editor()->toPlainText(), QString::fromUtf8(kSmallScene));
}

void EditorTest::diskChangeWithUnsavedEditsAsks() {
    QTemporaryDir dir;
    const QString path = smallSceneFile(dir);
    auto w = windowOn(path, 0);
    QVERIFY(w);
    ScriptedAnswers answers;
    w->setAsker(answers.asker());

    // No edits: a change on disk simply reloads.
    const QByteArray onDisk1 = QByteArray(kSmallScene).append("/fps 12\n");
    writeFile(path, onDisk1);
    QTRY_COMPARE_WITH_TIMEOUT(w->editor()->toPlainText(), QString::fromUtf8(onDisk1), kWaitMs);
    QVERIFY(answers.asked.empty());

    // With edits: ask; "keep mine" keeps them.
    typeOver(w->editor(), 2, 13, 2, "90");
    QTRY_VERIFY_WITH_TIMEOUT(w->document()->scene()->background.r == 90, kWaitMs);
    const QString mine = w->editor()->toPlainText();
    answers.answer = QMessageBox::No;
    writeFile(path, QByteArray(kSmallScene).append("/fps 13\n"));
    QTRY_COMPARE_WITH_TIMEOUT(answers.asked.size(), std::size_t{1}, kWaitMs);
    QCOMPARE(answers.asked.back(), Question::ReloadChangedFile);
    QCOMPARE(w->editor()->toPlainText(), mine);
    QVERIFY(w->isWindowModified());

    // "Load the file" takes the disk's text.
    answers.answer = QMessageBox::Yes;
    const QByteArray onDisk3 = QByteArray(kSmallScene).append("/fps 14\n");
    writeFile(path, onDisk3);
    QTRY_COMPARE_WITH_TIMEOUT(w->editor()->toPlainText(), QString::fromUtf8(onDisk3), kWaitMs);
    QCOMPARE(answers.asked.size(), std::size_t{2});
    QVERIFY(!w->isWindowModified());
    QTRY_COMPARE_WITH_TIMEOUT(w->document()->scene()->fps, 14, kWaitMs);
}

void EditorTest::openAndCloseAskAboutUnsavedEdits() {
    QTemporaryDir dir;
    const QString path = dir.filePath("scene.f2");
    const QString other = dir.filePath("other.f2");
    writeFile(path, kSmallScene);
    writeFile(other, kSmallScene);
    auto w = windowOn(path, 0);
    QVERIFY(w);
    ScriptedAnswers answers;
    w->setAsker(answers.asker());
    typeOver(w->editor(), 2, 13, 2, "90");

    answers.answer = QMessageBox::Cancel;
    QVERIFY(!w->openFile(other));
    QCOMPARE(w->document()->path(), path);
    QVERIFY(!w->close());
    QVERIFY(w->isVisible());
    QCOMPARE(answers.asked, (std::vector<Question>{Question::SaveChanges, Question::SaveChanges}));

    answers.answer = QMessageBox::Save;
    QVERIFY(w->openFile(other));
    QCOMPARE(w->document()->path(), other);
    QVERIFY(readFile(path).contains("/background 90"));

    answers.asked.clear();
    QVERIFY(w->close());  // nothing unsaved: no question
    QVERIFY(answers.asked.empty());
}

void EditorTest::commentFindAndGoToLine() {
    QTemporaryDir dir;
    auto w = windowOn(smallSceneFile(dir), 0);
    QVERIFY(w);
    SceneEditor* editor = w->editor();
    QTextDocument* doc = editor->document();

    // Lines 2-3 selected: commented in one step, uncommented by the same command.
    QTextCursor c(doc->findBlockByNumber(1));
    c.setPosition(doc->findBlockByNumber(2).position() + 3, QTextCursor::KeepAnchor);
    editor->setTextCursor(c);
    editor->toggleComment();
    QCOMPARE(doc->findBlockByNumber(1).text(), QStringLiteral("# /background 20 30 40"));
    QCOMPARE(doc->findBlockByNumber(2).text(), QStringLiteral("# /amb_light 0.3"));
    QCOMPARE(doc->findBlockByNumber(3).text(), QStringLiteral("/dir_light 0.8 0.3 -0.5 1"));
    QTRY_COMPARE_WITH_TIMEOUT(w->document()->scene()->ambient, 0.0f, kWaitMs);
    editor->undo();
    QCOMPARE(editor->toPlainText(), QString::fromUtf8(kSmallScene));
    editor->redo();
    editor->setTextCursor(c);
    editor->toggleComment();
    QCOMPARE(editor->toPlainText(), QString::fromUtf8(kSmallScene));

    // Go to line 6, column 10 (inside "ball"); find the next "ball" from there.
    editor->goTo(6, 10);
    QCOMPARE(editor->textCursor().blockNumber(), 5);
    QCOMPARE(editor->textCursor().positionInBlock(), 9);
    w->editorDock()->showFind();
    w->editorDock()->findField()->setText("ball");
    QVERIFY(w->editorDock()->findNext());
    QCOMPARE(editor->textCursor().blockNumber(), 6);  // "/key 0 ball"
    QCOMPARE(editor->textCursor().selectedText(), QStringLiteral("ball"));
    QVERIFY(w->editorDock()->findNext(true));
    QCOMPARE(editor->textCursor().blockNumber(), 5);
    w->editorDock()->findField()->setText("nowhere");
    QVERIFY(!w->editorDock()->findNext());
}

void EditorTest::missingOrBrokenFileShowsItself() {
    QTemporaryDir dir;
    const QString missing = dir.filePath("missing.f2");
    MainWindow w;
    QVERIFY(!w.document()->scene()->objects.empty());  // the default scene
    w.openFile(missing);
    QCOMPARE(w.document()->path(), missing);
    QVERIFY(w.document()->hasErrors());
    QVERIFY2(problemsText(w).startsWith(missing + ":1:1: error:"), qPrintable(problemsText(w)));
    QVERIFY(w.document()->scene()->objects.empty());  // an empty stage, not the demo
    QVERIFY(w.editor()->toPlainText().isEmpty());
    QVERIFY(w.windowTitle().startsWith("missing.f2"));

    // A broken file: its text in the editor, its errors, an empty stage.
    const QString broken = dir.filePath("broken.f2");
    const QByteArray text = QByteArray(kSmallScene).replace("/amb_light 0.3", "/amb_lite 0.3");
    writeFile(broken, text);
    w.openFile(broken);
    QCOMPARE(w.editor()->toPlainText(), QString::fromUtf8(text));
    QVERIFY(problemsText(w).contains(broken + ":3:1: error:"));
    QVERIFY(w.document()->scene()->objects.empty());

    // Fixing it in the editor brings the scene.
    typeOver(w.editor(), 3, 6, 4, "light");
    QTRY_VERIFY_WITH_TIMEOUT(!w.document()->hasErrors(), kWaitMs);
    QCOMPARE(w.document()->scene()->objects.size(), std::size_t{2});
}

void EditorTest::largeSceneTypesSmoothly() {
    // 10,000 lines: typing must not wait for the parser (it runs on a worker
    // after a pause) nor for the highlighter (it redoes only the changed line).
    QTemporaryDir dir;
    const QString path = dir.filePath("big.f2");
    QByteArray text = "/camera 96 72 0.6 0 0 -10\n/amb_light 0.3\n/dir_light 0.8 0.3 -0.5 1\n";
    for (int i = 0; text.count('\n') < 10000; ++i)
        text += "/sphere s" + QByteArray::number(i) + " 0.2 " + QByteArray::number(i % 100 - 50) + " " +
                QByteArray::number(i / 100 - 50) + " 60\n";
    writeFile(path, text);
    QElapsedTimer parseClock;
    parseClock.start();
    QVERIFY(parseScene(text.toStdString(), "big.f2").ok());
    const double parseMs = double(parseClock.nsecsElapsed()) * 1e-6;

    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QElapsedTimer openClock;
    openClock.start();
    w.openFile(path);
    const double openMs = double(openClock.nsecsElapsed()) * 1e-6;
    w.playback()->pause();
    w.editor()->goTo(5000, 1);

    // Keystrokes with the event loop turning between them, as when a user types.
    const QString typed = "# typing in the middle of a big scene ";
    QElapsedTimer typeClock;
    typeClock.start();
    double slowestMs = 0;
    for (QChar ch : typed) {
        QElapsedTimer one;
        one.start();
        QTest::keyClicks(w.editor(), QString(ch));
        QCoreApplication::processEvents();
        slowestMs = std::max(slowestMs, double(one.nsecsElapsed()) * 1e-6);
    }
    const double perKeyMs = double(typeClock.nsecsElapsed()) * 1e-6 / double(typed.size());
    QTRY_VERIFY_WITH_TIMEOUT(!w.document()->isParsing() && w.document()->text() == w.editor()->toPlainText(),
                             kWaitMs);
    QVERIFY(!w.document()->hasErrors());
    QVERIFY(w.editor()->document()->findBlockByNumber(4999).text().startsWith(typed));
    qInfo(
        "10,000-line scene: parse %.1f ms (worker thread), open %.1f ms, typing %.2f ms per key "
        "(slowest %.2f ms) with the parse off the GUI thread",
        parseMs, openMs, perKeyMs, slowestMs);
}

void EditorTest::largeFileOpensInTheBackground() {
    QTemporaryDir dir;
    const QString path = smallSceneFile(dir);
    // Unsaved edits from a crash: the offer to restore them must wait for the
    // file's text, or the restored text would go into the empty placeholder.
    const QString edited = QString::fromUtf8(kSmallScene) + "/fps 30\n";
    Autosave::write(path, edited);
    EverythingOpensInTheBackground large;

    ScriptedAnswers answers;
    answers.answer = QMessageBox::Yes;
    MainWindow w;
    w.setAsker(answers.asker());
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    // The window's own empty text may still be on the worker (a race that
    // once named the wrong file here): make sure of it; this file supersedes it.
    w.editorDock()->setSceneText(QString());
    QVERIFY(w.isOpening());
    QVERIFY(w.openFile(path));

    // openFile returned before the file was parsed and laid out.
    QVERIFY(w.isOpening());
    QVERIFY(w.document()->isOpening());
    QVERIFY(w.editorDock()->isLoading());
    QVERIFY(w.openingIndicator()->text().startsWith("Opening scene.f2 ("));
    QVERIFY(w.document()->scene()->objects.empty());  // not the previous scene beside this text
    QVERIFY(w.editor()->isReadOnly());
    QCOMPARE(w.editor()->toPlainText(), QString());
    QVERIFY(answers.asked.empty());
    // What would write the placeholder's empty text over the file is refused.
    QVERIFY(!w.saveScene());
    QVERIFY(!w.keySelectionHere());
    w.setCameraFromView();
    QCOMPARE(w.editor()->toPlainText(), QString());
    QCOMPARE(readFile(path), QByteArray(kSmallScene));

    QTRY_VERIFY_WITH_TIMEOUT(!w.isOpening(), kWaitMs);
    QCOMPARE(w.openingIndicator()->text(), QString());
    QVERIFY(w.statusBar()->currentMessage().startsWith("Opened scene.f2 in "));
    QVERIFY(!w.editor()->isReadOnly());
    // The offer came once the text was there; the restored edits are one undo step on it.
    QCOMPARE(answers.asked, std::vector<Question>{Question::RestoreAutosave});
    QCOMPARE(w.editor()->toPlainText(), edited);
    QVERIFY(w.isWindowModified());
    w.editor()->undo();
    QCOMPARE(w.editor()->toPlainText(), QString::fromUtf8(kSmallScene));
    QVERIFY(!w.editor()->document()->isUndoAvailable());
    QVERIFY(!w.editorDock()->isModified());

    // Laid out on the worker, coloured as the editor colours what it shows.
    const QTextBlock first = w.editor()->document()->firstBlock();
    SceneHighlighter* highlighter = w.editor()->highlighter();
    QVERIFY(highlighter && highlighter->document() == w.editor()->document());
    QCOMPARE(formatAt(first, 0).foreground(),
             highlighter->format(SceneHighlighter::Kind::Command).foreground());
    QCOMPARE(formatAt(first, 8).foreground(),
             highlighter->format(SceneHighlighter::Kind::Number).foreground());

    // The scene is the file's, and the picture is the core's.
    QTRY_VERIFY_WITH_TIMEOUT(!w.document()->isParsing(), kWaitMs);
    QVERIFY(hasObject(*w.document()->scene(), "ball"));
    w.playback()->pause();
    w.playback()->seek(0);
    QVERIFY(waitForShownFrame(w, 0));
    expectViewportMatchesCore(w, 0);

    // Typing in the loaded document is parsed as before.
    w.editor()->moveCursor(QTextCursor::End);
    QTest::keyClicks(w.editor(), "/fps 12");
    QTRY_COMPARE_WITH_TIMEOUT(w.document()->scene()->fps, 12, kWaitMs);
}

void EditorTest::newerFileWinsOverOneStillOpening() {
    QTemporaryDir dir;
    const QString first = dir.filePath("first.f2");
    const QString second = dir.filePath("second.f2");
    const QByteArray secondText = QByteArray(kSmallScene).replace("ball", "other");
    writeFile(first, kSmallScene);
    writeFile(second, secondText);
    EverythingOpensInTheBackground large;

    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(first));
    QVERIFY(w.openFile(second));  // at once: the first file is still on the workers
    QTRY_VERIFY_WITH_TIMEOUT(
        !w.isOpening() && !w.editorDock()->hasLayoutsInFlight() && !w.document()->isParsing(), kWaitMs);
    QCOMPARE(w.editor()->toPlainText(), QString::fromUtf8(secondText));
    QVERIFY(hasObject(*w.document()->scene(), "other"));
    QVERIFY(!hasObject(*w.document()->scene(), "ball"));
    QVERIFY(w.windowTitle().startsWith("second.f2"));
    QVERIFY(!w.isWindowModified());

    // A small file after a large one still opening: shown at once, and it stays.
    QVERIFY(w.openFile(first));
    SceneDocument::kBackgroundBytes = 1'000'000;
    EditorDock::kBackgroundChars = 1'000'000;
    QVERIFY(w.openFile(second));
    QVERIFY(!w.editorDock()->isLoading());
    QCOMPARE(w.editor()->toPlainText(), QString::fromUtf8(secondText));
    QTRY_VERIFY_WITH_TIMEOUT(
        !w.isOpening() && !w.editorDock()->hasLayoutsInFlight() && !w.document()->isParsing(), kWaitMs);
    QCOMPARE(w.editor()->toPlainText(), QString::fromUtf8(secondText));
    QVERIFY(hasObject(*w.document()->scene(), "other"));
    QVERIFY(!w.editor()->isReadOnly());
}

void EditorTest::captureWritesLinesInOneUndoStep() {
    QTemporaryDir dir;
    auto w = windowOn(smallSceneFile(dir), 5);
    QVERIFY(w);
    SceneEditor* editor = w->editor();
    const QString original = editor->toPlainText();
    QTextDocument* doc = editor->document();

    // Set Camera from View after a drag: /camera keeps "96 72 0.6", takes the orbit's pose.
    const QPoint centre = w->viewport()->rect().center();
    QTest::mousePress(w->viewport(), Qt::LeftButton, {}, centre);
    QTest::mouseMove(w->viewport(), centre + QPoint(30, 10));
    QTest::mouseRelease(w->viewport(), Qt::LeftButton, {}, centre + QPoint(30, 10));
    QVERIFY(w->viewport()->isOrbiting());
    const Pose view = w->viewport()->orbit()->pose();
    w->setCameraFromView();
    const QString expected =
        QStringLiteral("/camera 96 72 0.6 %1 %2 %3 %4 %5 0")
            .arg(formatNumber(view.position.x), formatNumber(view.position.y), formatNumber(view.position.z),
                 formatNumber(view.rotation.x), formatNumber(view.rotation.y));
    QCOMPARE(doc->firstBlock().text(), expected);
    QCOMPARE(editor->textCursor().selectedText(), expected);
    QTRY_VERIFY_WITH_TIMEOUT(
        std::fabs(w->document()->scene()->camera.pose.rotation.y - view.rotation.y) < 0.01f, kWaitMs);
    editor->undo();
    QCOMPARE(editor->toPlainText(), original);

    // Key Selection Here at frame 5: the ball's pose there, after its last key.
    w->setSelection(Selection{"ball", std::nullopt, {}});
    QVERIFY(w->keySelectionHere());
    QCOMPARE(doc->findBlockByNumber(8).text(), QStringLiteral("/key 5 ball 0 0 8 0 0 0"));
    QCOMPARE(doc->findBlockByNumber(7).text(), QStringLiteral("/key 10 ball 3 0 8 0 0 0"));
    editor->undo();
    QCOMPARE(editor->toPlainText(), original);

    // At a frame that has a key, that key is replaced in place.
    w->playback()->seek(0);
    QVERIFY(w->keySelectionHere());
    QCOMPARE(doc->findBlockByNumber(6).text(), QStringLiteral("/key 0 ball -3 0 8 0 0 0"));
    QCOMPARE(doc->blockCount(), original.count('\n') + 1);
    editor->undo();
    QCOMPARE(editor->toPlainText(), original);

    // Without a selection nothing is written.
    w->setSelection(std::nullopt);
    QVERIFY(!w->keySelectionHere());
    QCOMPARE(editor->toPlainText(), original);
}

void EditorTest::captureLinesGoNextToTheirTarget() {
    const Pose pose{{1.5f, -0.001f, 2}, {0, 90, 0}};
    QCOMPARE(formatNumber(1.0), QStringLiteral("1"));
    QCOMPARE(formatNumber(-0.001), QStringLiteral("0"));
    QCOMPARE(formatNumber(-2.5), QStringLiteral("-2.5"));
    const QString text = "/camera 800 600 (1/2)   # wide\n/robot r 0 0 0\n/sphere s 1 0 0 0\n/key 4 s\n";
    // /camera keeps its expression and its comment.
    const TextEdit camera = cameraEdit(text, CameraDesc{}, pose);
    QCOMPARE(camera.line, 1);
    QVERIFY(camera.replace);
    QCOMPARE(camera.text, QStringLiteral("/camera 800 600 (1/2) 1.5 0 2 0 90 0   # wide"));
    // A part without keys: after the robot's creating line.
    const TextEdit head = keyEdit(text, "r.head", 3, pose, 2);
    QCOMPARE(head.line, 3);
    QVERIFY(!head.replace);
    QCOMPARE(head.text, QStringLiteral("/key 3 r.head 1.5 0 2 0 90 0"));
    // After the target's last key; at the end for an unknown line; /camera first if missing.
    QCOMPARE(keyEdit(text, "s", 9, pose, 3).line, 5);
    QCOMPARE(keyEdit(text, "s", 4, pose, 3).replace, true);
    QCOMPARE(keyEdit(text, "gen{1}", 0, pose, 0).line, 5);
    // The camera's first key goes after the /camera line.
    QCOMPARE(cameraLine(text), 1);
    QCOMPARE(keyEdit(text, "camera", 2, pose, cameraLine(text)).line, 2);
    QCOMPARE(cameraLine("/sphere s 1 0 0 0\n"), 0);
    const TextEdit missing = cameraEdit("/sphere s 1 0 0 0\n", CameraDesc{}, pose);
    QCOMPARE(missing.line, 1);
    QVERIFY(!missing.replace);
    QCOMPARE(missing.text, QStringLiteral("/camera 800 600 0.5 1.5 0 2 0 90 0"));
}

void EditorTest::keyCameraHereWritesTheView() {
    QTemporaryDir dir;
    auto w = windowOn(smallSceneFile(dir), 5);
    QVERIFY(w);
    SceneEditor* editor = w->editor();
    const QString original = editor->toPlainText();
    QTextDocument* doc = editor->document();

    // The scene camera, not orbited: its /camera pose at frame 5, after the /camera line. The
    // camera's first key, so /key 0 camera with the /camera pose comes first (studio_test.cpp).
    w->keyCameraHere();
    QCOMPARE(doc->findBlockByNumber(1).text(), QStringLiteral("/key 0 camera 0 0 -10 0 0 0"));
    QCOMPARE(doc->findBlockByNumber(2).text(), QStringLiteral("/key 5 camera 0 0 -10 0 0 0"));
    QCOMPARE(editor->textCursor().selectedText(), QStringLiteral("/key 5 camera 0 0 -10 0 0 0"));
    QCOMPARE(doc->blockCount(), original.count('\n') + 3);
    editor->undo();
    QCOMPARE(editor->toPlainText(), original);

    // After an orbit: the look-around's eye and rotation. The scene then shows that view at frame 5.
    const QPoint centre = w->viewport()->rect().center();
    QTest::mousePress(w->viewport(), Qt::LeftButton, {}, centre);
    QTest::mouseMove(w->viewport(), centre + QPoint(-25, 12));
    QTest::mouseRelease(w->viewport(), Qt::LeftButton, {}, centre + QPoint(-25, 12));
    QVERIFY(w->viewport()->isOrbiting());
    const Pose view = w->viewport()->orbit()->pose();
    w->keyCameraHere();
    const QString keyed =
        QStringLiteral("/key 5 camera %1 %2 %3 %4 %5 0")
            .arg(formatNumber(view.position.x), formatNumber(view.position.y), formatNumber(view.position.z),
                 formatNumber(view.rotation.x), formatNumber(view.rotation.y));
    QCOMPARE(doc->findBlockByNumber(1).text(), QStringLiteral("/key 0 camera 0 0 -10 0 0 0"));
    QCOMPARE(doc->findBlockByNumber(2).text(), keyed);
    QTRY_VERIFY_WITH_TIMEOUT(!w->document()->scene()->camera.track.keys.empty(), kWaitMs);
    const Camera scene5 = cameraAt(*w->document()->scene(), 5);
    QVERIFY(length(scene5.eye - view.position) < 0.02f);  // two decimals per number
    // A key at frame 8 goes after the camera's last key; one at frame 5 replaces it in place.
    w->playback()->seek(8);
    w->keyCameraHere();
    QVERIFY(doc->findBlockByNumber(3).text().startsWith("/key 8 camera "));
    w->playback()->seek(5);
    w->viewport()->resetView();
    w->keyCameraHere();
    QTRY_VERIFY_WITH_TIMEOUT(w->document()->scene()->camera.track.keys.size() == 3, kWaitMs);
    QVERIFY(doc->findBlockByNumber(2).text().startsWith("/key 5 camera "));
    QCOMPARE(doc->blockCount(), original.count('\n') + 4);
    // Each capture was one undo step.
    for (int i = 0; i < 3; ++i) editor->undo();
    QCOMPARE(editor->toPlainText(), original);
}

void EditorTest::cameraKeyOfAnAttachedCamera() {
    const ParseResult parsed = parseScene(
        "/camera 80 60 0.5 0 50 -100 10 0 0\n/box cart 10 10 10 0 0 0\n/key 0 cart 0 0 0 0 0 0\n"
        "/key 10 cart 100 0 50 0 90 0\n/attach camera cart\n/key 0 camera 0 50 -100 10 0 0\n",
        "attached.f2");
    QVERIFY(parsed.ok());
    const SceneDesc& scene = *parsed.scene;
    // Without a view: the camera's own key pose, in the cart's frame.
    const Pose own = cameraKeyPose(scene, 5, std::nullopt);
    QCOMPARE(own, (Pose{{0, 50, -100}, {10, 0, 0}}));
    // With a view: the key that, riding on the cart at frame 5, puts the eye there.
    const Pose view{{20, 30, -40}, {15, -30, 0}};
    const Pose key = cameraKeyPose(scene, 5, view);
    const Transform world =
        worldFromRef(scene, *scene.camera.attachedTo, 5) * Transform::fromPose(key.position, key.rotation);
    QVERIFY(length(world.translation - view.position) < 1e-3f);
    const Mat3 wanted = rotationFromEulerDegrees(view.rotation);
    for (int r = 0; r < 3; ++r) QVERIFY(length(world.linear.row[r] - wanted.row[r]) < 1e-5f);
    // The cart turned 45 degrees by frame 5: the key's rotation differs from the view's.
    QVERIFY(std::fabs(key.rotation.y - (view.rotation.y - 45)) < 1e-3f);
}

namespace {

/// The middle of the text `token` (its first occurrence) in the editor's viewport.
QPoint pointOf(SceneEditor* editor, const QString& token) {
    QTextCursor cursor(editor->document());
    cursor.setPosition(int(editor->toPlainText().indexOf(token)) + 1);
    return editor->cursorRect(cursor).center();
}

}  // namespace

void EditorTest::ctrlDragScrubsANumber() {
    QTemporaryDir dir;
    auto w = windowOn(smallSceneFile(dir), 0);
    QVERIFY(w);
    SceneEditor* editor = w->editor();
    const QString original = editor->toPlainText();
    const QPoint radius = pointOf(editor, "1.5 -3");
    constexpr int step = NumberScrubber::kPixelsPerStep;

    // Esc during the drag: the number as it was.
    QTest::mousePress(editor->viewport(), Qt::LeftButton, Qt::ControlModifier, radius);
    QTest::mouseMove(editor->viewport(), radius + QPoint(3 * step + 1, 0));
    QCOMPARE(editor->toPlainText(), QString(original).replace("ball 1.5 -3", "ball 1.8 -3"));
    QTest::keyClick(editor, Qt::Key_Escape);
    QTest::mouseRelease(editor->viewport(), Qt::LeftButton, Qt::ControlModifier,
                        radius + QPoint(3 * step + 1, 0));
    QCOMPARE(editor->toPlainText(), original);
    editor->undo();
    QCOMPARE(editor->toPlainText(), original);

    // 5 steps of 0.1: only that number changes, the picture follows, one undo step.
    QTest::mousePress(editor->viewport(), Qt::LeftButton, Qt::ControlModifier, radius);
    for (int i = 1; i <= 5; ++i) QTest::mouseMove(editor->viewport(), radius + QPoint(i * step + 1, 0));
    QTest::mouseRelease(editor->viewport(), Qt::LeftButton, Qt::ControlModifier,
                        radius + QPoint(5 * step + 1, 0));
    const QString scrubbed = QString(original).replace("ball 1.5 -3", "ball 2.0 -3");
    QCOMPARE(editor->toPlainText(), scrubbed);
    QTRY_COMPARE_WITH_TIMEOUT(w->document()->scene()->objects[1].size.x, 2.0f, kWaitMs);
    editor->undo();
    QCOMPARE(editor->toPlainText(), original);  // byte-identical
    editor->redo();
    QCOMPARE(editor->toPlainText(), scrubbed);

    // A plain click with Ctrl on a word is no scrub.
    QTest::mouseClick(editor->viewport(), Qt::LeftButton, Qt::ControlModifier, pointOf(editor, "ball 2.0"));
    QCOMPARE(editor->toPlainText(), scrubbed);
}

void EditorTest::altWheelScrubsANumber() {
    QTemporaryDir dir;
    auto w = windowOn(smallSceneFile(dir), 0);
    QVERIFY(w);
    SceneEditor* editor = w->editor();
    const QString original = editor->toPlainText();
    const QPoint at = pointOf(editor, "40 1 40");
    auto turn = [&](int notches) {
        QWheelEvent wheel(at, editor->viewport()->mapToGlobal(at), {}, {0, 120 * notches}, Qt::NoButton,
                          Qt::AltModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(editor->viewport(), &wheel);
    };
    // Three turns up and one down on `40` (steps of 1): one undo step.
    turn(1);
    turn(1);
    turn(1);
    turn(-1);
    QCOMPARE(editor->toPlainText(), QString(original).replace("floor 40 1 40", "floor 42 1 40"));
    editor->undo();
    QCOMPARE(editor->toPlainText(), original);
}

QTEST_MAIN(EditorTest)
#include "editor_test.moc"
