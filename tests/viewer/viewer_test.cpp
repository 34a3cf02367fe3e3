// QtTest suite of f2-viewer, run on the offscreen platform. It drives the real
// MainWindow and checks what it shows against the core renderer.
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QPlainTextEdit>
#include <QProcess>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTimer>
#include <QWheelEvent>
#include <atomic>
#include <thread>

#include "animation_exporter.h"
#include "autosave.h"
#include "core/anim/frame_builder.h"
#include "core/anim/frame_time.h"
#include "core/parse/parser.h"
#include "core/render/orbit_camera.h"
#include "core/render/pick.h"
#include "core/render/renderer.h"
#include "editor_dock.h"
#include "help_windows.h"
#include "image_convert.h"
#include "io/png_writer.h"
#include "io/sequence_sink.h"
#include "io/video_sink.h"
#include "key_marker_slider.h"
#include "main_window.h"
#include "playback.h"
#include "playback_antialias.h"
#include "render_controller.h"
#include "scene_document.h"
#include "scene_editor.h"
#include "scene_highlighter.h"
#include "test_support.h"
#include "timeline_widget.h"
#include "viewport_widget.h"

using namespace f2;
using namespace f2::viewer;
using namespace f2::viewer::test;
using namespace std::chrono_literals;

class ViewerTest : public QObject {
    Q_OBJECT
   private slots:
    void initTestCase();

    void orbitStartsAtSceneCamera();
    void orbitTurnsAndZoomsAroundTarget();
    void imageConversionRoundTrips();
    void playStepScrubShowsCoreImage();
    void keyboardShortcutsDrivePlayback();
    void savedFrameSizeIgnoresDocks();
    void dialogsStartInTheScenesFolder();
    void helpMenuListsShortcutsAndReference();
    void clickSelectsWhatIsDrawn();
    void ctrlClickGoesToTheShapesLine();
    void pausedPictureRefinesToAa4();
    void playbackAntialiasFitsTheBudget();
    void playingUsesTheChosenAntialias();
    void stepGoesFromTheFrameShown();
    void viewFollowsTheMovingCamera();
    void renderScaleFollowsWindow();
    void dragOrbitsWheelZoomsAndSceneCameraResets();
    void brokenFileShowsErrorsAndKeepsImage();
    void reloadsAfterEditorReplacesFile();
    void reloadsWhenAnIncludedFileChanges();
    void problemsNameTheIncludedFileAndLoopValues();
    void windowRespondsDuringSlowFrame();
    void latestRequestWins();
    void aStillIsNeitherSkippedNorLate();
    void exportWritesPngSequence();
    void exportWritesVideo();
    void cancelledVideoExportLeavesNoFile();
    void loopPointsDrivePlaybackAndExport();
    void pickNamesTheLineALoopOrIncludeMadeItBy();
};

namespace {

/// An export of frames 0..`lastFrame` of the seed example at `width`x`height`
/// into `sink`, as MainWindow's export actions build it.
ExportJob seedExportJob(int width, int height, int lastFrame, std::unique_ptr<FrameSink> sink) {
    const ParseResult parsed = parseSceneFile(F2_SOURCE_DIR "/scenes/seed_example.f2");
    if (!parsed.ok()) return {};
    ExportJob job;
    job.scene = std::make_shared<const SceneDesc>(*parsed.scene);
    job.view = FrameView::sceneCamera(width, height);
    job.lastFrame = lastFrame;
    job.sink = std::move(sink);
    return job;
}

/// Files in `dir` whose name contains ".tmp-" (the encoder's temporary files).
QStringList tempFiles(const QString& dir) {
    return QDir(dir).entryList({"*.tmp-*"}, QDir::Files | QDir::Hidden);
}

/// An MP4 of `path`, as the Export Video action makes it.
std::unique_ptr<VideoSink> mp4Sink(const QString& path) {
    return std::make_unique<VideoSink>(QFile::encodeName(path).toStdString(), VideoFormat::Mp4);
}

/// Forwards to a VideoSink, but holds frame 1 until `release` is raised, so a
/// test can cancel while the export is certainly in the middle.
class GatedSink : public FrameSink {
   public:
    GatedSink(const QString& path, std::shared_ptr<std::atomic<bool>> release)
        : video_(mp4Sink(path)), release_(std::move(release)) {}
    bool begin(const FrameFormat& format, std::string& error) override {
        return video_->begin(format, error);
    }
    bool write(const Image& image, std::int64_t frame, std::string& error,
               const std::atomic<bool>* cancel) override {
        while (frame == 1 && !release_->load()) std::this_thread::sleep_for(5ms);
        return video_->write(image, frame, error, cancel);
    }
    bool finish(std::string& error, const std::atomic<bool>* cancel) override {
        return video_->finish(error, cancel);
    }
    void abandon() override { video_->abandon(); }
    std::int64_t framesCompleted() const override { return video_->framesCompleted(); }

   private:
    std::unique_ptr<VideoSink> video_;
    std::shared_ptr<std::atomic<bool>> release_;
};

/// A loop range as Playback reports it.
std::optional<FrameRange> loopOf(int first, int last) { return FrameRange{first, last}; }

}  // namespace

void ViewerTest::initTestCase() {
    // Settings (recent files, scale) go to the test's XDG_CONFIG_HOME, not the user's.
    QCoreApplication::setOrganizationName("F2StageTest");
    QCoreApplication::setApplicationName("f2-viewer-test");
}

void ViewerTest::orbitStartsAtSceneCamera() {
    CameraDesc desc;
    desc.pose = {{10, 230, -620}, {16, -20, 0}};
    const Camera camera = Camera::fromDesc(desc);
    const OrbitCamera orbit = OrbitCamera::fromCamera(camera, 900);
    const Camera same = orbit.apply(camera);
    QVERIFY(length(same.eye - camera.eye) < 1e-2f);
    for (int c = 0; c < 3; ++c)
        QVERIFY(length(same.worldFromCamera.column(c) - camera.worldFromCamera.column(c)) < 1e-5f);
    QVERIFY(length(orbit.target() - (camera.eye + camera.worldFromCamera.column(2) * 900)) < 1e-2f);
}

void ViewerTest::orbitTurnsAndZoomsAroundTarget() {
    const Camera camera = Camera::fromDesc(CameraDesc{});  // at the origin looking along +z
    OrbitCamera orbit = OrbitCamera::fromCamera(camera, 100);
    QVERIFY(length(orbit.target() - Vec3{0, 0, 100}) < 1e-4f);

    orbit.orbit(180, 0);  // half way round: the eye ends up behind the target
    Camera turned = orbit.apply(camera);
    QVERIFY(length(turned.eye - Vec3{0, 0, 200}) < 1e-3f);
    QVERIFY(length(turned.worldFromCamera.column(2) - Vec3{0, 0, -1}) < 1e-5f);

    orbit.orbit(0, 500);  // pitch clamps short of the pole
    QCOMPARE(orbit.pitchDeg(), OrbitCamera::kMaxPitchDeg);
    QVERIFY(orbit.apply(camera).eye.y > 99.0f);  // looking down from above

    orbit.zoom(0.5f);
    QVERIFY(std::abs(length(orbit.apply(camera).eye - orbit.target()) - 50.0f) < 1e-3f);
    orbit.zoom(0.0f);  // ignored
    QCOMPARE(orbit.distance(), 50.0f);

    // The default scene's pivot lands among its objects, in front of the eye.
    const ParseResult seed = parseSceneFile(F2_SOURCE_DIR "/scenes/seed_example.f2");
    QVERIFY(seed.ok());
    const float d = orbitTargetDistance(*seed.scene, Camera::fromDesc(seed.scene->camera));
    QVERIFY(d > 100 && d < 400);
}

