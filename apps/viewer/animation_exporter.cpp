#include "animation_exporter.h"

#include <QMetaObject>
#include <QProgressDialog>
#include <functional>

#include "core/render/renderer.h"

namespace f2::viewer {

AnimationExporter::AnimationExporter(QObject* parent) : QObject(parent) {}

AnimationExporter::~AnimationExporter() {
    cancel();
    join();
}

void AnimationExporter::join() {
    if (worker_.joinable()) worker_.join();
}

void AnimationExporter::start(ExportJob job) {
    if (running_) return;
    join();
    running_ = true;
    cancel_.store(false);
    worker_ = std::thread([this, job = std::move(job)]() mutable { run(std::move(job)); });
}

void AnimationExporter::run(ExportJob job) {
    const int total = job.lastFrame - job.firstFrame + 1;
    auto report = [this](bool ok, QString message) {
        QMetaObject::invokeMethod(
            this,
            [this, ok, message] {
                running_ = false;
                join();
                emit finished(ok, message);
            },
            Qt::QueuedConnection);
    };
    std::string error;
    if (!job.sink->begin(job.camera.width, job.camera.height, job.scene->fps, total, error))
        return report(false, QString::fromStdString(error));

    Renderer renderer;
    Image image;
    for (int i = 0; i < total; ++i) {
        renderer.render(*job.scene, job.firstFrame + i, job.cameraAt(job.firstFrame + i), image, {}, &cancel_);
        if (cancel_.load()) {
            job.sink->finish(true, error);
            return report(false, tr("Export cancelled after %1 of %2 frames").arg(i).arg(total));
        }
        if (!job.sink->write(image, i, error)) {
            job.sink->finish(true, error);
            return report(false, QString::fromStdString(error));
        }
        QMetaObject::invokeMethod(
            this, [this, i, total] { emit progress(i + 1, total); }, Qt::QueuedConnection);
    }
    if (!job.sink->finish(false, error)) return report(false, QString::fromStdString(error));
    report(true, tr("Exported %1 frames to %2").arg(total).arg(job.sink->destination()));
}

void exportWithProgress(QWidget* parent, ExportJob job,
                        std::function<void(bool ok, bool cancelled, const QString& message)> done) {
    const int total = job.lastFrame - job.firstFrame + 1;
    auto* dialog =
        new QProgressDialog(QObject::tr("Rendering frames…"), QObject::tr("Cancel"), 0, total, parent);
    dialog->setWindowModality(Qt::WindowModal);
    dialog->setMinimumDuration(0);
    dialog->setAutoClose(false);
    dialog->setAutoReset(false);
    auto* exporter = new AnimationExporter(dialog);
    QObject::connect(exporter, &AnimationExporter::progress, dialog, &QProgressDialog::setValue);
    QObject::connect(dialog, &QProgressDialog::canceled, exporter, &AnimationExporter::cancel);
    QObject::connect(exporter, &AnimationExporter::finished, dialog,
                     [dialog, done](bool ok, const QString& m) {
                         const bool cancelled = dialog->wasCanceled();
                         dialog->close();
                         dialog->deleteLater();  // also deletes the (already joined) exporter
                         if (done) done(ok, cancelled, m);
                     });
    dialog->setValue(0);
    exporter->start(std::move(job));
}

}  // namespace f2::viewer
