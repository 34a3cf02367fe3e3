#include "bench_measure.h"

#include <sys/resource.h>
#include <time.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

#include "core/parse/parser.h"
#include "core/render/renderer.h"

namespace f2::cli {

namespace {
using Clock = std::chrono::steady_clock;

/// CPU time used by every thread of this process so far, in ms.
double processCpuMs() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) / 1e6;
}

/// Minor and major page faults of this process so far.
std::pair<long, long> pageFaults() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return {usage.ru_minflt, usage.ru_majflt};
}

const char* updateActionName(Bvh::UpdateAction action) {
    switch (action) {
        case Bvh::UpdateAction::Refit:
            return "refit";
        case Bvh::UpdateAction::Subtrees:
            return "subtrees";
        case Bvh::UpdateAction::Staged:
            return "staged";
        case Bvh::UpdateAction::Swapped:
            return "swapped";
        case Bvh::UpdateAction::Rebuilt:
            break;
    }
    return "rebuilt";
}

double msBetween(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}

/// Value at fraction q (0..1) of sorted data, linear between neighbours.
double quantile(const std::vector<double>& sorted, double q) {
    if (sorted.empty()) return 0;
    double pos = q * double(sorted.size() - 1);
    std::size_t i = std::size_t(pos);
    if (i + 1 >= sorted.size()) return sorted.back();
    return sorted[i] + (sorted[i + 1] - sorted[i]) * (pos - double(i));
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return quantile(v, 0.5);
}

std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", unsigned(c));
            out += buf;
        } else {
            out += c;
        }
    }
    return out + '"';
}

/// Fixed-point number for JSON and tables; snprintf with '.' as the program
/// never calls setlocale.
std::string fixed(double v, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}
}  // namespace

std::optional<LoadedScene> loadBenchScene(const BenchSceneSpec& spec, int width, int height) {
    const std::string name = benchSceneName(spec);
    ParseResult parsed = parseScene(benchSceneText(spec, width, height), "<" + name + ">");
    for (const Diagnostic& d : parsed.diagnostics) std::cerr << d.format() << '\n';
    if (!parsed.ok()) return std::nullopt;
    return LoadedScene{std::move(*parsed.scene), name, std::move(parsed.files), parsed.linesInFiles,
                       parsed.linesRead};
}

double peakRssMb() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind("VmHWM:", 0) == 0) {
            std::istringstream fields(line.substr(6));
            double kb = 0;
            if (fields >> kb) return kb / 1024.0;
        }
    }
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

bool resetPeakRss() {
#if defined(__GLIBC__)
    malloc_trim(0);  // hand freed heap back first, or the new mark starts at the old peak
#endif
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5\n";  // 5 = reset the peak RSS (proc(5))
    clear.flush();
    return bool(clear);
}