void ViewerTest::imageConversionRoundTrips() {
    Image image;
    image.resize(5, 3);  // odd width: QImage pads scanlines
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) image.at(x, y) = {std::uint8_t(x * 50), std::uint8_t(y * 80), 7};
    const QImage q = toQImage(image);
    QCOMPARE(q.size(), QSize(5, 3));
    QCOMPARE(q.pixelColor(4, 2), QColor(200, 160, 7));
    QVERIFY(fromQImage(q) == image);
}

void ViewerTest::playStepScrubShowsCoreImage() {
    MainWindow w;
    w.resizeForViewport({200, 150});
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.openFile(F2_SOURCE_DIR "/scenes/seed_example.f2");
    QVERIFY(!w.document()->hasErrors());
    QCOMPARE(w.playback()->lastFrame(), 15);

    // Plays: time advances and frames arrive.
    const quint64 before = w.renderController()->framesDelivered();
    w.playback()->play();
    QTRY_VERIFY_WITH_TIMEOUT(w.playback()->time() > 2.0, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(w.renderController()->framesDelivered() >= before + 3, kWaitMs);

    // Steps: stepping pauses on a whole frame.
    w.playback()->seek(3);
    w.timeline()->stepRequested(1);
    QVERIFY(!w.playback()->isPlaying());
    QCOMPARE(w.playback()->time(), 4.0);
    QVERIFY(waitForShownFrame(w, 4));
    expectViewportMatchesCore(w, 4);

    // Scrubs: drag the slider as a user would; the picture follows while held.
    QSlider* slider = w.timeline()->slider();
    w.playback()->play();
    slider->setSliderDown(true);
    QVERIFY(!w.playback()->isPlaying());
    for (int v : {6, 8, 11}) slider->setValue(v);
    QVERIFY(waitForShownFrame(w, 11));
    expectViewportMatchesCore(w, 11);
    slider->setSliderDown(false);
    QVERIFY(w.playback()->isPlaying());  // playing again after the drag
    w.playback()->pause();
}

void ViewerTest::keyboardShortcutsDrivePlayback() {
    MainWindow w;
    w.resizeForViewport({160, 120});
    w.show();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    w.openFile(F2_SOURCE_DIR "/scenes/seed_example.f2");
    w.playback()->pause();
    QTest::keyClick(&w, Qt::Key_End);
    QCOMPARE(w.playback()->time(), 15.0);
    QTest::keyClick(&w, Qt::Key_Right);  // wraps round to the start
    QCOMPARE(w.playback()->time(), 0.0);
    QTest::keyClick(&w, Qt::Key_Left);
    QCOMPARE(w.playback()->time(), 15.0);
    QTest::keyClick(&w, Qt::Key_Home);
    QCOMPARE(w.playback()->time(), 0.0);
    QTest::keyClick(&w, Qt::Key_Space);
    QVERIFY(w.playback()->isPlaying());
    QTest::keyClick(&w, Qt::Key_Space);
    QVERIFY(!w.playback()->isPlaying());
}

void ViewerTest::viewFollowsTheMovingCamera() {
    // A keyed camera with /look_at (SPEC 9.1): at every frame the viewport
    // shows what f2 render shows with the scene's camera at that time.
    MainWindow w;
    w.resizeForViewport({160, 120});
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.openFile(F2_SOURCE_DIR "/tests/cli/data/motion.f2");
    QVERIFY(!w.document()->hasErrors());
    w.playback()->pause();
    const Vec3 startEye = w.viewport()->viewCamera().eye;
    for (double t : {12.0, 30.0, 48.0}) {
        w.playback()->seek(t);
        QVERIFY(waitForShownFrame(w, t));
        expectViewportMatchesCore(w, t);
    }
    QVERIFY(length(w.viewport()->viewCamera().eye - startEye) > 100.0f);  // it did move
}

void ViewerTest::savedFrameSizeIgnoresDocks() {
    QTemporaryDir dir;
    auto window = windowOn(smallSceneFile(dir), 4);
    QVERIFY(window);
    MainWindow& w = *window;
    w.playback()->pause();
    w.playback()->seek(4);
    w.setRenderScale(RenderScale::SceneSize);
    // Both docks open take room from the picture; the saved frame keeps the /camera size.
    w.editorDock()->show();
    w.diagnosticsDock()->show();
    QCoreApplication::processEvents();
    QVERIFY(w.viewport()->width() < 800);
    const Image saved = frameToSave(w);
    QCOMPARE(saved.width, 96);
    QCOMPARE(saved.height, 72);
    QVERIFY(saved == coreRender(*w.document()->scene(), 4, 96, 72));
    w.setRenderScale(RenderScale::Full);
    const Image full = frameToSave(w);
    QCOMPARE(QSize(full.width, full.height), w.viewport()->renderSize());
}

void ViewerTest::dialogsStartInTheScenesFolder() {
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkpath("shots"));
    const QString path = dir.filePath("shots/scene.f2");
    writeFile(path, kSmallScene);
    MainWindow w;
    QCOMPARE(w.outputFolder(), QDir::currentPath());  // untitled: the working folder
    w.openFile(path);
    QCOMPARE(w.outputFolder(), QFileInfo(path).absolutePath());
}

void ViewerTest::helpMenuListsShortcutsAndReference() {
    MainWindow w;
    const QString shortcuts = shortcutList(w.menuBar());
    for (const char* line :
         {"File › Save Scene\t", "File › Save Frame as PNG…\tF12", "Playback › Play / Pause\tSpace",
          "Edit › Find…\t", "Edit › Comment / Uncomment Lines\t"})
        QVERIFY2(shortcuts.contains(QString::fromUtf8(line)), qPrintable(shortcuts));
    QVERIFY(shortcuts.contains(QKeySequence(QKeySequence::Save).toString(QKeySequence::NativeText)));
    const QString reference = languageReference();
    QVERIFY(reference.contains("/camera"));
    QVERIFY(reference.contains("/key"));
    QStringList menus;
    for (QAction* a : w.menuBar()->actions()) menus << a->text().remove('&');
    QCOMPARE(menus.last(), QStringLiteral("Help"));
}

