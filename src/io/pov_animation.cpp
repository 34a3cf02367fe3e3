#include "io/pov_animation.h"

#include <algorithm>
#include <functional>
#include <optional>
#include <set>
#include <sstream>
#include <type_traits>

#include "core/anim/frame_builder.h"
#include "core/render/camera.h"
#include "io/comment_text.h"
#include "io/frame_primitives.h"
#include "io/pov_scene_text.h"
#include "io/pov_track.h"

namespace f2 {

namespace {
/// Merges the values of every frame into one SDL expression each: the
/// value itself when every frame has the same, else a look-up in an array of
/// every frame's value, declared in `declarations`.
class FrameMerger {
   public:
    explicit FrameMerger(const std::vector<PovValues>& frames) : frames_(frames) {}

    using Field = std::function<const std::string&(const PovValues&)>;

    /// `transform`: the values are `matrix <…>`, which an array holds as a `transform {}`.
    std::string expression(const std::string& name, const Field& field, bool transform = false) {
        const std::string& first = field(frames_[0]);
        const bool same = std::all_of(frames_.begin(), frames_.end(),
                                      [&](const PovValues& v) { return field(v) == first; });
        if (same) return first;
        ++arrays_;
        declarations_ << "#declare " << name << " = array[" << frames_.size() << "] {\n";
        for (std::size_t f = 0; f < frames_.size(); ++f) {
            declarations_ << "  "
                          << (transform ? "transform { " + field(frames_[f]) + " }" : field(frames_[f]))
                          << (f + 1 < frames_.size() ? ",\n" : "\n");
        }
        declarations_ << "};\n";
        return transform ? "transform { " + name + "[F2_K] }" : name + "[F2_K]";
    }

    /// Whether `field` has another value at some frame.
    bool varies(const Field& field) const {
        const std::string& first = field(frames_[0]);
        return std::any_of(frames_.begin(), frames_.end(),
                           [&](const PovValues& v) { return field(v) != first; });
    }

    /// A comment's value: the same at every frame, or a word saying it is not.
    std::string note(const Field& field) const {
        const std::string& first = field(frames_[0]);
        for (const PovValues& v : frames_)
            if (field(v) != first) return "(changes over the animation)";
        return first;
    }

    std::string declarations() const { return declarations_.str(); }
    std::size_t arrays() const { return arrays_; }

