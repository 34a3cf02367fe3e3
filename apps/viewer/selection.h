#pragma once
/// The picked object or part: what identifies it across edits (its name, not
/// its index), and the helpers that show it (outline, label).
#include <QRectF>
#include <QString>
#include <optional>
#include <string>

#include "core/render/camera.h"
#include "core/render/pick.h"

namespace f2::viewer {

struct Selection {
    std::string object;       ///< the object's name (a light's, or `camera`)
    std::optional<int> part;  ///< a part of a model instance: its index among the model's parts
    std::string partName;     ///< that part's name
    /// The shape clicked on that part: its index among the model's shapes
    /// (Ctrl+click goes to its line in the `/model` block; the outline and
    /// the keys stay the part's, as a shape takes no pose).
    std::optional<int> shape = std::nullopt;
    /// An object (or a part of one), else a named light or the camera: what
    /// the handles move besides objects (selected by their markers in the
    /// picture, gizmo_tool.h). findObject() finds only objects.
    enum class Kind { Object, Light, Camera };
    Kind kind = Kind::Object;

    /// `name` or `name.part`, as the scene language writes the target.
    QString target() const;
    friend bool operator==(const Selection&, const Selection&) = default;
};

/// The selection a pick names.
Selection selectionOf(const SceneDesc& scene, const PickHit& hit);
/// Index of the selected object in `scene`, if it (and its selected part) still exists.
std::optional<std::size_t> findObject(const SceneDesc& scene, const Selection& selection);

/// The image rectangle (pixels of `camera`'s image) that holds the projection
/// of `bounds`; nothing if part of it is behind the eye or it is empty.
std::optional<QRectF> outlineRect(const Camera& camera, const Bounds& bounds);

}  // namespace f2::viewer
