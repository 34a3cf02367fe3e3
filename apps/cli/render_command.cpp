// f2 render: one frame to a PNG, or an animation to a numbered PNG sequence
// or a video (mp4, webm, gif through ffmpeg).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.h"
#include "frame_range.h"
#include "interrupt.h"
#include "io/frame_pattern.h"
#include "io/image_sink.h"
#include "io/output_target.h"
#include "io/render_animation.h"
#include "io/sequence_sink.h"
#include "io/video_sink.h"
#include "options.h"
#include "output_kind.h"
#include "pixel_story.h"
#include "progress.h"
#include "scene_source.h"
#include "view_option.h"

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
    std::string pixel;  ///< "X,Y": print that pixel's story instead of writing an image
    ViewMode view = ViewMode::Shaded;
    MotionBlur motionBlur;
    const CLI::Option* frameOption = nullptr;
    const CLI::Option* motionBlurOption = nullptr;
};

/// Everything an animation render needs, resolved from the arguments.
struct AnimationJob {
    const LoadedScene* loaded;
    FrameView view;  ///< the scene's camera at each frame's time, at the image size
    AnimationRange range;
    int antialias;
    int threads;
    ViewMode viewMode;
    MotionBlur motionBlur;
};

int interruptedExit() { return 128 + (interruptSignal() ? interruptSignal() : 2); }

std::string describe(const AnimationJob& job) {
    std::ostringstream s;
    if (job.range.first == job.range.lastRendered()) {
        s << job.loaded->name << " frame " << job.range.first;  // not "frames 5-5 every 10"
    } else {
        s << job.loaded->name << " frames " << job.range.first << "-" << job.range.lastRendered();
        if (job.range.step > 1) s << " every " << job.range.step;
    }
    if (job.range.shardCount > 1) s << " shard " << job.range.shardIndex << "/" << job.range.shardCount;
    s << " (" << job.view.width << "x" << job.view.height << ", " << job.range.outputFps << " fps, aa "
      << job.antialias;
    if (job.viewMode != ViewMode::Shaded) s << ", view " << viewModeName(job.viewMode);
    if (job.motionBlur.enabled())
        s << ", motion blur " << job.motionBlur.shutter << " x " << job.motionBlur.samples;
    s << ")";
    return s.str();
}

/// f2::renderAnimation with the live progress bar and Ctrl+C.
AnimationResult renderWithProgress(const AnimationJob& job, FrameSink& sink, Progress& progress) {
    std::int64_t skipped = 0;
    AnimationResult result =
        renderAnimation(job.loaded->scene, job.range, job.view, sink, &interruptFlag(),
                        [&](const AnimationProgress& p) {
                            progress.skipped(int(p.skipped - skipped));
                            skipped = p.skipped;
                            progress.update(int(p.done), double(p.subFramesDone) / p.subFramesPerFrame);
                        },
                        {job.threads, {job.antialias, job.viewMode}, job.motionBlur});
    progress.clear();
    return result;
}

int renderSequence(const AnimationJob& job, const FramePattern& pattern, const std::string& output,
                   bool resume) {
    PngSequenceSink sink(pattern, resume);
    Progress progress(int(job.range.count()), Progress::isInteractive());
    const AnimationResult result = renderWithProgress(job, sink, progress);
    switch (result.outcome) {
        case AnimationResult::Outcome::Failed:
            std::cerr << "f2 render: " << result.error << '\n';
            return 1;
        case AnimationResult::Outcome::Cancelled:
            std::cerr << "f2 render: interrupted after " << result.done << " of " << result.total
                      << " frames; the finished frames are on disk (rerun with --resume to continue)\n";
            return interruptedExit();
        case AnimationResult::Outcome::Finished:
            break;
    }
    std::cerr << "f2 render: " << describe(job) << " -> " << output << ": " << result.rendered()
              << " rendered";
    if (resume) std::cerr << ", " << result.skipped << " already on disk";
    std::cerr << ", " << result.threads << " threads, " << progress.summary() << "\n";
    return 0;
}

