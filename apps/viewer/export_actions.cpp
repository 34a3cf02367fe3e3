#include "export_actions.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QMessageBox>
#include <QStatusBar>

#include "io/png_writer.h"
#include "io/sequence_sink.h"
#include "io/video_sink.h"
#include "playback.h"
#include "scene_document.h"
#include "studio_session.h"
#include "viewport_widget.h"

namespace f2::viewer {

ExportActions::ExportActions(QMainWindow* window, StudioSession* session, ViewportWidget* viewport)
    : QObject(window), window_(window), session_(session), viewport_(viewport) {}

QString ExportActions::exportStem() const {
    // "<default scene>" has no file name: its brackets do not belong in one.
    return QFileInfo(session_->document()->displayName()).completeBaseName().remove('<').remove('>');
}

bool ExportActions::refuseSceneFile(const QString& path, const QString& title) {
    // The viewer never writes the scene file or a file it includes, whatever
    // name the user picks.
    for (const QString& source : session_->document()->sources()) {
        if (QFileInfo(path) != QFileInfo(source)) continue;
        QMessageBox::warning(window_, title,
                             source == session_->document()->path()
                                 ? tr("Refusing to overwrite the scene file.")
                                 : tr("Refusing to overwrite a file the scene includes."));
        return true;
    }
    return false;
}

QString ExportActions::outputFolder() const {
    return session_->document()->path().isEmpty() ? QDir::currentPath()
                                                  : QFileInfo(session_->document()->path()).absolutePath();
}

void ExportActions::frameToSave(std::function<void(const Image&)> done) const {
    session_->renderStill(viewport_->viewCamera(viewport_->renderSize()), std::move(done));
}

void ExportActions::saveFrame() {
    const QString stem = exportStem();
    const QString suggested =
        QStringLiteral("%1_frame_%2.png").arg(stem).arg(session_->playback()->frame(), 4, 10, QChar('0'));
    const QString path = QFileDialog::getSaveFileName(
        window_, tr("Save Frame"), QDir(outputFolder()).filePath(suggested), tr("PNG images (*.png)"));
    if (path.isEmpty() || refuseSceneFile(path, tr("Save Frame"))) return;
    window_->statusBar()->showMessage(tr("Saving %1…").arg(path));
    frameToSave([window = window_, path](const Image& image) {
        std::string error;
        if (!writePng(image, QFile::encodeName(path).toStdString(), error)) {
            window->statusBar()->clearMessage();
            QMessageBox::warning(window, tr("Save Frame"), QString::fromStdString(error));
        } else {
            window->statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
        }
    });
}

void ExportActions::exportPngSequence() {
    auto scene = session_->document()->scene();
    if (!scene) return;
    session_->playback()->pause();  // the export gets the CPU
    const QString dir =
        QFileDialog::getExistingDirectory(window_, tr("Export PNG Sequence to Folder"), outputFolder());
    if (dir.isEmpty()) return;
    const QString stem = exportStem();
    const FramePattern pattern = exportSequencePattern(dir, stem, session_->playback()->playRange().last + 1);
    runExport(std::move(scene), std::make_unique<PngSequenceSink>(pattern),
              QDir(dir).filePath(stem + "_*.png"));
}

void ExportActions::exportVideo() {
    auto scene = session_->document()->scene();
    if (!scene) return;
    session_->playback()->pause();
    QFileDialog dialog(window_, tr("Export Video"), QDir(outputFolder()).filePath(exportStem() + ".mp4"),
                       tr("MP4 video (*.mp4);;WebM video (*.webm);;GIF animation (*.gif)"));
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setDefaultSuffix("mp4");
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty()) return;
    const QString path = dialog.selectedFiles().first();
    const std::string file = QFile::encodeName(path).toStdString();
    const auto format = videoFormatForPath(file);
    if (!format) {
        QMessageBox::warning(window_, tr("Export Video"), tr("Use a .mp4, .webm or .gif file name."));
        return;
    }
    if (refuseSceneFile(path, tr("Export Video"))) return;
    const Color8 bg = scene->background;
    runExport(std::move(scene), std::make_unique<VideoSink>(file, *format, Rgb8{bg.r, bg.g, bg.b}), path);
}

ExportJob ExportActions::exportJob(std::shared_ptr<const SceneDesc> scene, std::unique_ptr<FrameSink> sink,
                                   const QString& destination) const {
    ExportJob job;
    // Like `f2 render`: the scene's /camera size, seen from the current view.
    // The scene's moving camera, unless the user is looking around.
    const QSize size(scene->camera.width, scene->camera.height);
    job.view = viewport_->isOrbiting() ? FrameView::fixedCamera(viewport_->viewCamera(size))
                                       : FrameView::sceneCamera(size.width(), size.height());
    job.scene = std::move(scene);
    // The loop's frames when it is set, else the whole scene.
    const FrameRange frames = session_->playback()->playRange();
    job.firstFrame = frames.first;
    job.lastFrame = frames.last;
    job.sink = std::move(sink);
    job.destination = destination;
    return job;
}

void ExportActions::runExport(std::shared_ptr<const SceneDesc> scene, std::unique_ptr<FrameSink> sink,
                              const QString& destination) {
    ExportJob job = exportJob(std::move(scene), std::move(sink), destination);
    exportWithProgress(window_, std::move(job), [this](bool ok, bool cancelled, const QString& message) {
        if (ok || cancelled)
            window_->statusBar()->showMessage(message, 10000);
        else
            QMessageBox::warning(window_, tr("Export"), message);
    });
}

}  // namespace f2::viewer
