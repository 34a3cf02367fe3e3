#pragma once
/// Renders a range of frames into a FrameSink on its own thread, reporting
/// progress with queued signals and stopping promptly when cancelled.
#include <QObject>
#include <QString>
#include <atomic>
#include <functional>
#include <memory>
#include <thread>

#include "core/render/camera.h"
#include "core/scene/scene_desc.h"
#include "frame_sink.h"

class QWidget;

namespace f2::viewer {

struct ExportJob {
    std::shared_ptr<const SceneDesc> scene;
    Camera camera;  ///< image size of every frame, and the view when `followScene` is false
    /// Each frame seen by the scene's camera at its time (cameraAt), at
    /// `camera`'s size; false keeps `camera`'s view (the user looks around).
    bool followScene = true;
    Camera cameraAt(double t) const {
        return followScene ? f2::cameraAt(*scene, t).resized(camera.width, camera.height) : camera;
    }
    int firstFrame = 0;
    int lastFrame = 0;
    std::unique_ptr<FrameSink> sink;
};

class AnimationExporter : public QObject {
    Q_OBJECT
   public:
    explicit AnimationExporter(QObject* parent = nullptr);
    /// Cancels and joins a running export.
    ~AnimationExporter() override;

    /// Starts rendering on a worker thread (its own Renderer: the live view's
    /// renderer belongs to RenderController's thread). One job at a time.
    void start(ExportJob job);
    bool isRunning() const { return running_; }

   public slots:
    void cancel() { cancel_.store(true); }

   signals:
    /// `done` of `total` frames are written.
    void progress(int done, int total);
    /// `ok` false on error or cancel; `message` says what happened.
    void finished(bool ok, const QString& message);

   private:
    void run(ExportJob job);
    void join();

    std::atomic<bool> cancel_{false};
    bool running_ = false;  // GUI thread
    std::thread worker_;
};

/// Runs `job` behind a cancellable QProgressDialog over `parent`; the dialog
/// and the exporter delete themselves when done. `done` gets the result and
/// whether the user cancelled.
void exportWithProgress(QWidget* parent, ExportJob job,
                        std::function<void(bool ok, bool cancelled, const QString& message)> done);

}  // namespace f2::viewer