void ViewerTest::clickSelectsWhatIsDrawn() {
    QTemporaryDir dir;
    auto window = windowOn(smallSceneFile(dir), 5);
    QVERIFY(window);
    MainWindow& w = *window;
    w.editorDock()->hide();  // the offscreen screen is 800 pixels wide: room for the timeline
    w.setRenderScale(RenderScale::SceneSize);  // a 96x72 picture, scaled up on screen
    w.playback()->pause();
    w.playback()->seek(5);
    QVERIFY(waitForShownFrame(w, 5));
    QCOMPARE(w.viewport()->image().size(), QSize(96, 72));

    // The ball moves from x = -3 to 3 over frames 0-10: at frame 5 it is at (0, 0, 8).
    const Camera camera = Camera::fromDesc(w.document()->scene()->camera);
    float px = 0, py = 0;
    QVERIFY(camera.project({0, 0, 8}, px, py));
    const QRectF onScreen = w.viewport()->imageRect();
    auto widgetPoint = [&](float x, float y) {
        return QPoint(int(onScreen.left() + x * onScreen.width() / 96),
                      int(onScreen.top() + y * onScreen.height() / 72));
    };
    QTest::mouseClick(w.viewport(), Qt::LeftButton, {}, widgetPoint(px, py));
    QVERIFY(w.selection().has_value());
    QCOMPARE(w.selection()->target(), QStringLiteral("ball"));
    QVERIFY2(w.selectionStatus().startsWith("ball at (0.0, 0.0, 8.0)"), qPrintable(w.selectionStatus()));
    QCOMPARE(w.editor()->textCursor().selectedText(), QStringLiteral("/sphere ball 1.5 -3 0 8"));
    const auto outline = w.viewport()->selectionOutline();
    QVERIFY(outline.has_value());
    QVERIFY(outline->contains(QPointF(px, py)));
    QVERIFY(outline->width() < 40 && outline->width() > 5);

    // Its keys (frames 0 and 10) are marked on the timeline; a click on a marker goes there.
    KeyMarkerSlider* slider = w.timeline()->slider();
    QCOMPARE(slider->markers(), (QList<int>{0, 10}));
    QTest::mouseClick(slider, Qt::LeftButton, {}, QPoint(slider->positionOf(10), slider->height() - 5));
    QCOMPARE(w.playback()->time(), 10.0);
    // Typing a frame number goes there too.
    QSpinBox* box = w.timeline()->frameBox();
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, "3");
    QTest::keyClick(box, Qt::Key_Return);
    QCOMPARE(w.playback()->time(), 3.0);

    // The outline follows the ball to frame 10.
    w.playback()->seek(10);
    QVERIFY(waitForShownFrame(w, 10));
    QVERIFY(w.viewport()->selectionOutline()->left() > outline->left());

    // A drag orbits and does not change the selection; the background clears it.
    QTest::mousePress(w.viewport(), Qt::LeftButton, {}, widgetPoint(10, 5));
    QTest::mouseMove(w.viewport(), widgetPoint(40, 5));
    QTest::mouseRelease(w.viewport(), Qt::LeftButton, {}, widgetPoint(40, 5));
    QVERIFY(w.viewport()->isOrbiting());
    QCOMPARE(w.selection()->target(), QStringLiteral("ball"));
    w.viewport()->resetView();
    QVERIFY(waitForShownFrame(w, 10));
    QTest::mouseClick(w.viewport(), Qt::LeftButton, {}, widgetPoint(2, 2));
    QVERIFY(!w.selection().has_value());
    QVERIFY(!w.viewport()->selectionOutline().has_value());
    QVERIFY(w.selectionStatus().isEmpty());
    QVERIFY(slider->markers().isEmpty());
}

void ViewerTest::ctrlClickGoesToTheShapesLine() {
    QTemporaryDir dir;
    const QString path = dir.filePath("lamp.f2");
    writeFile(path, kLampScene);
    auto window = windowOn(path, 0);
    QVERIFY(window);
    MainWindow& w = *window;
    w.editorDock()->hide();
    w.setRenderScale(RenderScale::SceneSize);
    QVERIFY(waitForShownFrame(w, 0));
    // The middle of the bulb, the lamp's arm's shape, where the picture shows it.
    const SceneDesc& scene = *w.document()->scene();
    EvaluatedFrame frame;
    evaluateFrame(scene, 0, frame);
    const Bounds bulb = selectionBounds(scene, frame, 0, 1);
    float px = 0, py = 0;
    QVERIFY(Camera::fromDesc(scene.camera).project((bulb.lo + bulb.hi) * 0.5f, px, py));
    const QRectF onScreen = w.viewport()->imageRect();
    const QPoint at(int(onScreen.left() + px * onScreen.width() / 96),
                    int(onScreen.top() + py * onScreen.height() / 72));

    // A click selects the part and the instance's line; Ctrl+click the shape's line in the model.
    QTest::mouseClick(w.viewport(), Qt::LeftButton, {}, at);
    QCOMPARE(w.selection()->target(), QStringLiteral("l1.arm"));
    QCOMPARE(w.editor()->textCursor().selectedText(), QStringLiteral("/lamp l1 0 -2 8"));
    QTest::mouseClick(w.viewport(), Qt::LeftButton, Qt::ControlModifier, at);
    QCOMPARE(w.selection()->target(), QStringLiteral("l1.arm"));
    QCOMPARE(w.editor()->textCursor().selectedText(), QStringLiteral("/sphere arm.bulb 1.5 0 2 0"));
    QCOMPARE(w.statusBar()->currentMessage(),
             QStringLiteral("l1.arm.bulb: line 9, in the /model lamp block"));
    // The outline is round the bulb alone.
    const auto outline = w.viewport()->selectionOutline();
    QVERIFY(outline && outline->contains(QPointF(px, py)));
    float lx = 0, ly = 0;
    QVERIFY(Camera::fromDesc(scene.camera).project({0, -2, 8}, lx, ly));  // the foot's centre
    QVERIFY(!outline->contains(QPointF(lx, ly)));
}

