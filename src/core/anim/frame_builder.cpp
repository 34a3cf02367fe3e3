#include "core/anim/frame_builder.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/anim/animation_program.h"
#include "core/anim/light_frame.h"
#include "core/anim/track.h"
#include "core/scene/models.h"

namespace f2 {

namespace {
Vec3 toUnitColor(Color8 c) { return Vec3{float(c.r), float(c.g), float(c.b)} / 255.0f; }

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
        worldFromPart[index] = childFrame(worldFromParent, part.pivot + motion.position, motion.rotation);
    }
    return worldFromPart;
}

Transform worldFromRef(const SceneDesc& scene, FrameRef ref, double t) {
    // Bottom up: each level's frame in its parent's space, multiplied on the left.
    Transform world;
    bool first = true;
    for (std::optional<FrameRef> at = ref; at; at = scene.objects[at->object].attachedTo) {
        const SceneObject& object = scene.objects[at->object];
        const Transform root = objectFrame(object, t);
        const Transform level = at->part < 0 ? root : modelPartFrames(object, root, t)[std::size_t(at->part)];
        world = first ? level : level * world;
        first = false;
    }
    return world;
}

void attachedRootFrames(const SceneDesc& scene, double t, std::vector<Transform>& roots) {
    if (scene.attachOrder.empty()) return;
    roots.resize(scene.objects.size());
    for (std::uint32_t i : scene.attachOrder) {
        const SceneObject& object = scene.objects[i];
        const FrameRef mount = *object.attachedTo;
        const SceneObject& parent = scene.objects[mount.object];
        // The parent comes earlier in attachOrder when it is attached itself.
        const Transform parentRoot = parent.attachedTo ? roots[mount.object] : objectFrame(parent, t);
        const Transform worldFromMount =
            mount.part < 0 ? parentRoot : modelPartFrames(parent, parentRoot, t)[std::size_t(mount.part)];
        roots[i] = worldFromMount * objectFrame(object, t);
    }
}

Vec3 partShapeCentre(ObjectKind kind, int part, const Transform& worldFromPart) {
    for (const ModelShape& shape : modelOf(kind).shapes) {
        if (int(shape.part) == part) return worldFromPart.applyToPoint(shape.centre);
    }
    return worldFromPart.translation;
}

namespace {
// Objects per parallel work item: big enough to hide the hand-out cost.
constexpr std::size_t kObjectsPerChunk = 256;
}  // namespace

void evaluateFrame(const SceneDesc& scene, double t, EvaluatedFrame& frame, ThreadPool* pool) {
    // The front ends refuse a time that is not a finite number (a NaN frame is
    // meaningless); the tracks still stay on their keys if one gets through.
    assert(std::isfinite(t));
    evaluateLights(scene, frame);
    frame.ambient = scene.ambient;
    frame.background = toUnitColor(scene.background);

    // Each object owns a fixed run of primitive slots, so objects can be
    // evaluated in any order, in parallel, straight into place.
    std::shared_ptr<const AnimationProgram> program = animationProgramOf(scene);
    const bool refill = frame.filledBy == program;
    frame.filledBy = nullptr;  // until the frame is whole again
    frame.firstPrimitive = program->firstPrimitive;
    const std::size_t total = program->firstPrimitive.back();
    frame.primitives.resize(total);
    frame.surfaces.resize(total);
    // Attached objects need their parents' frames first: one pass in order.
    attachedRootFrames(scene, t, frame.attachedRoots);
    // Where t falls among the keys, once per key layout.
    program->segmentsAt(t, frame.segments);

    const std::size_t objectCount = scene.objects.size();
    auto evaluateChunk = [&](std::uint32_t chunk) {
        const std::size_t begin = chunk * kObjectsPerChunk;
        program->evaluateObjects(begin, std::min(objectCount, begin + kObjectsPerChunk),
                                 frame.segments.data(), refill, frame);
    };
    std::uint32_t chunks = std::uint32_t((objectCount + kObjectsPerChunk - 1) / kObjectsPerChunk);
    if (pool) {
        pool->parallelFor(chunks, evaluateChunk);
    } else {
        for (std::uint32_t c = 0; c < chunks; ++c) evaluateChunk(c);
    }
    frame.filledBy = std::move(program);
}

}  // namespace f2