   private:
    const std::vector<PovValues>& frames_;
    std::ostringstream declarations_;
    std::size_t arrays_ = 0;
};

/// The camera's values in `v`: evaluated by POV-Ray from its keys (declared
/// in `tracks`; true) when it moves by keys alone (no ride, no drive), its
/// `/look_at` too when it names a point or an object POV-Ray moves; else as
/// `merge` gives them.
bool povCamera(const SceneDesc& scene, int width, int height, FrameMerger& merge, std::ostringstream& tracks,
               std::set<std::size_t>& posed, PovValues& v) {
    const CameraDesc& camera = scene.camera;
    auto field = [](std::string PovValues::*member) {
        return [member](const PovValues& x) -> const std::string& { return x.*member; };
    };
    const bool moves = merge.varies(field(&PovValues::eye)) || merge.varies(field(&PovValues::right)) ||
                       merge.varies(field(&PovValues::direction));
    const std::optional<FrameRef> target = camera.lookAt ? camera.lookAt->target : std::nullopt;
    if (!moves || camera.attachedTo || (target && !povEvaluatesMotion(scene, target->object)) ||
        !povEvaluatesOrStill(camera.track) || !povEvaluatesOrStill(camera.zoom)) {
        v.eye = merge.expression("F2_Eye", field(&PovValues::eye));
        v.right = merge.expression("F2_Right", field(&PovValues::right));
        v.up = merge.expression("F2_Up", field(&PovValues::up));
        v.direction = merge.expression("F2_Direction", field(&PovValues::direction));
        return false;
    }
    // As povValuesAt: R·x^, R·y^·h/w, R·z^·d, vrotate being f2's Rz·Ry·Rx.
    const bool keyed = !camera.track.keys.empty();
    if (keyed) tracks << "// the camera: its keys\n" << povTrackPose(camera.track, "F2_Camera");
    std::string rotation = keyed ? "F2_Camera_Rotation" : povVector(camera.pose.rotation);
    const std::string eye = keyed ? "F2_Camera_Position" : povVector(camera.pose.position);
    if (camera.lookAt) {
        // cameraFrameAt: rx = -asin(f_y), ry = atan2(f_x, f_z) toward the
        // point; straight up or down keeps the keyed ry, at the eye the keyed rotation.
        if (target) tracks << povObjectPoses(scene, target->object, posed);
        const std::string point = target ? povRefPoint(scene, *target) : povVector(camera.lookAt->point);
        tracks << "// the camera looks at "
               << (target ? commentText(scene.objects[target->object].name) : "a point")
               << "\n#declare F2_To = " << point << " - " << eye << ";\n#declare F2_Dist = vlength(F2_To);\n"
               << "#if (F2_Dist = 0)\n  #declare F2_Look = " << rotation << ";\n#else\n"
               << "  #declare F2_Look = <-degrees(asin(min(max(F2_To.y / F2_Dist, -1), 1))), "
               << "(F2_To.x != 0 | F2_To.z != 0 ? degrees(atan2(F2_To.x, F2_To.z)) : (" << rotation
               << ").y), 0>;\n#end\n";
        rotation = "F2_Look";
    }
    std::string distance = formatNumber(camera.distance);
    if (!camera.zoom.keys.empty()) {
        // cameraDistanceAt: never below a thousandth of the smallest key.
        double smallest = camera.zoom.keys.front().pose.position.x;
        for (const Key& k : camera.zoom.keys) smallest = std::min(smallest, double(k.pose.position.x));
        tracks << "// the camera's d: its keys\n" << povTrackPose(camera.zoom, "F2_Zoom");
        distance = "max(F2_Zoom_Position.x, " + formatNumber(smallest / 1000.0) + ")";
    }
    v.eye = eye;
    v.right = "vrotate(<1, 0, 0>, " + rotation + ")";
    v.up = "vrotate(<0, 1, 0>, " + rotation + ") * " + formatNumber(float(height) / float(width));
    v.direction = "vrotate(<0, 0, 1>, " + rotation + ") * " + distance;
    return true;
}

/// The `colour` and `visible` tracks (SPEC 10.3, 10.7) of each shape, as
/// frame_builder.h applies them: the last colour track that reaches it
/// wins; it is seen while all its visible tracks show it.
struct KeyedLooks {
    std::vector<const TargetTrack*> colour;               ///< per shape; null: none
    std::vector<std::vector<std::size_t>> visibleTracks;  ///< per shape: indices in scene.visibilityTracks

    KeyedLooks(const SceneDesc& scene, const std::vector<std::size_t>& firstOf, std::size_t shapes)
        : colour(shapes, nullptr), visibleTracks(shapes) {
        for (const TargetTrack& c : scene.colourTracks) {
            if (c.track.keys.empty() && !c.track.drives) continue;  // as forEachKeyedColour
            forEachShapeOf(scene, c.target, c.shape, [&](std::size_t shape, const ModelShape* inModel) {
                if (inModel && inModel->ownColor && c.shape < 0) return;
                colour[firstOf[c.target.object] + shape] = &c;
            });
        }
        for (std::size_t j = 0; j < scene.visibilityTracks.size(); ++j) {
            const TargetTrack& v = scene.visibilityTracks[j];
            forEachShapeOf(scene, v.target, v.shape, [&](std::size_t shape, const ModelShape*) {
                visibleTracks[firstOf[v.target.object] + shape].push_back(j);
            });
        }
    }
};

/// The named lights' keys POV-Ray evaluates (SPEC 10.2, 10.3): pose keys of
/// a light that rides on nothing, and intensity keys; each declared once in
/// `tracks` when first asked for. An empty answer: read per frame.
class LightKeys {
   public:
    LightKeys(const SceneDesc& scene, std::ostringstream& tracks) : scene_(scene), tracks_(tracks) {}