BenchResult runBench(const SceneDesc& scene, const std::string& name, int width, int height,
                     const BenchSettings& settings) {
    Renderer renderer(settings.threads);
    Image image;
    const RenderOptions options{settings.antialias};
    BenchResult result;
    result.scene = name;
    result.width = width;
    result.height = height;
    result.threads = renderer.threadCount();
    result.antialias = settings.antialias;
    result.frame = settings.frame;
    result.step = settings.step;
    // Time of iteration k: with a step, loop over [0, last key] like playback.
    const double span = std::max(scene.lastFrame(), 1);
    long iteration = 0;
    auto nextTime = [&] {
        double t = settings.frame + settings.step * double(iteration++);
        return settings.step == 0 ? t : std::fmod(t, span);
    };

    // Warm-up: fills caches, grows the renderer's buffers, wakes the pool and
    // lets the CPU clock settle; none of it is timed.
    const auto warmStart = Clock::now();
    // The camera is evaluated per frame like the animation: a moving camera is
    // part of the frame's work.
    auto renderAt = [&](double t) {
        return renderer.render(scene, t, cameraAt(scene, t).resized(width, height), image, options);
    };
    do {
        renderAt(nextTime());
        ++result.warmupFrames;
    } while (msBetween(warmStart, Clock::now()) < settings.warmupSeconds * 1e3);

    std::vector<double> total, eval, build, trace, cpu;
    const auto start = Clock::now();
    for (;;) {
        const auto faultsBefore = pageFaults();
        const double cpuBefore = processCpuMs();
        const double time = nextTime();
        const auto before = Clock::now();
        FrameTimings t = renderAt(time);
        const auto after = Clock::now();
        cpu.push_back(processCpuMs() - cpuBefore);
        const auto faultsAfter = pageFaults();
        total.push_back(msBetween(before, after));
        eval.push_back(t.evaluateMs);
        build.push_back(t.buildMs);
        trace.push_back(t.traceMs);
        result.perFrame.push_back({time, total.back(), cpu.back(), t.evaluateMs, t.buildMs, t.traceMs,
                                   renderer.frame().bvh.lastUpdate(), faultsAfter.first - faultsBefore.first,
                                   faultsAfter.second - faultsBefore.second});
        result.rays = t.rays;  // counted by the renderer as it casts them
        if (settings.frames > 0 ? total.size() >= std::size_t(settings.frames)
                                : total.size() >= std::size_t(kMinTimedFrames) &&
                                      msBetween(start, after) >= settings.seconds * 1e3)
            break;
    }
    result.seconds = msBetween(start, Clock::now()) / 1e3;
    result.frames = int(total.size());
    result.cpuMsMedian = median(cpu);
    result.cpuMsMax = *std::max_element(cpu.begin(), cpu.end());
    std::sort(total.begin(), total.end());
    result.msMedian = quantile(total, 0.5);
    result.msMin = total.front();
    result.msMax = total.back();
    result.msP10 = quantile(total, 0.1);
    result.msP90 = quantile(total, 0.9);
    result.msEval = median(eval);
    result.msBuild = median(build);
    result.msTrace = median(trace);
    result.primitives = renderer.frame().primitives.size();
    result.lights = scene.lights.size() + scene.localLights.size();
    for (const BenchFrame& f : result.perFrame) {
        result.bvhRebuilds += f.bvh.action == Bvh::UpdateAction::Rebuilt;
        result.bvhSwaps += f.bvh.action == Bvh::UpdateAction::Swapped;
        result.bvhMaxSplitWork = std::max(result.bvhMaxSplitWork, f.bvh.splitWork);
    }
    result.peakRssMb = peakRssMb();
    return result;
}

std::string benchJson(const BenchResult& r) {
    std::ostringstream j;
    j << "{\"scene\": " << jsonString(r.scene) << ", \"size\": \"" << r.width << 'x' << r.height << "\""
      << ", \"width\": " << r.width << ", \"height\": " << r.height << ", \"threads\": " << r.threads
      << ", \"simd\": \"" << packetIsaName() << "\", \"aa\": " << r.antialias
      << ", \"frame_t\": " << fixed(r.frame, 3) << ", \"step\": " << fixed(r.step, 3)
      << ", \"primitives\": " << r.primitives << ", \"frames\": " << r.frames
      << ", \"warmup_frames\": " << r.warmupFrames << ", \"seconds\": " << fixed(r.seconds, 3)
      << ", \"fps\": " << fixed(r.fps(), 2) << ", \"ms_median\": " << fixed(r.msMedian, 4)
      << ", \"ms_min\": " << fixed(r.msMin, 4) << ", \"ms_max\": " << fixed(r.msMax, 4)
      << ", \"ms_p10\": " << fixed(r.msP10, 4) << ", \"ms_p90\": " << fixed(r.msP90, 4)
      << ", \"ms_eval\": " << fixed(r.msEval, 4) << ", \"ms_build\": " << fixed(r.msBuild, 4)
      << ", \"ms_trace\": " << fixed(r.msTrace, 4) << ", \"cpu_ms\": " << fixed(r.cpuMsMedian, 4)
      << ", \"cpu_ms_max\": " << fixed(r.cpuMsMax, 4) << ", \"bvh_rebuilds\": " << r.bvhRebuilds
      << ", \"bvh_swaps\": " << r.bvhSwaps << ", \"bvh_max_split_work\": " << r.bvhMaxSplitWork
      << ", \"primary_rays\": " << r.rays.primary << ", \"shadow_rays\": " << r.rays.shadow
      << ", \"reflected_rays\": " << r.rays.reflected << ", \"mrays_per_s\": " << fixed(r.mraysPerSecond(), 3)
      << ", \"mrays_per_s_trace\": " << fixed(r.mraysPerSecondTrace(), 3)
      << ", \"peak_rss_mb\": " << fixed(r.peakRssMb, 2) << ", \"lights\": " << r.lights
      << ", \"ms_trace_per_light\": " << fixed(r.msTracePerLight(), 4) << "}";
    return j.str();
}

