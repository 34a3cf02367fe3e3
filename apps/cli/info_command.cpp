// f2 info: what a scene holds.
#include <cstdio>
#include <iostream>
#include <memory>

#include "commands.h"
#include "options.h"
#include "core/scene/models.h"
#include "scene_source.h"

namespace f2::cli {

namespace {
const char* kindName(ObjectKind kind) {
    switch (kind) {
        case ObjectKind::Sphere: return "sphere";
        case ObjectKind::Cylinder: return "cylinder";
        case ObjectKind::Box: return "box";
        case ObjectKind::Robot: return "robot";
        case ObjectKind::Human: return "human";
    }
    return "?";
}

void printTrack(const std::string& target, const Track& track) {
    if (track.keys.empty()) return;
    static const char* kInterp[] = {"linear", "ease", "spline"};
    std::cout << "    " << target << ": " << track.keys.size() << " keys, frames " << track.keys.front().frame
              << ".." << track.keys.back().frame << ", " << kInterp[int(track.interpolation)] << '\n';
}

/// "241 frames, 10.00 s from the first to the last (10.04 s played as a video)":
/// N frames span N-1 intervals, but a video shows each for 1/fps.
std::string describeLength(int lastFrame, int fps) {
    if (lastFrame == 0) return "1 frame (no animation)";
    char text[128];
    std::snprintf(text, sizeof text, "%d frames, %.2f s from the first to the last (%.2f s played as a video)",
                  lastFrame + 1, double(lastFrame) / fps, double(lastFrame + 1) / fps);
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
              << "  frames:     0.." << last << " at " << s.fps << " fps: " << describeLength(last, s.fps) << '\n'
              << "  lights:     ambient " << s.ambient << ", " << s.lights.size() << " directional\n"
              << "  objects:    " << s.objects.size() << " (" << s.primitiveCount() << " primitives)\n"
              << "  source:     " << loaded->files.size() << (loaded->files.size() == 1 ? " file, " : " files, ")
              << loaded->linesInFiles << " lines, " << loaded->linesRead
              << " read with /repeat and /include expanded\n";
    for (const SceneObject& o : s.objects) {
        std::cout << "  " << kindName(o.kind) << ' ' << o.name << '\n';
        printTrack(o.name, o.track);
        if (isModel(o.kind))
            for (int p = 0; p < kPartCount; ++p)
                printTrack(o.name + "." + kPartNames[p], o.partTracks[p]);
    }
    return 0;
}
}  // namespace

Command addInfoCommand(CLI::App& app) {
    auto path = std::make_shared<std::string>();
    CLI::App* sub = app.add_subcommand("info", "Print a scene's objects, parts, key frames, frame range and fps");
    sub->add_option("scene", *path, "Scene file; '-' reads standard input; none = the default scene")
        ->check(nonEmptyPath("describe the default scene"));
    return {sub, [path] { return runInfo(*path); }};
}

}  // namespace f2::cli