    /// `max(0, keyed)` as lightIntensityAt, or empty.
    std::string intensity(std::int32_t motion) {
        if (motion == kStillLight) return "";
        const LightMotion& m = scene_.lightMotions[std::size_t(motion)];
        if (m.intensity.keys.empty() || !povEvaluates(m.intensity)) return "";
        const std::string name = "F2_Intensity" + std::to_string(motion);
        if (intensities_.insert(motion).second)
            tracks_ << "// " << commentText(m.name) << "'s intensity: its keys\n"
                    << povTrackPose(m.intensity, name);
        return "max(0, " + name + "_Position.x)";
    }

    /// The name of its pose (NAME_Position, NAME_Rotation: lightFrameAt), or empty.
    std::string pose(std::int32_t motion) {
        if (motion == kStillLight) return "";
        const LightMotion& m = scene_.lightMotions[std::size_t(motion)];
        if (m.attachedTo || m.track.keys.empty() || !povEvaluates(m.track)) return "";
        const std::string name = "F2_LightPose" + std::to_string(motion);
        if (poses_.insert(motion).second)
            tracks_ << "// " << commentText(m.name) << ": its keys\n" << povTrackPose(m.track, name);
        return name;
    }

    /// The ambient level as ambientAt sums it, when it `varies` and every
    /// named ambient light's intensity is still or evaluated; else empty.
    std::string ambient(bool varies) {
        if (!varies) return "";
        std::string sum = formatNumber(scene_.ambient);
        for (const AmbientLight& light : scene_.namedAmbients) {
            const Track& keys = scene_.lightMotions[std::size_t(light.motion)].intensity;
            if (keys.keys.empty() && !keys.drives) {
                sum += " + " + formatNumber(light.intensity);
                continue;
            }
            const std::string keyed = intensity(std::int32_t(light.motion));
            if (keyed.empty()) return "";
            sum += " + " + keyed;
        }
        return "(" + sum + ")";
    }

   private:
    const SceneDesc& scene_;
    std::ostringstream& tracks_;
    std::set<std::int32_t> intensities_, poses_;
};

/// SDL of a colour track's 0..255 values as POV-Ray's 0..1: clamped and
/// rounded to whole levels, as framePrimitives does.
std::string colourOf(const std::string& pose) {
    std::string text = "<";
    for (const char* axis : {"x", "y", "z"}) {
        if (text.size() > 1) text += ", ";
        text += "floor(min(max(" + pose + "_Position." + axis + ", 0), 255) + 0.5)";
    }
    return text + "> / 255";
}
}  // namespace

bool povIniName(std::string_view name) {
    if (name.empty()) return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
               c == '_' || c == '+' || c == '-';
    });
}

