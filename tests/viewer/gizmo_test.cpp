// QtTest suite of the handles and the motion path over the picture (issue 27):
// the gizmo's geometry against the camera, and in the window, synthetic drags
// of its handles that write `/key` lines (one undo step), Esc, Ctrl snapping,
// a part turned about its pivot and a click on a key's dot.
#include "gizmo.h"

#include <QFile>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <cmath>

#include "capture_pose.h"
#include "core/anim/frame_builder.h"
#include "core/parse/parser.h"
#include "core/render/pick.h"
#include "gizmo_tool.h"
#include "key_target.h"
#include "main_window.h"
#include "playback.h"
#include "scene_document.h"
#include "scene_editor.h"
#include "studio_session.h"
#include "test_support.h"
#include "viewport_widget.h"

using namespace f2;
using namespace f2::viewer;
using namespace f2::viewer::test;

namespace {

/// A window on `text` (written as scene.f2 in `dir`) with a 480x360 picture,
/// paused at frame `t` with that frame on screen.
std::unique_ptr<MainWindow> bigWindowOn(const QTemporaryDir& dir, const char* text, double t) {
    const QString path = dir.filePath("scene.f2");
    writeFile(path, text);
    auto w = std::make_unique<MainWindow>();
    w->resizeForViewport({480, 360});
    w->show();
    if (!QTest::qWaitForWindowExposed(w.get())) return nullptr;
    w->openFile(path);
    w->playback()->pause();
    w->playback()->seek(t);
    if (!waitForShownFrame(*w, t)) return nullptr;
    return w;
}

/// Waits until the editor's text has parsed and its frame `t` is on screen
/// (a drag's picture stays until the text it wrote has parsed).
bool settled(MainWindow& w, double t) {
    return QTest::qWaitFor(
               [&] {
                   return w.document()->text() == w.editor()->toPlainText() && !w.document()->isParsing();
               },
               kWaitMs) &&
           waitForShownFrame(w, t);
}

/// A window with an 800x600 picture on a copy of the repository's scene `file`
/// in `dir` (a drag edits it: an autosave copy of the original would be offered
/// to the next test), paused at frame `t` with that frame on screen.
std::unique_ptr<MainWindow> copyOpened(const QTemporaryDir& dir, const char* file, double t) {
    const QString path = dir.filePath("scene.f2");
    if (!QFile::copy(QStringLiteral(F2_SOURCE_DIR "/") + file, path)) return nullptr;
    auto w = std::make_unique<MainWindow>();
    w->resizeForViewport({800, 600});
    w->show();
    if (!QTest::qWaitForWindowExposed(w.get()) || !w->openFile(path)) return nullptr;
    w->playback()->pause();
    w->playback()->seek(t);
    return settled(*w, t) ? std::move(w) : nullptr;
}

/// Widget position of display point `p` (a Gizmo's pixels).
QPoint onScreen(MainWindow& w, QPointF p) { return (w.viewport()->imageRect().topLeft() + p).toPoint(); }

/// The handles once the window shows `target` selected (a click at world point `at`).
std::optional<Gizmo> select(MainWindow& w, Vec3 at, const QString& target) {
    if (!clickWorldPoint(w, at) || !w.selection() || w.selection()->target() != target) return std::nullopt;
    return w.gizmoTool()->gizmo();
}

/// Where the ray through display point `p` crosses the plane z = `z`.
Vec3 onPlaneZ(const Camera& camera, QPointF p, float z) {
    const Ray ray = camera.rayThrough(float(p.x()), float(p.y()));
    return ray.origin + ray.direction * ((z - ray.origin.z) / ray.direction.z);
}

/// The numbers of the `/key` line of `target` at `frame` in `text`, if there is one.
std::optional<QStringList> keyNumbers(const QString& text, const QString& target, int frame) {
    const QString head = QStringLiteral("/key %1 %2").arg(frame).arg(target);
    for (const QString& line : text.split('\n'))
        if (line == head || line.startsWith(head + ' '))
            return line.mid(head.size()).split(' ', Qt::SkipEmptyParts);
    return std::nullopt;
}

}  // namespace

class GizmoTest : public QObject {
    Q_OBJECT
   private slots:
    void initTestCase();
    void handlesFollowTheCamera();
    void anAttachedTargetMovesInItsMountsAxes();
    void draggingTheXHandleWritesTheKey();
    void ctrlSnapsAndEscCancels();
    void undoAndRedoTheDrag();
    void partTurnsAboutItsPivot();
    void clickingAPathDotJumpsToItsFrame();
    void aTargetWithoutKeysOrMadeInALoop();
    void dragOfARobotsArm();
    void dragOfABallInFlight();
    void aLightAndTheCameraByTheirMarkers();
};