void ViewerTest::pausedPictureRefinesToAa4() {
    QTemporaryDir dir;
    auto window = windowOn(smallSceneFile(dir), 5);
    QVERIFY(window);
    MainWindow& w = *window;
    w.setRenderScale(RenderScale::SceneSize);
    w.playback()->pause();
    w.playback()->seek(5);
    QVERIFY(waitForShownFrame(w, 5));  // waits for the refinement to end
    // Byte for byte what `f2 render --frame 5 --aa 4` writes for this scene.
    QCOMPARE(w.shownFrame().antialias, MainWindow::kRefinedAntialias);
    QVERIFY(fromQImage(w.viewport()->image()) == coreRender(*w.document()->scene(), 5, 96, 72, 4));
    QVERIFY(fromQImage(w.viewport()->image()) != coreRender(*w.document()->scene(), 5, 96, 72, 1));

    // The picture is complete (what --screenshot waits for): refined, at the window's size.
    QVERIFY(w.isPictureComplete());

    // A change restarts it: one sample first, then 2x2, then 4x4, all of frame 6;
    // only the last is a complete picture.
    QSignalSpy frames(w.renderController(), &RenderController::frameReady);
    QList<bool> complete;
    connect(w.renderController(), &RenderController::frameReady, this,
            [&] { complete << w.isPictureComplete(); });
    w.playback()->seek(6);
    QVERIFY(!w.isPictureComplete());
    QVERIFY(waitForShownFrame(w, 6));
    disconnect(w.renderController(), &RenderController::frameReady, this, nullptr);
    QList<int> steps;
    for (const auto& args : frames) {
        const auto info = args.at(1).value<FrameInfo>();
        QCOMPARE(info.time, 6.0);
        steps << info.antialias;
    }
    QCOMPARE(steps, (QList<int>{1, 2, 4}));
    QCOMPARE(complete, (QList<bool>{false, false, true}));
    QVERIFY(fromQImage(w.viewport()->image()) == coreRender(*w.document()->scene(), 6, 96, 72, 4));

    // Playing shows one sample per frame; switched off, paused frames stay at one sample.
    w.setRefinement(false);
    w.playback()->seek(7);
    QVERIFY(waitForShownFrame(w, 7));
    QCOMPARE(w.shownFrame().antialias, 1);
}

void ViewerTest::playbackAntialiasFitsTheBudget() {
    // Scripted costs, no clock: a frame at N x N takes 2 ms + 3 ms per sample.
    PlaybackAntialias aa;
    aa.setCostModel([](int n) { return PlaybackAntialias::Cost{2, 3.0 * n * n}; });
    aa.setBudgetMs(1000.0 / 24);  // may take 75 %: 31.3 ms; steps up to what fits in 80 % of that, 25 ms
    QCOMPARE(aa.level(), 1);      // nothing measured yet
    aa.observe(1, {});
    QCOMPARE(aa.level(), 2);  // 2x2: 14 ms fits; 3x3: 29 ms would fit but not with the margin
    aa.observe(2, {});
    QCOMPARE(aa.level(), 2);
    aa.setBudgetMs(1000.0 / 60);  // 12.5 ms allowed: 2x2 (14 ms) no longer fits
    aa.observe(2, {});
    QCOMPARE(aa.level(), 1);
    aa.setMode(PlaybackAntialiasMode::On);
    QCOMPARE(aa.level(), PlaybackAntialias::kOnLevel);
    aa.setMode(PlaybackAntialiasMode::Off);
    QCOMPARE(aa.level(), 1);

    // A cheaper scene: the estimates follow over a few frames (smoothed), up to
    // the refined picture's 4x4, not beyond.
    aa.setMode(PlaybackAntialiasMode::Auto);
    aa.setCostModel([](int n) { return PlaybackAntialias::Cost{0.5, 0.25 * n * n}; });
    aa.observe(1, {});
    QCOMPARE(aa.level(), 1);  // 2x2 predicted at 10.25 ms: more than 80 % of 12.5 ms
    for (int frame = 0; frame < 10; ++frame) aa.observe(aa.level(), {});
    QCOMPARE(aa.level(), PlaybackAntialias::kMaxAutoLevel);

    // Without a model the frame's own timings are the measurement: evaluate + build
    // is the fixed part, the trace is per sample (12 ms at 2x2 = 3 ms a sample).
    PlaybackAntialias measured;
    measured.setBudgetMs(1000.0 / 24);
    FrameTimings timings;
    timings.evaluateMs = 1;
    timings.buildMs = 1;
    timings.traceMs = 12;
    measured.observe(2, timings);
    QCOMPARE(measured.level(), 2);
    // One slow frame (a hiccup) is smoothed, not followed: 30 % of the way.
    timings.traceMs = 40;
    measured.observe(2, timings);
    QCOMPARE(measured.level(), 2);  // estimate 5.1 ms a sample: 2x2 = 22 ms still fits
    measured.reset();
    QCOMPARE(measured.level(), 1);
}

void ViewerTest::playingUsesTheChosenAntialias() {
    QTemporaryDir dir;
    auto window = windowOn(smallSceneFile(dir), 0);
    QVERIFY(window);
    MainWindow& w = *window;
    QCOMPARE(w.playbackAntialias().budgetMs(), double(1000 / 24));  // the clock's tick at /fps 24
    // From here on, every frame's cost is the model's (the estimates so far came from real timings).
    w.playbackAntialias().setCostModel([](int n) { return PlaybackAntialias::Cost{2, 3.0 * n * n}; });
    w.playbackAntialias().reset();
    QVERIFY(w.playbackAntialiasStatus().isEmpty());  // paused: the refinement's status speaks

    // Frames asked for before a change may still arrive after it: a few frames later the
    // picture on screen is one the new choice made.
    quint64 since = 0;
    auto playingAt = [&w, &since](int n) {
        return w.playback()->isPlaying() && w.renderController()->framesDelivered() >= since + 3 &&
               w.shownFrame().antialias == n;
    };
    auto change = [&w, &since](PlaybackAntialiasMode mode) {
        since = w.renderController()->framesDelivered();
        w.setPlaybackAntialias(mode);
    };
    change(PlaybackAntialiasMode::Auto);
    w.playback()->play();
    QTRY_VERIFY_WITH_TIMEOUT(playingAt(2), kWaitMs);
    QTRY_COMPARE_WITH_TIMEOUT(w.playbackAntialiasStatus(), QString("playing: 2×2 samples (auto)"), kWaitMs);
    expectViewportMatchesCore(w, w.shownFrame().time);  // what `f2 render --aa 2` gives

    change(PlaybackAntialiasMode::Off);
    QTRY_VERIFY_WITH_TIMEOUT(playingAt(1), kWaitMs);
    QTRY_COMPARE_WITH_TIMEOUT(w.playbackAntialiasStatus(), QString("playing: 1×1 samples (off)"), kWaitMs);

    // A cost that 2x2 does not fit: Auto plays with one sample.
    w.playbackAntialias().setCostModel([](int n) { return PlaybackAntialias::Cost{10, 10.0 * n * n}; });
    change(PlaybackAntialiasMode::Auto);
    QTRY_VERIFY_WITH_TIMEOUT(playingAt(1), kWaitMs);
    QCOMPARE(w.playbackAntialias().level(), 1);
    QCOMPARE(w.playbackAntialiasStatus(), QString("playing: 1×1 samples (auto)"));
    change(PlaybackAntialiasMode::On);
    QTRY_VERIFY_WITH_TIMEOUT(playingAt(2), kWaitMs);

    w.playback()->pause();
    QVERIFY(waitForShownFrame(w, w.playback()->time()));
    QVERIFY(w.playbackAntialiasStatus().isEmpty());
    w.setPlaybackAntialias(PlaybackAntialiasMode::Auto);  // the settings are shared with other tests
}