PovAnimation povAnimation(const SceneDesc& scene, int width, int height, const std::string& source,
                          const std::string& stem) {
    PovAnimation result;
    result.lastFrame = scene.lastFrame();
    const std::size_t count = std::size_t(result.lastFrame) + 1;

    // Every frame's shapes (hidden ones kept, so the list is the same at
    // every frame) and camera: a first pass for the box the suns stand
    // beyond, a second for the values (only frame 0's shapes are kept, for
    // what never changes: a long animation need not hold every frame's).
    const auto cameraAtFrame = [&](std::size_t f) {
        return cameraAt(scene, double(f)).resized(width, height);
    };
    PovBounds bounds;
    for (std::size_t f = 0; f < count; ++f)
        bounds.grow(cameraAtFrame(f), framePrimitives(scene, double(f), true));
    const std::vector<PlacedPrimitive> firstPrims = framePrimitives(scene, 0, true);
    std::vector<PovValues> frames(count);
    for (std::size_t f = 0; f < count; ++f)
        frames[f] =
            povValuesAt(scene, double(f), cameraAtFrame(f), framePrimitives(scene, double(f), true), bounds);

    FrameMerger merge(frames);
    PovValues v;
    std::ostringstream tracks;    // the key tracks POV-Ray evaluates
    std::set<std::size_t> posed;  // the objects whose poses are declared
    result.cameraEvaluated = povCamera(scene, width, height, merge, tracks, posed, v);
    LightKeys lightKeys(scene, tracks);
    const Vec3 centre = bounds.centre();
    const float far = bounds.far();
    auto lights = [&](const std::string& prefix, std::vector<PovLightValues> PovValues::*list, auto& descs) {
        std::vector<PovLightValues> out(descs.size());
        for (std::size_t i = 0; i < descs.size(); ++i) {
            const std::string name = prefix + std::to_string(i) + "_";
            auto field = [&](std::string PovLightValues::*member) {
                return [list, i, member](const PovValues& x) -> const std::string& {
                    return (x.*list)[i].*member;
                };
            };
            // A changing value from the light's keys when POV-Ray can evaluate them, else per frame.
            auto value = [&](const char* part, std::string PovLightValues::*member,
                             const std::string& keyed) {
                return !keyed.empty() && merge.varies(field(member))
                           ? keyed
                           : merge.expression(name + part, field(member));
            };
            const auto& light = descs[i];
            out[i].intensity =
                value("Intensity", &PovLightValues::intensity, lightKeys.intensity(light.motion));
            std::string location, pointAt;
            if constexpr (std::is_same_v<std::decay_t<decltype(light)>, DirectionalLight>) {
                // povValuesAt: beyond everything, against the direction it travels.
                // A soft sun's disc axes turn with it: its place is read per frame.
                const std::string pose = light.sun.soft() ? "" : lightKeys.pose(light.motion);
                if (!pose.empty())
                    location = povVector(centre) + " - vnormalize(vrotate(" + povVector(light.direction) +
                               ", " + pose + "_Rotation)) * " + formatNumber(far);
            } else {
                const std::string pose = lightKeys.pose(light.motion);
                if (!pose.empty()) {
                    location = "(vrotate(" + povVector(light.position) + ", " + pose + "_Rotation) + " +
                               pose + "_Position)";
                    if (light.kind == LocalLightKind::Spot)
                        pointAt = location + " + vnormalize(vrotate(" + povVector(light.direction) + ", " +
                                  pose + "_Rotation))";
                }
            }
            out[i].location = value("Location", &PovLightValues::location, location);
            out[i].pointAt = value("PointAt", &PovLightValues::pointAt, pointAt);
            out[i].areaA = merge.expression(name + "AreaA", field(&PovLightValues::areaA));
            out[i].areaB = merge.expression(name + "AreaB", field(&PovLightValues::areaB));
            out[i].note = merge.note(field(&PovLightValues::note));
        }
        return out;
    };
    v.suns = lights("F2_Sun", &PovValues::suns, scene.lights);
    v.locals = lights("F2_Light", &PovValues::locals, scene.localLights);
    // The ambient level (each finish carries ka times it): the unnamed ones
    // plus the named ones' intensities, from their keys or per frame.
    const std::string ambient =
        lightKeys.ambient(merge.varies([](const PovValues& x) -> const std::string& { return x.ambient; }));
    // A shape whose object, and what it rides on, move by keys alone (no
    // drive, no changing ride) has them evaluated by POV-Ray (pov_track.h);
    // other changing values are read from their arrays.
    std::vector<std::size_t> objectOf, firstOf;  // each primitive's object, each object's first primitive
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        firstOf.push_back(objectOf.size());
        objectOf.insert(objectOf.end(), primitiveCountOf(scene.objects[o]), o);
    }
    const KeyedLooks looks(scene, firstOf, firstPrims.size());
    std::set<std::size_t> colourDeclared, visibleDeclared;  // tracks already written
    const std::size_t shapes = firstPrims.size();
    for (std::size_t i = 0; i < shapes; ++i) {
        const std::string name = "F2_Shape" + std::to_string(i) + "_";
        auto field = [i](std::string PovShapeValues::*member) {
            return [i, member](const PovValues& x) -> const std::string& { return x.shapes[i].*member; };
        };
        PovShapeValues& s = v.shapes.emplace_back();
        const std::size_t o = objectOf[i];
        if (povEvaluatesMotion(scene, o) && merge.varies(field(&PovShapeValues::transform))) {
            tracks << povObjectPoses(scene, o, posed);
            s.transform = "transform {" + povShapeMotion(scene, o, i - firstOf[o]) + " }";
            ++result.evaluated;
        } else {
            s.transform = merge.expression(name + "Transform", field(&PovShapeValues::transform), true);
        }
        const TargetTrack* colour = looks.colour[i];
        if (colour && povEvaluates(colour->track) && merge.varies(field(&PovShapeValues::colour))) {
            const std::size_t j = std::size_t(colour - scene.colourTracks.data());
            const std::string pose = "F2_Colour" + std::to_string(j);
            if (colourDeclared.insert(j).second)
                tracks << "// colour keys of " << commentText(firstPrims[i].label) << "...\n"
                       << povTrackPose(colour->track, pose);
            s.colour = colourOf(pose);
            ++result.evaluatedLooks;
        } else {
            s.colour = merge.expression(name + "Colour", field(&PovShapeValues::colour));
        }
        s.ambient = ambient.empty() ? merge.expression(name + "Ambient", field(&PovShapeValues::ambient))
                                    : formatNumber(firstPrims[i].material.ka) + " * " + ambient;
        const std::vector<std::size_t>& shown = looks.visibleTracks[i];
        const auto evaluable = [&](std::size_t j) {
            return povEvaluatesOrStill(scene.visibilityTracks[j].track);
        };
        if (merge.varies(field(&PovShapeValues::visible)) &&
            std::all_of(shown.begin(), shown.end(), evaluable)) {
            // visibleAt: keyed 0 or 1, shown from 0.5; a track without keys shows it.
            std::string all;
            for (std::size_t j : shown) {
                if (scene.visibilityTracks[j].track.keys.empty()) continue;
                const std::string pose = "F2_Visible" + std::to_string(j);
                if (visibleDeclared.insert(j).second)
                    tracks << "// visible keys of " << commentText(firstPrims[i].label) << "...\n"
                           << povTrackPose(scene.visibilityTracks[j].track, pose);
                all += (all.empty() ? "" : " & ") + pose + "_Position.x >= 0.5";
            }
            s.visible = all.empty() ? "1" : all;
            ++result.evaluatedLooks;
        } else {
            s.visible = merge.expression(name + "Visible", field(&PovShapeValues::visible));
        }
    }
    result.arrays = merge.arrays();

    const double fps = double(scene.fps);
    std::ostringstream out;
    out.imbue(std::locale::classic());
    out << "// " << commentText(source) << ", frames 0-" << result.lastFrame << " at " << scene.fps
        << " fps, exported by f2 (F2 Stage).\n"
        << "// Render every frame: cd <this directory> && povray " << stem
        << ".ini (+SFk +EFk: frame k only).\n"
        << "// clock is the time in seconds; keys below are evaluated at clock * fps, other values\n"
        << "// that change are read from their arrays at the nearest frame (docs/output.md).\n"
        << "// Coordinates are f2's: left-handed, y up, like POV-Ray's.\n"
        << "#version 3.7;\n\n"
        // f2's time in frames; within 1e-6 of a whole frame it is that frame,
        // so that a step key or an array lands on it despite the clock's rounding.
        << "#declare F2_Frame = clock * " << scene.fps << ";\n"
        << "#declare F2_Frame = (abs(F2_Frame - floor(F2_Frame + 0.5)) < 1e-6 ? floor(F2_Frame + 0.5) : "
           "F2_Frame);\n"
        << "#declare F2_K = min(max(floor(F2_Frame + 0.5), 0), " << result.lastFrame << ");\n\n"
        << merge.declarations() << "\n"
        << tracks.str() << "\n"
        << povSceneBody(scene, firstPrims, v);
    result.scene = out.str();

    std::ostringstream ini;
    ini.imbue(std::locale::classic());
    ini << "; " << commentText(source) << ": every frame, exported by f2 (F2 Stage).\n"
        << "; Run in this directory: povray " << stem << ".ini\n"
        << "Input_File_Name=" << stem << ".pov\n"
        << "Output_File_Name=" << stem << "_.png\n"
        << "Output_File_Type=N\n"
        << "Width=" << width << "\nHeight=" << height << "\n"
        << "Antialias=Off\nDisplay=Off\n"
        << "Initial_Frame=0\nFinal_Frame=" << result.lastFrame << "\n"
        << "Initial_Clock=0\nFinal_Clock=" << formatNumber(double(result.lastFrame) / fps) << "\n";
    result.ini = ini.str();
    return result;
}

}  // namespace f2