void GizmoTest::initTestCase() {
    QCoreApplication::setOrganizationName("F2StageTest");
    QCoreApplication::setApplicationName("f2-viewer-gizmo-test");
}

void GizmoTest::handlesFollowTheCamera() {
    // The eye at the origin looking along +z; the target 20 ahead, unrotated.
    const Camera camera{400, 300, 0.5f, {0, 0, 0}, Mat3{}};
    GizmoFrame frame;
    frame.pose = {{0, 0, 20}, {}};
    const Gizmo move(camera, frame, GizmoMode::Move, false);
    QVERIFY(move.visible());
    QCOMPARE(move.centre(), QPointF(200, 150));
    // 20 / (0.5 · 400): a tenth of a unit per pixel; the x arrow points right, y up.
    QCOMPARE(move.unitsPerPixel(), 0.1);
    QVERIFY(std::fabs(move.arrowEnd(0).x() - 200 - move.armPixels()) < 0.01);
    QVERIFY(std::fabs(move.arrowEnd(1).y() - 150 + move.armPixels()) < 0.01);
    QCOMPARE(move.hit({200 + 30, 151}), std::optional(GizmoHandle::X));
    QCOMPARE(move.hit({199, 150 - 40}), std::optional(GizmoHandle::Y));
    QCOMPARE(move.hit({201, 149}), std::optional(GizmoHandle::Screen));
    QVERIFY(!move.hit({300, 250}));  // the z arrow points at the eye: no handle

    // 50 pixels along x: 5 units; the other numbers stay as they were.
    GizmoDrag drag(move, GizmoHandle::X, {230, 150});
    const Pose moved = drag.update({280, 150}, false);
    QVERIFY(std::fabs(moved.position.x - 5) < 1e-3);
    QCOMPARE(moved.position.y, 0.0f);
    QCOMPARE(moved.position.z, 20.0f);
    QCOMPARE(drag.update({284, 150}, true).position.x, 10.0f);  // 5.4 snaps to 10

    // The z ring: from its upper right to its upper left is a quarter turn, +x toward +y.
    const Gizmo turn(camera, frame, GizmoMode::Turn, false);
    const double r = turn.armPixels() / std::sqrt(2.0);
    QCOMPARE(turn.hit({200 + r, 150 - r}), std::optional(GizmoHandle::Z));
    GizmoDrag turning(turn, GizmoHandle::Z, {200 + r, 150 - r});
    turning.update({200, 150 - r * 1.4}, false);
    QVERIFY(std::fabs(turning.update({200 - r, 150 - r}, false).rotation.z - 90) < 1e-3);

    // A light's handles are at its written position: a turn is about that point, so
    // the pose's origin swings round it (and the light stays where it is).
    GizmoFrame light;
    light.pose = {{0, 0, 20}, {}};
    light.handle = {10, 0, 0};
    const Gizmo lightTurn(camera, light, GizmoMode::Turn, false);
    QCOMPARE(lightTurn.centre(), QPointF(300, 150));  // 10 units at a tenth of a unit per pixel
    GizmoDrag swing(lightTurn, GizmoHandle::Z, lightTurn.centre() + QPointF(r, -r));
    const Pose swung = swing.update(lightTurn.centre() + QPointF(-r, -r), false);
    QVERIFY(length(swung.position - Vec3{10, -10, 20}) < 1e-3f);
    QCOMPARE(swung.rotation, (Vec3{0, 0, 90}));

    // Its own axes (L): turned 90 degrees about z, its x is the world's y; a move
    // along it changes the key's y, a turn about it adds to rx alone.
    GizmoFrame turned;
    turned.pose = {{0, 0, 20}, {0, 0, 90}};
    const Gizmo local(camera, turned, GizmoMode::Move, true);
    QVERIFY(length(local.axis(0) - Vec3{0, 1, 0}) < 1e-5f);
    GizmoDrag along(local, GizmoHandle::X, {200, 150 - 20});
    const Pose up = along.update({200, 150 - 40}, false);
    QVERIFY(std::fabs(up.position.y - 2) < 0.02);
    QCOMPARE(up.position.x, 0.0f);
    const Gizmo localTurn(camera, turned, GizmoMode::Turn, true);
    // Its x ring (about the world's y) is edge on; from a point of it to the one across the centre is half a
    // turn.
    const QPointF onRing = localTurn.ring(0)[6];
    GizmoDrag spin(localTurn, GizmoHandle::X, onRing);
    const Pose spun = spin.update(QPointF(200, 150) + (QPointF(200, 150) - onRing), false);
    QCOMPARE(spun.rotation.y, 0.0f);
    QCOMPARE(spun.rotation.z, 90.0f);
    QVERIFY(std::fabs(std::fabs(spun.rotation.x) - 180) < 0.02);

    // A turn about another axis writes the nearest of the equal angle triples.
    const Mat3 m = rotationFromEulerDegrees(Vec3{170, 10, -20});
    const Vec3 near = eulerDegreesNear(m, {170, 10, -20});
    QVERIFY(length(near - Vec3{170, 10, -20}) < 1e-3f);
}