void ViewerTest::stepGoesFromTheFrameShown() {
    // Time 3.7 shows frame 3 (f2::frameAt, the rule `f2 render` uses); a step
    // goes to frame 4, not 5 (stepping used to round the time instead).
    Playback playback;
    playback.setRange(15, 24);
    playback.seek(3.7);
    QCOMPARE(playback.frame(), 3);
    playback.step(1);
    QCOMPARE(playback.time(), 4.0);
    playback.seek(3.7);
    playback.step(-1);
    QCOMPARE(playback.time(), 2.0);
    playback.seek(0.1 * 3 * 10);  // 2.9999999999999996: frame 3, as everywhere
    QCOMPARE(playback.frame(), 3);

    TimelineWidget timeline;
    timeline.setRange(15, 24);
    timeline.setTime(3.7);
    QCOMPARE(timeline.slider()->value(), 3);
}

void ViewerTest::renderScaleFollowsWindow() {
    MainWindow w;
    w.editorDock()->hide();           // the offscreen screen is 800 pixels wide: all of it for the picture
    w.resizeForViewport({480, 300});  // wider than the transport bar needs
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.playback()->pause();
    w.playback()->seek(50);
    QCOMPARE(w.viewport()->size(), QSize(480, 300));
    w.setRenderScale(RenderScale::Half);
    QVERIFY(waitForShownFrame(w, 50));
    QCOMPARE(w.viewport()->image().size(), QSize(240, 150));
    expectViewportMatchesCore(w, 50);

    w.resizeForViewport({520, 320});  // resizing re-renders at the new size
    QTRY_COMPARE_WITH_TIMEOUT(w.viewport()->image().size(), QSize(260, 160), kWaitMs);
    QVERIFY(waitForShownFrame(w, 50));
    expectViewportMatchesCore(w, 50);

    w.setRenderScale(RenderScale::SceneSize);  // the scene's /camera, like `f2 render`
    QTRY_COMPARE_WITH_TIMEOUT(w.viewport()->image().size(), QSize(800, 600), kWaitMs);
    w.setRenderScale(RenderScale::Full);
}

void ViewerTest::dragOrbitsWheelZoomsAndSceneCameraResets() {
    MainWindow w;
    w.resizeForViewport({480, 300});
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.playback()->pause();
    w.playback()->seek(120);
    ViewportWidget* view = w.viewport();
    const Camera scene = view->viewCamera();
    QVERIFY(!view->isOrbiting());

    // Drag left to right: the eye swings round the target, the target stays in view.
    const QPoint centre = view->rect().center();
    QTest::mousePress(view, Qt::LeftButton, {}, centre);
    QTest::mouseMove(view, centre + QPoint(60, 0));
    QTest::mouseMove(view, centre + QPoint(120, 20));
    QTest::mouseRelease(view, Qt::LeftButton, {}, centre + QPoint(120, 20));
    QVERIFY(view->isOrbiting());
    const Camera orbited = view->viewCamera();
    QVERIFY(length(orbited.eye - scene.eye) > 10.0f);
    QVERIFY(waitForShownFrame(w, 120));
    QVERIFY(fromQImage(view->image()) != coreRender(*w.document()->scene(), 120, view->image().width(),
                                                    view->image().height(), w.shownFrame().antialias));
    if (qEnvironmentVariableIsSet("F2_VIEWER_DUMP_DIR"))
        view->image().save(qEnvironmentVariable("F2_VIEWER_DUMP_DIR") + "/orbited.png");

    // Wheel forward zooms in: the eye moves toward the target.
    const Vec3 before = view->viewCamera().eye;
    QWheelEvent wheel(QPointF(centre), view->mapToGlobal(QPointF(centre)), {}, {0, 240}, Qt::NoButton, {},
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(view, &wheel);
    QVERIFY(length(view->viewCamera().eye - before) > 1.0f);

    // View > Scene Camera goes back to exactly the scene's view.
    view->resetView();
    QVERIFY(!view->isOrbiting());
    QVERIFY(waitForShownFrame(w, 120));
    expectViewportMatchesCore(w, 120);
}

void ViewerTest::brokenFileShowsErrorsAndKeepsImage() {
    QTemporaryDir dir;
    const QString path = smallSceneFile(dir);
    MainWindow w;
    w.resizeForViewport({96, 72});
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.openFile(path);
    w.playback()->pause();
    w.playback()->seek(5);
    QVERIFY(waitForShownFrame(w, 5));
    const QImage good = w.viewport()->image();
    const auto goodScene = w.document()->scene();
    QVERIFY(!w.diagnosticsDock()->isVisible());

    // Break line 3 on disk; the watcher reloads by itself.
    const QByteArray broken = QByteArray(kSmallScene).replace("/amb_light 0.3", "/amb_lite 0.3");
    writeFile(path, broken);
    QTRY_VERIFY_WITH_TIMEOUT(w.document()->hasErrors(), kWaitMs);
    const QString shown = problemsText(w);
    QVERIFY2(shown.contains(path + ":3:1: error:"), qPrintable(shown));
    QVERIFY(w.diagnosticsDock()->isVisible());
    QCOMPARE(w.document()->scene(), goodScene);  // the last good scene stays

    // Rendering goes on with the old scene: a new frame still looks like it.
    w.playback()->seek(5.0);
    w.scheduleFrame();
    QVERIFY(waitForShownFrame(w, 5));
    QCOMPARE(w.viewport()->image(), good);

    // F5 on the broken file changes nothing either; the viewer never writes it.
    QVERIFY(!w.document()->reload());
    QCOMPARE(readFile(path), broken);

    // Fixing it clears the errors and shows the edit.
    writeFile(path, QByteArray(kSmallScene).replace("/background 20 30 40", "/background 90 30 40"));
    QTRY_VERIFY_WITH_TIMEOUT(!w.document()->hasErrors(), kWaitMs);
    QVERIFY(w.document()->scene() != goodScene);
    QVERIFY(waitForShownFrame(w, 5));
    QVERIFY(w.viewport()->image() != good);
    expectViewportMatchesCore(w, 5);
    QCOMPARE(problemsText(w), QStringLiteral("No problems."));
}

void ViewerTest::reloadsAfterEditorReplacesFile() {
    QTemporaryDir dir;
    const QString path = smallSceneFile(dir);
    SceneDocument doc;
    QSignalSpy changed(&doc, &SceneDocument::sceneChanged);
    QVERIFY(doc.load(path));
    QCOMPARE(changed.count(), 1);
    QCOMPARE(changed.at(0).at(0).toBool(), true);  // a new document

    // Save the way many editors do: write a new file, rename it over the old.
    for (int round = 0; round < 2; ++round) {
        const QString temp = dir.filePath("scene.f2.tmp");
        writeFile(temp, QByteArray(kSmallScene)
                            .replace("/fps", "#")
                            .append("/fps " + QByteArray::number(30 + round) + "\n"));
        QVERIFY(QFile::remove(path));
        QVERIFY(QFile::rename(temp, path));
        QTRY_COMPARE_WITH_TIMEOUT(doc.scene()->fps, 30 + round, kWaitMs);
        QCOMPARE(changed.last().at(0).toBool(), false);  // same file: keep time and view
    }
}

void ViewerTest::reloadsWhenAnIncludedFileChanges() {
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkpath("parts"));
    const QString path = dir.filePath("scene.f2");
    const QString part = dir.filePath("parts/speed.f2");
    const QString later = dir.filePath("parts/later.f2");
    writeFile(part, "/fps 30\n");
    writeFile(path, QByteArray(kSmallScene).append("/include parts/speed.f2\n"));
    SceneDocument doc;
    QVERIFY(doc.load(path));
    QCOMPARE(doc.scene()->fps, 30);
    QCOMPARE(doc.sources(), (QStringList{path, part}));

    // Editing only the included file reloads the scene.
    writeFile(part, "/fps 31\n");
    QTRY_COMPARE_WITH_TIMEOUT(doc.scene()->fps, 31, kWaitMs);

    // An include of a file that does not exist yet: the error names it, and
    // creating the file reloads (its folder is watched).
    writeFile(part, "/include later.f2\n");
    QTRY_VERIFY_WITH_TIMEOUT(doc.hasErrors(), kWaitMs);
    QVERIFY2(doc.diagnostics().join("\n").contains(part + ":1:10: error: cannot include"),
             qPrintable(doc.diagnostics().join("\n")));
    QCOMPARE(doc.sources(), (QStringList{path, part, later}));
    writeFile(later, "/fps 32\n");
    QTRY_COMPARE_WITH_TIMEOUT(doc.scene()->fps, 32, kWaitMs);
    QVERIFY(!doc.hasErrors());
}

