#include "core/anim/frame_builder.h"

#include <algorithm>

#include "core/anim/light_frame.h"
#include "core/anim/track.h"
#include "core/scene/models.h"

namespace f2 {

namespace {
Vec3 toUnitColor(Color8 c) { return Vec3{float(c.r), float(c.g), float(c.b)} / 255.0f; }

Surface surfaceOf(const Appearance& look) {
    return {toUnitColor(look.color), look.material, toUnitColor(look.checker.color), look.checker.size};
}

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
        Vec3 origin = part.pivot + motion.position;
        if (motion.rotation == Vec3{}) {  // most parts of most frames: no matrix product
            worldFromPart[index] = worldFromParent.translated(origin);
        } else {
            worldFromPart[index] =
                worldFromParent * Transform{rotationFromEulerDegrees(motion.rotation), origin};
        }
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
/// Writes the primitives of one object placed at `worldFromObject` at `out`
/// (primitiveCountOf(kind) slots).
void evaluateObject(const SceneObject& object, const Transform& worldFromObject, double t, Primitive* prims,
                    Surface* surfaces) {
    if (!isModel(object.kind)) {
        *prims = makePrimitive(shapeKindOf(object.kind), object.size, worldFromObject);
        *surfaces = surfaceOf(object.appearance[0]);
        return;
    }
    auto worldFromPart = modelPartFrames(object, worldFromObject, t);
    for (const ModelShape& shape : modelOf(object.kind).shapes) {
        const Transform& partFrame = worldFromPart[int(shape.part)];
        *prims++ = makePrimitive(shape.kind, shape.size, partFrame.translated(shape.centre));
        const Appearance& look = object.appearance[int(shape.part)];
        // The eyes keep their own plain colour, painted or chequered head alike.
        *surfaces++ =
            shape.ownColor ? Surface{toUnitColor(shape.color), look.material, Vec3{}, 0.0f} : surfaceOf(look);
    }
}

/// Starts loading the key frames of an object evaluated soon: each track's
/// keys are a heap block of their own, and waiting for them one object at a
/// time was most of the evaluation of a large scene.
void prefetchKeys(const SceneObject& object) {
    __builtin_prefetch(object.track.keys.data());
    for (const Track& track : object.partTracks) __builtin_prefetch(track.keys.data());
}

// Objects ahead whose keys are prefetched.
constexpr std::size_t kPrefetchAhead = 8;
// Objects per parallel work item: big enough to hide the hand-out cost.
constexpr std::size_t kObjectsPerChunk = 256;
}  // namespace

void evaluateFrame(const SceneDesc& scene, double t, EvaluatedFrame& frame, ThreadPool* pool) {
    evaluateLights(scene, frame);
    frame.ambient = scene.ambient;
    frame.background = toUnitColor(scene.background);

    // Each object owns a fixed run of primitive slots, so objects can be
    // evaluated in any order, in parallel, straight into place.
    const std::size_t objectCount = scene.objects.size();
    frame.firstPrimitive.resize(objectCount + 1);
    std::size_t total = 0;
    for (std::size_t i = 0; i < objectCount; ++i) {
        frame.firstPrimitive[i] = std::uint32_t(total);
        total += primitiveCountOf(scene.objects[i].kind);
    }
    frame.firstPrimitive[objectCount] = std::uint32_t(total);
    frame.primitives.resize(total);
    frame.surfaces.resize(total);
    // Attached objects need their parents' frames first: one pass in order.
    attachedRootFrames(scene, t, frame.attachedRoots);

    auto evaluateChunk = [&](std::uint32_t chunk) {
        std::size_t end = std::min(objectCount, (chunk + 1) * kObjectsPerChunk);
        for (std::size_t i = chunk * kObjectsPerChunk; i < end; ++i) {
            if (i + kPrefetchAhead < end) prefetchKeys(scene.objects[i + kPrefetchAhead]);
            evaluateObject(scene.objects[i], worldFromRoot(scene, i, t, frame.attachedRoots), t,
                           &frame.primitives[frame.firstPrimitive[i]],
                           &frame.surfaces[frame.firstPrimitive[i]]);
        }
    };
    std::uint32_t chunks = std::uint32_t((objectCount + kObjectsPerChunk - 1) / kObjectsPerChunk);
    if (pool) {
        pool->parallelFor(chunks, evaluateChunk);
    } else {
        for (std::uint32_t c = 0; c < chunks; ++c) evaluateChunk(c);
    }
}

}  // namespace f2
