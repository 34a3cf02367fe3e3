// f2 bench: frames per second of the whole frame (evaluate + build + trace).
#include <algorithm>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <thread>
#include <vector>

#include "bench_measure.h"
#include "bench_study.h"
#include "commands.h"
#include "core/scene/default_scene.h"
#include "io/atomic_file.h"
#include "options.h"

namespace f2::cli {

namespace {
struct BenchArgs {
    std::string scene;      ///< file (positional)
    std::string generated;  ///< --scene robots:N | spheres:N
    std::string size = "800x600";
    BenchSettings settings;
    double seconds = -1;  ///< -1: 3 s, or 1 s a point with --study
    bool json = false;
    bool study = false;
    std::string csvOut = "bench_study.csv";
    std::string plotOut = "bench_study.png";
    std::string peer;         ///< f2_embree_peer for --study, or empty
    std::vector<int> counts;  ///< --study's N, or empty for StudySettings' own
    std::string writeScene;
    std::string frameLog;  ///< --frame-log: CSV of every timed frame
};

constexpr const char* kFooter =
    "Each timed iteration is one Renderer::render at time --frame: evaluate the animation, update the BVH,\n"
    "trace and shade every pixel with shadow rays, fill the image. Same frame every iteration unless "
    "--step;\n"
    "FPS = 1000 / median frame time. Mrays/s counts w*h*aa^2 primary rays plus one shadow ray per hit and "
    "light that\n"
    "faces it, as counted by the renderer while it casts them.\n"
    "\n"
    "Generated scenes (--scene): N robots (arms swing on a spline, head turns, each out of phase; keys\n"
    "at frames 0..48) or N spheres of radius 50 (bobbing) on a grid of C = ceil(sqrt N) columns and\n"
    "ceil(N / C) rows, spacing 150, centred on the origin, on a box floor (top y = -105) with one cell of\n"
    "margin; ambient 0.2, one directional light 0.75 along (0.5, -1, 0.7). Camera: d = 0.5,\n"
    "rotation (35, 0, 0), half = 75 * max(columns, rows), D = 100 + 2 * half,\n"
    "eye = (0, -5 + D sin 35deg, -D cos 35deg). drives:N: N spheres (radius 50) each driven on px and py\n"
    "(SPEC 10.7); drivekeys:N: the same spheres with two linear keys instead. See docs/performance.md.";

int writeSceneText(const BenchArgs& args, int width, int height) {
    std::string text;
    if (!args.generated.empty()) {
        BenchSceneSpec spec;
        std::string error;
        if (!parseBenchSceneSpec(args.generated, spec, error)) {
            return usageError("bench", "--scene: " + error);
        }
        text = benchSceneText(spec, width, height);
    } else {
        text = std::string(defaultSceneText());
    }
    std::ofstream out(args.writeScene, std::ios::binary);
    out << text;
    out.flush();
    if (!out) {
        std::cerr << "f2 bench: cannot write " << args.writeScene << '\n';
        return 1;
    }
    std::cerr << "f2 bench: wrote "
              << (args.generated.empty() ? std::string(kDefaultSceneName) : args.generated) << " to "
              << args.writeScene << '\n';
    return 0;
}

int runBenchCommand(BenchArgs args) {
    int width = 800, height = 600;
    std::string error;
    if (!parseSize(args.size, width, height, error)) {
        return usageError("bench", error);
    }
    if (!args.writeScene.empty()) return writeSceneText(args, width, height);

    if (args.study) {
        StudySettings study;
        study.bench = args.settings;
        study.bench.seconds = args.seconds < 0 ? 1.0 : args.seconds;
        study.width = width;
        study.height = height;
        study.csvOut = args.csvOut;
        study.plotOut = args.plotOut;
        if (!args.counts.empty()) study.counts = args.counts;
        if (!args.peer.empty()) {
            PeerSettings peer;
            peer.program = args.peer;
            peer.threads = args.settings.threads > 0 ? args.settings.threads
                                                     : int(std::max(1u, std::thread::hardware_concurrency()));
            peer.seconds = study.bench.seconds;
            study.peer = peer;
        }
        return runStudy(study);
    }

    std::optional<LoadedScene> loaded;
    if (!args.generated.empty()) {
        BenchSceneSpec spec;
        if (!parseBenchSceneSpec(args.generated, spec, error)) {
            return usageError("bench", "--scene: " + error);
        }
        loaded = loadBenchScene(spec, width, height);
    } else {
        loaded = loadScene(args.scene);
    }
    if (!loaded) return 1;
    // The bench size replaces the scene's /camera size; the view (and so the
    // horizontal field of view) stays, as with `f2 render --size`.
    args.settings.seconds = args.seconds < 0 ? 3.0 : args.seconds;
    BenchResult result = runBench(loaded->scene, loaded->name, width, height, args.settings);
    if (!args.frameLog.empty()) {
        AtomicFile file(args.frameLog);
        std::ostringstream csv;
        writeFrameLog(csv, result);
        const std::string text = csv.str();
        if (!file.ok() || std::fwrite(text.data(), 1, text.size(), file.handle()) != text.size() ||
            !file.commit()) {
            std::cerr << "f2 bench: "
                      << (file.error().empty() ? "cannot write '" + args.frameLog + "'" : file.error())
                      << '\n';
            return 1;
        }
    }
    if (args.json)
        std::cout << benchJson(result) << '\n';
    else
        printBench(std::cout, result);
    return 0;
}
}  // namespace

Command addBenchCommand(CLI::App& app) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* sub = app.add_subcommand(
        "bench",
        "Measure frames per second of whole frames (evaluate + build + trace), or run the FPS study");
    sub->footer(kFooter);
    auto* file = sub->add_option("scene", args->scene,
                                 "Scene file; '-' reads standard input; none = the default scene")
                     ->check(nonEmptyPath("measure the default scene"));
    auto* generated =
        sub->add_option("--scene", args->generated,
                        "Generated scene robots:N or spheres:N (or drives:N, drivekeys:N) instead of a file");
    file->excludes(generated);
    sub->add_option("--frame", args->settings.frame,
                    "Animation time to render, in frames; may be fractional (default 0)")
        ->check(finiteNumberIn(0.0, 1e7, "a frame time"));
    sub->add_option("--step", args->settings.step,
                    "Advance the time by this many frames each iteration, looping over the animation "
                    "(default 0: every iteration renders --frame)")
        ->check(finiteNumberIn(0.0, 1e7, "a step"));
    sub->add_option("--size", args->size, "Image size WIDTHxHEIGHT (default 800x600)");
    sub->add_option("--threads", args->settings.threads, "Render threads, 0..1024 (default 0: all cores)")
        ->check(wholeNumberIn(0, 1024));
    sub->add_option("--seconds", args->seconds,
                    "Timed seconds, at least 3 frames (default 3; 1 per point with --study)")
        ->check(finiteNumberIn(0.0, 3600.0, "a duration"));
    sub->add_option("--frames", args->settings.frames,
                    "Time exactly this many frames instead of --seconds (e.g. 240 with --step 1: the "
                    "slowest frame of a playback)")
        ->check(wholeNumberIn(1, 1000000));
    sub->add_option("--warmup", args->settings.warmupSeconds,
                    "Untimed warm-up seconds, at least 1 frame (default 0.5)")
        ->check(finiteNumberIn(0.0, 600.0, "a duration"));
    sub->add_option("--aa", args->settings.antialias, "N x N samples per pixel, N = 1..16 (default 1)")
        ->check(wholeNumberIn(1, 16));
    auto* json =
        sub->add_flag("--json", args->json,
                      "Print one JSON object: fps, ms_median, ms_min, ms_max, ms_eval, ms_build, ms_trace, "
                      "mrays_per_s, peak_rss_mb, scene, size, threads, frames, ...");
    auto* study =
        sub->add_flag("--study", args->study,
                      "Tables 4.1/4.2: FPS of robots:N and spheres:N for N = 1, 10, 100, 1000, 10000, "
                      "100000, as Markdown on stdout, CSV and a PNG plot");
    study->excludes(file)->excludes(generated)->excludes(json);
    sub->add_option("--csv-out", args->csvOut, "With --study: CSV file (default bench_study.csv)")
        ->needs(study);
    sub->add_option("--plot-out", args->plotOut,
                    "With --study: PNG plot of FPS against N via gnuplot (default "
                    "bench_study.png; empty = no plot)")
        ->needs(study);
    sub->add_option("--counts", args->counts,
                    "With --study: the values of N, comma-separated (default 1,10,100,1000,10000,100000)")
        ->delimiter(',')
        ->check(CLI::Range(1, kMaxBenchObjects))
        ->needs(study);
    sub->add_option("--peer", args->peer,
                    "With --study: also run the Embree peer (the f2_embree_peer program, bench/embree_peer) "
                    "on each point's frame, best of its BVH update modes, in the tables, CSV and plot")
        ->check(CLI::ExistingFile)
        ->needs(study);
    sub->add_option("--frame-log", args->frameLog,
                    "Write a CSV line per timed frame to FILE: time, wall and CPU ms, the evaluate / build "
                    "/ trace split, what the BVH update did (refit, subtrees, rebuild; primitives "
                    "rebuilt) and page faults")
        ->excludes(study);
    sub->add_option(
           "--write-scene", args->writeScene,
           "Write the scene as scene-language text to FILE and exit without measuring (for --scene "
           "robots:N / spheres:N, so `f2 export` and other renderers can read it; --size sets its /camera)")
        ->excludes(file)
        ->excludes(study);
    return {sub, [args] { return runBenchCommand(*args); }};
}

}  // namespace f2::cli
