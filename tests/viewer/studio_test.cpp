// QtTest suite of frictions a new user met in the studio (docs/robustness.md,
// "Studio frictions, round 3"), on the offscreen platform: the camera's first
// key keeps the shot's start, the Problems dock leaves the picture's size alone,
// a pick in an included file selects its /include line, and a large scene opens
// off the GUI thread.
#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QLabel>
#include <QMenu>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <cstdlib>

#include "core/render/camera.h"
#include "dope_sheet.h"
#include "editor_dock.h"
#include "main_window.h"
#include "playback.h"
#include "problems_dock.h"
#include "scene_document.h"
#include "scene_editor.h"
#include "test_support.h"
#include "viewer_options.h"
#include "viewport_widget.h"

using namespace f2;
using namespace f2::viewer;
using namespace f2::viewer::test;

namespace {

/// A ball moving over frames 0..40, seen by a /camera without keys.
constexpr const char* kLongShot = R"(/camera 96 72 0.6 0 1 -10 5 0 0
/background 20 30 40
/amb_light 0.3
/dir_light 0.8 0.3 -0.5 1
/sphere ball 1.5 -3 0 8
/key 0 ball
/key 40 ball 3 0 8 0 0 0
)";

/// Drags in the picture from its centre by `delta` (an orbit).
void orbitBy(MainWindow& w, QPoint delta) {
    const QPoint centre = w.viewport()->rect().center();
    QTest::mousePress(w.viewport(), Qt::LeftButton, {}, centre);
    QTest::mouseMove(w.viewport(), centre + delta);
    QTest::mouseRelease(w.viewport(), Qt::LeftButton, {}, centre + delta);
}

bool sameView(const Camera& a, const Camera& b) {
    for (int r = 0; r < 3; ++r)
        if (length(a.worldFromCamera.row[r] - b.worldFromCamera.row[r]) > 1e-5f) return false;
    return length(a.eye - b.eye) < 1e-5f;
}

}  // namespace

class StudioTest : public QObject {
    Q_OBJECT
   private slots:
    void initTestCase();
    void firstCameraKeyKeepsTheShotsStart();
    void problemsDockKeepsThePictureSize();
    void pickInAnIncludedFileSelectsItsInclude();
    void aFileBrokenFromTheStartKeepsThePictureSize();
    void dopeSheetDragMovesThatKeysTime();
    void dopeSheetCopiesDeletesAndSetsModes();
};

void StudioTest::initTestCase() {
    QCoreApplication::setOrganizationName("F2StageTest");
    QCoreApplication::setApplicationName("f2-viewer-studio-test");
}

void StudioTest::firstCameraKeyKeepsTheShotsStart() {
    QTemporaryDir dir;
    const QString path = dir.filePath("shot.f2");
    writeFile(path, kLongShot);
    auto window = windowOn(path, 30);
    QVERIFY(window);
    MainWindow& w = *window;
    const QString original = w.editor()->toPlainText();
    const Camera start = cameraAt(*w.document()->scene(), 0);

    // Frame 30, orbit to a new shot, key it: the camera's first key.
    orbitBy(w, {-25, 12});
    QVERIFY(w.viewport()->isOrbiting());
    const Pose view = w.viewport()->orbit()->pose();
    w.keyCameraHere();
    QTextDocument* doc = w.editor()->document();
    QCOMPARE(doc->findBlockByNumber(1).text(), QStringLiteral("/key 0 camera 0 1 -10 5 0 0"));
    QVERIFY2(doc->findBlockByNumber(2).text().startsWith("/key 30 camera "),
             qPrintable(doc->findBlockByNumber(2).text()));
    QCOMPARE(doc->blockCount(), original.count('\n') + 3);
    QCOMPARE(w.editor()->textCursor().selectedText(), doc->findBlockByNumber(2).text());
    QVERIFY2(w.statusBar()->currentMessage().contains("/key 0 camera"),
             qPrintable(w.statusBar()->currentMessage()));

    // Parsed: frame 0 is still the old shot, frame 30 the new one.
    QTRY_VERIFY_WITH_TIMEOUT(w.document()->scene()->camera.track.keys.size() == 2, kWaitMs);
    QVERIFY(sameView(cameraAt(*w.document()->scene(), 0), start));
    QVERIFY(length(cameraAt(*w.document()->scene(), 30).eye - view.position) < 0.02f);
    QVERIFY(!sameView(cameraAt(*w.document()->scene(), 30), start));

    // One undo removes both lines.
    w.editor()->undo();
    QCOMPARE(w.editor()->toPlainText(), original);

    // A first key at frame 0 needs no second one.
    w.playback()->seek(0);
    w.keyCameraHere();
    QCOMPARE(doc->blockCount(), original.count('\n') + 2);
    w.editor()->undo();
    QCOMPARE(w.editor()->toPlainText(), original);
}