void GizmoTest::anAttachedTargetMovesInItsMountsAxes() {
    // A ball riding on a box turned 90 degrees about z: its key is read in the box's
    // frame, whose x is the world's y.
    const auto parsed = parseScene(
        "/camera 400 300 0.5\n/box holder 2 2 2 0 0 20 0 0 90\n"
        "/sphere ball 1 3 0 0\n/attach ball holder\n/key 0 ball 3 0 0 0 0 0\n"
        "/key 10 ball 3 0 0 0 0 0\n",
        "t.f2");
    QVERIFY(parsed.ok());
    const SceneDesc& scene = *parsed.scene;
    const Selection ball{"ball", std::nullopt, {}};
    const auto key = targetKeyFrame(scene, ball, 5);
    QVERIFY(key);
    QVERIFY(length(key->centre() - Vec3{0, 3, 20}) < 1e-5f);
    const Camera camera = cameraAt(scene, 5).resized(400, 300);
    const Gizmo g(camera, *key, GizmoMode::Move, false);
    QVERIFY(length(g.axis(0) - Vec3{0, 1, 0}) < 1e-5f);
    // Up the screen along that axis: the key's x grows, nothing else changes.
    GizmoDrag drag(g, GizmoHandle::X, g.centre() + (g.arrowEnd(0) - g.centre()) * 0.5);
    const Pose moved = drag.update(g.centre() + (g.arrowEnd(0) - g.centre()) * 0.5 + QPointF(0, -20), false);
    QVERIFY(moved.position.x > 3.5f);
    QCOMPARE(moved.position.y, 0.0f);
    QCOMPARE(moved.position.z, 0.0f);
    // The preview's scene: the key at 5 goes between the two, and the ball is there in the world.
    const auto preview = sceneWithKey(scene, ball, 5, moved);
    QVERIFY(preview);
    QCOMPARE(int(preview->objects[1].track.keys.size()), 3);
    QCOMPARE(preview->objects[1].track.keys[1].time, 5.0);
    QVERIFY(length(*targetPosition(*preview, ball, 5) - Vec3{0, moved.position.x, 20}) < 1e-4f);
    // At a keyed frame the key is replaced; the original scene is untouched.
    QCOMPARE(int(sceneWithKey(scene, ball, 10, moved)->objects[1].track.keys.size()), 2);
    QCOMPARE(scene.objects[1].track.keys.size(), std::size_t(2));
}

void GizmoTest::draggingTheXHandleWritesTheKey() {
    QTemporaryDir dir;
    auto w = bigWindowOn(dir, kSmallScene, 0);
    QVERIFY(w);
    // The ball at frame 0 is at (-3, 0, 8); its x arrow points right.
    const auto g = select(*w, {-3, 0, 8}, "ball");
    QVERIFY(g);
    const QPointF from = g->centre() + (g->arrowEnd(0) - g->centre()) * 0.6;
    QCOMPARE(g->hit(from), std::optional(GizmoHandle::X));
    const QPointF to = from + QPointF(40, 3);  // a hand is never quite straight
    // Over the arrow the cursor says it can be taken; off it, the picture's open hand.
    QTest::mouseMove(w->viewport(), onScreen(*w, from));
    QCOMPARE(w->viewport()->cursor().shape(), Qt::PointingHandCursor);
    QTest::mouseMove(w->viewport(), onScreen(*w, from + QPointF(0, 30)));
    QCOMPARE(w->viewport()->cursor().shape(), Qt::OpenHandCursor);
    QTest::mousePress(w->viewport(), Qt::LeftButton, {}, onScreen(*w, from));
    QTest::mouseMove(w->viewport(), onScreen(*w, from + QPointF(20, 1)));
    QTest::mouseMove(w->viewport(), onScreen(*w, to));
    QVERIFY(w->session()->isDragging());
    // The picture follows at a quarter of the size while the text stays.
    const QSize full = w->viewport()->renderSize();
    QTRY_VERIFY_WITH_TIMEOUT(w->shownFrame().size == QSize(full.width() / 4, full.height() / 4), kWaitMs);
    QCOMPARE(w->editor()->toPlainText(), QString(kSmallScene));
    QTest::mouseRelease(w->viewport(), Qt::LeftButton, {}, onScreen(*w, to));
    QVERIFY(!w->session()->isDragging());

    // The x the camera gives for 40 pixels at the ball's depth, within a pixel's worth.
    const Camera camera = w->viewport()->displayCamera();
    const double expected = -3 + (onPlaneZ(camera, to, 8).x - onPlaneZ(camera, from, 8).x);
    const auto numbers = keyNumbers(w->editor()->toPlainText(), "ball", 0);
    QVERIFY(numbers);
    QCOMPARE(numbers->size(), 6);
    QVERIFY2(std::fabs(numbers->at(0).toDouble() - expected) <= g->unitsPerPixel(),
             qPrintable(numbers->join(' ') + " vs " + QString::number(expected)));
    QCOMPARE(numbers->mid(1), (QStringList{"0", "8", "0", "0", "0"}));
    // The key replaced `/key 0 ball` in place; the picture settles at full size with it.
    QCOMPARE(w->editor()->document()->findBlockByNumber(6).text().left(11), QStringLiteral("/key 0 ball"));
    QVERIFY(settled(*w, 0));
    QCOMPARE(w->shownFrame().size, full);
    expectViewportMatchesCore(*w, 0);
}

