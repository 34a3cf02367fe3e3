// f2 info: what a scene holds.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.h"
#include "core/parse/expression.h"
#include "core/parse/language.h"
#include "core/scene/models.h"
#include "options.h"
#include "scene_source.h"

namespace f2::cli {

namespace {
/// Keys with a mode word of their own shown by frame; the rest are counted.
constexpr std::size_t kShownKeyModes = 4;

/// A key time to ten significant digits: `3.8s` at 24 fps is frame 91.2, not
/// the double's 91.19999999999999.
std::string keyTimeText(double frames) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", frames);
    return text;
}

/// A track's keys on one line, then its drives (SPEC 10.7), one a line.
void printTrack(const std::string& target, const Track& track) {
    if (track.drives) {
        for (const std::shared_ptr<const Drive>& d : track.drives->bySlot)
            if (d)
                std::cout << "    " << target << ": drive " << driveChannelName(d->channel) << ' '
                          << d->expression << '\n';
    }
    if (track.keys.empty()) return;
    std::cout << "    " << target << ": " << track.keys.size() << " keys, frames "
              << keyTimeText(track.keys.front().time) << ".." << keyTimeText(track.keys.back().time) << ", "
              << easingText(track.interpolation);
    std::size_t withMode = 0;
    for (const Key& k : track.keys) {
        if (!k.mode) continue;
        if (withMode < kShownKeyModes)
            std::cout << (withMode == 0 ? "; from key " : ", ") << keyTimeText(k.time) << ' '
                      << easingText(*k.mode);
        ++withMode;
    }
    if (withMode > kShownKeyModes)
        std::cout << " (and " << withMode - kShownKeyModes << " more keys with a mode)";
    std::cout << '\n';
}

std::string refName(const SceneDesc& s, FrameRef ref, int shape = -1) {
    const SceneObject& o = s.objects[ref.object];
    std::string name = o.name;
    if (ref.part >= 0) name += "." + o.model->parts[std::size_t(ref.part)].name;
    if (shape >= 0) name += "." + o.model->shapes[std::size_t(shape)].name;
    return name;
}

/// The scene's own model types (SPEC 10.1, 10.6): "model lamp: 3 parts (base,
/// arm on base, …), 4 shapes; parameters arm 120, shade 20".
void printModels(const SceneDesc& s) {
    for (const std::shared_ptr<const ModelType>& model : s.models) {
        std::cout << "  model " << model->name << ": " << model->parts.size()
                  << (model->parts.size() == 1 ? " part (" : " parts (");
        for (std::size_t p = 0; p < model->parts.size(); ++p) {
            const ModelPart& part = model->parts[p];
            std::cout << (p > 0 ? ", " : "") << part.name;
            if (part.parent >= 0) std::cout << " on " << model->parts[std::size_t(part.parent)].name;
        }
        std::cout << "), " << model->shapes.size() << (model->shapes.size() == 1 ? " shape" : " shapes");
        for (std::size_t k = 0; k < model->params.size(); ++k)
            std::cout << (k == 0 ? "; parameters " : ", ") << model->params[k].name << ' '
                      << formatNumber(model->params[k].value);
        std::cout << '\n';
    }
}

void printVec(const Vec3& v) { std::cout << '(' << v.x << ", " << v.y << ", " << v.z << ')'; }

/// The camera's pose, keys, attachment and /look_at (SPEC 9.1, 9.2).
void printCamera(const SceneDesc& s) {
    const CameraDesc& c = s.camera;
    std::cout << "  camera:     eye ";
    printVec(c.pose.position);
    std::cout << ", rotation ";
    printVec(c.pose.rotation);
    std::cout << '\n';
    printTrack("camera", c.track);
    printTrack("camera d", c.zoom);
    if (c.attachedTo) std::cout << "    rides on " << refName(s, *c.attachedTo) << '\n';
    if (c.lookAt) {
        std::cout << "    looks at ";
        if (!c.lookAt->target) {
            printVec(c.lookAt->point);
        } else {
            std::cout << refName(s, *c.lookAt->target)
                      << (c.lookAt->target->part < 0 ? " (its origin)" : " (the centre of its shape)");
        }
        std::cout << '\n';
    }
}

/// Softness of a light's shadows, as its option is written ("size 20 4").
std::string shadowText(const char* word, const SoftShadow& shadow) {
    if (!shadow.soft()) return "hard shadows";
    std::ostringstream text;
    text << "soft shadows: " << word << ' ' << shadow.size << ' ' << shadow.samplesPerSide << " ("
         << shadow.samplesPerSide * shadow.samplesPerSide << " samples)";
    return text.str();
}

/// " 'lamp'" for a named light, nothing for another.
std::string lightName(const SceneDesc& s, std::int32_t motion) {
    return motion == kStillLight ? std::string() : " '" + s.lightMotions[std::size_t(motion)].name + "'";
}

/// A named light's attachment and keys (SPEC 10.2, 10.3).
void printLightMotion(const SceneDesc& s, std::int32_t motion) {
    if (motion == kStillLight) return;
    const LightMotion& m = s.lightMotions[std::size_t(motion)];
    if (m.attachedTo) std::cout << "    rides on " << refName(s, *m.attachedTo) << '\n';
    printTrack(m.name, m.track);
    printTrack(m.name + " intensity", m.intensity);
}

/// One line per named ambient, directional, point and spot light.
void printLights(const SceneDesc& s) {
    for (const AmbientLight& l : s.namedAmbients) {
        std::cout << "  amb_light" << lightName(s, std::int32_t(l.motion)) << ' ' << l.intensity << '\n';
        printLightMotion(s, std::int32_t(l.motion));
    }
    for (const DirectionalLight& l : s.lights) {
        std::cout << "  dir_light" << lightName(s, l.motion) << ' ' << l.intensity << " along "
                  << l.direction.x << ' ' << l.direction.y << ' ' << l.direction.z << ", "
                  << shadowText("angle", l.sun) << '\n';
        printLightMotion(s, l.motion);
    }
    for (const LocalLight& l : s.localLights) {
        const bool spot = l.kind == LocalLightKind::Spot;
        std::cout << (spot ? "  spot_light" : "  point_light") << lightName(s, l.motion) << ' ' << l.intensity
                  << " at " << l.position.x << ' ' << l.position.y << ' ' << l.position.z;
        if (spot)
            std::cout << " along " << l.direction.x << ' ' << l.direction.y << ' ' << l.direction.z
                      << ", radius " << l.radius << " falloff " << l.falloff << " tightness " << l.tightness;
        if (l.fade.fades()) std::cout << ", fade " << l.fade.distance << ' ' << l.fade.power;
        std::cout << ", " << shadowText("size", l.area) << '\n';
        printLightMotion(s, l.motion);
    }
}

/// "241 frames, 10.00 s from the first to the last (10.04 s played as a video)":
/// N frames span N-1 intervals, but a video shows each for 1/fps.
std::string describeLength(int lastFrame, int fps) {
    if (lastFrame == 0) return "1 frame (no animation)";
    char text[128];
    std::snprintf(text, sizeof text,
                  "%d frames, %.2f s from the first to the last (%.2f s played as a video)", lastFrame + 1,
                  double(lastFrame) / fps, double(lastFrame + 1) / fps);
    return text;
}

int runInfo(const std::string& path) {
    auto loaded = loadScene(path);
    if (!loaded) return 1;
    const SceneDesc& s = loaded->scene;
    int last = s.lastFrame();
    std::cout << loaded->name << '\n'
              << "  image:      " << s.camera.width << "x" << s.camera.height << ", d " << s.camera.distance
              << '\n'
              << "  frames:     0.." << last << " at " << s.fps << " fps: " << describeLength(last, s.fps)
              << '\n'
              << "  lights:     ambient " << s.ambient << ", " << s.namedAmbients.size() << " named ambient, "
              << s.lights.size() << " directional, " << s.localLights.size() << " point or spot\n"
              << "  objects:    " << s.objects.size() << " (" << s.primitiveCount() << " primitives)\n"
              << "  source:     " << loaded->files.size()
              << (loaded->files.size() == 1 ? " file, " : " files, ") << loaded->linesInFiles << " lines, "
              << loaded->linesRead << " read with /repeat and /include expanded\n";
    if (!s.captions.empty()) {
        double first = s.captions.front().from, end = s.captions.front().to;
        for (const Caption& c : s.captions) {
            first = std::min(first, c.from);
            end = std::max(end, c.to);
        }
        std::cout << "  captions:   " << s.captions.size() << ", from frame " << formatNumber(first) << " to "
                  << formatNumber(end) << '\n';
    }
    printCamera(s);
    printLights(s);
    printModels(s);
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
        const SceneObject& o = s.objects[i];
        std::cout << "  " << typeNameOf(o) << ' ' << o.name << '\n';
        if (o.mayRide()) {
            // "rides on f2.rhand, from 48 on h.rhand, from 96 on nothing" (SPEC 9.2, 10.7).
            std::cout << "    rides on " << (o.attachedTo ? refName(s, *o.attachedTo) : "nothing");
            for (const AttachChange& c : o.attachChanges)
                std::cout << ", from " << formatNumber(c.time) << " on "
                          << (c.mount ? refName(s, *c.mount) : "nothing");
            std::cout << '\n';
        }
        printTrack(o.name, o.track);
        for (std::size_t p = 0; p < o.partTracks.size(); ++p)
            printTrack(o.name + "." + o.model->parts[p].name, o.partTracks[p]);
        // Its colour keys (SPEC 10.3), the whole object's before its parts', and visibility keys (10.7).
        for (const TargetTrack& c : s.colourTracks)
            if (c.target.object == i) printTrack(refName(s, c.target, c.shape) + " colour", c.track);
        for (const TargetTrack& v : s.visibilityTracks)
            if (v.target.object == i) printTrack(refName(s, v.target, v.shape) + " visible", v.track);
    }
    return 0;
}
}  // namespace

Command addInfoCommand(CLI::App& app) {
    auto path = std::make_shared<std::string>();
    CLI::App* sub = app.add_subcommand(
        "info", "Print a scene's camera, objects, parts, key frames, attachments, frame range and fps");
    sub->add_option("scene", *path, "Scene file; '-' reads standard input; none = the default scene")
        ->check(nonEmptyPath("describe the default scene"));
    return {sub, [path] { return runInfo(*path); }};
}

}  // namespace f2::cli
