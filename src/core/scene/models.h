#pragma once
/// Model types (SPEC 10.1): a tree of parts with pivots and rest rotations,
/// and shapes on the parts. The robot F-2 and the human (SPEC 5) are two of
/// them, built from the same data a `/model … /end` block gives.
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/geometry/shape_kind.h"
#include "core/math/transform.h"
#include "core/scene/scene_desc.h"

namespace f2 {

/// SPEC 10.1's limits per model, and of model types per scene (the robot and
/// the human count among them).
inline constexpr int kMaxModelParts = 64;
inline constexpr int kMaxModelShapes = 256;
inline constexpr int kMaxModelTypes = 1000;

/// One part of a model: its parent (-1 = the model's root frame, else an
/// earlier part), pivot in the parent's frame and rest rotation (degrees).
struct ModelPart {
    std::string name;
    int parent = -1;
    Vec3 pivot;
    Vec3 restRotation;
    /// restRotation's matrix, when it is not zero (else no matrix product).
    std::optional<Mat3> rest;
};

/// A shape on a part: centred at `centre` in the part's frame, turned by
/// `rotation` (degrees) about that centre.
struct ModelShape {
    std::string name;  ///< `<part>.<name>` is unique in its model (the robot's two arms are `arm`)
    int part = 0;
    ShapeKind kind = ShapeKind::Sphere;
    Vec3 size;  ///< as SceneObject::size
    Vec3 centre;
    Vec3 rotation;
    std::optional<Mat3> turn;  ///< rotation's matrix, when it is not zero
    /// Its look as the model gives it: every instance starts from it.
    Appearance look;
    /// `/paint` inside the model: its colour stays when its instance or part
    /// is painted or keyed (only the shape itself changes it).
    bool ownColor = false;
};

/// A numeric parameter of a model type (SPEC 10.6) and its default.
struct ModelParam {
    std::string name;
    double value = 0;
};

struct ModelType {
    std::string name;
    std::vector<ModelParam> params;  ///< `/model <type> [<param> <default>]…`, in that order
    std::vector<ModelPart> parts;    ///< parents before children
    std::vector<ModelShape> shapes;  ///< the instance's primitives, in this order

    /// Index of the part called `name`, of the shape `name` on `part`, or -1.
    int partIndex(std::string_view name) const;
    int shapeIndex(int part, std::string_view name) const;
    /// The part's first shape (its main one: the robot's head box, not its
    /// eyes), or -1 if it has none.
    int mainShapeOf(int part) const;
};

/// Sets the matrices of `part` or `shape` from their angles.
void setRestRotation(ModelPart& part, Vec3 degrees);
void setShapeRotation(ModelShape& shape, Vec3 degrees);

/// Robot F-2 and the human of SPEC 5, shared by every scene.
const std::shared_ptr<const ModelType>& robotModel();
const std::shared_ptr<const ModelType>& humanModel();

/// The frame of a part: `worldFromParent · translate(pivot + offset) ·
/// rotate(rest) · rotate(rotation)` (SPEC 10.1); `rotation` null for none.
/// Without a rest rotation, exactly childFrame of SPEC 5's parts.
inline Transform partFrame(const Transform& worldFromParent, const ModelPart& part, Vec3 offset,
                           const Mat3* rotation) {
    const Vec3 origin = part.pivot + offset;
    if (!part.rest) {
        return rotation ? worldFromParent * Transform{*rotation, origin} : worldFromParent.translated(origin);
    }
    return worldFromParent * Transform{rotation ? *part.rest * *rotation : *part.rest, origin};
}

/// The frame of a shape whose part's frame is `worldFromPart`.
inline Transform shapeFrame(const Transform& worldFromPart, const ModelShape& shape) {
    return shape.turn ? worldFromPart * Transform{*shape.turn, shape.centre}
                      : worldFromPart.translated(shape.centre);
}

/// Makes `object` an instance of `model` (SPEC 10.1): its shapes' looks as
/// the model gives them, a key track per part.
void makeInstance(SceneObject& object, std::shared_ptr<const ModelType> model);

/// How many primitives an object expands to: 1 for a primitive, a model's shapes.
std::size_t primitiveCountOf(const SceneObject& object);

/// Shape kind of a primitive object.
ShapeKind shapeKindOf(ObjectKind kind);

/// "sphere", "cylinder", "box", or the model's type ("robot", "lamp").
std::string_view typeNameOf(const SceneObject& object);

}  // namespace f2