void StudioTest::problemsDockKeepsThePictureSize() {
    QTemporaryDir dir;
    const QString path = smallSceneFile(dir);
    auto window = windowOn(path, 0);
    QVERIFY(window);
    MainWindow& w = *window;
    w.resizeForViewport({320, 240});
    QVERIFY(waitForShownFrame(w, 0));  // laid out at that size
    const QSize picture = w.viewport()->size();
    QVERIFY(!w.diagnosticsDock()->isVisible());

    // An error opens the dock; the picture keeps its size (the window grows).
    const QByteArray broken = QByteArray(kSmallScene).replace("/amb_light 0.3", "/amb_lite 0.3");
    writeFile(path, broken);
    QTRY_VERIFY_WITH_TIMEOUT(w.document()->hasErrors(), kWaitMs);
    QVERIFY(w.diagnosticsDock()->isVisible());
    QVERIFY(w.diagnosticsDock()->openedItself());
    QTRY_COMPARE_WITH_TIMEOUT(w.viewport()->size(), picture, kWaitMs);
    QVERIFY(w.diagnosticsDock()->height() >= ProblemsDock::kHeight / 2);
    QVERIFY2(problemsText(w).contains(":3:1: error:"), qPrintable(problemsText(w)));
    if (const QByteArray shot = qgetenv("F2_STUDIO_SCREENSHOT"); !shot.isEmpty())
        w.grab().save(QString::fromLocal8Bit(shot) + "-error.png");

    // Fixed: it opened itself, so it closes itself, and the window gives the room back.
    writeFile(path, kSmallScene);
    QTRY_VERIFY_WITH_TIMEOUT(!w.document()->hasErrors(), kWaitMs);
    QVERIFY(!w.diagnosticsDock()->isVisible());
    QTRY_COMPARE_WITH_TIMEOUT(w.viewport()->size(), picture, kWaitMs);
    if (const QByteArray shot = qgetenv("F2_STUDIO_SCREENSHOT"); !shot.isEmpty())
        w.grab().save(QString::fromLocal8Bit(shot) + "-fixed.png");

    // Opened by the user (View › Problems), it stays open after the fix, saying so.
    w.diagnosticsDock()->toggleViewAction()->trigger();
    QVERIFY(w.diagnosticsDock()->isVisible());
    QTRY_COMPARE_WITH_TIMEOUT(w.viewport()->size(), picture, kWaitMs);
    writeFile(path, broken);
    QTRY_VERIFY_WITH_TIMEOUT(w.document()->hasErrors(), kWaitMs);
    writeFile(path, kSmallScene);
    QTRY_VERIFY_WITH_TIMEOUT(!w.document()->hasErrors(), kWaitMs);
    QVERIFY(w.diagnosticsDock()->isVisible());
    QCOMPARE(problemsText(w), QStringLiteral("No problems."));
    // Closed by the user: the picture keeps its size again.
    w.diagnosticsDock()->toggleViewAction()->trigger();
    QVERIFY(!w.diagnosticsDock()->isVisible());
    QTRY_COMPARE_WITH_TIMEOUT(w.viewport()->size(), picture, kWaitMs);
}

