#include "core/scene/models.h"

namespace f2 {

namespace {
constexpr Color8 kEyeColor{20, 20, 20};

// Robot F-2, SPEC 5: stands on local y = -105, 200 tall.
constexpr ModelShape kRobotShapes[] = {
    {PartId::Body, ShapeKind::Cylinder, {40, 150, 0}, {0, 75, 0}},
    {PartId::Head, ShapeKind::Box, {60, 50, 50}, {0, 25, 0}},
    {PartId::Head, ShapeKind::Sphere, {6, 0, 0}, {-14, 30, 25}, true, kEyeColor},  // left eye
    {PartId::Head, ShapeKind::Sphere, {6, 0, 0}, {14, 30, 25}, true, kEyeColor},   // right eye
    {PartId::LHand, ShapeKind::Cylinder, {10, 100, 0}, {0, -50, 0}},
    {PartId::RHand, ShapeKind::Cylinder, {10, 100, 0}, {0, -50, 0}},
};

constexpr ModelShape kHumanShapes[] = {
    {PartId::Body, ShapeKind::Cylinder, {25, 140, 0}, {0, 70, 0}},
    {PartId::Head, ShapeKind::Sphere, {20, 0, 0}, {0, 22, 0}},
    {PartId::LHand, ShapeKind::Cylinder, {7, 90, 0}, {0, -45, 0}},
    {PartId::RHand, ShapeKind::Cylinder, {7, 90, 0}, {0, -45, 0}},
};

const ModelDef kRobot{
    {{{PartId::Body, -1, {0, -105, 0}},
      {PartId::Head, 0, {0, 150, 0}},
      {PartId::LHand, 0, {-52, 140, 0}},
      {PartId::RHand, 0, {52, 140, 0}}}},
    kRobotShapes,
};

const ModelDef kHuman{
    {{{PartId::Body, -1, {0, -105, 0}},
      {PartId::Head, 0, {0, 140, 0}},
      {PartId::LHand, 0, {-33, 133, 0}},
      {PartId::RHand, 0, {33, 133, 0}}}},
    kHumanShapes,
};
}  // namespace

const ModelDef& robotModel() { return kRobot; }
const ModelDef& humanModel() { return kHuman; }
const ModelDef& modelOf(ObjectKind kind) { return kind == ObjectKind::Robot ? kRobot : kHuman; }

std::size_t primitiveCountOf(ObjectKind kind) {
    switch (kind) {
        case ObjectKind::Robot:
            return std::size(kRobotShapes);
        case ObjectKind::Human:
            return std::size(kHumanShapes);
        default:
            return 1;
    }
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

}  // namespace f2
