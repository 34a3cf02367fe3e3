#include "render_controller.h"

#include <QMetaObject>

#include "image_convert.h"

namespace f2::viewer {

namespace {
constexpr qint64 kFpsWindowMs = 1000;  // achieved FPS averages over the last second
constexpr int kDelaySliceMs = 10;      // the debug delay checks for shutdown this often
}  // namespace

RenderController::RenderController(int threads, QObject* parent) : QObject(parent) {
    qRegisterMetaType<FrameInfo>();
    clock_.start();
    worker_ = std::thread([this, threads] { workerLoop(threads); });
}

RenderController::~RenderController() {
    {
        std::lock_guard lock(mutex_);
        quit_ = true;
        pending_.reset();
        stills_.clear();
    }
    cancel_.store(true);
    wake_.notify_all();
    worker_.join();
    // Frames the worker posted but the GUI has not run yet die with this
    // object: Qt drops queued calls whose context object is destroyed.
}

void RenderController::request(RenderRequest request) {
    {
        std::lock_guard lock(mutex_);
        if (pending_) skipped_.fetch_add(1);
        pending_ = std::move(request);
        pendingSerial_ = nextSerial_++;
    }
    wake_.notify_one();
}

void RenderController::requestStill(RenderRequest request, std::function<void(const Image&)> done) {
    {
        std::lock_guard lock(mutex_);
        stills_.push_back({std::move(request), std::move(done)});
    }
    wake_.notify_one();
}

double RenderController::achievedFps() const {
    const qint64 now = clock_.elapsed();
    int count = 0;
    for (qint64 t : deliveryTimesMs_)
        if (now - t <= kFpsWindowMs) ++count;
    return double(count) * 1000.0 / double(kFpsWindowMs);
}

void RenderController::workerLoop(int threads) {
    // The Renderer lives on this thread only: it is not safe to share.
    Renderer renderer(threads);
    Image image;
    for (;;) {
        RenderRequest request;
        quint64 serial = 0;
        std::optional<Still> still;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] { return quit_ || pending_.has_value() || !stills_.empty(); });
            if (quit_) return;
            if (!stills_.empty()) {  // a picture asked for is not skipped, and first
                still = std::move(stills_.front());
                stills_.pop_front();
            }
        }
        if (still) {
            renderStill(renderer, std::move(*still));
            if (cancel_.load()) return;
            continue;
        }
        {
            std::lock_guard lock(mutex_);
            if (!pending_) continue;
            request = std::move(*pending_);
            serial = pendingSerial_;
            pending_.reset();
        }
        // The delay is read again every slice: lowering it releases a frame it holds.
        const auto held = std::chrono::steady_clock::now();
        while (!cancel_.load() &&
               std::chrono::steady_clock::now() - held < std::chrono::milliseconds(debugDelayMs_.load()))
            std::this_thread::sleep_for(std::chrono::milliseconds(kDelaySliceMs));

        FrameInfo info;
        info.time = request.time;
        info.serial = serial;
        info.antialias = request.options.antialias;
        info.view = request.options.view;
        info.driveProblem = firstDriveProblem(*request.scene, request.time).value_or("");
        info.timings =
            renderer.render(*request.scene, request.time, request.camera, image, request.options, &cancel_);
        info.size = QSize(image.width, image.height);
        if (cancel_.load()) return;  // only the destructor cancels
        info.scene = request.scene;
        info.boundsOf = request.boundsOf;
        if (request.boundsOf)
            info.bounds = selectionBounds(*request.scene, renderer.frame(), request.boundsOf->object,
                                          request.boundsOf->part);
        QImage frame = toQImage(image);
        // Hand the frame to the GUI thread; the worker never waits for it.
        QMetaObject::invokeMethod(
            this, [this, frame, info] { deliver(frame, info); }, Qt::QueuedConnection);
    }
}

void RenderController::renderStill(Renderer& renderer, Still still) {
    auto image = std::make_shared<Image>();
    const RenderRequest& r = still.request;
    renderer.render(*r.scene, r.time, r.camera, *image, r.options, &cancel_);
    if (cancel_.load()) return;  // only the destructor cancels
    QMetaObject::invokeMethod(
        this, [done = std::move(still.done), image] { done(*image); }, Qt::QueuedConnection);
}

void RenderController::deliver(const QImage& image, const FrameInfo& info) {
    ++delivered_;
    lastDeliveredSerial_ = info.serial;
    const qint64 now = clock_.elapsed();
    deliveryTimesMs_.push_back(now);
    while (!deliveryTimesMs_.empty() && now - deliveryTimesMs_.front() > kFpsWindowMs)
        deliveryTimesMs_.pop_front();
    emit frameReady(image, info);
}

}  // namespace f2::viewer
