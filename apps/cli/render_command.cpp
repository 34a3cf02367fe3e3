// f2 render: one frame of a scene to a PNG.
#include <iostream>
#include <memory>

#include "commands.h"
#include "core/render/renderer.h"
#include "io/png_writer.h"
#include "scene_source.h"

namespace f2::cli {

namespace {
struct RenderArgs {
    std::string scene;
    double frame = 0;
    std::string output = "f2.png";
    std::string size;
    int threads = 0;
    int antialias = 1;
};

int runRender(const RenderArgs& args) {
    auto loaded = loadScene(args.scene);
    if (!loaded) return 1;
    Camera camera = Camera::fromDesc(loaded->scene.camera);
    if (!args.size.empty()) {
        std::string error;
        if (!parseSize(args.size, camera.width, camera.height, error)) {
            std::cerr << "f2 render: " << error << '\n';
            return 2;
        }
    }
    Renderer renderer(args.threads);
    Image image;
    FrameTimings timings = renderer.render(loaded->scene, args.frame, camera, image, {args.antialias});
    std::string error;
    if (!writePng(image, args.output, error)) {
        std::cerr << "f2 render: " << error << '\n';
        return 1;
    }
    std::cerr << "f2 render: " << loaded->name << " frame " << args.frame << " -> " << args.output << " ("
              << camera.width << "x" << camera.height << ", " << renderer.threadCount() << " threads, "
              << timings.totalMs() << " ms)\n";
    return 0;
}
}  // namespace

Command addRenderCommand(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* sub = app.add_subcommand("render", "Render a frame of a scene to a PNG image");
    sub->add_option("scene", args->scene, "Scene file; '-' reads standard input; none = the default scene");
    sub->add_option("--frame", args->frame, "Frame to render; may be fractional (default 0)")
        ->check(CLI::Range(0.0, 1e7));
    sub->add_option("-o,--output", args->output, "Output PNG file (default f2.png)");
    sub->add_option("--size", args->size, "Image size WIDTHxHEIGHT (default: the scene's /camera)");
    sub->add_option("--threads", args->threads, "Render threads (default: all cores)")
        ->check(CLI::Range(0, 1024));
    sub->add_option("--aa", args->antialias, "N x N stratified samples per pixel (default 1)")
        ->check(CLI::Range(1, 16));
    return {sub, [args] { return runRender(*args); }};
}

}  // namespace f2::cli
