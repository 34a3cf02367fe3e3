// f2 render: one frame to a PNG, or an animation to a numbered PNG sequence
// or a video (mp4, webm, gif through ffmpeg).
#include <unistd.h>

#include <deque>
#include <filesystem>
#include <future>
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.h"
#include "core/render/renderer.h"
#include "frame_range.h"
#include "interrupt.h"
#include "options.h"
#include "output_target.h"
#include "io/frame_pattern.h"
#include "io/png_writer.h"
#include "io/video_encoder.h"
#include "progress.h"
#include "scene_source.h"

namespace f2::cli {

namespace {
struct RenderArgs {
    std::string scene;
    double frame = 0;
    std::string frames;
    std::string output = "f2.png";
    std::string size;
    int threads = 0;
    int antialias = 1;
    int fps = 0;  ///< 0 = the scene's /fps
    std::string shard;
    bool resume = false;
    const CLI::Option* frameOption = nullptr;
};

/// Everything an animation render needs, resolved from the arguments.
struct AnimationJob {
    const LoadedScene* loaded;
    Camera camera;
    FrameRange range;
    Shard shard;
    int fps;  ///< output frames per second
    int antialias;
    int threads;
    /// Scene time (in scene frames) shown by output frame `i`: the animation
    /// keeps its duration whatever the output rate.
    double timeOf(std::int64_t i) const { return double(i) * loaded->scene.fps / fps; }
};

int interruptedExit() { return 128 + (interruptSignal() ? interruptSignal() : 2); }

std::string describe(const AnimationJob& job) {
    std::ostringstream s;
    s << job.loaded->name << " frames " << job.range.first << "-" << job.range.lastRendered();
    if (job.range.step > 1) s << " every " << job.range.step;
    if (job.shard.count > 1) s << " shard " << job.shard.index << "/" << job.shard.count;
    s << " (" << job.camera.width << "x" << job.camera.height << ", " << job.fps << " fps, aa "
      << job.antialias << ")";
    return s.str();
}

int renderSequence(const AnimationJob& job, const FramePattern& pattern, const std::string& output,
                   bool resume) {
    // A sequence is a directory's worth of files: create the directory, so farm
    // workers need no setup (creating an existing one is fine).
    std::error_code ec;
    std::filesystem::path dir = std::filesystem::path(pattern.format(0)).parent_path();
    if (!dir.empty()) std::filesystem::create_directories(dir, ec);

    Renderer renderer(job.threads);
    Image image;
    const int total = int(job.shard.countIn(job.range));
    Progress progress(total, Progress::isInteractive());
    int done = 0, skipped = 0;
    // Compressing a PNG takes longer than tracing a frame on a few cores, so
    // finished frames are written on their own threads while the next ones
    // render; a couple in flight keep memory bounded.
    constexpr std::size_t kWritesInFlight = 2;
    std::deque<std::future<std::string>> writes;  // each write's error, empty on success
    std::string error;
    auto collectOldest = [&] {
        std::string e = writes.front().get();
        writes.pop_front();
        if (e.empty()) progress.update(++done);
        if (error.empty()) error = e;
        return error.empty();
    };
    bool ok = true;
    for (std::int64_t f = job.range.first; f <= job.range.last && ok && !interruptFlag(); f += job.range.step) {
        if (!job.shard.contains(f)) continue;
        std::string path = pattern.format(int(f));  // at most kMaxOutputFrame
        // Files appear only complete (temporary file, then rename), so one that
        // exists is a finished frame.
        if (resume && std::filesystem::exists(path, ec)) {
            ++skipped;
            progress.skipped(1);
            progress.update(++done);
            continue;
        }
        renderer.render(job.loaded->scene, job.timeOf(f), job.camera, image, {job.antialias},
                        &interruptFlag());
        if (interruptFlag()) break;  // the image is incomplete: drop it
        if (writes.size() >= kWritesInFlight && !(ok = collectOldest())) break;
        writes.push_back(std::async(std::launch::async, [frame = image, path] {
            std::string e;
            writePng(frame, path, e);
            return e;
        }));
    }
    while (!writes.empty()) ok = collectOldest() && ok;  // frames in flight finish even when interrupted
    progress.clear();
    if (!ok) {
        std::cerr << "f2 render: " << error << '\n';
        return 1;
    }
    int rendered = done - skipped;
    if (interruptFlag()) {
        std::cerr << "f2 render: interrupted after " << done << " of " << total
                  << " frames; the finished frames are on disk (rerun with --resume to continue)\n";
        return interruptedExit();
    }
    std::cerr << "f2 render: " << describe(job) << " -> " << output << ": " << rendered << " rendered";
    if (resume) std::cerr << ", " << skipped << " already on disk";
    std::cerr << ", " << renderer.threadCount() << " threads, " << progress.summary() << "\n";
    return 0;
}

int renderVideo(const AnimationJob& job, VideoFormat format, const std::string& output) {
    VideoSettings settings{format, job.camera.width, job.camera.height, job.fps, {}};
    const Color8 bg = job.loaded->scene.background;
    settings.padColor = {bg.r, bg.g, bg.b};
    if (videoNeedsPadding(settings))
        std::cerr << "f2 render: note: H.264 needs an even width and height; padding " << settings.width
                  << "x" << settings.height << " to " << (settings.width + 1) / 2 * 2 << "x"
                  << (settings.height + 1) / 2 * 2 << " with the background colour\n";
    VideoEncoder encoder;
    std::string error;
    if (!encoder.open(settings, output, error)) {
        std::cerr << "f2 render: " << error << '\n';
        return 1;
    }
    Renderer renderer(job.threads);
    Image image;
    Progress progress(int(job.range.count()), Progress::isInteractive());
    int done = 0;
    for (std::int64_t f = job.range.first; f <= job.range.last && !interruptFlag(); f += job.range.step) {
        renderer.render(job.loaded->scene, job.timeOf(f), job.camera, image, {job.antialias},
                        &interruptFlag());
        if (interruptFlag()) break;
        if (!encoder.write(image, error)) {
            progress.clear();
            std::cerr << "f2 render: " << error << '\n';
            return 1;
        }
        progress.update(++done);
    }
    progress.clear();
    // Ctrl+C while ffmpeg still encodes the last frames counts as well.
    bool finished = !interruptFlag() && encoder.finish(error, &interruptFlag());
    if (interruptFlag()) {
        encoder.abort();
        std::cerr << "f2 render: interrupted after " << done << " of " << job.range.count() << " frames; no "
                  << output << " written\n";
        return interruptedExit();
    }
    if (!finished) {
        std::cerr << "f2 render: " << error << '\n';
        return 1;
    }
    std::cerr << "f2 render: " << describe(job) << " -> " << output << ": " << done << " frames of "
              << videoFormatName(format) << ", " << renderer.threadCount() << " threads, "
              << progress.summary() << "\n";
    return 0;
}

int renderImage(const RenderArgs& args, const LoadedScene& loaded, const Camera& camera, double t) {
    Renderer renderer(args.threads);
    Image image;
    FrameTimings timings =
        renderer.render(loaded.scene, t, camera, image, {args.antialias}, &interruptFlag());
    const bool toStdout = args.output == "-";
    const std::string where = toStdout ? "standard output" : args.output;
    if (interruptFlag()) {
        std::cerr << "f2 render: interrupted; " << where << " not written\n";
        return interruptedExit();
    }
    std::string error;
    if (!(toStdout ? writePng(image, stdout, error) : writePng(image, args.output, error))) {
        std::cerr << "f2 render: " << error << '\n';
        return 1;
    }
    std::cerr << "f2 render: " << loaded.name << " frame " << t << " -> " << where << " (" << camera.width
              << "x" << camera.height << ", " << renderer.threadCount() << " threads, "
              << formatMilliseconds(timings.totalMs()) << ")\n";
    return 0;
}

int usageError(const std::string& message) { return f2::cli::usageError("render", message); }

/// Option combinations that do not fit the output kind, checked before the scene is read.
std::string outputMismatch(const RenderArgs& args, const OutputTarget& target) {
    const bool oneFrameOption = args.frameOption->count() > 0;
    switch (target.kind) {
        case OutputTarget::Kind::Video:
            if (oneFrameOption) return "--frame picks one image; a video takes --frames (default: all)";
            if (!args.shard.empty())
                return "--shard splits a PNG sequence (-o f_%04d.png) across machines; a video cannot "
                       "be split: render the sequence, then join it with ffmpeg (docs/output.md)";
            if (args.resume) return "--resume works with a PNG sequence (-o f_%04d.png), not a video";
            return {};
        case OutputTarget::Kind::Sequence:
            if (oneFrameOption) return "--frame picks one image; a sequence takes --frames (default: all)";
            return {};
        case OutputTarget::Kind::StandardOutput:
            if (::isatty(STDOUT_FILENO))
                return "-o - writes PNG data to standard output, which is a terminal; redirect it "
                       "(f2 render -o - > f.png) or pipe it";
            [[fallthrough]];
        case OutputTarget::Kind::Image:
            if (!args.shard.empty() || args.resume)
                return "--shard and --resume need a numbered sequence such as -o f_%04d.png";
            return {};
    }
    return {};
}

int runRender(const RenderArgs& args) {
    std::string error;
    auto target = classifyOutput(args.output, error);
    if (!target) return usageError(error);
    if (std::string mismatch = outputMismatch(args, *target); !mismatch.empty()) return usageError(mismatch);
    // Reading the scene needs no cleanup: until it is read, Ctrl+C simply ends f2 (exit 130).
    auto loaded = loadScene(args.scene);
    if (!loaded) return 1;
    installInterruptHandlers();
    Camera camera = Camera::fromDesc(loaded->scene.camera);
    if (!args.size.empty() && !parseSize(args.size, camera.width, camera.height, error))
        return usageError(error);

    const int fps = args.fps > 0 ? args.fps : loaded->scene.fps;
    // Default range: the whole animation, frame 0 to the last key at the output rate.
    const std::int64_t lastFrame = outputLastFrame(loaded->scene.lastFrame(), loaded->scene.fps, fps);
    FrameRange range;
    if (target->isAnimation() || !args.frames.empty()) {
        auto parsed = parseFrameRange(args.frames.empty() ? "0-" : args.frames, lastFrame, error);
        if (!parsed) return usageError(error);
        range = *parsed;
        if (range.lastRendered() > lastFrame)
            std::cerr << "f2 render: warning: " << pastTheEndWarning(range, lastFrame, fps) << '\n';
    }
    Shard shard;
    if (!args.shard.empty()) {
        auto parsed = parseShard(args.shard, error);
        if (!parsed) return usageError(error);
        shard = *parsed;
    }
    AnimationJob job{&*loaded, camera, range, shard, fps, args.antialias, args.threads};
    if (target->kind == OutputTarget::Kind::Sequence)
        return renderSequence(job, target->pattern, args.output, args.resume);
    // A single file's directory is created as a sequence's is.
    if (target->kind != OutputTarget::Kind::StandardOutput && !createParentDirectory(args.output, error)) {
        std::cerr << "f2 render: " << error << '\n';
        return 1;
    }
    if (target->kind == OutputTarget::Kind::Video) return renderVideo(job, target->video, args.output);
    if (!args.frames.empty() && range.count() != 1)
        return usageError((target->kind == OutputTarget::Kind::StandardOutput ? std::string("-o - writes one PNG")
                                                                              : "'" + args.output + "' holds one image") +
                          "; for --frames " + args.frames +
                          " write a numbered sequence (-o f_%04d.png) or a video (-o out.mp4)");
    double t = args.frames.empty() ? args.frame : job.timeOf(range.first);
    return renderImage(args, *loaded, camera, t);
}
}  // namespace

Command addRenderCommand(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* sub = app.add_subcommand(
        "render", "Render a frame to a PNG, or the animation to a PNG sequence or a video (mp4, webm, gif)");
    sub->footer(
        "The output name decides: -o f.png = one image; -o - = one PNG to standard output; "
        "-o frames/f_%04d.png = one file per frame (%d or %0Nd = frame number); -o out.mp4 | out.webm | "
        "out.gif = a video, encoded by the ffmpeg program. Any other extension is refused. Missing "
        "directories of the output are created. Ctrl+C stops cleanly: no partial file is left.");
    sub->add_option("scene", args->scene, "Scene file; '-' reads standard input; none = the default scene")
        ->check(nonEmptyPath("render the default scene"));
    args->frameOption = sub->add_option("--frame", args->frame,
                                        "One image: the scene time in frames; may be fractional (default 0)")
                            ->check(finiteNumberIn(0.0, 1e7, "a frame time"));
    sub->add_option("--frames", args->frames,
                    "Frames of a sequence or video: FIRST-LAST, FIRST or FIRST- (default: 0 to the last key "
                    "frame), then optionally :STEP for every STEP-th frame (0-239:4); numbered at the output "
                    "--fps")
        ->excludes(sub->get_option("--frame"));
    sub->add_option("-o,--output", args->output,
                    "Output: .png, '-' (PNG to standard output), numbered PNG pattern, .mp4, .webm or .gif "
                    "(default f2.png)")
        ->check(nonEmptyPath("write f2.png"));
    sub->add_option("--size", args->size, "Image size WIDTHxHEIGHT (default: the scene's /camera)");
    sub->add_option("--threads", args->threads, "Render threads (default: all cores)")
        ->check(wholeNumberIn(0, 1024));
    sub->add_option(
           "--aa", args->antialias,
           "Anti-aliasing: N x N stratified samples per pixel, averaged (default 1 = the pixel centre)")
        ->check(wholeNumberIn(1, 16));
    sub->add_option("--fps", args->fps,
                    "Output frames per second (default: the scene's /fps). The animation keeps its length: "
                    "output frame i shows scene time i * (scene fps) / FPS")
        ->check(wholeNumberIn(1, 1000));
    sub->add_option("--shard", args->shard,
                    "Render farm: worker K of N (K = 0..N-1) renders the frames whose number is K modulo N "
                    "(round-robin); sequences only")
        ->type_name("K/N");
    sub->add_flag("--resume", args->resume, "Sequence: skip frames whose file already exists");
    return {sub, [args] { return runRender(*args); }};
}

}  // namespace f2::cli
