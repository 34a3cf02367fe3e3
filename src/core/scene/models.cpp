#include "core/scene/models.h"

#include <algorithm>

namespace f2 {

int ModelType::partIndex(std::string_view name) const {
    for (std::size_t i = 0; i < parts.size(); ++i) {
        if (parts[i].name == name) return int(i);
    }
    return -1;
}

int ModelType::shapeIndex(int part, std::string_view name) const {
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        if (shapes[i].part == part && shapes[i].name == name) return int(i);
    }
    return -1;
}

int ModelType::mainShapeOf(int part) const {
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        if (shapes[i].part == part) return int(i);
    }
    return -1;
}

void setRestRotation(ModelPart& part, Vec3 degrees) {
    part.restRotation = degrees;
    part.rest = degrees == Vec3{} ? std::nullopt : std::optional<Mat3>(rotationFromEulerDegrees(degrees));
}

void setShapeRotation(ModelShape& shape, Vec3 degrees) {
    shape.rotation = degrees;
    shape.turn = degrees == Vec3{} ? std::nullopt : std::optional<Mat3>(rotationFromEulerDegrees(degrees));
}

namespace {
constexpr Color8 kEyeColor{20, 20, 20};

/// A table row of SPEC 5: a part and its shape(s), as a `/model` block writes them.
struct PartRow {
    const char* name;
    int parent;
    Vec3 pivot;
};
struct ShapeRow {
    const char* name;
    int part;
    ShapeKind kind;
    Vec3 size;
    Vec3 centre;
    bool eye = false;
};

std::shared_ptr<const ModelType> makeModel(const char* name, std::span<const PartRow> parts,
                                           std::span<const ShapeRow> shapes) {
    auto model = std::make_shared<ModelType>();
    model->name = name;
    for (const PartRow& p : parts) model->parts.push_back({p.name, p.parent, p.pivot, {}, std::nullopt});
    for (const ShapeRow& s : shapes) {
        ModelShape shape;
        shape.name = s.name;
        shape.part = s.part;
        shape.kind = s.kind;
        shape.size = s.size;
        shape.centre = s.centre;
        if (s.eye) {  // painted 20 20 20 in the model (SPEC 10.1)
            shape.look.color = kEyeColor;
            shape.ownColor = true;
        }
        model->shapes.push_back(std::move(shape));
    }
    return model;
}

// Robot F-2, SPEC 5: stands on local y = -105, 200 tall.
constexpr PartRow kRobotParts[] = {
    {"body", -1, {0, -105, 0}},
    {"head", 0, {0, 150, 0}},
    {"lhand", 0, {-52, 140, 0}},
    {"rhand", 0, {52, 140, 0}},
};
constexpr ShapeRow kRobotShapes[] = {
    {"torso", 0, ShapeKind::Cylinder, {40, 150, 0}, {0, 75, 0}},
    {"face", 1, ShapeKind::Box, {60, 50, 50}, {0, 25, 0}},
    {"leye", 1, ShapeKind::Sphere, {6, 0, 0}, {-14, 30, 25}, true},
    {"reye", 1, ShapeKind::Sphere, {6, 0, 0}, {14, 30, 25}, true},
    {"arm", 2, ShapeKind::Cylinder, {10, 100, 0}, {0, -50, 0}},
    {"arm", 3, ShapeKind::Cylinder, {10, 100, 0}, {0, -50, 0}},
};

constexpr PartRow kHumanParts[] = {
    {"body", -1, {0, -105, 0}},
    {"head", 0, {0, 140, 0}},
    {"lhand", 0, {-33, 133, 0}},
    {"rhand", 0, {33, 133, 0}},
};
constexpr ShapeRow kHumanShapes[] = {
    {"torso", 0, ShapeKind::Cylinder, {25, 140, 0}, {0, 70, 0}},
    {"face", 1, ShapeKind::Sphere, {20, 0, 0}, {0, 22, 0}},
    {"arm", 2, ShapeKind::Cylinder, {7, 90, 0}, {0, -45, 0}},
    {"arm", 3, ShapeKind::Cylinder, {7, 90, 0}, {0, -45, 0}},
};
}  // namespace

const std::shared_ptr<const ModelType>& robotModel() {
    static const std::shared_ptr<const ModelType> robot = makeModel("robot", kRobotParts, kRobotShapes);
    return robot;
}

const std::shared_ptr<const ModelType>& humanModel() {
    static const std::shared_ptr<const ModelType> human = makeModel("human", kHumanParts, kHumanShapes);
    return human;
}

void makeInstance(SceneObject& object, std::shared_ptr<const ModelType> model) {
    object.kind = ObjectKind::Model;
    object.appearance.clear();
    for (const ModelShape& shape : model->shapes) object.appearance.push_back(shape.look);
    object.partTracks.assign(model->parts.size(), Track{});
    object.model = std::move(model);
}

std::size_t primitiveCountOf(const SceneObject& object) {
    return object.model ? object.model->shapes.size() : 1;
}

ShapeKind shapeKindOf(ObjectKind kind) {
    switch (kind) {
        case ObjectKind::Cylinder:
            return ShapeKind::Cylinder;
        case ObjectKind::Box:
            return ShapeKind::Box;
        default:
            return ShapeKind::Sphere;
    }
}

std::string_view typeNameOf(const SceneObject& object) {
    return object.model ? std::string_view(object.model->name) : objectKindName(object.kind);
}

}  // namespace f2
