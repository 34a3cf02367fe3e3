#include "selection.h"

#include <algorithm>

#include "core/scene/models.h"

namespace f2::viewer {

QString Selection::target() const {
    QString name = QString::fromStdString(object);
    if (part) name += QLatin1Char('.') + QString::fromStdString(partName);
    return name;
}

Selection selectionOf(const SceneDesc& scene, const PickHit& hit) {
    const SceneObject& object = scene.objects[hit.object];
    return {object.name, hit.part,
            hit.part ? object.model->parts[std::size_t(*hit.part)].name : std::string(),
            hit.part ? std::optional(hit.shape) : std::nullopt};
}

std::optional<std::size_t> findObject(const SceneDesc& scene, const Selection& selection) {
    if (selection.kind != Selection::Kind::Object) return std::nullopt;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        if (scene.objects[i].name != selection.object) continue;
        // A part is known by its name too: an edit of its model may move or drop it (SPEC 10.1).
        const ModelType* model = scene.objects[i].model.get();
        if (selection.part && (!model || model->partIndex(selection.partName) != *selection.part))
            return std::nullopt;
        return i;
    }
    return std::nullopt;
}

std::optional<QRectF> outlineRect(const Camera& camera, const Bounds& bounds) {
    if (!(bounds.lo.x <= bounds.hi.x)) return std::nullopt;
    float left = kInfinity, top = kInfinity, right = -kInfinity, bottom = -kInfinity;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p{corner & 1 ? bounds.hi.x : bounds.lo.x, corner & 2 ? bounds.hi.y : bounds.lo.y,
                     corner & 4 ? bounds.hi.z : bounds.lo.z};
        float px = 0, py = 0;
        if (!camera.project(p, px, py)) return std::nullopt;
        left = std::min(left, px);
        right = std::max(right, px);
        top = std::min(top, py);
        bottom = std::max(bottom, py);
    }
    return QRectF(QPointF(left, top), QPointF(right, bottom));
}

}  // namespace f2::viewer
