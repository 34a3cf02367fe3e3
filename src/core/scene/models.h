#pragma once
/// The robot F-2 and the human (SPEC 5): part tree, pivots and shapes as data.
#include <array>
#include <span>

#include "core/geometry/shape_kind.h"
#include "core/scene/scene_desc.h"

namespace f2 {

/// One part of a model: its parent (-1 = the model's root frame) and pivot in
/// the parent's frame.
struct ModelPart {
    PartId id;
    int parent;
    Vec3 pivot;
};

/// A shape attached to a part, centred at `centre` in the part's frame.
struct ModelShape {
    PartId part;
    ShapeKind kind;
    Vec3 size;  ///< as SceneObject::size
    Vec3 centre;
    bool ownColor = false;  ///< eyes keep their colour when the head is painted
    Color8 color{};
};

struct ModelDef {
    /// Parents come before children, so one pass computes every part frame.
    std::array<ModelPart, kPartCount> parts;
    std::span<const ModelShape> shapes;  ///< in the order `f2 export --prims` writes them
};

const ModelDef& robotModel();
const ModelDef& humanModel();
/// The model of a robot or human object.
const ModelDef& modelOf(ObjectKind kind);

/// How many primitives an object expands to: 1 for a primitive, 6 robot, 4 human.
std::size_t primitiveCountOf(ObjectKind kind);

/// Shape kind of a primitive object.
ShapeKind shapeKindOf(ObjectKind kind);

}  // namespace f2
