#pragma once
// Helpers shared by the viewer's QtTest suites: a tiny scene, file helpers,
// the core's picture for comparison and waits for the window's frames.
#include <QByteArray>
#include <QSize>
#include <QString>
#include <memory>

#include "core/render/image.h"
#include "core/scene/scene_desc.h"

namespace f2::viewer {
class MainWindow;
}
class QTemporaryDir;

/// A test that needs a program the machine lacks: QSKIP with the reason, or
/// QFAIL under F2_REQUIRE_ALL_TESTS=1 (.ci/run; tests/skip.sh says why).
#define F2_QSKIP_MISSING(reason)                                                              \
    do {                                                                                      \
        if (qgetenv("F2_REQUIRE_ALL_TESTS") == "1")                                           \
            QFAIL(reason " (F2_REQUIRE_ALL_TESTS=1: nothing the tests need may be missing)"); \
        QSKIP(reason);                                                                        \
    } while (false)

namespace f2::viewer::test {

// Only a guard against a hang: every wait ends as soon as its condition holds, so a
// pass never takes this long, and a slow, shared CI machine must not fail by chance.
constexpr int kWaitMs = 60000;

/// A tiny animated scene: a sphere moving right over frames 0..10.
inline constexpr const char* kSmallScene = R"(/camera 96 72 0.6 0 0 -10
/background 20 30 40
/amb_light 0.3
/dir_light 0.8 0.3 -0.5 1
/box floor 40 1 40 0 -2 10
/sphere ball 1.5 -3 0 8
/key 0 ball
/key 10 ball 3 0 8 0 0 0
)";

/// SPEC 10.1: a model of the scene (a lamp: a foot on its base, a bulb on its
/// arm), an instance whose arm is keyed, and a robot out of sight.
inline constexpr const char* kLampScene = R"(/camera 96 72 0.6 0 0 -10
/background 20 30 40
/amb_light 0.3
/dir_light 0.8 0.3 -0.5 1
/model lamp
/part base root 0 0 0
/part arm base 0 2 0 0 0 30
/box base.foot 4 1 4 0 0 0
/sphere arm.bulb 1.5 0 2 0
/end
/lamp l1 0 -2 8
/key 0 l1.arm
/key 10 l1.arm 0 0 0 0 0 -40
/robot r 300 0 50
)";

/// Writes kSmallScene as scene.f2 in `dir`; returns its path.
QString smallSceneFile(const QTemporaryDir& dir);

/// A shown window on `path` with a `picture`-sized picture, paused at frame
/// `t` with that frame on screen (null if that does not happen in time).
std::unique_ptr<MainWindow> windowOn(const QString& path, double t, QSize picture = {96, 72});

/// Writes `text` to `path` (a QVERIFY failure if it cannot).
void writeFile(const QString& path, const QByteArray& text);
QByteArray readFile(const QString& path);

/// What `f2 render --frame t --size WxH --aa N` gives for the scene's own camera.
Image coreRender(const SceneDesc& scene, double t, int width, int height, int antialias = 1);

/// Waits until the window shows the latest requested frame, it is frame `t`
/// and, when paused, refined to its last step.
bool waitForShownFrame(MainWindow& w, double t);

/// The frame Save Frame writes, once the render controller has rendered it
/// (an empty image if it never comes).
Image frameToSave(const MainWindow& w);

/// The Problems list's lines, one per line.
QString problemsText(MainWindow& w);

/// Clicks the picture where world point `world` is drawn by the scene's
/// /camera (the window at *Scene Size*, frame 0's camera: a camera without
/// keys). False if the point is behind the camera.
bool clickWorldPoint(MainWindow& w, Vec3 world);

/// The picture on screen is the core's at the same camera, size and samples.
void expectViewportMatchesCore(MainWindow& w, double t);

}  // namespace f2::viewer::test