void ViewerTest::problemsNameTheIncludedFileAndLoopValues() {
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkpath("parts"));
    const QString path = smallSceneFile(dir);
    const QString part = dir.filePath("parts/ring.f2");
    writeFile(part, "# a ring of spheres\n/sphere s{i} (2 - i) (i) 0 8\n");
    auto w = windowOn(path, 5);
    QVERIFY(w);
    const auto goodScene = w->document()->scene();

    // Line 9 of the scene loops over the included file; its pass i = 2 gives
    // radius 0, an error on line 2 of parts/ring.f2 at the "(" (column 14).
    writeFile(path,
              QByteArray(kSmallScene).append("/repeat i 0 2\n  /include parts/ring.f2\n/end\n/fps 0\n"));
    QTRY_VERIFY_WITH_TIMEOUT(w->document()->hasErrors(), kWaitMs);
    QCOMPARE(w->document()->scene(), goodScene);
    QCOMPARE(problemsText(*w), part + ":2:14: error: radius must be > 0, got 0 (in /repeat i = 2)\n" + path +
                                   ":12:6: error: fps must be a whole number from 1 to 1000, got 0");
    QVERIFY(w->diagnosticsDock()->isVisible());
    // Only the problem in the open file is underlined in its editor.
    QCOMPARE(int(w->editor()->problems().size()), 1);
    QCOMPARE(w->editor()->problems().front().line, 12);
    QCOMPARE(w->editor()->problems().front().column, 6);
}

void ViewerTest::windowRespondsDuringSlowFrame() {
    MainWindow w;
    w.resizeForViewport({160, 120});
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.playback()->pause();
    QVERIFY(waitForShownFrame(w, 0));

    // The worker now holds every frame until the test releases it: no timing
    // assumption, so a loaded machine cannot make this test fail.
    w.renderController()->setDebugDelay(std::chrono::hours(1));
    int ticks = 0;
    QTimer ticker;
    connect(&ticker, &QTimer::timeout, [&ticks] { ++ticks; });
    ticker.start(10);
    QSignalSpy frames(w.renderController(), &RenderController::frameReady);

    w.playback()->seek(100);
    w.scheduleFrame();
    // Runs requestFrame(); had it waited for the held frame, it would never return.
    QCoreApplication::processEvents();
    QVERIFY(w.renderController()->hasPendingFrames());

    // Meanwhile the window keeps handling events: timers, resizes, repaints.
    QTRY_VERIFY_WITH_TIMEOUT(ticks >= 20, kWaitMs);
    w.resize(w.size() + QSize(30, 20));
    w.viewport()->repaint();  // synchronous paint of the old image, stretched
    QCOMPARE(frames.count(), 0);

    w.renderController()->setDebugDelay(0ms);  // release the frame
    QVERIFY(frames.wait(kWaitMs));
}

void ViewerTest::latestRequestWins() {
    const ParseResult parsed = parseScene(kSmallScene, "small.f2");
    QVERIFY(parsed.ok());
    const auto scene = std::make_shared<const SceneDesc>(*parsed.scene);
    const Camera camera = Camera::fromDesc(scene->camera);

    RenderController controller;
    controller.setDebugDelay(300ms);
    QSignalSpy frames(&controller, &RenderController::frameReady);
    for (int t = 0; t <= 10; ++t) controller.request({scene, double(t), camera, {}});
    QTRY_VERIFY_WITH_TIMEOUT(!controller.hasPendingFrames(), kWaitMs);
    QTest::qWait(400);  // nothing else is coming
    // The first request was in flight; the nine in between were skipped.
    QVERIFY2(frames.count() <= 2, qPrintable(QString::number(frames.count())));
    QCOMPARE(controller.framesSkipped(), quint64(11 - frames.count()));
    const auto last = frames.last().at(1).value<FrameInfo>();
    QCOMPARE(last.time, 10.0);
    QVERIFY(fromQImage(frames.last().at(0).value<QImage>()) == coreRender(*scene, 10, 96, 72));
}

void ViewerTest::aStillIsNeitherSkippedNorLate() {
    // Save Frame's picture goes through the same worker as the playing frames
    // (issue 23): a frame held in the worker, a still asked for, then ten
    // frames that replace each other; the still is rendered next, whole.
    const ParseResult parsed = parseScene(kSmallScene, "small.f2");
    QVERIFY(parsed.ok());
    const auto scene = std::make_shared<const SceneDesc>(*parsed.scene);
    const Camera camera = Camera::fromDesc(scene->camera);

    RenderController controller;
    controller.setDebugDelay(std::chrono::hours(1));  // holds the first frame until released
    QSignalSpy frames(&controller, &RenderController::frameReady);
    controller.request({scene, 0.0, camera, {}});
    std::optional<Image> still;
    int framesBeforeStill = -1;
    controller.requestStill({scene, 7.0, camera, {}}, [&](const Image& image) {
        still = image;
        framesBeforeStill = int(frames.count());
    });
    for (int t = 1; t <= 10; ++t) controller.request({scene, double(t), camera, {}});
    controller.setDebugDelay(0ms);
    QTRY_VERIFY_WITH_TIMEOUT(still.has_value(), kWaitMs);
    QVERIFY(*still == coreRender(*scene, 7, 96, 72));
    QVERIFY2(framesBeforeStill <= 1, qPrintable(QString::number(framesBeforeStill)));
    QTRY_VERIFY_WITH_TIMEOUT(!controller.hasPendingFrames(), kWaitMs);
    QCOMPARE(frames.last().at(1).value<FrameInfo>().time, 10.0);
}