void StudioTest::pickInAnIncludedFileSelectsItsInclude() {
    // A cap from parts/cap.f2 (line 3), included at line 7; a post from a file included twice.
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkpath("parts"));
    writeFile(dir.filePath("parts/cap.f2"), "# a cap\n\n/sphere cap 1 0 2.5 8\n");
    writeFile(dir.filePath("parts/post.f2"), "/box post{k} 1 1 1 (k - 3) -1.5 8\n");
    const QByteArray text =
        "/camera 96 72 0.6 0 0 -10\n/background 20 30 40\n/amb_light 0.3\n/dir_light 0.8 0.3 -0.5 1\n"
        "/let k 0\n/include parts/post.f2\n/include parts/cap.f2\n/let k 6\n/include parts/post.f2\n";
    writeFile(dir.filePath("main.f2"), text);
    auto window = windowOn(dir.filePath("main.f2"), 0);
    QVERIFY(window);
    MainWindow& w = *window;
    w.setRenderScale(RenderScale::SceneSize);
    QVERIFY(waitForShownFrame(w, 0));
    auto clickAt = [&](Vec3 world) { QVERIFY(clickWorldPoint(w, world)); };

    // The cap: its /include line is selected, the status bar names the file and line.
    clickAt({0, 2.5f, 8});
    QVERIFY(w.selection());
    QCOMPARE(w.selection()->target(), QStringLiteral("cap"));
    QCOMPARE(w.editor()->textCursor().selectedText(), QStringLiteral("/include parts/cap.f2"));
    QCOMPARE(w.editor()->textCursor().blockNumber(), 6);
    const QString message = w.statusBar()->currentMessage();
    QCOMPARE(message, QStringLiteral("cap made in parts/cap.f2:3 (included at line 7)"));

    // Shown whole: the readouts left of it make room, and it is the tooltip too.
    QCOMPARE(w.statusBar()->toolTip(), message);
    QCoreApplication::processEvents();
    int readouts = w.statusBar()->width();
    for (QLabel* label : w.statusBar()->findChildren<QLabel*>(Qt::FindDirectChildrenOnly))
        if (label->isVisible()) readouts = std::min(readouts, label->x());
    if (const QByteArray shot = qgetenv("F2_STUDIO_SCREENSHOT"); !shot.isEmpty())
        w.grab().save(QString::fromLocal8Bit(shot) + "-pick.png");
    QVERIFY2(w.statusBar()->fontMetrics().horizontalAdvance(message) < readouts,
             qPrintable(QStringLiteral("message %1 px, readouts from x = %2")
                            .arg(w.statusBar()->fontMetrics().horizontalAdvance(message))
                            .arg(readouts)));

    // The second of two includes of one file: the post it made selects that line.
    clickAt({3, -1.5f, 8});
    QVERIFY(w.selection());
    QCOMPARE(w.selection()->target(), QStringLiteral("post6"));
    QCOMPARE(w.editor()->textCursor().blockNumber(), 8);
    QCOMPARE(w.statusBar()->currentMessage(),
             QStringLiteral("post6 made in parts/post.f2:1 (included at line 9)"));
    clickAt({-3, -1.5f, 8});
    QCOMPARE(w.selection()->target(), QStringLiteral("post0"));
    QCOMPARE(w.editor()->textCursor().blockNumber(), 5);
}

QTEST_MAIN(StudioTest)
void StudioTest::aFileBrokenFromTheStartKeepsThePictureSize() {
    // `f2-viewer FILE --size 320x240`: the same picture for a good file and
    // for one whose errors open the Problems dock before the window is shown.
    QTemporaryDir dir;
    const QString good = smallSceneFile(dir);
    const QString broken = dir.filePath("broken.f2");
    writeFile(broken, QByteArray(kSmallScene).replace("/amb_light 0.3", "/amb_lite 0.3"));
    ViewerOptions options;
    options.viewportSize = {320, 240};
    options.frame = 0;
    auto pictureFor = [&](MainWindow& w, const QString& scene) {
        options.scene = scene;
        applyViewerOptions(options, w);
        return QTest::qWaitForWindowExposed(&w);
    };
    MainWindow reference;
    QVERIFY(pictureFor(reference, good));
    QVERIFY(waitForShownFrame(reference, 0));
    QVERIFY(!reference.diagnosticsDock()->isVisible());
    MainWindow w;
    QVERIFY(pictureFor(w, broken));
    QVERIFY(w.diagnosticsDock()->isVisible());
    // The height is what the dock took (240 against 124 before); the width
    // may differ by a few pixels as the docks settle their minimum widths.
    QTRY_COMPARE_WITH_TIMEOUT(w.viewport()->height(), reference.viewport()->height(), kWaitMs);
    QVERIFY(std::abs(w.viewport()->width() - reference.viewport()->width()) <= 16);
}

