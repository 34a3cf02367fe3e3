#pragma once
/// Runs f2::renderAnimation (the loop `f2 render` uses too) on its own thread
/// for an export, reporting progress with queued signals and stopping promptly
/// when cancelled.
#include <QObject>
#include <QString>
#include <atomic>
#include <functional>
#include <memory>
#include <thread>

#include "core/render/camera.h"
#include "core/scene/scene_desc.h"
#include "io/frame_pattern.h"
#include "io/frame_sink.h"

class QWidget;

namespace f2::viewer {

struct ExportJob {
    std::shared_ptr<const SceneDesc> scene;
    Camera camera;  ///< view and image size of every frame
    int firstFrame = 0;
    int lastFrame = 0;
    std::unique_ptr<FrameSink> sink;
    QString destination;  ///< where the sink writes, for the final message
};

/// The export's PNG sequence `<directory>/<stem>_0000.png`, ...: at least four
/// digits, more if `frameCount` needs them.
FramePattern exportSequencePattern(const QString& directory, const QString& stem, int frameCount);

class AnimationExporter : public QObject {
    Q_OBJECT
   public:
    explicit AnimationExporter(QObject* parent = nullptr);
    /// Cancels and joins a running export.
    ~AnimationExporter() override;

    /// Starts rendering on a worker thread (renderAnimation's own Renderer: the
    /// live view's renderer belongs to RenderController's thread). One job at a time.
    void start(ExportJob job);
    bool isRunning() const { return running_; }

   public slots:
    void cancel() { cancel_.store(true); }

   signals:
    /// `done` of `total` frames are in the output (written, or handed to the encoder).
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