void writeFrameLog(std::ostream& out, const BenchResult& r) {
    out << "frame,t,ms,cpu_ms,ms_eval,ms_build,ms_trace,bvh,subtrees_rebuilt,primitives_rebuilt,split_work,"
           "sah_growth,"
           "minor_faults,major_faults\n";
    for (std::size_t i = 0; i < r.perFrame.size(); ++i) {
        const BenchFrame& f = r.perFrame[i];
        const char* bvh = updateActionName(f.bvh.action);
        out << i << ',' << fixed(f.time, 3) << ',' << fixed(f.ms, 4) << ',' << fixed(f.cpuMs, 4) << ','
            << fixed(f.msEval, 4) << ',' << fixed(f.msBuild, 4) << ',' << fixed(f.msTrace, 4) << ',' << bvh
            << ',' << f.bvh.subtreesRebuilt << ',' << f.bvh.primitivesRebuilt << ',' << f.bvh.splitWork << ','
            << fixed(f.bvh.costGrowth, 4) << ',' << f.minorFaults << ',' << f.majorFaults << '\n';
    }
}

void printBench(std::ostream& out, const BenchResult& r) {
    out << "f2 bench: " << r.scene << " frame " << r.frame
        << (r.step != 0 ? " stepping " + fixed(r.step, 3) : "") << " (" << r.primitives << " primitives), "
        << r.width << 'x' << r.height << (r.antialias > 1 ? " aa " + std::to_string(r.antialias) : "") << ", "
        << r.threads << " threads, " << packetIsaName() << " lanes (" << packetWidth() << " wide)\n"
        << "  frames      " << r.frames << " timed in " << fixed(r.seconds, 2) << " s after "
        << r.warmupFrames << " warm-up\n"
        << "  frame time  median " << fixed(r.msMedian, 3) << " ms  (min " << fixed(r.msMin, 3) << ", p10 "
        << fixed(r.msP10, 3) << ", p90 " << fixed(r.msP90, 3) << ", max " << fixed(r.msMax, 3) << ")\n"
        << "  FPS         " << fixed(r.fps(), 1) << "  (1000 / median frame time)\n"
        << "  split       evaluate " << fixed(r.msEval, 3) << " ms, build " << fixed(r.msBuild, 3)
        << " ms, trace " << fixed(r.msTrace, 3) << " ms  (medians)\n"
        << "  CPU time    median " << fixed(r.cpuMsMedian, 3) << " ms per frame, all threads (max "
        << fixed(r.cpuMsMax, 3) << ")\n"
        << "  BVH         " << r.bvhRebuilds << " built whole, " << r.bvhSwaps
        << " staged rebuilds put in; at most " << r.bvhMaxSplitWork << " primitives split in one frame\n"
        << "  rays        " << r.rays.primary << " primary + " << r.rays.shadow << " shadow + "
        << r.rays.reflected << " mirrored per frame: " << fixed(r.mraysPerSecond(), 1)
        << " Mrays/s over the frame, " << fixed(r.mraysPerSecondTrace(), 1) << " over trace\n"
        << "  lights      " << r.lights << " casting shadows: trace " << fixed(r.msTracePerLight(), 3)
        << " ms per light (median trace / lights)\n"
        << "  peak RSS    " << fixed(r.peakRssMb, 1) << " MB\n";
}

}  // namespace f2::cli