namespace {

/// The ball keyed at 0, 40 and 80, and a sphere no key reaches.
constexpr const char* kKeyedBall = R"(/camera 96 72 0.6 0 1 -10
/amb_light 0.3
/dir_light 0.8 0.3 -0.5 1
/sphere ball 1.5 -3 0 8
/key 0 ball
/key 40  ball 0 1 8 0 0 0   # the top
/key 80 ball 3 0 8 0 0 0
)";

/// The dope sheet of `w` with the rows of `object` shown, its slider wide
/// enough for a frame per pixel or two.
/// A window on kKeyedBall (as keys.f2 in `dir`) at frame 0.
std::unique_ptr<MainWindow> keyedBallWindow(const QTemporaryDir& dir) {
    const QString path = dir.filePath("keys.f2");
    writeFile(path, kKeyedBall);
    return windowOn(path, 0);
}

DopeSheet* dopeSheetOf(MainWindow& w, const std::string& object) {
    w.resize(900, w.height());
    if (!QTest::qWaitFor([&] { return w.width() == 900; }, kWaitMs)) return nullptr;
    w.session()->setSelection(Selection{object, std::nullopt, {}});
    auto* sheet = w.findChild<DopeSheet*>();
    return sheet && !sheet->rows().empty() && sheet->rows()[0].target == QString::fromStdString(object)
               ? sheet
               : nullptr;
}

/// An x where the dope sheet draws `frame` (the middle of the pixels that show it).
int xOfFrame(const DopeSheet& sheet, int frame) {
    int first = -1, last = -1;
    for (int x = 0; x < sheet.width(); ++x) {
        if (sheet.frameAt(x) != frame) continue;
        if (first < 0) first = x;
        last = x;
    }
    return (first + last) / 2;
}

/// Waits until the dope sheet shows the keys of the editor's text (parsed, a
/// frame shown since): its rows' lines are that text's.
bool rowsFollowTheText(MainWindow& w) {
    return QTest::qWaitFor(
        [&] {
            const QString text = w.editor()->toPlainText();
            return w.document()->text() == text && !w.document()->isParsing() &&
                   w.session()->dopeSheetText() == text;
        },
        kWaitMs);
}

void drag(DopeSheet* sheet, QPoint from, QPoint to, Qt::KeyboardModifiers modifiers = {}) {
    QTest::mousePress(sheet, Qt::LeftButton, modifiers, from);
    QTest::mouseMove(sheet, (from + to) / 2);
    QTest::mouseMove(sheet, to);
    QTest::mouseRelease(sheet, Qt::LeftButton, modifiers, to);
}

}  // namespace

void StudioTest::dopeSheetDragMovesThatKeysTime() {
    QTemporaryDir dir;
    auto window = keyedBallWindow(dir);
    QVERIFY(window);
    MainWindow& w = *window;
    const QString original = w.editor()->toPlainText();
    DopeSheet* sheet = dopeSheetOf(w, "ball");
    QVERIFY(sheet);
    QCOMPARE(sheet->rows()[0].keys.size(), std::size_t(3));

    // Esc during a drag: nothing written, nothing to undo.
    const QPoint key40 = sheet->keyPoint(0, 1);
    const QPoint at60(xOfFrame(*sheet, 60), key40.y());
    QTest::mousePress(sheet, Qt::LeftButton, {}, key40);
    QTest::mouseMove(sheet, at60);
    QTest::keyClick(sheet, Qt::Key_Escape);
    QTest::mouseRelease(sheet, Qt::LeftButton, {}, at60);
    QCOMPARE(w.editor()->toPlainText(), original);
    QVERIFY(!w.editor()->document()->isUndoAvailable());

    // 40 → 60: exactly that line's time, spacing and comment kept; one undo step.
    drag(sheet, key40, at60);
    const QString moved = QString(original).replace("/key 40  ball", "/key 60  ball");
    QCOMPARE(w.editor()->toPlainText(), moved);
    QTRY_VERIFY_WITH_TIMEOUT(w.document()->scene()->objects[0].track.keys[1].time == 60, kWaitMs);
    w.editor()->undo();
    QCOMPARE(w.editor()->toPlainText(), original);
    w.editor()->redo();
    QCOMPARE(w.editor()->toPlainText(), moved);

    // Two selected keys move together (Shift+click adds one), in one undo step.
    QVERIFY(rowsFollowTheText(w));
    QCOMPARE(sheet->rows()[0].keys[1].time, 60.0);
    QTest::mouseClick(sheet, Qt::LeftButton, {}, sheet->keyPoint(0, 0));
    QTest::mouseClick(sheet, Qt::LeftButton, Qt::ShiftModifier, sheet->keyPoint(0, 1));
    QCOMPARE(sheet->selectedKeys().size(), std::size_t(2));
    drag(sheet, sheet->keyPoint(0, 1), {xOfFrame(*sheet, 70), sheet->keyPoint(0, 1).y()});
    QCOMPARE(w.editor()->toPlainText(),
             QString(moved).replace("/key 0 ball", "/key 10 ball").replace("/key 60  ball", "/key 70  ball"));
    w.editor()->undo();
    QCOMPARE(w.editor()->toPlainText(), moved);
    w.editor()->undo();
    QCOMPARE(w.editor()->toPlainText(), original);
}