void GizmoTest::ctrlSnapsAndEscCancels() {
    QTemporaryDir dir;
    auto w = bigWindowOn(dir, kSmallScene, 0);
    QVERIFY(w);
    const auto g = select(*w, {-3, 0, 8}, "ball");
    QVERIFY(g);
    const QString original = w->editor()->toPlainText();
    const QPointF from = g->centre() + (g->arrowEnd(0) - g->centre()) * 0.6;

    // Esc during the drag: the text byte for byte as it was, the picture of the text again.
    QTest::mousePress(w->viewport(), Qt::LeftButton, {}, onScreen(*w, from));
    QTest::mouseMove(w->viewport(), onScreen(*w, from + QPointF(50, 0)));
    QVERIFY(w->session()->isDragging());
    QTest::keyClick(w->viewport(), Qt::Key_Escape);
    QVERIFY(!w->session()->isDragging());
    QTest::mouseRelease(w->viewport(), Qt::LeftButton, {}, onScreen(*w, from + QPointF(50, 0)));
    QCOMPARE(w->editor()->toPlainText().toUtf8(), original.toUtf8());
    QVERIFY(!w->editor()->document()->isUndoAvailable());
    QVERIFY(settled(*w, 0));
    expectViewportMatchesCore(*w, 0);

    // Ctrl held at the release: x is the multiple of 10 nearest where the mouse has it.
    for (const double pixels : {40.0, 250.0}) {
        QTest::mousePress(w->viewport(), Qt::LeftButton, {}, onScreen(*w, from));
        QTest::mouseMove(w->viewport(), onScreen(*w, from + QPointF(pixels, 0)));
        QTest::mouseRelease(w->viewport(), Qt::LeftButton, Qt::ControlModifier,
                            onScreen(*w, from + QPointF(pixels, 0)));
        const auto numbers = keyNumbers(w->editor()->toPlainText(), "ball", 0);
        QVERIFY(numbers);
        const double x = numbers->at(0).toDouble();
        QCOMPARE(std::fmod(x, 10.0), 0.0);
        QCOMPARE(x, std::round((-3 + pixels * g->unitsPerPixel()) / 10) * 10);
        w->editor()->undo();
        QCOMPARE(w->editor()->toPlainText(), original);
        QVERIFY(settled(*w, 0));
    }
}

void GizmoTest::undoAndRedoTheDrag() {
    QTemporaryDir dir;
    auto w = bigWindowOn(dir, kSmallScene, 5);
    QVERIFY(w);
    // At frame 5 the ball is halfway, at (0, 0, 8); frame 5 has no key: one is added.
    const auto g = select(*w, {0, 0, 8}, "ball");
    QVERIFY(g);
    const QString original = w->editor()->toPlainText();
    // The screen-plane square moves it in x and y at once.
    QCOMPARE(g->hit(g->centre()), std::optional(GizmoHandle::Screen));
    QTest::mousePress(w->viewport(), Qt::LeftButton, {}, onScreen(*w, g->centre()));
    QTest::mouseMove(w->viewport(), onScreen(*w, g->centre() + QPointF(30, -30)));
    QTest::mouseRelease(w->viewport(), Qt::LeftButton, {}, onScreen(*w, g->centre() + QPointF(30, -30)));
    const QString edited = w->editor()->toPlainText();
    QCOMPARE(edited.count('\n'), original.count('\n') + 1);
    const auto numbers = keyNumbers(edited, "ball", 5);
    QVERIFY(numbers);
    QVERIFY(numbers->at(0).toDouble() > 1 && numbers->at(1).toDouble() > 1);  // right and up
    QCOMPARE(numbers->at(2), QStringLiteral("8"));

    // One undo step: undo gives the text back byte for byte, redo the key again.
    w->editor()->undo();
    QCOMPARE(w->editor()->toPlainText().toUtf8(), original.toUtf8());
    QVERIFY(!w->editor()->document()->isUndoAvailable());
    w->editor()->redo();
    QCOMPARE(w->editor()->toPlainText().toUtf8(), edited.toUtf8());
    QVERIFY(settled(*w, 5));
    expectViewportMatchesCore(*w, 5);
}

