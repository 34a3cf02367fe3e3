// f2 export: one evaluated frame as a scene for another renderer — POV-Ray
// (--pov) or the Embree peer's primitive list (--prims).
#include <cerrno>
#include <cstring>
#include <iostream>
#include <memory>

#include "commands.h"
#include "io/atomic_file.h"
#include "io/output_target.h"
#include "io/pov_export.h"
#include "io/prims_export.h"
#include "options.h"
#include "scene_source.h"

namespace f2::cli {

namespace {
struct ExportArgs {
    std::string scene;
    double frame = 0;
    bool pov = false, prims = false;
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

int runExport(const ExportArgs& args) {
    if (args.pov == args.prims) {
        return usageError("export",
                          "choose one format: --pov (POV-Ray 3.7 scene) or --prims (primitive list)");
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
        "Embree peer's primitive list (--prims)");
    sub->add_option("scene", args->scene, "Scene file; '-' reads standard input; none = the default scene")
        ->check(nonEmptyPath("export the default scene"));
    sub->add_option("--frame", args->frame, "Frame to export; may be fractional (default 0)")
        ->check(finiteNumberIn(0.0, 1e7, "a frame time"));
    auto* pov = sub->add_flag("--pov", args->pov,
                              "POV-Ray 3.7 scene; render it with: povray +IFILE +Oout.png +WW +HH -A +FN -D");
    sub->add_flag("--prims", args->prims, "Plain-text primitive list (Embree peer renderer format)")
        ->excludes(pov);
    sub->add_option("-o,--output", args->output, "Output file; '-' = standard output (default)")
        ->check(nonEmptyPath("write to standard output"));
    sub->add_option("--size", args->size,
                    "Image size WIDTHxHEIGHT written into the camera (default: /camera)");
    return {sub, [args] { return runExport(*args); }};
}

}  // namespace f2::cli
