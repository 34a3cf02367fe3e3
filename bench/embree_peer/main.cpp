// f2_embree_peer — the Embree 3 renderer that f2 is measured against
// (docs/performance.md). It renders a frame exported by `f2 export --prims`
// with Embree's BVH and ray packets, the same image by SPEC 2-4, and times it
// as f2 bench times f2: warm-up, then the median of the timed frames.
//
//   f2_embree_peer FRAME.prims [--threads N] [--rebuild MODE] [--out FILE.png] ...
//
// It prints a summary and one machine-readable line,
//   RESULT prims=... threads=... packet=... rebuild=... fps=... total_fps=... ...
// which scripts/compare_peers.sh reads.
#include <embree3/rtcore.h>
#include <tbb/global_control.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "io/png_writer.h"
#include "packet_renderer.h"
#include "prims_file.h"
#include "user_shapes.h"

namespace {

using Clock = std::chrono::steady_clock;
using namespace f2::peer;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Options {
    std::string prims, out, rebuild = "none";
    int threads = int(std::max(1u, std::thread::hardware_concurrency()));
    int packet = 16, tile = 32, minFrames = 20;
    double seconds = 1.0, warmup = 0.3;
};

void reportError(void*, RTCError code, const char* message) {
    std::fprintf(stderr, "f2_embree_peer: Embree error %d: %s\n", int(code), message ? message : "");
}

/// One frame's timed parts, in ms.
struct FrameTimes {
    double update = 0, build = 0, render = 0;
    double total() const { return update + build + render; }
};

int run(const Options& options) {
    const std::map<std::string, BuildMode> modes = {{"none", BuildMode::Static},
                                                    {"low", BuildMode::Low},
                                                    {"medium", BuildMode::Medium},
                                                    {"high", BuildMode::High},
                                                    {"refit", BuildMode::Refit}};
    const BuildMode mode = modes.at(options.rebuild);
    const bool perFrameBuild = mode != BuildMode::Static;

    PrimsFrame frame;
    std::string error;
    if (!readPrimsFile(options.prims, frame, error)) {
        std::fprintf(stderr, "%s\n", error.c_str());
        return 1;
    }

    // Both Embree's builders and our tiles run on TBB: one limit for both.
    tbb::global_control threadLimit(tbb::global_control::max_allowed_parallelism,
                                    std::size_t(options.threads));
    const std::string config = "threads=" + std::to_string(options.threads);
    RTCDevice device = rtcNewDevice(config.c_str());
    if (!device) {
        std::fprintf(stderr, "f2_embree_peer: cannot create an Embree device (error %d)\n",
                     int(rtcGetDeviceError(nullptr)));
        return 1;
    }
    rtcSetDeviceErrorFunction(device, reportError, nullptr);
    int status = 0;
    {
        UserShapeScene scene(device, mode);
        PacketRenderer renderer(frame, options.packet, options.tile);

        // The first build; a static scene keeps it.
        auto start = Clock::now();
        scene.setPrimitives(frame.prims);
        scene.commit();
        const double firstBuildMs = msSince(start);

        auto renderFrame = [&](RayCounts& counts) {
            FrameTimes times;
            auto t0 = Clock::now();
            if (perFrameBuild) {
                // What an animation does each frame: hand over the moved primitives, update the BVH.
                scene.setPrimitives(frame.prims);
                times.update = msSince(t0);
                auto t1 = Clock::now();
                scene.commit();
                times.build = msSince(t1);
            }
            auto t2 = Clock::now();
            counts = renderer.render(scene);
            times.render = msSince(t2);
            return times;
        };

        RayCounts counts;
        int warmupFrames = 0;
        for (auto begin = Clock::now(); warmupFrames < 3 || msSince(begin) < options.warmup * 1000;
             ++warmupFrames)
            renderFrame(counts);
        std::vector<double> update, build, render, total;
        for (auto begin = Clock::now();
             int(total.size()) < options.minFrames || msSince(begin) < options.seconds * 1000;) {
            const FrameTimes t = renderFrame(counts);
            update.push_back(t.update);
            build.push_back(t.build);
            render.push_back(t.render);
            total.push_back(t.total());
        }

        const double renderMs = median(render), totalMs = median(total);
        const double rays = double(counts.primary + counts.shadow);
        const bool ray16 = rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED) != 0;
        std::printf(
            "f2_embree_peer: %s, %zu primitives, %dx%d, %d threads, %d-ray packets (native 16: %s), "
            "%dx%d tiles\n",
            options.prims.c_str(), frame.prims.size(), frame.width, frame.height, options.threads,
            options.packet, ray16 ? "yes" : "no", options.tile, options.tile);
        std::printf("first build %.3f ms; %zu frames timed after %d warm-up frames\n", firstBuildMs,
                    total.size(), warmupFrames);
        std::printf("render: median %.3f ms (min %.3f, max %.3f) -> %.1f FPS, %.1f Mrays/s\n", renderMs,
                    *std::min_element(render.begin(), render.end()),
                    *std::max_element(render.begin(), render.end()), 1000.0 / renderMs,
                    rays / (renderMs * 1e3));
        if (perFrameBuild)
            std::printf(
                "per frame with the BVH updated (%s): update %.3f + build %.3f ms, whole frame %.3f ms -> "
                "%.1f FPS\n",
                options.rebuild.c_str(), median(update), median(build), totalMs, 1000.0 / totalMs);
        std::printf(
            "RESULT prims=%zu threads=%d packet=%d tile=%d rebuild=%s build_ms=%.3f render_ms=%.4f fps=%.2f "
            "primary=%llu shadow=%llu mrays=%.2f update_ms=%.4f rebuild_ms=%.4f total_ms=%.4f "
            "total_fps=%.2f\n",
            frame.prims.size(), options.threads, options.packet, options.tile, options.rebuild.c_str(),
            firstBuildMs, renderMs, 1000.0 / renderMs, static_cast<unsigned long long>(counts.primary),
            static_cast<unsigned long long>(counts.shadow), rays / (renderMs * 1e3), median(update),
            median(build), totalMs, 1000.0 / totalMs);

        if (!options.out.empty() && !f2::writePng(renderer.image(), options.out, error)) {
            std::fprintf(stderr, "f2_embree_peer: %s\n", error.c_str());
            status = 1;
        }
    }
    rtcReleaseDevice(device);
    return status;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    CLI::App app{"f2_embree_peer: renders a frame of `f2 export --prims` with Intel Embree 3 and times it"};
    app.add_option("prims", options.prims, "the frame, as written by f2 export --prims")->required();
    app.add_option("--threads", options.threads, "threads (TBB; default: every core)")
        ->check(CLI::Range(1, 1024));
    app.add_option("--rebuild", options.rebuild,
                   "none: BVH built once; low|medium|high: rebuilt every frame at that Embree quality; "
                   "refit: refitted every frame")
        ->check(CLI::IsMember({"none", "low", "medium", "high", "refit"}));
    app.add_option("--packet", options.packet, "rays per packet: 16 (4x4 pixels), 8 (4x2) or 4 (2x2)")
        ->check(CLI::IsMember({4, 8, 16}));
    app.add_option("--tile", options.tile, "tile side in pixels, a multiple of 4 up to 64")
        ->check(CLI::Range(4, 64) & CLI::Validator(
                                        [](std::string& s) {
                                            return std::stoi(s) % 4 == 0 ? std::string()
                                                                         : std::string("not a multiple of 4");
                                        },
                                        "MULTIPLE OF 4"));
    app.add_option("--seconds", options.seconds, "timed seconds (at least --min-frames frames)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--warmup", options.warmup, "untimed seconds first (at least 3 frames)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--min-frames", options.minFrames, "timed frames at least")->check(CLI::Range(1, 1000000));
    app.add_option("--out", options.out, "write the last frame as PNG");
    CLI11_PARSE(app, argc, argv);
    return run(options);
}