void GizmoTest::partTurnsAboutItsPivot() {
    QTemporaryDir dir;
    auto w = bigWindowOn(dir, kLampScene, 0);
    QVERIFY(w);
    // l1.arm at frame 0: the pivot (0, 2, 0) on the base at (0, -2, 8), rest rz 30, the
    // bulb 2 up the arm: (0, 0, 8) + Rz(30)·(0, 2, 0).
    const Vec3 pivot{0, 0, 8};
    const auto bulbAt = [&](double degrees) {
        const double a = degrees * kPi / 180;
        return pivot + Vec3{float(-2 * std::sin(a)), float(2 * std::cos(a)), 0};
    };
    QVERIFY(select(*w, bulbAt(30), "l1.arm"));
    QTest::keyClick(w->viewport(), Qt::Key_E);
    QCOMPARE(w->gizmoTool()->mode(), GizmoMode::Turn);
    const auto g = w->gizmoTool()->gizmo();
    QVERIFY(g);
    // The handles are at the pivot, not at the bulb.
    float px = 0, py = 0;
    QVERIFY(g->camera().project(pivot, px, py));
    QVERIFY(std::hypot(g->centre().x() - px, g->centre().y() - py) < 0.5);

    // The z ring from its upper right to its upper left, Ctrl held: +90 degrees.
    const double r = g->armPixels() / std::sqrt(2.0);
    const QPointF from = g->centre() + QPointF(r, -r);
    QCOMPARE(g->hit(from), std::optional(GizmoHandle::Z));
    QTest::mousePress(w->viewport(), Qt::LeftButton, {}, onScreen(*w, from));
    QTest::mouseMove(w->viewport(), onScreen(*w, g->centre() + QPointF(0, -r * 1.4)));
    QTest::mouseMove(w->viewport(), onScreen(*w, g->centre() + QPointF(-r + 2, -r - 1)));
    QTest::mouseRelease(w->viewport(), Qt::LeftButton, Qt::ControlModifier,
                        onScreen(*w, g->centre() + QPointF(-r + 2, -r - 1)));
    const auto numbers = keyNumbers(w->editor()->toPlainText(), "l1.arm", 0);
    QVERIFY(numbers);
    QCOMPARE(*numbers, (QStringList{"0", "0", "0", "0", "0", "90"}));

    // The edited scene's bulb: the part frame's formula, turned 30 + 90 about the pivot.
    QTRY_VERIFY_WITH_TIMEOUT(w->document()->scene()->objects[0].partTracks[1].keys[0].pose.rotation.z == 90,
                             kWaitMs);
    const SceneDesc& scene = *w->document()->scene();
    EvaluatedFrame frame;
    evaluateFrame(scene, 0, frame);
    const Bounds bounds = selectionBounds(scene, frame, 0, 1);
    const Vec3 centre = (bounds.lo + bounds.hi) * 0.5f;
    QVERIFY2(
        length(centre - bulbAt(120)) < 1e-3f,
        qPrintable(
            QStringLiteral("%1 %2 %3").arg(double(centre.x)).arg(double(centre.y)).arg(double(centre.z))));
    // The gizmo frame of the session names the same pivot, and the key's turn.
    const auto key = w->session()->selectionKeyFrame();
    QVERIFY(key);
    QVERIFY(length(key->world().translation - pivot) < 1e-4f);
    QCOMPARE(key->pose.rotation.z, 90.0f);
}

