// QtTest suite of the studio session without a window (issue 23): the
// editor's text goes to a picture (text set, scene parsed, frame rendered and
// refined as the core renders it) and the capture commands write their lines,
// all driven through StudioSession alone.
#include <QSignalSpy>
#include <QTest>

#include "core/anim/frame_builder.h"
#include "core/render/camera.h"
#include "core/render/pick.h"
#include "image_convert.h"
#include "playback.h"
#include "scene_document.h"
#include "studio_session.h"
#include "test_support.h"

using namespace f2;
using namespace f2::viewer;
using namespace f2::viewer::test;

namespace {

/// The text `capture` leaves of `text` (as the window's editor would hold it).
QString applied(QString text, const StudioSession::Capture& capture) {
    for (const TextEdit& edit : capture.edits) text = withEdit(text, edit);
    return text;
}

/// Sets `text` as the editor would and waits until its refined frame is shown.
bool showText(StudioSession& session, const QString& text) {
    session.document()->setText(text);
    return QTest::qWaitFor(
        [&] {
            return !session.document()->isParsing() && session.document()->text() == text &&
                   session.isFrameSettled();
        },
        kWaitMs);
}

}  // namespace

class SessionTest : public QObject {
    Q_OBJECT
   private slots:
    void initTestCase();
    void editedTextBecomesThePicture();
    void keyCameraHereWritesTheCameraKey();
    void pickNamesTheLineAndKeysTheSelection();
    void pickOfAModelsShapeNamesItsPartAndLines();
    void selectedTargetsKeysAndWriteBack();
};

void SessionTest::initTestCase() {
    QCoreApplication::setOrganizationName("F2StageTest");
    QCoreApplication::setApplicationName("f2-viewer-session-test");
}

void SessionTest::editedTextBecomesThePicture() {
    StudioSession session;
    QSignalSpy scenes(&session, &StudioSession::sceneChanged);
    QSignalSpy frames(&session, &StudioSession::frameShown);
    QVERIFY(showText(session, kSmallScene));
    QVERIFY(!scenes.isEmpty());
    QCOMPARE(session.playback()->lastFrame(), 10);
    // Paused: the frame refines to the last step, which is what `f2 render --aa 4` gives
    // at the scene's /camera size (no window: the view is the scene camera).
    const FrameInfo& shown = session.shownFrame();
    QCOMPARE(shown.antialias, StudioSession::kRefinedAntialias);
    QCOMPARE(shown.size, QSize(96, 72));
    const auto last = frames.last();
    QCOMPARE(last.at(1).value<FrameInfo>().serial, shown.serial);
    QVERIFY(fromQImage(last.at(0).value<QImage>()) ==
            coreRender(*session.document()->scene(), 0, 96, 72, StudioSession::kRefinedAntialias));

    // An edit of the same text keeps the time and renders the new scene there.
    session.playback()->seek(4);
    QString edited = kSmallScene;
    edited.replace("/background 20 30 40", "/background 200 30 40");
    QVERIFY(showText(session, edited));
    QCOMPARE(session.shownFrame().time, 4.0);
    QCOMPARE(int(session.document()->scene()->background.r), 200);
    QVERIFY(fromQImage(frames.last().at(0).value<QImage>()) ==
            coreRender(*session.document()->scene(), 4, 96, 72, StudioSession::kRefinedAntialias));
}

