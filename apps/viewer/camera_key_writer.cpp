#include "camera_key_writer.h"

#include <QCoreApplication>

namespace f2::viewer {

CameraKeyWrite cameraKeyWrite(const QString& text, const SceneDesc& scene, int frame, const Pose& pose) {
    const QString camera = QStringLiteral("camera");
    CameraKeyWrite write;
    QString written = text;
    // The camera's first key, away from frame 0: the frames before it would
    // take its pose. Keys in the text that did not parse yet count too.
    if (frame != 0 && scene.camera.track.keys.empty()) {
        const TextEdit start = keyEdit(written, camera, 0, scene.camera.pose, cameraLine(written));
        if (!start.replace) {
            write.edits.push_back(start);
            written = withEdit(written, start);
            write.note = QCoreApplication::translate(
                             "f2::viewer::MainWindow",
                             "The camera's first key: /key 0 camera keeps the shot's /camera pose at "
                             "frame 0, so frames before %1 still start there.")
                             .arg(frame);
        }
    }
    write.edits.push_back(keyEdit(written, camera, frame, pose, cameraLine(written)));
    return write;
}

}  // namespace f2::viewer