void GizmoTest::clickingAPathDotJumpsToItsFrame() {
    QTemporaryDir dir;
    auto w = bigWindowOn(dir, kSmallScene, 0);
    QVERIFY(w);
    QVERIFY(select(*w, {-3, 0, 8}, "ball"));
    const auto& path = w->session()->motionPath();
    QVERIFY(path);
    QCOMPARE(int(path->points.size()), 11);  // frames 0..10
    QCOMPARE(int(path->keys.size()), 2);
    QVERIFY(length(path->keys[1].at - Vec3{3, 0, 8}) < 1e-4f);
    const auto dots = w->gizmoTool()->pathDots();
    QCOMPARE(int(dots.size()), 2);
    QCOMPARE(dots[1].second, 10);
    // A click on the dot of the key at frame 10 jumps there; the text is untouched.
    QTest::mouseClick(w->viewport(), Qt::LeftButton, {}, dots[1].first.toPoint());
    QCOMPARE(w->playback()->frame(), 10);
    QVERIFY(!w->editor()->document()->isUndoAvailable());
    QVERIFY(settled(*w, 10));
    QCOMPARE(w->selection()->target(), QStringLiteral("ball"));
}

void GizmoTest::aTargetWithoutKeysOrMadeInALoop() {
    QTemporaryDir dir;
    const QByteArray text = QByteArray(kSmallScene) + "/repeat i 1 2\n/sphere b{i} 1 (i * 3 - 6) 3 8\n/end\n";
    auto w = bigWindowOn(dir, text.constData(), 0);
    QVERIFY(w);
    const QString original = w->editor()->toPlainText();

    // The floor has no keys: a drag changes its creating command's numbers.
    auto g = select(*w, {5, -1.5f, 2}, "floor");
    QVERIFY(g);
    QPointF from = g->centre() + (g->arrowEnd(1) - g->centre()) * 0.6;  // the y arrow
    QCOMPARE(g->hit(from), std::optional(GizmoHandle::Y));
    QTest::mousePress(w->viewport(), Qt::LeftButton, {}, onScreen(*w, from));
    QTest::mouseMove(w->viewport(), onScreen(*w, from + QPointF(0, -60)));
    QTest::mouseRelease(w->viewport(), Qt::LeftButton, Qt::ControlModifier,
                        onScreen(*w, from + QPointF(0, -60)));
    const QString floorLine = w->editor()->document()->findBlockByNumber(4).text();
    QVERIFY2(floorLine.startsWith(QStringLiteral("/box floor 40 1 40 0 ")) && !floorLine.contains(" -2 "),
             qPrintable(floorLine));
    QCOMPARE(w->editor()->toPlainText().count('\n'), original.count('\n'));
    w->editor()->undo();
    QCOMPARE(w->editor()->toPlainText(), original);
    QVERIFY(settled(*w, 0));

    // b1 is made in a loop: refused, with the offer of a key after the loop.
    QString refusal, label;
    bool take = false;
    w->gizmoTool()->setOffer([&](const QString& why, const QString& offer) {
        refusal = why;
        label = offer;
        return take;
    });
    for (const bool accept : {false, true}) {
        take = accept;
        g = select(*w, {-3, 3, 8}, "b1");
        QVERIFY(g);
        from = g->centre() + (g->arrowEnd(0) - g->centre()) * 0.6;
        QTest::mousePress(w->viewport(), Qt::LeftButton, {}, onScreen(*w, from));
        QTest::mouseMove(w->viewport(), onScreen(*w, from + QPointF(30, 0)));
        QTest::mouseRelease(w->viewport(), Qt::LeftButton, {}, onScreen(*w, from + QPointF(30, 0)));
        QVERIFY2(refusal.contains(QStringLiteral("/repeat")), qPrintable(refusal));
        QVERIFY(!label.isEmpty());
        QVERIFY(!w->session()->isDragging());
        if (!accept) {
            QCOMPARE(w->editor()->toPlainText(), original);
            QVERIFY(settled(*w, 0));
            expectViewportMatchesCore(*w, 0);
        } else {
            // The key after the loop's /end: the last line.
            const auto numbers = keyNumbers(w->editor()->toPlainText(), "b1", 0);
            QVERIFY(numbers);
            QVERIFY(w->editor()->toPlainText().trimmed().endsWith(numbers->join(' ')));
        }
    }
}

