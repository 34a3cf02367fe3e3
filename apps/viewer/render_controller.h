#pragma once
/// Renders frames off the GUI thread (the pattern of Qt's Mandelbrot example):
/// the GUI posts requests, one worker thread owning a core Renderer serves
/// them, and finished frames come back as queued signals carrying a QImage.
#include <QElapsedTimer>
#include <QImage>
#include <QObject>
#include <QSize>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "core/render/camera.h"
#include "core/render/pick.h"
#include "core/render/renderer.h"
#include "core/scene/scene_desc.h"

namespace f2::viewer {

/// An object of the request's scene, or one part of it, whose world bounds
/// come back with the frame (the selection's outline: the worker has the
/// evaluated frame at hand, so the GUI thread need not evaluate it again).
struct BoundsOf {
    std::size_t object = 0;
    std::optional<int> part;
    friend bool operator==(const BoundsOf&, const BoundsOf&) = default;
};

/// Everything one frame depends on. The scene is an immutable snapshot, so the
/// worker can read it while the GUI loads the next version of the file.
struct RenderRequest {
    std::shared_ptr<const SceneDesc> scene;
    double time = 0;        ///< in frames, may be fractional
    Camera camera;          ///< already at the render size
    RenderOptions options;  ///< anti-aliasing and view mode, as `f2 render --aa --view`
    std::optional<BoundsOf> boundsOf = std::nullopt;  ///< bounds to bring back with the frame
};

/// What came back with a frame.
struct FrameInfo {
    double time = 0;
    FrameTimings timings;
    QSize size;
    int antialias = 1;                       ///< N of the N x N samples per pixel it was rendered with
    ViewMode view = ViewMode::Shaded;        ///< what its pixels show
    quint64 serial = 0;                      ///< request number, increasing
    std::shared_ptr<const SceneDesc> scene;  ///< the scene it shows
    std::optional<BoundsOf> boundsOf;        ///< the request's
    std::optional<Bounds> bounds;            ///< of boundsOf, at this frame's time
    /// A drive of the scene without a finite value at this time (SPEC 10.7): its error, else empty.
    std::string driveProblem;
};

class RenderController : public QObject {
    Q_OBJECT
   public:
    /// `threads` for the core Renderer (0 = every core).
    explicit RenderController(int threads = 0, QObject* parent = nullptr);
    /// Cancels the frame in flight and joins the worker.
    ~RenderController() override;

    /// Never blocks. Latest request wins: if the worker is busy, this replaces
    /// any request still waiting (that one is skipped, never rendered).
    void request(RenderRequest request);

    /// A picture to keep (Save Frame): rendered by the same worker before a
    /// waiting frame, never replaced by a newer request, and handed whole (the
    /// core image, the bytes `f2 render` writes) to `done` on the GUI thread.
    /// Not called if the controller is destroyed first.
    void requestStill(RenderRequest request, std::function<void(const Image&)> done);

    /// GUI thread: the latest request has not come back as frameReady yet.
    bool hasPendingFrames() const { return lastDeliveredSerial_ + 1 < nextSerial_; }
    /// Frames delivered in the last second, per second (0 when idle).
    double achievedFps() const;
    quint64 framesDelivered() const { return delivered_; }
    /// Requests replaced before the worker got to them.
    quint64 framesSkipped() const { return skipped_.load(); }

    /// Test hook: the worker sleeps this long before each frame, to stand in
    /// for a slow scene. 0 (the default) disables it. Lowering it releases a
    /// frame being held, so a test can hold one (a long delay) until it is done.
    void setDebugDelay(std::chrono::milliseconds delay) { debugDelayMs_.store(int(delay.count())); }

   signals:
    /// Emitted in the GUI thread with a finished frame.
    void frameReady(const QImage& image, const f2::viewer::FrameInfo& info);

   private:
    struct Still {
        RenderRequest request;
        std::function<void(const Image&)> done;
    };
    void workerLoop(int threads);
    /// Worker thread: renders `still` and posts its picture to the GUI thread.
    void renderStill(Renderer& renderer, Still still);
    void deliver(const QImage& image, const FrameInfo& info);

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<RenderRequest> pending_;  // guarded by mutex_
    quint64 pendingSerial_ = 0;             // guarded by mutex_
    std::deque<Still> stills_;              // guarded by mutex_
    bool quit_ = false;                     // guarded by mutex_
    quint64 nextSerial_ = 1;                // GUI thread only
    std::atomic<bool> cancel_{false};
    std::atomic<int> debugDelayMs_{0};
    std::atomic<quint64> skipped_{0};

    // GUI thread only.
    quint64 delivered_ = 0;
    quint64 lastDeliveredSerial_ = 0;
    QElapsedTimer clock_;
    std::deque<qint64> deliveryTimesMs_;

    std::thread worker_;  // last: started after every other member exists
};

}  // namespace f2::viewer

Q_DECLARE_METATYPE(f2::viewer::FrameInfo)
