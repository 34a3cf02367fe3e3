#include "test_support.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QListWidget>
#include <QTemporaryDir>
#include <QTest>
#include <optional>

#include "core/render/camera.h"
#include "core/render/renderer.h"
#include "image_convert.h"
#include "main_window.h"
#include "playback.h"
#include "scene_document.h"
#include "viewport_widget.h"

namespace f2::viewer::test {

QString smallSceneFile(const QTemporaryDir& dir) {
    const QString path = dir.filePath("scene.f2");
    writeFile(path, kSmallScene);
    return path;
}

std::unique_ptr<MainWindow> windowOn(const QString& path, double t, QSize picture) {
    auto w = std::make_unique<MainWindow>();
    w->resizeForViewport(picture);
    w->show();
    if (!QTest::qWaitForWindowExposed(w.get())) return nullptr;
    w->openFile(path);
    w->playback()->pause();
    w->playback()->seek(t);
    if (!waitForShownFrame(*w, t)) return nullptr;
    return w;
}

void writeFile(const QString& path, const QByteArray& text) {
    QFile f(path);
    QVERIFY2(f.open(QIODevice::WriteOnly | QIODevice::Truncate), qPrintable(path));
    QCOMPARE(f.write(text), text.size());
}

QByteArray readFile(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

Image coreRender(const SceneDesc& scene, double t, int width, int height, int antialias) {
    Renderer renderer;
    Image image;
    RenderOptions options;
    options.antialias = antialias;
    renderer.render(scene, t, cameraAt(scene, t).resized(width, height), image, options);
    return image;
}

Image frameToSave(const MainWindow& w) {
    std::optional<Image> saved;
    w.frameToSave([&](const Image& image) { saved = image; });
    if (!QTest::qWaitFor([&] { return saved.has_value(); }, kWaitMs)) return Image{};
    return saved.value_or(Image{});
}

bool waitForShownFrame(MainWindow& w, double t) {
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < kWaitMs) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        if (!w.renderController()->hasPendingFrames() && w.shownFrame().serial != 0 &&
            w.shownFrame().time == t && !w.isRefining())
            return true;
        QTest::qWait(5);
    }
    return false;
}

QString problemsText(MainWindow& w) {
    QStringList lines;
    for (int i = 0; i < w.problemsList()->count(); ++i) lines << w.problemsList()->item(i)->text();
    return lines.join('\n');
}

bool clickWorldPoint(MainWindow& w, Vec3 world) {
    const CameraDesc& desc = w.document()->scene()->camera;
    float px = 0, py = 0;
    if (!Camera::fromDesc(desc).project(world, px, py)) return false;
    const QRectF onScreen = w.viewport()->imageRect();
    QTest::mouseClick(w.viewport(), Qt::LeftButton, {},
                      QPoint(int(onScreen.left() + px * onScreen.width() / desc.width),
                             int(onScreen.top() + py * onScreen.height() / desc.height)));
    return true;
}

void expectViewportMatchesCore(MainWindow& w, double t) {
    const QImage shown = w.viewport()->image();
    QVERIFY(!shown.isNull());
    QCOMPARE(shown.size(), w.viewport()->renderSize());
    const Image expected =
        coreRender(*w.document()->scene(), t, shown.width(), shown.height(), w.shownFrame().antialias);
    QVERIFY2(fromQImage(shown) == expected,
             "viewer image differs from Renderer::render at the same camera/size");
}

}  // namespace f2::viewer::test
