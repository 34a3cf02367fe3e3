#include "core/anim/frame_builder.h"

#include "core/anim/track.h"

namespace f2 {

namespace {
Vec3 toUnitColor(Color8 c) { return Vec3{float(c.r), float(c.g), float(c.b)} / 255.0f; }

Transform translation(Vec3 t) { return {Mat3{}, t}; }
}  // namespace

Transform objectFrame(const SceneObject& object, double t) {
    Pose pose = evaluateTrack(object.track, t, object.rest);
    return Transform::fromPose(pose.position, pose.rotation);
}

std::array<Transform, kPartCount> modelPartFrames(const SceneObject& object, const Transform& worldFromRoot,
                                                  double t) {
    const ModelDef& model = modelOf(object.kind);
    std::array<Transform, kPartCount> worldFromPart;
    for (const ModelPart& part : model.parts) {
        int index = int(part.id);
        Pose motion = evaluateTrack(object.partTracks[index], t, Pose{});
        const Transform& worldFromParent = part.parent < 0 ? worldFromRoot : worldFromPart[part.parent];
        // parent . translate(pivot + offset) . rotate(rotation)  (SPEC 5)
        Transform parentFromPart{rotationFromEulerDegrees(motion.rotation), part.pivot + motion.position};
        worldFromPart[index] = worldFromParent * parentFromPart;
    }
    return worldFromPart;
}

void evaluateFrame(const SceneDesc& scene, double t, FrameScene& frame) {
    frame.primitives.clear();
    frame.surfaces.clear();
    frame.lights.clear();
    frame.ambient = scene.ambient;
    frame.background = toUnitColor(scene.background);
    for (const DirectionalLight& light : scene.lights)
        frame.lights.push_back({-normalize(light.direction), light.intensity});

    for (const SceneObject& object : scene.objects) {
        Transform worldFromObject = objectFrame(object, t);
        if (!isModel(object.kind)) {
            frame.primitives.push_back(makePrimitive(shapeKindOf(object.kind), object.size, worldFromObject));
            const Appearance& look = object.appearance[0];
            frame.surfaces.push_back({toUnitColor(look.color), look.material});
            continue;
        }
        auto worldFromPart = modelPartFrames(object, worldFromObject, t);
        for (const ModelShape& shape : modelOf(object.kind).shapes) {
            const Transform& partFrame = worldFromPart[int(shape.part)];
            frame.primitives.push_back(makePrimitive(shape.kind, shape.size, partFrame * translation(shape.centre)));
            const Appearance& look = object.appearance[int(shape.part)];
            frame.surfaces.push_back({toUnitColor(shape.ownColor ? shape.color : look.color), look.material});
        }
    }
}

}  // namespace f2