int renderVideo(const AnimationJob& job, VideoFormat format, const std::string& output) {
    VideoSettings settings{format, job.view.width, job.view.height, job.range.outputFps, {}};
    const Color8 bg = job.loaded->scene.background;
    if (videoNeedsPadding(settings))
        std::cerr << "f2 render: note: H.264 needs an even width and height; padding " << settings.width
                  << "x" << settings.height << " to " << (settings.width + 1) / 2 * 2 << "x"
                  << (settings.height + 1) / 2 * 2 << " with the background colour\n";
    VideoSink sink(output, format, {bg.r, bg.g, bg.b});
    Progress progress(int(job.range.count()), Progress::isInteractive());
    const AnimationResult result = renderWithProgress(job, sink, progress);
    switch (result.outcome) {
        case AnimationResult::Outcome::Failed:
            std::cerr << "f2 render: " << result.error;
            if (findProgram("ffmpeg").empty())
                std::cerr << "; or write a PNG sequence with -o frames/f_%04d.png";
            std::cerr << '\n';
            return 1;
        case AnimationResult::Outcome::Cancelled:
            std::cerr << "f2 render: interrupted after " << result.done << " of " << result.total
                      << " frames; no " << output << " written\n";
            return interruptedExit();
        case AnimationResult::Outcome::Finished:
            break;
    }
    std::cerr << "f2 render: " << describe(job) << " -> " << output << ": " << result.done << " frames of "
              << videoFormatName(format) << ", " << result.threads << " threads, " << progress.summary()
              << "\n";
    return 0;
}

int renderImage(const RenderArgs& args, const LoadedScene& loaded, const FrameView& view, double t) {
    const bool toStdout = args.output == "-";
    PngImageSink sink = toStdout ? PngImageSink(stdout, "standard output") : PngImageSink(args.output);
    const std::string where = toStdout ? "standard output" : args.output;
    const AnimationResult result =
        renderAnimation(loaded.scene, AnimationRange::still(t, loaded.scene.fps), view, sink,
                        &interruptFlag(), {}, {args.threads, {args.antialias, args.view}, args.motionBlur});
    switch (result.outcome) {
        case AnimationResult::Outcome::Failed:
            std::cerr << "f2 render: " << result.error << '\n';
            return 1;
        case AnimationResult::Outcome::Cancelled:
            std::cerr << "f2 render: interrupted; " << where << " not written\n";
            return interruptedExit();
        case AnimationResult::Outcome::Finished:
            break;
    }
    std::cerr << "f2 render: " << loaded.name << " frame " << t << " -> " << where << " (" << view.width
              << "x" << view.height << ", "
              << (args.view != ViewMode::Shaded ? "view " + std::string(viewModeName(args.view)) + ", " : "");
    if (args.motionBlur.enabled())
        std::cerr << "motion blur " << args.motionBlur.shutter << " x " << args.motionBlur.samples << ", ";
    std::cerr << result.threads << " threads, " << formatMilliseconds(result.renderMs) << ")\n";
    return 0;
}

int usageError(const std::string& message) { return f2::cli::usageError("render", message); }

/// Option combinations that do not fit the output kind, checked before the scene is read.
std::string outputMismatch(const RenderArgs& args, const OutputKind& output) {
    const bool oneFrameOption = args.frameOption->count() > 0;
    switch (output.kind) {
        case OutputKind::Kind::Video:
            if (oneFrameOption) return "--frame picks one image; a video takes --frames (default: all)";
            if (!args.shard.empty())
                return "--shard splits a PNG sequence (-o f_%04d.png) across machines; a video cannot "
                       "be split: render the sequence, then join it with ffmpeg (docs/output.md)";
            if (args.resume) return "--resume works with a PNG sequence (-o f_%04d.png), not a video";
            return {};
        case OutputKind::Kind::Sequence:
            if (oneFrameOption) return "--frame picks one image; a sequence takes --frames (default: all)";
            return {};
        case OutputKind::Kind::StandardOutput:
            if (::isatty(STDOUT_FILENO))
                return "-o - writes PNG data to standard output, which is a terminal; redirect it "
                       "(f2 render -o - > f.png) or pipe it";
            [[fallthrough]];
        case OutputKind::Kind::Image:
            if (!args.shard.empty() || args.resume)
                return "--shard and --resume need a numbered sequence such as -o f_%04d.png";
            return {};
    }
    return {};
}