void StudioTest::dopeSheetCopiesDeletesAndSetsModes() {
    QTemporaryDir dir;
    auto window = keyedBallWindow(dir);
    QVERIFY(window);
    MainWindow& w = *window;
    const QString original = w.editor()->toPlainText();
    DopeSheet* sheet = dopeSheetOf(w, "ball");
    QVERIFY(sheet);

    // Alt+drag copies the key at 80 to 20: a line after it, the original stays.
    drag(sheet, sheet->keyPoint(0, 2), {xOfFrame(*sheet, 20), sheet->keyPoint(0, 2).y()}, Qt::AltModifier);
    QCOMPARE(w.editor()->toPlainText(), original + "/key 20 ball 3 0 8 0 0 0\n");
    w.editor()->undo();
    QCOMPARE(w.editor()->toPlainText(), original);
    QVERIFY(rowsFollowTheText(w));

    // Right-click: the mode menu sets the key's mode word, comment kept.
    QTest::mouseClick(sheet, Qt::LeftButton, {}, sheet->keyPoint(0, 1));
    const auto menu = sheet->modeMenu();
    QAction* easeIn = nullptr;
    for (QAction* action : menu->actions())
        if (action->text() == "ease_in") easeIn = action;
    QVERIFY(easeIn && easeIn->isEnabled());
    easeIn->trigger();
    QCOMPARE(w.editor()->toPlainText(),
             QString(original).replace("0 0 0   # the top", "0 0 0 ease_in   # the top"));
    w.editor()->undo();
    QVERIFY(rowsFollowTheText(w));

    // Delete removes the selected key's line.
    QTest::mouseClick(sheet, Qt::LeftButton, {}, sheet->keyPoint(0, 1));
    QTest::keyClick(sheet, Qt::Key_Delete);
    QCOMPARE(w.editor()->toPlainText(),
             QString(original).replace("/key 40  ball 0 1 8 0 0 0   # the top\n", ""));
    w.editor()->undo();
    QCOMPARE(w.editor()->toPlainText(), original);

    // A drag from an empty place selects the keys in its rectangle: 40 and 80, not 0.
    QVERIFY(rowsFollowTheText(w));
    const int y = sheet->keyPoint(0, 0).y();
    drag(sheet, {xOfFrame(*sheet, 30), y - 3}, {sheet->keyPoint(0, 2).x() + 2, y + 3});
    QCOMPARE(sheet->selectedKeys(), (std::vector<std::pair<int, int>>{{0, 1}, {0, 2}}));
    QCOMPARE(w.editor()->toPlainText(), original);
    // A click on the row's name selects its three keys; a click on an empty place none.
    QTest::mouseClick(sheet, Qt::LeftButton, {}, {4, y});
    QCOMPARE(sheet->selectedKeys().size(), std::size_t(3));
    QTest::mouseClick(sheet, Qt::LeftButton, {}, {xOfFrame(*sheet, 60), y});
    QVERIFY(sheet->selectedKeys().empty());
    drag(sheet, {xOfFrame(*sheet, 30), y - 3}, {sheet->keyPoint(0, 2).x() + 2, y + 3});
    QTest::keyClick(sheet, Qt::Key_Delete);
    QCOMPARE(w.editor()->toPlainText(), QString(original).replace(QRegularExpression("/key [48]0 .*\n"), ""));
    w.editor()->undo();
    QCOMPARE(w.editor()->toPlainText(), original);
}

#include "studio_test.moc"