void GizmoTest::dragOfARobotsArm() {
    // The seed's example at frame 10 in a larger window: F-2's left arm turned about
    // its shoulder, its hand's path over the animation drawn with the key dots.
    QTemporaryDir dir;
    auto w = copyOpened(dir, "scenes/seed_example.f2", 10);
    QVERIFY(w);
    w->setSelection(Selection{"r1", 2, "lhand"});
    QCOMPARE(w->selection()->target(), QStringLiteral("r1.lhand"));
    QTest::keyClick(w->viewport(), Qt::Key_E);
    const auto g = w->gizmoTool()->gizmo();
    QVERIFY(g);
    // A point of the x ring no other handle is near, and round the centre from there.
    std::optional<QPointF> from;
    for (const QPointF& p : g->ring(0))
        if (g->hit(p) == GizmoHandle::X && (!from || p.y() < from->y())) from = p;
    QVERIFY(from);
    const QPointF c = g->centre();
    const QPointF arm = *from - c;
    const auto turnedBy = [&](double degrees) {
        const double a = degrees * kPi / 180;
        return c + QPointF(arm.x() * std::cos(a) - arm.y() * std::sin(a),
                           arm.x() * std::sin(a) + arm.y() * std::cos(a));
    };
    QTest::mousePress(w->viewport(), Qt::LeftButton, {}, onScreen(*w, *from));
    for (const double degrees : {10.0, 20.0, 30.0})
        QTest::mouseMove(w->viewport(), onScreen(*w, turnedBy(degrees)));
    const QSize full = w->viewport()->renderSize();
    QTRY_VERIFY_WITH_TIMEOUT(w->shownFrame().size == QSize(full.width() / 4, full.height() / 4) &&
                                 !w->renderController()->hasPendingFrames(),
                             kWaitMs);
    QTest::mouseRelease(w->viewport(), Qt::LeftButton, {}, onScreen(*w, turnedBy(30)));
    // /key 10 r1.lhand: between its keys at 5 and 15, a new line in time order.
    const auto numbers = keyNumbers(w->editor()->toPlainText(), "r1.lhand", 10);
    QVERIFY(numbers);
    QCOMPARE(numbers->size(), 6);
    QCOMPARE(numbers->mid(0, 3), (QStringList{"0", "0", "0"}));  // a turn moves no pivot
    const QStringList lines = w->editor()->toPlainText().split('\n');
    QCOMPARE(lines.indexOf(QRegularExpression("^/key 10 r1.lhand .*")), lines.indexOf("/key 5 r1.lhand") + 1);
    QVERIFY(settled(*w, 10));
}

void GizmoTest::dragOfABallInFlight() {
    // The gallery's game of catch at frame 24: the ball at the top of its arc,
    // its path over the animation with a dot per key, lifted by its y arrow.
    QTemporaryDir dir;
    auto w = copyOpened(dir, "scenes/gallery/catch.f2", 24);
    QVERIFY(w);
    w->setSelection(Selection{"ball", std::nullopt, {}});
    const auto g = w->gizmoTool()->gizmo();
    QVERIFY(g);
    QVERIFY(w->gizmoTool()->pathDots().size() >= 20);
    const QPointF from = g->centre() + (g->arrowEnd(1) - g->centre()) * 0.7;
    QCOMPARE(g->hit(from), std::optional(GizmoHandle::Y));
    QTest::mousePress(w->viewport(), Qt::LeftButton, {}, onScreen(*w, from));
    QTest::mouseMove(w->viewport(), onScreen(*w, from + QPointF(0, -20)));
    QTest::mouseMove(w->viewport(), onScreen(*w, from + QPointF(1, -45)));
    const QSize full = w->viewport()->renderSize();
    QTRY_VERIFY_WITH_TIMEOUT(w->shownFrame().size == QSize(full.width() / 4, full.height() / 4) &&
                                 !w->renderController()->hasPendingFrames(),
                             kWaitMs);
    // The picture of a drag in progress, for docs/viewer.md.
    if (qEnvironmentVariableIsSet("F2_GIZMO_SCREENSHOT"))
        QVERIFY(w->grab().save(qEnvironmentVariable("F2_GIZMO_SCREENSHOT")));
    QTest::mouseRelease(w->viewport(), Qt::LeftButton, {}, onScreen(*w, from + QPointF(1, -45)));
    // Its key at 24 gets a higher y in place; x and z stay as written.
    const auto numbers = keyNumbers(w->editor()->toPlainText(), "ball", 24);
    QVERIFY(numbers);
    QCOMPARE(numbers->at(0), QStringLiteral("-5"));
    QVERIFY(numbers->at(1).toDouble() > 140);
    QCOMPARE(numbers->at(2), QStringLiteral("285.8"));
    QVERIFY(settled(*w, 24));
}

