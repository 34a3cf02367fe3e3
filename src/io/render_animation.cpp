#include "io/render_animation.h"

#include <numeric>

namespace f2 {

AnimationRange AnimationRange::still(double t, int sceneFps) {
    AnimationRange range;
    range.sceneFps = range.outputFps = sceneFps;
    range.timeOffset = t;
    return range;
}

std::int64_t AnimationRange::count() const {
    if (last < first) return 0;
    // Frame first + k*step (k = 0..frames-1) is in the shard when it is shardIndex
    // mod shardCount; that repeats in k with period shardCount / gcd(step, shardCount):
    // count one period, then the whole periods and the rest.
    const std::int64_t n = shardCount;
    const std::int64_t period = n / std::gcd(step % n, n);
    const std::int64_t frames = (last - first) / step + 1;
    std::int64_t perPeriod = 0, rest = 0;
    for (std::int64_t k = 0; k < period && k < frames; ++k) {
        if (!inShard(first + k * step)) continue;
        ++perPeriod;
        if (k < frames % period) ++rest;
    }
    return frames / period * perPeriod + rest;
}

AnimationResult renderAnimation(const SceneDesc& scene, const AnimationRange& range, const FrameView& view,
                                FrameSink& sink, const std::atomic<bool>* cancel,
                                const std::function<void(const AnimationProgress&)>& progress,
                                const AnimationOptions& options) {
    AnimationResult result;
    result.total = range.count();
    const MotionBlur& blur = options.motionBlur;
    Renderer renderer(options.threads);
    result.threads = renderer.threadCount();
    auto cancelled = [cancel] { return cancel && cancel->load(); };
    auto stop = [&](std::string error) {
        sink.abandon();
        result.outcome = cancelled() ? AnimationResult::Outcome::Cancelled : AnimationResult::Outcome::Failed;
        if (result.outcome == AnimationResult::Outcome::Failed) result.error = std::move(error);
        result.done = sink.framesCompleted();
        return result;
    };
    auto report = [&] {
        result.done = sink.framesCompleted();
        if (progress)
            progress({result.done, result.skipped, result.total, 0, blur.enabled() ? blur.samples : 1});
    };

    std::string error;
    if (!sink.begin({view.width, view.height, range.outputFps, result.total}, error)) return stop(error);
    Image image;
    for (std::int64_t f = range.first; f <= range.last; f += range.step) {
        if (!range.inShard(f)) continue;
        if (cancelled()) return stop("");
        if (sink.alreadyDone(f)) {
            ++result.skipped;
            report();
            continue;
        }
        const double t = range.timeOf(f);
        // A drive without a finite value makes the frame an error (SPEC 10.7), named before it is traced.
        std::vector<double> times{t};
        if (blur.enabled() && !scene.drives.empty()) {
            times.clear();
            for (int i = 0; i < blur.samples; ++i)
                times.push_back(blur.subFrameTime(t, range.frameLength(), i));
        }
        if (std::optional<std::string> problem = firstDriveProblem(scene, times))
            return stop(std::move(*problem));
        const FrameTimings timings =
            blur.enabled()
                ? renderer.renderAveraged(
                      scene, t, blur.subFrames(scene, view, t, range.frameLength()), image, options.render,
                      cancel,
                      [&](int subFrames) {
                          if (progress && subFrames < blur.samples)
                              progress({result.done, result.skipped, result.total, subFrames, blur.samples});
                      })
                : renderer.render(scene, t, view.at(scene, t), image, options.render, cancel);
        if (!timings.complete || cancelled()) return stop("");  // the image is partial: dropped
        result.renderMs += timings.totalMs();
        if (!sink.write(image, f, error, cancel)) return stop(error);
        report();
    }
    if (!sink.finish(error, cancel)) return stop(error);
    report();
    return result;
}

}  // namespace f2
