// QtTest of View › Mode: switching the menu changes the picture to the
// core's image of that mode, the status bar names it, the cost view carries
// its legend, picking keeps working, and back on Shaded the picture refines to
// the --aa 4 image again. Waits are bounded and driven by the frameReady signal.
#include <QAction>
#include <QCoreApplication>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>

#include "core/render/renderer.h"
#include "core/render/view_legend.h"
#include "image_convert.h"
#include "main_window.h"
#include "playback.h"
#include "render_controller.h"
#include "scene_document.h"
#include "test_support.h"
#include "view_mode_menu.h"
#include "viewport_widget.h"

using namespace f2;
using namespace f2::viewer;
using namespace f2::viewer::test;

namespace {

// kSmallScene at 200 x 150: large enough for the depth and cost legends.
QByteArray largerScene() { return QByteArray(kSmallScene).replace("/camera 96 72", "/camera 200 150"); }

/// Waits (frameReady, bounded) until the picture on screen is the latest
/// request, in `mode`, and done refining.
bool waitForView(MainWindow& w, ViewMode mode) {
    QSignalSpy frames(w.renderController(), &RenderController::frameReady);
    // A frame just asked for is scheduled on a zero timer: let it be requested first.
    QCoreApplication::processEvents();
    while (w.shownFrame().view != mode || w.renderController()->hasPendingFrames() || w.isRefining())
        if (!frames.wait(kWaitMs)) return false;
    return true;
}

/// The View › Mode action named `text`, found through the menu bar as a user would.
QAction* modeAction(MainWindow& w, const QString& text) {
    for (QAction* top : w.menuBar()->actions()) {
        if (top->text() != QStringLiteral("&View") || !top->menu()) continue;
        for (QAction* sub : top->menu()->actions()) {
            if (sub->text() != QStringLiteral("&Mode") || !sub->menu()) continue;
            for (QAction* a : sub->menu()->actions())
                if (a->text() == text) return a;
        }
    }
    return nullptr;
}

/// The core's image of `mode` at the window's camera and picture size.
Image coreView(MainWindow& w, double t, ViewMode mode) {
    Renderer renderer;
    Image image;
    RenderOptions options;
    options.view = mode;
    const QImage& shown = w.viewport()->image();
    renderer.render(*w.document()->scene(), t, w.viewport()->viewCamera(shown.size()), image, options);
    return image;
}

bool statusNames(MainWindow& w, const QString& text) {
    for (QLabel* label : w.statusBar()->findChildren<QLabel*>())
        if (label->text() == text) return true;
    return false;
}

}  // namespace

class ViewModeTest : public QObject {
    Q_OBJECT
   private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName("F2StageTest");
        QCoreApplication::setApplicationName("f2-viewer-view-mode-test");
    }
    void menuSwitchesThePicture();
    void pickingWorksInEveryMode();
};

void ViewModeTest::menuSwitchesThePicture() {
    QTemporaryDir dir;
    const QString path = dir.filePath("scene.f2");
    writeFile(path, largerScene());
    auto window = windowOn(path, 5);
    QVERIFY(window);
    MainWindow& w = *window;
    w.setRenderScale(RenderScale::SceneSize);
    QVERIFY(waitForView(w, ViewMode::Shaded));
    const Image shaded = fromQImage(w.viewport()->image());
    QVERIFY(shaded == coreRender(*w.document()->scene(), 5, 200, 150, MainWindow::kRefinedAntialias));
    QVERIFY(statusNames(w, "view: Shaded"));

    for (ViewMode mode : kViewModes) {
        if (mode == ViewMode::Shaded) continue;
        const QString text = ViewModeMenu::label(mode);
        QAction* action = modeAction(w, text);
        QVERIFY2(action, qPrintable(text));
        QVERIFY(action->isCheckable());
        action->trigger();
        QVERIFY(action->isChecked());
        QCOMPARE(w.viewModes()->mode(), mode);
        QVERIFY2(waitForView(w, mode), qPrintable(text));
        const Image shown = fromQImage(w.viewport()->image());
        QVERIFY2(shown != shaded, qPrintable(text));
        QVERIFY2(shown == coreView(w, 5, mode), qPrintable(text));
        QCOMPARE(w.shownFrame().antialias, 1);  // diagnostic views do not refine
        QVERIFY2(statusNames(w, "view: " + text), qPrintable(text));
        // Save Frame writes what the picture shows.
        QVERIFY2(frameToSave(w) == shown, qPrintable(text));
    }
    // The cost view (last) shows its legend's panel at the bottom left.
    const Image cost = fromQImage(w.viewport()->image());
    QVERIFY(cost.at(kLegendMargin, 150 - kLegendMargin - kLegendHeight) == (Rgb8{24, 24, 24}));

    // Back to Shaded: refined again to the --aa 4 image, byte for byte.
    modeAction(w, ViewModeMenu::label(ViewMode::Shaded))->trigger();
    QVERIFY(waitForView(w, ViewMode::Shaded));
    QCOMPARE(w.shownFrame().antialias, MainWindow::kRefinedAntialias);
    QVERIFY(fromQImage(w.viewport()->image()) == shaded);
}

void ViewModeTest::pickingWorksInEveryMode() {
    QTemporaryDir dir;
    auto window = windowOn(smallSceneFile(dir), 5);
    QVERIFY(window);
    MainWindow& w = *window;
    for (ViewMode mode : kViewModes) {
        w.viewModes()->setMode(mode);
        QVERIFY(waitForView(w, mode));
        // At frame 5 the ball is straight ahead, in the picture's centre.
        const QImage& shown = w.viewport()->image();
        w.selectAt(QPointF(shown.width() / 2.0, shown.height() / 2.0));
        QVERIFY2(w.selection(), qPrintable(ViewModeMenu::label(mode)));
        QCOMPARE(w.selection()->target(), QStringLiteral("ball"));
        w.setSelection(std::nullopt);
    }
}

QTEST_MAIN(ViewModeTest)
#include "view_mode_test.moc"
