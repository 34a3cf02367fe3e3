// f2 export: one evaluated frame as a scene for another renderer — POV-Ray
// (--pov) or the Embree peer's primitive list (--prims) — or the whole
// animation as glTF 2.0 (--gltf) for Blender, three.js and the like, or as a
// clock-driven POV-Ray scene and its .ini (--pov --animation).
#include <cerrno>
#include <cstring>
#include <iostream>
#include <memory>
#include <optional>
#include <vector>

#include "commands.h"
#include "core/scene/drive.h"
#include "io/atomic_file.h"
#include "io/gltf_export.h"
#include "io/output_target.h"
#include "io/pov_animation.h"
#include "io/pov_export.h"
#include "io/prims_export.h"
#include "io/tessellate.h"
#include "options.h"
#include "scene_source.h"

namespace f2::cli {

namespace {
struct ExportArgs {
    std::string scene;
    double frame = 0;
    bool pov = false, prims = false, gltf = false, animation = false, gltfPointer = false;
    int tessellation = 32;
    std::string output = "-";
    std::string size;
};

bool writeOutput(const std::string& text, const std::string& path, std::string& error) {
    if (path == "-") {
        errno = 0;
        std::cout << text << std::flush;
        if (!std::cout)
            error = std::string("cannot write to standard output") +
                    (errno ? ": " + std::string(std::strerror(errno)) : "");
        return bool(std::cout);
    }
    if (!createDirectoryOf(path, error)) return false;
    AtomicFile file(path);  // never a half-written scene, even on Ctrl+C
    if (!file.ok()) {
        error = file.error();
        return false;
    }
    if (std::fwrite(text.data(), 1, text.size(), file.handle()) != text.size() || !file.commit()) {
        error = file.error().empty() ? "cannot write '" + path + "'" : file.error();
        return false;
    }
    return true;
}

bool endsWith(const std::string& text, const std::string& tail) {
    return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

/// Frames 0..lastFrame of `scene`, or the first drive problem among them (SPEC 10.7).
std::optional<std::string> animationDriveProblem(const SceneDesc& scene) {
    std::vector<double> frames(std::size_t(scene.lastFrame()) + 1);
    for (std::size_t f = 0; f < frames.size(); ++f) frames[f] = double(f);
    return firstDriveProblem(scene, frames);
}

/// --gltf: the whole animation; a .gltf gets its buffer in a .bin beside it.
int runGltfExport(const ExportArgs& args, const LoadedScene& loaded, const Camera& camera) {
    if (args.output == "-")
        return usageError("export", "--gltf writes a file: give it with -o out.glb (or out.gltf)");
    const bool text = endsWith(args.output, ".gltf");
    const std::string binPath = text ? args.output.substr(0, args.output.size() - 5) + ".bin" : "";
    GltfOptions options;
    options.width = camera.width;
    options.height = camera.height;
    options.tessellation = args.tessellation;
    options.pointer = args.gltfPointer;
    options.source = loaded.name;
    if (text) options.bufferUri = uriOfFileName(binPath.substr(binPath.find_last_of('/') + 1));
    // Every frame is written: a drive without a finite value at any is an error (SPEC 10.7).
    if (std::optional<std::string> problem = animationDriveProblem(loaded.scene)) {
        std::cerr << "f2 export: " << *problem << '\n';
        return 1;
    }
    const GltfDocument document = gltfScene(loaded.scene, options);
    for (const std::string& w : document.warnings) std::cerr << "f2 export: warning: " << w << '\n';
    std::string error;
    const bool written =
        text ? writeOutput(std::string(document.bin.begin(), document.bin.end()), binPath, error) &&
                   writeOutput(document.json, args.output, error)
             : writeOutput(glbBytes(document), args.output, error);
    if (!written) {
        std::cerr << "f2 export: " << error << '\n';
        return 1;
    }
    std::cerr << "f2 export: " << loaded.name << " frames 0-" << loaded.scene.lastFrame() << " at "
              << loaded.scene.fps << " fps -> " << args.output << (text ? " + " + binPath : "")
              << " (glTF 2.0, " << document.nodes << " nodes, " << document.meshes << " meshes, "
              << document.materials << " materials, " << document.channels << " animation channels)\n";
    return 0;
}

/// --pov --animation: NAME.pov driven by clock and NAME.ini beside it.
int runPovAnimationExport(const ExportArgs& args, const LoadedScene& loaded, const Camera& camera) {
    const std::string& path = args.output;
    if (path == "-" || !endsWith(path, ".pov"))
        return usageError("export", "--animation writes NAME.pov and NAME.ini: give -o NAME.pov");
    const std::size_t slash = path.find_last_of('/');
    const std::string directory = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    const std::string stem = path.substr(directory.size(), path.size() - directory.size() - 4);
    if (!povIniName(stem))
        return usageError("export", "--animation: the file name '" + stem +
                                        "' must be letters, digits and ._+- only (it goes into the .ini)");
    if (std::optional<std::string> problem = animationDriveProblem(loaded.scene)) {
        std::cerr << "f2 export: " << *problem << '\n';
        return 1;
    }
    if (!loaded.scene.captions.empty())
        std::cerr << "f2 export: warning: " << loaded.scene.captions.size()
                  << (loaded.scene.captions.size() == 1 ? " caption" : " captions")
                  << " left out (captions are drawn by f2 only)\n";
    const PovAnimation animation = povAnimation(loaded.scene, camera.width, camera.height, loaded.name, stem);
    const std::string iniPath = directory + stem + ".ini";
    std::string error;
    if (!writeOutput(animation.scene, path, error) || !writeOutput(animation.ini, iniPath, error)) {
        std::cerr << "f2 export: " << error << '\n';
        return 1;
    }
    std::cerr << "f2 export: " << loaded.name << " frames 0-" << animation.lastFrame << " at "
              << loaded.scene.fps << " fps -> " << path << " + " << iniPath << " (POV-Ray 3.7, "
              << loaded.scene.primitiveCount() << " primitives, " << animation.evaluated
              << (animation.cameraEvaluated ? " shapes and the camera" : " shapes")
              << " moved by POV-Ray from their keys, " << animation.evaluatedLooks
              << " colours or visibilities keyed in POV-Ray, " << animation.arrays
              << " values read per frame, " << camera.width << "x" << camera.height << ")\n";
    return 0;
}

int runExport(const ExportArgs& args) {
    if (int(args.pov) + int(args.prims) + int(args.gltf) != 1) {
        return usageError("export",
                          "choose one format: --pov (POV-Ray 3.7 scene), --prims (primitive list) or --gltf "
                          "(glTF 2.0 animation)");
    }
    auto loaded = loadScene(args.scene);
    if (!loaded) return 1;
    // A drive without a finite value makes the frame an error (SPEC 10.7).
    if (std::optional<std::string> problem = firstDriveProblem(loaded->scene, args.frame)) {
        std::cerr << "f2 export: " << *problem << '\n';
        return 1;
    }
    Camera camera = cameraAt(loaded->scene, args.frame);
    std::string error;
    if (!args.size.empty() && !parseSize(args.size, camera.width, camera.height, error))
        return usageError("export", error);
    if (args.gltf) return runGltfExport(args, *loaded, camera);
    if (args.animation) return runPovAnimationExport(args, *loaded, camera);
    // Text over the picture is F2's own (SPEC 10.5): neither output can hold it.
    std::size_t shown = 0;
    for (const Caption& c : loaded->scene.captions) shown += c.shownAt(args.frame);
    if (shown > 0)
        std::cerr << "f2 export: warning: " << shown << (shown == 1 ? " caption" : " captions")
                  << " of frame " << args.frame << " left out (captions are drawn by f2 only)\n";
    std::string text = args.pov ? povScene(loaded->scene, args.frame, camera, loaded->name)
                                : primsScene(loaded->scene, args.frame, camera, loaded->name);
    if (!writeOutput(text, args.output, error)) {
        std::cerr << "f2 export: " << error << '\n';
        return 1;
    }
    if (args.output != "-")
        std::cerr << "f2 export: " << loaded->name << " frame " << args.frame << " -> " << args.output << " ("
                  << (args.pov ? "POV-Ray 3.7" : "primitive list") << ", " << loaded->scene.primitiveCount()
                  << " primitives, " << camera.width << "x" << camera.height << ")\n";
    return 0;
}
}  // namespace

Command addExportCommand(CLI::App& app) {
    auto args = std::make_shared<ExportArgs>();
    CLI::App* sub = app.add_subcommand(
        "export",
        "Write one evaluated frame as a scene for another renderer: POV-Ray (--pov) or the "
        "Embree peer's primitive list (--prims); or the whole animation as glTF 2.0 (--gltf) for "
        "Blender, three.js and other tools, or as a clock-driven POV-Ray scene and .ini (--pov --animation)");
    sub->add_option("scene", args->scene, "Scene file; '-' reads standard input; none = the default scene")
        ->check(nonEmptyPath("export the default scene"));
    auto* frame = sub->add_option("--frame", args->frame, "Frame to export; may be fractional (default 0)")
                      ->check(finiteNumberIn(0.0, 1e7, "a frame time"));
    auto* pov = sub->add_flag("--pov", args->pov,
                              "POV-Ray 3.7 scene; render it with: povray +IFILE +Oout.png +WW +HH -A +FN -D");
    sub->add_flag(
           "--animation", args->animation,
           "With --pov: the whole animation as NAME.pov driven by clock (seconds) plus NAME.ini "
           "(cd to it and run: povray NAME.ini -> NAME_000.png...; +SFk +EFk for frame k); no --frame. "
           "Keys of objects, models, rides, the camera, lights, colours and visibility are evaluated "
           "by POV-Ray (/look_at too); changing rides, a riding camera and drives are read per frame "
           "(docs/output.md)")
        ->needs(pov)
        ->excludes(frame);
    auto* prims =
        sub->add_flag("--prims", args->prims, "Plain-text primitive list (Embree peer renderer format)")
            ->excludes(pov);
    auto* gltf =
        sub->add_flag("--gltf", args->gltf,
                      "glTF 2.0 of the whole animation (every frame, so no --frame): binary .glb, or "
                      ".gltf + .bin when the output ends in .gltf; what it leaves out: docs/output.md")
            ->excludes(pov)
            ->excludes(prims)
            ->excludes(frame);  // it writes them all: a --frame would be a mistake, not a choice
    sub->add_flag("--gltf-pointer", args->gltfPointer,
                  "--gltf: colour, light intensity and camera d keys and drives too, as channels of "
                  "KHR_animation_pointer (sampled at every frame; not every glTF reader plays them)")
        ->needs(gltf);
    sub->add_option("--tessellation", args->tessellation,
                    "--gltf: segments around each sphere and cylinder (default 32)")
        ->check(CLI::Range(kMinTessellation, kMaxTessellation));
    sub->add_option("-o,--output", args->output,
                    "Output file; '-' = standard output (default; not for --gltf or --animation)")
        ->check(nonEmptyPath("write to standard output"));
    sub->add_option("--size", args->size,
                    "Image size WIDTHxHEIGHT written into the camera (default: /camera)");
    return {sub, [args] { return runExport(*args); }};
}

}  // namespace f2::cli