void GizmoTest::aLightAndTheCameraByTheirMarkers() {
    QTemporaryDir dir;
    const QByteArray text = QByteArray(kSmallScene) + "/point_light 0.5 0 3 8 name bulb\n";
    auto w = bigWindowOn(dir, text.constData(), 0);
    QVERIFY(w);
    // The bulb's marker (the camera's is the eye: not drawn); a click on it selects it.
    auto markers = w->gizmoTool()->markers();
    QCOMPARE(int(markers.size()), 1);
    QCOMPARE(markers[0].second.target(), QStringLiteral("bulb"));
    QTest::mouseClick(w->viewport(), Qt::LeftButton, {}, markers[0].first.toPoint());
    QVERIFY(w->selection());
    QCOMPARE(w->selection()->kind, Selection::Kind::Light);
    QVERIFY(w->selectionStatus().startsWith(QStringLiteral("bulb at (0.0, 3.0, 8.0)")));
    // The dope sheet has its pose row (no keys yet).
    QCOMPARE(int(w->session()->dopeSheetRows().size()), 1);
    QCOMPARE(w->session()->dopeSheetRows()[0].target, QStringLiteral("bulb"));
    auto g = w->gizmoTool()->gizmo();
    QVERIFY(g);
    QVERIFY(std::hypot(onScreen(*w, g->centre()).x() - markers[0].first.x(),
                       onScreen(*w, g->centre()).y() - markers[0].first.y()) < 1);

    // Its x arrow: a light without keys gets its first key after its line, the pose's x.
    QPointF from = g->centre() + (g->arrowEnd(0) - g->centre()) * 0.6;
    QTest::mousePress(w->viewport(), Qt::LeftButton, {}, onScreen(*w, from));
    QTest::mouseMove(w->viewport(), onScreen(*w, from + QPointF(40, 0)));
    QTest::mouseRelease(w->viewport(), Qt::LeftButton, {}, onScreen(*w, from + QPointF(40, 0)));
    const Camera camera = w->viewport()->displayCamera();
    const double dx = onPlaneZ(camera, from + QPointF(40, 0), 8).x - onPlaneZ(camera, from, 8).x;
    const QStringList lines = w->editor()->toPlainText().split('\n');
    const int lightLine = int(lines.indexOf("/point_light 0.5 0 3 8 name bulb"));
    QVERIFY(lightLine > 0);
    const auto numbers = keyNumbers(lines.value(lightLine + 1), "bulb", 0);
    QVERIFY2(numbers, qPrintable(lines.value(lightLine + 1)));
    QVERIFY(std::fabs(numbers->at(0).toDouble() - dx) <= g->unitsPerPixel());
    QCOMPARE(numbers->mid(1), (QStringList{"0", "0", "0", "0", "0"}));
    QVERIFY(settled(*w, 0));
    expectViewportMatchesCore(*w, 0);

    // Looking around (three drags on the floor, 180 degrees), the camera's marker is in view.
    ViewportWidget* view = w->viewport();
    const QPointF corner = view->imageRect().bottomLeft() + QPointF(8, -8);
    for (int i = 0; i < 3; ++i) {
        QTest::mousePress(view, Qt::LeftButton, {}, corner.toPoint());
        QTest::mouseMove(view, (corner + QPointF(100, 0)).toPoint());
        QTest::mouseMove(view, (corner + QPointF(200, 0)).toPoint());
        QTest::mouseRelease(view, Qt::LeftButton, {}, (corner + QPointF(200, 0)).toPoint());
    }
    QVERIFY(view->isOrbiting());
    QVERIFY(settled(*w, 0));
    markers = w->gizmoTool()->markers();
    const auto cameraMarker = std::find_if(markers.begin(), markers.end(), [](const auto& m) {
        return m.second.kind == Selection::Kind::Camera;
    });
    QVERIFY(cameraMarker != markers.end());
    QTest::mouseClick(view, Qt::LeftButton, {}, cameraMarker->first.toPoint());
    QCOMPARE(w->selection()->target(), QStringLiteral("camera"));
    QCOMPARE(w->session()->dopeSheetRows()[0].target, QStringLiteral("camera"));
    g = w->gizmoTool()->gizmo();
    QVERIFY(g);
    // Up its y arrow: the camera has no keys, so its /camera line's eye rises.
    from = g->centre() + (g->arrowEnd(1) - g->centre()) * 0.6;
    QCOMPARE(g->hit(from), std::optional(GizmoHandle::Y));
    QTest::mousePress(view, Qt::LeftButton, {}, onScreen(*w, from));
    QTest::mouseMove(view, onScreen(*w, from + QPointF(0, -30)));
    QTest::mouseRelease(view, Qt::LeftButton, {}, onScreen(*w, from + QPointF(0, -30)));
    QVERIFY(w->editor()->toPlainText().startsWith(QStringLiteral("/camera 96 72 0.6 0 ")));
    QVERIFY(settled(*w, 0));
    QVERIFY(w->document()->scene()->camera.pose.position.y > 0.5f);
    QCOMPARE(w->document()->scene()->camera.pose.position.z, -10.0f);
    QVERIFY(view->isOrbiting());  // the view is still the look-around
}

QTEST_MAIN(GizmoTest)
#include "gizmo_test.moc"
