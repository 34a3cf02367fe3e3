#include "animation_exporter.h"

#include <QDir>
#include <QFile>
#include <QMetaObject>
#include <QProgressDialog>
#include <algorithm>
#include <functional>

#include "io/render_animation.h"

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
    AnimationRange range;
    range.first = job.firstFrame;
    range.last = job.lastFrame;
    range.sceneFps = range.outputFps = job.scene->fps;
    const AnimationResult result =
        renderAnimation(*job.scene, range, job.view, *job.sink, &cancel_, [this](const AnimationProgress& p) {
            QMetaObject::invokeMethod(
                this, [this, p] { emit progress(int(p.done), int(p.total)); }, Qt::QueuedConnection);
        });
    switch (result.outcome) {
        case AnimationResult::Outcome::Cancelled:
            return report(false,
                          tr("Export cancelled after %1 of %2 frames").arg(result.done).arg(result.total));
        case AnimationResult::Outcome::Failed:
            return report(false, QString::fromStdString(result.error));
        case AnimationResult::Outcome::Finished:
            return report(true, tr("Exported %1 frames to %2").arg(result.done).arg(job.destination));
    }
}

FramePattern exportSequencePattern(const QString& directory, const QString& stem, int frameCount) {
    FramePattern pattern;
    pattern.prefix = QFile::encodeName(QDir(directory).filePath(stem + "_")).toStdString();
    pattern.suffix = ".png";
    pattern.width = std::max(4, int(QString::number(std::max(0, frameCount - 1)).size()));
    pattern.zeroPad = true;
    return pattern;
}

void exportWithProgress(QWidget* parent, ExportJob job,
                        std::function<void(bool ok, bool cancelled, const QString& message)> done) {
    const int total = job.lastFrame - job.firstFrame + 1;
    auto* dialog =
        new QProgressDialog(QObject::tr("Rendering frames %1–%2…").arg(job.firstFrame).arg(job.lastFrame),
                            QObject::tr("Cancel"), 0, total, parent);
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