void ViewerTest::exportWritesPngSequence() {
    const ParseResult parsed = parseScene(kSmallScene, "small.f2");
    QVERIFY(parsed.ok());
    const auto scene = std::make_shared<const SceneDesc>(*parsed.scene);
    QTemporaryDir dir;
    ExportJob job;
    job.scene = scene;
    job.view = FrameView::sceneCamera(scene->camera.width, scene->camera.height);
    job.firstFrame = 0;
    job.lastFrame = scene->lastFrame();
    job.sink = std::make_unique<PngSequenceSink>(exportSequencePattern(dir.filePath("out"), "small", 11));

    AnimationExporter exporter;
    QSignalSpy progress(&exporter, &AnimationExporter::progress);
    QSignalSpy finished(&exporter, &AnimationExporter::finished);
    exporter.start(std::move(job));
    QVERIFY(finished.wait(kWaitMs * 3));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(finished.at(0).at(1).toString()));
    // Progress rises to 11 of 11 (PNGs are written in the background, so it
    // counts files as they complete, and may report a count more than once).
    QVERIFY(progress.count() >= 1);
    for (int i = 1; i < progress.count(); ++i)
        QVERIFY(progress.at(i).at(0).toInt() >= progress.at(i - 1).at(0).toInt());
    QCOMPARE(progress.last().at(0).toInt(), 11);
    QCOMPARE(progress.last().at(1).toInt(), 11);
    for (int f : {0, 7, 10}) {
        Image read;
        std::string error;
        const QString file = dir.filePath(QStringLiteral("out/small_%1.png").arg(f, 4, 10, QChar('0')));
        QVERIFY2(readPng(file.toStdString(), read, error), error.c_str());
        QVERIFY(read == coreRender(*scene, f, 96, 72));
    }

    // Cancelling stops early and says so.
    ExportJob slow;
    slow.scene = scene;
    slow.view = FrameView::sceneCamera(1600, 1200);
    slow.lastFrame = 10;
    slow.sink =
        std::make_unique<PngSequenceSink>(exportSequencePattern(dir.filePath("cancelled"), "small", 11));
    QSignalSpy finished2(&exporter, &AnimationExporter::finished);
    exporter.start(std::move(slow));
    exporter.cancel();
    QVERIFY(finished2.wait(kWaitMs));
    QCOMPARE(finished2.at(0).at(0).toBool(), false);
    QVERIFY(finished2.at(0).at(1).toString().contains("cancelled"));
}

void ViewerTest::exportWritesVideo() {
    if (QStandardPaths::findExecutable("ffmpeg").isEmpty()) F2_QSKIP_MISSING("ffmpeg is not on PATH");
    QTemporaryDir dir;
    const QString path = dir.filePath("seed.mp4");
    ExportJob job = seedExportJob(80, 60, 5, mp4Sink(path));
    QVERIFY(job.scene);

    // The path the Export Video action takes: exportWithProgress with a VideoSink.
    bool called = false, ok = false, cancelled = true;
    QString message;
    exportWithProgress(nullptr, std::move(job), [&](bool o, bool c, const QString& m) {
        called = true, ok = o, cancelled = c, message = m;
    });
    QTRY_VERIFY_WITH_TIMEOUT(called, kWaitMs * 3);
    QVERIFY2(ok, qPrintable(message));
    QVERIFY(!cancelled);
    QVERIFY(message.contains("6 frames"));
    QVERIFY(QFileInfo(path).isFile());
    QVERIFY(QFileInfo(path).size() > 0);
    QVERIFY2(tempFiles(dir.path()).isEmpty(), qPrintable(tempFiles(dir.path()).join(' ')));

    const QString ffprobe = QStandardPaths::findExecutable("ffprobe");
    if (ffprobe.isEmpty()) return;
    QProcess probe;
    probe.start(ffprobe, {"-v", "error", "-select_streams", "v:0", "-count_frames", "-show_entries",
                          "stream=width,height,nb_read_frames", "-of", "default=noprint_wrappers=1", path});
    QVERIFY(probe.waitForFinished(kWaitMs));
    QCOMPARE(probe.exitCode(), 0);
    const QString out = QString::fromUtf8(probe.readAllStandardOutput());
    QVERIFY2(out.contains("width=80"), qPrintable(out));
    QVERIFY2(out.contains("height=60"), qPrintable(out));
    QVERIFY2(out.contains("nb_read_frames=6"), qPrintable(out));
}

void ViewerTest::cancelledVideoExportLeavesNoFile() {
    if (QStandardPaths::findExecutable("ffmpeg").isEmpty()) F2_QSKIP_MISSING("ffmpeg is not on PATH");
    QTemporaryDir dir;
    const QString path = dir.filePath("cancelled.mp4");
    auto release = std::make_shared<std::atomic<bool>>(false);
    ExportJob job = seedExportJob(160, 120, 15, std::make_unique<GatedSink>(path, release));
    QVERIFY(job.scene);
    bool called = false, ok = true, cancelled = false;
    exportWithProgress(nullptr, std::move(job),
                       [&](bool o, bool c, const QString&) { called = true, ok = o, cancelled = c; });
    QProgressDialog* dialog = nullptr;
    for (QWidget* w : QApplication::topLevelWidgets())
        if (auto* d = qobject_cast<QProgressDialog*>(w)) dialog = d;
    QVERIFY(dialog);
    // Mid-export: frame 0 has gone to ffmpeg, which is writing its temporary
    // file; frame 1 is held until after the cancel.
    QTRY_VERIFY_WITH_TIMEOUT(dialog->value() >= 1, kWaitMs * 3);
    QTRY_VERIFY_WITH_TIMEOUT(!tempFiles(dir.path()).isEmpty(), kWaitMs);
    QVERIFY(!called);
    auto* cancelButton = dialog->findChild<QPushButton*>();
    QVERIFY(cancelButton);
    cancelButton->click();
    release->store(true);
    QTRY_VERIFY_WITH_TIMEOUT(called, kWaitMs);
    QVERIFY(!ok);
    QVERIFY(cancelled);
    QVERIFY(!QFileInfo::exists(path));
    QVERIFY2(tempFiles(dir.path()).isEmpty(), qPrintable(tempFiles(dir.path()).join(' ')));
}

