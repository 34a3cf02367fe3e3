#pragma once
/// File › Save Frame, Export PNG Sequence and Export Video: the file dialogs,
/// the refusal to overwrite the scene or a file it includes, and the export
/// job taken from the current view and loop (animation_exporter.h runs it).
#include <QObject>
#include <QString>
#include <functional>
#include <memory>

#include "animation_exporter.h"
#include "core/render/image.h"

class QMainWindow;

namespace f2 {
struct SceneDesc;
class FrameSink;
}  // namespace f2

namespace f2::viewer {

class StudioSession;
class ViewportWidget;

class ExportActions : public QObject {
    Q_OBJECT
   public:
    /// Dialogs and messages go to `window`; the view is `viewport`'s.
    ExportActions(QMainWindow* window, StudioSession* session, ViewportWidget* viewport);

    /// The folder the save and export dialogs start in: the scene's (the
    /// working folder for an untitled scene).
    QString outputFolder() const;
    /// The frame *Save Frame* writes, given to `done` once rendered: the
    /// current time and view, at the render size (the scene's /camera size at
    /// *Scene Size*, whatever the docks take from the window).
    void frameToSave(std::function<void(const Image&)> done) const;
    /// The export of `scene` into `sink` from the current view: the loop's
    /// frames when loop points are set, else frames 0..last, at the scene's
    /// /camera size. `destination` names the output in messages.
    ExportJob exportJob(std::shared_ptr<const SceneDesc> scene, std::unique_ptr<FrameSink> sink,
                        const QString& destination) const;

    void saveFrame();
    void exportPngSequence();
    void exportVideo();

   private:
    /// The scene's name as the start of an exported file's name.
    QString exportStem() const;
    /// True (after saying so) if `path` is the scene file, which the viewer never writes.
    bool refuseSceneFile(const QString& path, const QString& title);
    /// The export flow shared by both: runs exportJob() with progress; errors
    /// go to a message box.
    void runExport(std::shared_ptr<const SceneDesc> scene, std::unique_ptr<FrameSink> sink,
                   const QString& destination);

    QMainWindow* window_;
    StudioSession* session_;
    ViewportWidget* viewport_;
};

}  // namespace f2::viewer
