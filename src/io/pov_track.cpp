#include "io/pov_track.h"

#include <algorithm>
#include <optional>
#include <sstream>

#include "io/comment_text.h"
#include "io/frame_primitives.h"
#include "io/pov_scene_text.h"

namespace f2 {

namespace {
/// w(u) of track.h's interpolationWeight as SDL of `F2_U`, u in [0, 1).
std::string weight(const Easing& easing) {
    switch (easing.mode) {
        case Interpolation::Ease:
            return "F2_U * F2_U * (3 - 2 * F2_U)";
        case Interpolation::EaseIn:
            return "F2_U * F2_U * F2_U";
        case Interpolation::EaseOut:
            return "1 - (1 - F2_U) * (1 - F2_U) * (1 - F2_U)";
        case Interpolation::Back:
            // c1 = 1.70158, c3 = c1 + 1; exactly 0 at u = 0 (backFraction).
            return "(F2_U <= 0 ? 0 : 1 + 2.70158 * pow(F2_U - 1, 3) + 1.70158 * pow(F2_U - 1, 2))";
        case Interpolation::Elastic:
            return "(F2_U <= 0 ? 0 : pow(2, -10 * F2_U) * sin((10 * F2_U - 0.75) * 2 * pi / 3) + 1)";
        case Interpolation::Bounce:
            // n = 7.5625, d = 2.75: four parabolas (bounceFraction).
            return "(F2_U < 1 / 2.75 ? 7.5625 * F2_U * F2_U"
                   " : F2_U < 2 / 2.75 ? 7.5625 * pow(F2_U - 1.5 / 2.75, 2) + 0.75"
                   " : F2_U < 2.5 / 2.75 ? 7.5625 * pow(F2_U - 2.25 / 2.75, 2) + 0.9375"
                   " : 7.5625 * pow(F2_U - 2.625 / 2.75, 2) + 0.984375)";
        case Interpolation::Linear:
        case Interpolation::Spline:
        case Interpolation::Step:
        case Interpolation::Bezier:
            break;
    }
    return "F2_U";
}
/// bezierFraction's w(u) into `F2_W`: the same 30 halvings of s, so that
/// POV-Ray takes the same steps as f2.
std::string bezierWeight(const BezierCurve& c) {
    auto along = [](const std::string& s, float c1, float c2) {
        return "3 * (1 - " + s + ") * (1 - " + s + ") * " + s + " * " + formatNumber(c1) + " + 3 * (1 - " +
               s + ") * " + s + " * " + s + " * " + formatNumber(c2) + " + " + s + " * " + s + " * " + s;
    };
    return "  #declare F2_Lo = 0;\n  #declare F2_Hi = 1;\n  #for (F2_Step, 0, 29)\n"
           "    #declare F2_Mid = 0.5 * (F2_Lo + F2_Hi);\n"
           "    #declare F2_X = " +
           along("F2_Mid", c.x1, c.x2) +
           ";\n"
           "    #if (F2_X < F2_U)\n      #declare F2_Lo = F2_Mid;\n    #else\n      #declare F2_Hi = "
           "F2_Mid;\n"
           "    #end\n  #end\n"
           "  #declare F2_S = 0.5 * (F2_Lo + F2_Hi);\n"
           "  #declare F2_W = (F2_U <= 0 ? 0 : " +
           along("F2_S", c.y1, c.y2) + ");\n";
}
}  // namespace

bool povEvaluates(const Track& track) { return !track.drives && !track.keys.empty(); }

std::string povTrackPose(const Track& track, const std::string& name) {
    const std::vector<Key>& keys = track.keys;
    const std::string position = name + "_Position", rotation = name + "_Rotation";
    std::ostringstream out;
    auto hold = [&](const Pose& pose) {
        out << "  #declare " << position << " = " << povVector(pose.position) << ";\n  #declare " << rotation
            << " = " << povVector(pose.rotation) << ";\n";
    };
    // As segmentAt: the first key up to its time, [key i, key i + 1) between, the last from its time.
    out << "#if (F2_Frame <= " << formatNumber(keys[0].time) << ")\n";
    hold(keys[0].pose);
    const std::size_t last = keys.size() - 1;
    for (std::size_t i = 0; i < last; ++i) {
        const Easing& easing = track.modeAfter(i);
        out << "#elseif (F2_Frame < " << formatNumber(keys[i + 1].time) << ")\n";
        if (easing.mode == Interpolation::Step) {
            hold(keys[i].pose);  // until the next key
            continue;
        }
        out << "  #declare F2_U = (F2_Frame - " << formatNumber(keys[i].time) << ") / "
            << formatNumber(keys[i + 1].time - keys[i].time) << ";\n";
        auto blend = [&](const std::string& target, Vec3 Pose::*channel) {
            const Vec3 p1 = keys[i].pose.*channel, p2 = keys[i + 1].pose.*channel;
            if (easing.mode == Interpolation::Spline) {
                // Uniform Catmull-Rom (catmullRom), an end key standing in for a missing neighbour.
                const Vec3 p0 = keys[i == 0 ? i : i - 1].pose.*channel;
                const Vec3 p3 = keys[i + 1 < last ? i + 2 : i + 1].pose.*channel;
                out << "  #declare " << target << " = 0.5 * (2 * " << povVector(p1) << " + (" << povVector(p2)
                    << " - " << povVector(p0) << ") * F2_U + (2 * " << povVector(p0) << " - 5 * "
                    << povVector(p1) << " + 4 * " << povVector(p2) << " - " << povVector(p3)
                    << ") * F2_U * F2_U + (3 * " << povVector(p1) << " - " << povVector(p0) << " - 3 * "
                    << povVector(p2) << " + " << povVector(p3) << ") * F2_U * F2_U * F2_U);\n";
            } else {
                out << "  #declare " << target << " = " << povVector(p1) << " + (" << povVector(p2) << " - "
                    << povVector(p1) << ") * F2_W;\n";
            }
        };
        if (easing.mode == Interpolation::Bezier) {
            out << bezierWeight(easing.curve);
        } else if (easing.mode != Interpolation::Spline) {
            out << "  #declare F2_W = " << weight(easing) << ";\n";
        }
        blend(position, &Pose::position);
        blend(rotation, &Pose::rotation);
    }
    out << "#else\n";
    hold(keys[last].pose);
    out << "#end\n";
    return out.str();
}

bool povEvaluatesOrStill(const Track& track) {
    return (track.keys.empty() && !track.drives) || povEvaluates(track);
}

namespace {
std::string partName(const std::string& name, std::size_t part) {
    return name + "_Part" + std::to_string(part);
}

/// ` rotate <r> translate <p>`, leaving out zeros.
std::string place(Vec3 rotation, Vec3 position) {
    std::string text;
    if (!(rotation == Vec3{})) text += " rotate " + povVector(rotation);
    if (!(position == Vec3{})) text += " translate " + povVector(position);
    return text;
}
}  // namespace

/// `F2_ObjectN`: the names of object N's poses.
std::string objectName(std::size_t object) { return "F2_Object" + std::to_string(object); }

/// Part `part` of `object` on its parent, up to the root (partFrame: the
/// motion's rotation, the rest rotation, the pivot plus the motion's offset).
std::string partChain(const SceneObject& object, int part, const std::string& name) {
    std::string text;
    for (int p = part; p >= 0; p = object.model->parts[std::size_t(p)].parent) {
        const ModelPart& model = object.model->parts[std::size_t(p)];
        const bool keyed = !object.partTracks[std::size_t(p)].keys.empty();
        const std::string motion = partName(name, std::size_t(p));
        if (keyed) text += " rotate " + motion + "_Rotation";
        text += place(model.restRotation, model.pivot);
        if (keyed) text += " translate " + motion + "_Position";
    }
    return text;
}

/// The object's own pose (objectFrame).
std::string rootPose(const SceneObject& object, const std::string& name) {
    if (object.track.keys.empty()) return place(object.rest.rotation, object.rest.position);
    return " rotate " + name + "_Rotation translate " + name + "_Position";
}

bool povEvaluatesMotion(const SceneDesc& scene, std::size_t index) {
    const SceneObject& object = scene.objects[index];
    if (!object.attachChanges.empty()) return false;  // rides that change (SPEC 10.7): per frame
    if (!povEvaluatesOrStill(object.track) ||
        !std::all_of(object.partTracks.begin(), object.partTracks.end(), povEvaluatesOrStill))
        return false;
    return !object.attachedTo || povEvaluatesMotion(scene, object.attachedTo->object);
}

std::string povObjectPoses(const SceneDesc& scene, std::size_t index, std::set<std::size_t>& declared) {
    std::string text;
    for (std::optional<std::size_t> o = index; o && declared.insert(*o).second;) {
        const SceneObject& object = scene.objects[*o];
        const std::string name = objectName(*o);
        text += "// " + commentText(object.name) + ": its keys\n";
        if (!object.track.keys.empty()) text += povTrackPose(object.track, name);
        for (std::size_t p = 0; p < object.partTracks.size(); ++p)
            if (!object.partTracks[p].keys.empty())
                text += povTrackPose(object.partTracks[p], partName(name, p));
        o = object.attachedTo ? std::optional<std::size_t>(object.attachedTo->object) : std::nullopt;
    }
    return text;
}

std::string povShapeMotion(const SceneDesc& scene, std::size_t index, std::size_t shape) {
    const SceneObject& object = scene.objects[index];
    std::string text;
    if (object.model) {
        const ModelShape& s = object.model->shapes[shape];
        text += place(s.rotation, s.centre) + partChain(object, s.part, objectName(index));
    }
    text += rootPose(object, objectName(index));
    // worldFromRef: what it rides on, a part's chain and its object's pose, level by level.
    for (std::optional<FrameRef> mount = object.attachedTo; mount;) {
        const SceneObject& holder = scene.objects[mount->object];
        if (mount->part >= 0) text += partChain(holder, mount->part, objectName(mount->object));
        text += rootPose(holder, objectName(mount->object));
        mount = holder.attachedTo;
    }
    return text;
}

}  // namespace f2