void ViewerTest::loopPointsDrivePlaybackAndExport() {
    QTemporaryDir dir;
    auto window = windowOn(smallSceneFile(dir), 3);
    QVERIFY(window);
    MainWindow& w = *window;
    w.editorDock()->hide();  // room for the timeline on the 800-pixel offscreen screen
    w.resizeForViewport({400, 100});
    Playback* playback = w.playback();
    KeyMarkerSlider* slider = w.timeline()->slider();
    QVERIFY(!playback->loopRange());

    // I and O (the picture has the focus) set the points at the frame shown.
    w.viewport()->setFocus();
    QTest::keyClick(w.viewport(), Qt::Key_I);
    QCOMPARE(playback->loopRange(), loopOf(3, 10));  // out defaults to the last frame
    playback->seek(6);
    QTest::keyClick(w.viewport(), Qt::Key_O);
    QCOMPARE(playback->loopRange(), loopOf(3, 6));
    QCOMPARE(slider->loop(), (std::optional<std::pair<int, int>>{{3, 6}}));

    // Playing from outside the loop starts at its in point and never leaves it;
    // it comes round again (4 frames at 4x speed: a sixth of a second a turn).
    playback->seek(8);
    playback->setSpeed(4);
    QList<double> times;
    connect(playback, &Playback::timeChanged, this, [&](double t) { times << t; });
    playback->play();
    QTRY_VERIFY_WITH_TIMEOUT(times.size() > 2 && frameAt(times.last()) < frameAt(times[times.size() - 2]),
                             kWaitMs);
    playback->pause();
    disconnect(playback, &Playback::timeChanged, this, nullptr);
    QCOMPARE(times.first(), 3.0);
    for (double t : times) QVERIFY2(t >= 3 && t < 7, qPrintable(QString::number(t)));

    // Dragging a flag on the slider moves that point.
    const double pausedAt = playback->time();
    const int top = slider->loopFlagY();
    QTest::mousePress(slider, Qt::LeftButton, {}, QPoint(slider->positionOf(3), top));
    QTest::mouseMove(slider, QPoint(slider->positionOf(2), top));
    QTest::mouseMove(slider, QPoint(slider->positionOf(1), top));
    QTest::mouseRelease(slider, Qt::LeftButton, {}, QPoint(slider->positionOf(1), top));
    QCOMPARE(playback->loopRange(), loopOf(1, 6));
    QTest::mousePress(slider, Qt::LeftButton, {}, QPoint(slider->positionOf(6), top));
    QTest::mouseMove(slider, QPoint(slider->positionOf(8), top));
    QTest::mouseRelease(slider, Qt::LeftButton, {}, QPoint(slider->positionOf(8), top));
    QCOMPARE(playback->loopRange(), loopOf(1, 8));
    QCOMPARE(playback->time(), pausedAt);  // dragging a flag does not scrub

    // The slider's context menu: in/out at the frame under the mouse, an out
    // point before the in point moves it along, and Clear.
    {
        auto menu = slider->loopMenu(5);
        QCOMPARE(menu->actions().size(), 3);
        menu->actions()[0]->trigger();
        QCOMPARE(playback->loopRange(), loopOf(5, 8));
    }
    slider->loopMenu(2)->actions()[1]->trigger();
    QCOMPARE(playback->loopRange(), loopOf(2, 2));

    // Export renders the loop's frames only, numbered as scene frames.
    playback->setLoopIn(4);
    playback->setLoopOut(7);
    const auto scene = w.document()->scene();
    ExportJob job = w.exportJob(
        scene, std::make_unique<PngSequenceSink>(exportSequencePattern(dir.filePath("out"), "small", 11)),
        "out");
    QCOMPARE(job.firstFrame, 4);
    QCOMPARE(job.lastFrame, 7);
    AnimationExporter exporter;
    QSignalSpy finished(&exporter, &AnimationExporter::finished);
    exporter.start(std::move(job));
    QVERIFY(finished.wait(kWaitMs * 3));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(finished.at(0).at(1).toString()));
    QCOMPARE(QDir(dir.filePath("out")).entryList({"*.png"}),
             (QStringList{"small_0004.png", "small_0005.png", "small_0006.png", "small_0007.png"}));
    Image read;
    std::string error;
    QVERIFY2(readPng(dir.filePath("out/small_0005.png").toStdString(), read, error), error.c_str());
    QVERIFY(read == coreRender(*scene, 5, 96, 72));

    // Cleared (Alt+X): the whole scene again, for playing and exporting.
    QTest::keyClick(w.viewport(), Qt::Key_X, Qt::AltModifier);
    QVERIFY(!playback->loopRange());
    QVERIFY(!slider->loop());
    const ExportJob all = w.exportJob(scene, nullptr, "all");
    QCOMPARE(all.firstFrame, 0);
    QCOMPARE(all.lastFrame, 10);
}

void ViewerTest::pickNamesTheLineALoopOrIncludeMadeItBy() {
    // Three balls made by one line of a /repeat loop, and a crate from an included file.
    QTemporaryDir dir;
    writeFile(dir.filePath("parts.f2"), "# parts\n/box crate 1.5 1.5 1.5 0 2.5 8\n");
    const QByteArray text =
        "/camera 96 72 0.6 0 0 -10\n/background 20 30 40\n/amb_light 0.3\n/dir_light 0.8 0.3 -0.5 1\n"
        "/repeat i 0 2\n  /sphere ball{i} 1 (i*3-3) 0 8\n/end\n/include parts.f2\n";
    writeFile(dir.filePath("loops.f2"), text);
    auto window = windowOn(dir.filePath("loops.f2"), 0);
    QVERIFY(window);
    MainWindow& w = *window;
    w.editorDock()->hide();
    w.setRenderScale(RenderScale::SceneSize);
    QVERIFY(waitForShownFrame(w, 0));
    auto clickAt = [&](Vec3 world) { QVERIFY(clickWorldPoint(w, world)); };

    // ball2 is selected at the loop's line, and the status bar says a loop made it.
    clickAt({3, 0, 8});
    QVERIFY(w.selection());
    QCOMPARE(w.selection()->target(), QStringLiteral("ball2"));
    QCOMPARE(w.editor()->textCursor().selectedText(), QStringLiteral("  /sphere ball{i} 1 (i*3-3) 0 8"));
    QCOMPARE(w.editor()->textCursor().blockNumber(), 5);
    QVERIFY2(w.statusBar()->currentMessage().contains("ball2 is made by line 6, one of 3 objects"),
             qPrintable(w.statusBar()->currentMessage()));

    // Its first key goes to the end, not into the loop (where every pass would read it).
    QVERIFY(w.keySelectionHere());
    QTextDocument* doc = w.editor()->document();
    QCOMPARE(doc->findBlockByNumber(8).text(), QStringLiteral("/key 0 ball2 3 0 8 0 0 0"));
    QCOMPARE(doc->findBlockByNumber(7).text(), QStringLiteral("/include parts.f2"));
    w.editor()->undo();
    QCOMPARE(w.editor()->toPlainText(), QString::fromUtf8(text));

    // The crate is made in parts.f2: its /include line is selected, the status bar names the place.
    w.editor()->moveCursor(QTextCursor::Start);
    clickAt({0, 2.5f, 8});
    QVERIFY(w.selection());
    QCOMPARE(w.selection()->target(), QStringLiteral("crate"));
    QCOMPARE(w.editor()->textCursor().selectedText(), QStringLiteral("/include parts.f2"));
    QCOMPARE(w.statusBar()->currentMessage(),
             QStringLiteral("crate made in parts.f2:2 (included at line 8)"));
}

QTEST_MAIN(ViewerTest)
#include "viewer_test.moc"