void SessionTest::keyCameraHereWritesTheCameraKey() {
    StudioSession session;
    QVERIFY(showText(session, kSmallScene));
    session.playback()->seek(5);
    const QString text = kSmallScene;
    // The camera's first key away from frame 0 comes with /key 0 camera at the /camera pose,
    // both after the /camera line, and a note saying so.
    const StudioSession::Capture key = session.keyCameraHere(text, std::nullopt);
    QCOMPARE(key.edits.size(), std::size_t(2));
    QVERIFY(!key.note.isEmpty());
    const QStringList lines = applied(text, key).split('\n');
    QCOMPARE(lines.value(1), QStringLiteral("/key 0 camera 0 0 -10 0 0 0"));
    QCOMPARE(lines.value(2), QStringLiteral("/key 5 camera 0 0 -10 0 0 0"));
    QCOMPARE(lines.size(), text.split('\n').size() + 2);

    // A look-around's pose is what the key holds.
    const Pose view{{1, 2, -9}, {5, 10, 0}};
    QCOMPARE(applied(text, session.keyCameraHere(text, view)).split('\n').value(2),
             QStringLiteral("/key 5 camera 1 2 -9 5 10 0"));
    // Set Camera from View rewrites the /camera line, keeping its size and d.
    QCOMPARE(applied(text, session.cameraFromView(text, view)).split('\n').value(0),
             QStringLiteral("/camera 96 72 0.6 1 2 -9 5 10 0"));
}

void SessionTest::pickNamesTheLineAndKeysTheSelection() {
    StudioSession session;
    QVERIFY(showText(session, kSmallScene));
    const QString text = kSmallScene;
    // Without a selection there is nothing to key: a note, no edit.
    const StudioSession::Capture none = session.keySelectionHere(text);
    QVERIFY(none.edits.empty());
    QVERIFY(!none.note.isEmpty());

    // The ball at frame 0 is at (-3, 0, 8): pick where the scene camera draws it.
    const Camera camera = Camera::fromDesc(session.document()->scene()->camera);
    float px = 0, py = 0;
    QVERIFY(camera.project({-3, 0, 8}, px, py));
    QSignalSpy changed(&session, &StudioSession::selectionChanged);
    QVERIFY(session.pick({px, py}, camera));
    QCOMPARE(changed.size(), 1);
    QCOMPARE(session.selection()->target(), QStringLiteral("ball"));
    QVERIFY(session.selectionView());
    QCOMPARE(session.selectionView()->keyFrames, (QList<int>{0, 10}));
    QVERIFY(session.selectionView()->label.startsWith("ball at (-3.0, 0.0, 8.0)"));
    // Its creating line, /sphere ball, is line 6.
    QCOMPARE(session.creatingLine(text).line, 6);

    // Keyed at frame 5: halfway along, replacing nothing, after its last key.
    session.playback()->seek(5);
    const QStringList lines = applied(text, session.keySelectionHere(text)).split('\n');
    QCOMPARE(lines.value(8), QStringLiteral("/key 5 ball 0 0 8 0 0 0"));

    // The frames rendered since bring the selection's bounds (no second evaluation on
    // this thread): the ones evaluating frame 5 gives, and the label follows the ball.
    QVERIFY(
        QTest::qWaitFor([&] { return session.isFrameSettled() && session.shownFrame().time == 5; }, kWaitMs));
    QVERIFY(session.shownFrame().bounds);
    EvaluatedFrame frame5;
    evaluateFrame(*session.document()->scene(), 5, frame5);
    const Bounds expected =
        selectionBounds(*session.document()->scene(), frame5,
                        *findObject(*session.document()->scene(), *session.selection()), std::nullopt);
    QCOMPARE(session.selectionView()->bounds.lo, expected.lo);
    QCOMPARE(session.selectionView()->bounds.hi, expected.hi);
    QVERIFY(session.selectionView()->label.startsWith("ball at (0.0, 0.0, 8.0)"));

    // The background clears the selection.
    QVERIFY(!session.pick({1, 1}, camera));
    QVERIFY(!session.selection());
    QVERIFY(!session.selectionView());
}