int runRender(const RenderArgs& args) {
    if (args.motionBlur.shutter == 0 && args.motionBlurOption->count() > 0)
        return usageError(
            "--motion-blur: the shutter must be more than 0 (a fraction of a frame, up to 1); leave the "
            "option out for sharp frames");
    if (args.motionBlur.enabled() && args.view != ViewMode::Shaded)
        return usageError("--view " + std::string(viewModeName(args.view)) +
                          " shows one instant; --motion-blur averages the shaded picture over many");
    std::string error;
    auto output = classifyOutput(args.output, error);
    if (!output) return usageError(error);
    if (std::string mismatch = outputMismatch(args, *output); !mismatch.empty()) return usageError(mismatch);
    // Reading the scene needs no cleanup: until it is read, Ctrl+C simply ends f2 (exit 130).
    auto loaded = loadScene(args.scene);
    if (!loaded) return 1;
    installInterruptHandlers();
    int width = loaded->scene.camera.width, height = loaded->scene.camera.height;
    if (!args.size.empty() && !parseSize(args.size, width, height, error)) return usageError(error);

    const int fps = args.fps > 0 ? args.fps : loaded->scene.fps;
    // Default range: the whole animation, frame 0 to the last key at the output rate (64-bit: a
    // key at 10^7 with /fps 1 at --fps 1000 is 10^10 frames, refused by parseFrameRange).
    const std::int64_t lastFrame = outputFrameAt(loaded->scene.lastFrame(), loaded->scene.fps, fps);
    FrameRange range;
    if (output->isAnimation() || !args.frames.empty()) {
        auto parsed = parseFrameRange(args.frames.empty() ? "0-" : args.frames, lastFrame, error);
        if (!parsed) return usageError(error);
        range = *parsed;
    }
    if (output->kind == OutputKind::Kind::Video && range.step > 1) {
        // A video shows each frame for 1/fps s: skipping frames would play the animation too fast.
        const long slower = std::max(1L, std::lround(double(fps) / double(range.step)));
        return usageError("--frames " + args.frames + ": a video plays every frame it holds at " +
                          std::to_string(fps) + " fps, so with a step of " + std::to_string(range.step) +
                          " it would play " + std::to_string(range.step) +
                          " times as fast; for a quick preview video lower the rate (--fps " +
                          std::to_string(slower) + "), or write a sequence (-o preview/f_%04d.png)");
    }
    Shard shard;
    if (!args.shard.empty()) {
        auto parsed = parseShard(args.shard, error);
        if (!parsed) return usageError(error);
        shard = *parsed;
    }
    const AnimationRange frames{range.first, range.last,  loaded->scene.fps, fps,
                                0,           shard.index, shard.count,       range.step};
    if (frames.lastRendered() > lastFrame)
        std::cerr << "f2 render: warning: " << pastTheEndWarning(frames, lastFrame) << '\n';
    // --frame is scene time; a scene without keys has no end to be past.
    const int sceneLast = loaded->scene.lastFrame();
    if (args.frames.empty() && !output->isAnimation() && sceneLast > 0 && args.frame > sceneLast)
        std::cerr << "f2 render: warning: frame " << args.frame << " is past the animation's last frame "
                  << sceneLast << ": it shows its final pose\n";
    AnimationJob job{&*loaded,       FrameView::sceneCamera(width, height),
                     frames,         args.antialias,
                     args.threads,   args.view,
                     args.motionBlur};
    if (!args.pixel.empty()) {
        if (!args.frames.empty() || !args.shard.empty() || args.resume)
            return usageError("--pixel traces one pixel of one frame: choose the frame with --frame");
        if (args.motionBlur.enabled())
            return usageError(
                "--pixel traces one pixel at one time; --motion-blur averages many: leave it out, or "
                "trace a sub-frame's time with --frame");
        int x = 0, y = 0;
        if (!parsePixel(args.pixel, width, height, x, y, error)) return usageError(error);
        if (std::optional<std::string> problem = firstDriveProblem(loaded->scene, args.frame)) {
            std::cerr << "f2 render: " << *problem << '\n';
            return 1;
        }
        return printPixelStory(*loaded, job.view.at(loaded->scene, args.frame), args.frame, x, y,
                               args.antialias, args.threads);
    }
    if (output->kind == OutputKind::Kind::Sequence)
        return renderSequence(job, output->pattern, args.output, args.resume);
    // A single file's directory is created as a sequence's is.
    if (output->kind != OutputKind::Kind::StandardOutput && !createDirectoryOf(args.output, error)) {
        std::cerr << "f2 render: " << error << '\n';
        return 1;
    }
    if (output->kind == OutputKind::Kind::Video) return renderVideo(job, output->video, args.output);
    if (!args.frames.empty() && range.count() != 1)
        return usageError((output->kind == OutputKind::Kind::StandardOutput
                               ? std::string("-o - writes one PNG")
                               : "'" + args.output + "' holds one image") +
                          "; for --frames " + args.frames +
                          " write a numbered sequence (-o f_%04d.png) or a video (-o out.mp4)");
    double t = args.frames.empty() ? args.frame : frames.timeOf(range.first);
    return renderImage(args, *loaded, job.view, t);
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
    args->frameOption =
        sub->add_option("--frame", args->frame,
                        "One image: the scene time in frames, 0..1e7; may be fractional (default 0)")
            ->check(finiteNumberIn(0.0, 1e7, "a frame time"));
    sub->add_option("--frames", args->frames,
                    "Frames of a sequence or video: FIRST-LAST, FIRST or FIRST- (default: 0 to the last key "
                    "frame), then optionally :STEP for every STEP-th frame of a sequence (0-239:4); numbered "
                    "at the output --fps")
        ->excludes(sub->get_option("--frame"));
    sub->add_option("-o,--output", args->output,
                    "Output: .png, '-' (PNG to standard output), numbered PNG pattern, .mp4, .webm or .gif "
                    "(default f2.png)")
        ->check(nonEmptyPath("write f2.png"));
    sub->add_option("--size", args->size, "Image size WIDTHxHEIGHT (default: the scene's /camera)");
    sub->add_option("--threads", args->threads, "Render threads, 0..1024 (default 0: all cores)")
        ->check(wholeNumberIn(0, 1024));
    sub->add_option(
           "--aa", args->antialias,
           "Anti-aliasing: N x N stratified samples per pixel, averaged; N = 1..16 (default 1 = the pixel "
           "centre)")
        ->check(wholeNumberIn(1, 16));
    sub->add_option(
           "--fps", args->fps,
           "Output frames per second, 1..1000 (default: the scene's /fps). The animation keeps its length: "
           "output frame i shows scene time i * (scene fps) / FPS")
        ->check(wholeNumberIn(1, 1000));
    sub->add_option("--shard", args->shard,
                    "Render farm: worker K of N (K = 0..N-1) renders the frames whose number is K modulo N "
                    "(round-robin); sequences only")
        ->type_name("K/N");
    sub->add_flag("--resume", args->resume, "Sequence: skip frames whose file already exists");
    CLI::Option* motionBlur =
        sub->add_option(
               "--motion-blur", args->motionBlur.shutter,
               "Motion blur: the shutter is open for S of each frame, 0 < S <= 1, centred on the "
               "frame's time; the frame is the mean of --motion-samples sub-frames at the centres of "
               "equal slices of that time (a moving camera blurs too)")
            ->type_name("S")
            ->check(finiteNumberIn(0.0, 1.0, "a shutter"));
    args->motionBlurOption = motionBlur;
    sub->add_option("--motion-samples", args->motionBlur.samples,
                    "Sub-frames averaged per frame with --motion-blur, 1.." +
                        std::to_string(MotionBlur::kMaxSamples) + " (default " +
                        std::to_string(MotionBlur::kDefaultSamples) + ")")
        ->type_name("N")
        ->check(wholeNumberIn(1, MotionBlur::kMaxSamples))
        ->needs(motionBlur);
    sub->add_option(
           "--pixel", args->pixel,
           "Print the story of one pixel (its ray, every primitive along it, the hit, the normal, each "
           "light's term and shadow, the colour) instead of writing an image")
        ->type_name("X,Y");
    addViewOption(*sub, args->view);
    return {sub, [args] { return runRender(*args); }};
}

}  // namespace f2::cli
