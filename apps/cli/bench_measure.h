#pragma once
/// The measurement behind `f2 bench`: render one frame over and over through
/// Renderer::render (evaluate + build + trace), after a warm-up, and summarise
/// the frame times. See docs/performance.md for what is timed and why.
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "core/render/camera.h"
#include "core/render/prepared_frame.h"
#include "core/render/renderer.h"
#include "io/bench_scenes.h"
#include "scene_source.h"

namespace f2::cli {

struct BenchSettings {
    double frame = 0;  ///< animation time t (frames)
    /// 0: every iteration renders t = frame. Otherwise iteration k renders
    /// frame + k * step, looped over the scene's animation (playback: things
    /// move between frames, so a BVH that refits pays what playback pays).
    double step = 0;
    int threads = 0;             ///< 0 = every core
    double seconds = 3.0;        ///< timed duration (at least kMinTimedFrames frames)
    double warmupSeconds = 0.5;  ///< untimed frames first (at least one frame)
    int frames = 0;              ///< > 0: exactly this many timed frames, whatever `seconds` says
    int antialias = 1;
};

/// Timed frames never fewer than this, however slow, so a median exists.
inline constexpr int kMinTimedFrames = 3;

/// One timed frame, for `f2 bench --frame-log` (finding which frames of a playback are slow, and why).
struct BenchFrame {
    double time = 0;           ///< animation time t rendered
    double ms = 0, cpuMs = 0;  ///< wall and CPU time of the whole frame
    double msEval = 0, msBuild = 0, msTrace = 0;
    Bvh::UpdateReport bvh;                  ///< what Bvh::update did
    long minorFaults = 0, majorFaults = 0;  ///< page faults of the process during the frame
};

struct BenchResult {
    std::string scene;
    int width = 0, height = 0, threads = 0, antialias = 1;
    double frame = 0, step = 0;
    std::size_t primitives = 0;
    int frames = 0, warmupFrames = 0;
    double seconds = 0;  ///< wall time of the timed frames
    /// Whole-frame wall time around Renderer::render (ms).
    double msMedian = 0, msMin = 0, msMax = 0, msP10 = 0, msP90 = 0;
    /// Medians of the split Renderer::render reports (ms).
    double msEval = 0, msBuild = 0, msTrace = 0;
    /// CPU time of the whole process (every thread) per timed frame, in ms:
    /// median and slowest. On a shared machine these vary far less than wall
    /// time, since the time spent waiting for a core is not counted.
    double cpuMsMedian = 0, cpuMsMax = 0;
    /// Timed frames whose BVH update built the whole tree at once, those that
    /// put in a staged rebuild, and the most splitting one timed update did
    /// (Bvh::UpdateReport::splitWork): a slow frame without any is the
    /// machine's doing, not the tree's.
    int bvhRebuilds = 0, bvhSwaps = 0;
    std::uint64_t bvhMaxSplitWork = 0;
    /// Lights that cast shadow rays (directional, point and spot): a lamps:N
    /// scene's N. Its trace time per light is msTracePerLight.
    std::size_t lights = 0;
    RayCounts rays;  ///< of the last timed frame
    double peakRssMb = 0;
    std::vector<BenchFrame> perFrame;  ///< every timed frame, in order

    double fps() const { return msMedian > 0 ? 1000.0 / msMedian : 0; }
    /// Rays per second over the whole frame (evaluate + build + trace).
    double mraysPerSecond() const { return msMedian > 0 ? double(rays.total()) / (msMedian * 1e3) : 0; }
    /// Trace time (median) over the number of lights, in ms (0 without lights).
    double msTracePerLight() const { return lights > 0 ? msTrace / double(lights) : 0; }
    /// Rays per second over the trace phase alone (the peers' usual figure).
    double mraysPerSecondTrace() const { return msTrace > 0 ? double(rays.total()) / (msTrace * 1e3) : 0; }
};

/// Parses a generated scene (robots:N, spheres:N, lamps:N) with its camera at width x height.
std::optional<LoadedScene> loadBenchScene(const BenchSceneSpec& spec, int width, int height);

/// Runs the benchmark at width x height (each frame seen by the scene's camera
/// at its time, cameraAt); `name` labels the result.
BenchResult runBench(const SceneDesc& scene, const std::string& name, int width, int height,
                     const BenchSettings& settings);

/// Peak resident set of this process in MB (VmHWM, else ru_maxrss).
double peakRssMb();
/// Restarts the peak-RSS mark at the current RSS (Linux clear_refs); false if unsupported.
bool resetPeakRss();

/// One-line JSON object with every field of the result.
std::string benchJson(const BenchResult& result);
/// CSV of the timed frames (a header, then one line per frame).
void writeFrameLog(std::ostream& out, const BenchResult& result);
/// Human-readable summary.
void printBench(std::ostream& out, const BenchResult& result);

}  // namespace f2::cli