void SessionTest::pickOfAModelsShapeNamesItsPartAndLines() {
    StudioSession session;
    QVERIFY(showText(session, kLampScene));
    const QString text = kLampScene;
    const SceneDesc& scene = *session.document()->scene();
    // Click the middle of the bulb, the arm's only shape.
    EvaluatedFrame frame0;
    evaluateFrame(scene, 0, frame0);
    const Bounds bulb = selectionBounds(scene, frame0, 0, 1);
    const Vec3 centre = (bulb.lo + bulb.hi) * 0.5f;
    const Camera camera = Camera::fromDesc(scene.camera);
    float px = 0, py = 0;
    QVERIFY(camera.project(centre, px, py));
    QVERIFY(session.pick({px, py}, camera));
    QCOMPARE(session.selection()->target(), QStringLiteral("l1.arm"));
    QCOMPARE(session.selection()->shape, std::optional(1));
    // The outline is the part's (its shapes'), its keys the part's.
    QCOMPARE(session.selectionView()->bounds.lo, bulb.lo);
    QCOMPARE(session.selectionView()->bounds.hi, bulb.hi);
    QCOMPARE(session.selectionView()->keyFrames, (QList<int>{0, 10}));
    // A click goes to the instance's line, a Ctrl+click to the shape's line in the model.
    QCOMPARE(session.creatingLine(text).line, 11);
    const StudioSession::CreatingLine shape = session.shapeLine(text);
    QCOMPARE(shape.line, 9);
    QCOMPARE(shape.message, QStringLiteral("l1.arm.bulb: line 9, in the /model lamp block"));
    // Edited since: the line no longer names the shape.
    QString edited = text;
    edited.replace("/sphere arm.bulb", "/sphere arm.lamp");
    QCOMPARE(session.shapeLine(edited).line, 0);

    // Key Selection Here writes the part's key: after its last key, halfway along.
    session.playback()->seek(5);
    QCOMPARE(applied(text, session.keySelectionHere(text)).split('\n').value(13),
             QStringLiteral("/key 5 l1.arm 0 0 0 0 0 -20"));
    // A part without keys: its first key goes after the instance's line.
    session.setSelection(Selection{"l1", 0, "base", std::nullopt});
    QCOMPARE(applied(text, session.keySelectionHere(text)).split('\n').value(11),
             QStringLiteral("/key 5 l1.base 0 0 0 0 0 0"));

    // The robot's shapes are built in: its creating line, and a message saying why.
    session.setSelection(Selection{"r", 1, "head", 2});
    QCOMPARE(session.creatingLine(text).line, 14);
    const StudioSession::CreatingLine eye = session.shapeLine(text);
    QCOMPARE(eye.line, 14);
    QCOMPARE(eye.message,
             QStringLiteral("r.head.leye is built into the robot model: no line of the scene defines it"));
    // A part the model no longer has is no selection.
    session.setSelection(Selection{"r", 1, "neck", std::nullopt});
    QVERIFY(!session.selection());
}

QTEST_MAIN(SessionTest)
void SessionTest::selectedTargetsKeysAndWriteBack() {
    StudioSession session;
    QVERIFY(showText(session, kLampScene));
    // --select's path: a target by name, a part by its name.
    QVERIFY(!session.selectTarget("nobody"));
    QVERIFY(!session.selectTarget("l1.leg"));
    QVERIFY(session.selectTarget("l1.arm"));
    QCOMPARE(session.selection()->target(), QStringLiteral("l1.arm"));
    // The dope sheet: the instance's pose, then the selected (keyed) part, from this text.
    const auto& rows = session.dopeSheetRows();
    QCOMPARE(rows.size(), std::size_t(2));
    QCOMPARE(rows[1].target, QStringLiteral("l1.arm"));
    QCOMPARE(rows[1].keys.size(), std::size_t(2));
    QCOMPARE(session.dopeSheetText(), QString(kLampScene));
    // The write-back of the session's parse: the part's key at 10 in place.
    const QString text = kLampScene;
    const WriteBack write = session.writeBack(text, {"l1.arm", std::nullopt, 10, {0, 0, 0, 0, 0, -45}});
    QVERIFY(!write.refused());
    QCOMPARE(withEdits(text, write.edits), QString(text).replace("0 0 0 0 0 -40", "0 0 0 0 0 -45"));
    // The camera by its name: its rows.
    QVERIFY(session.selectTarget("camera"));
    QCOMPARE(session.selection()->kind, Selection::Kind::Camera);
    QCOMPARE(session.dopeSheetRows().front().target, QStringLiteral("camera"));
}

#include "session_test.moc"
