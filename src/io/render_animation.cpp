#include "io/render_animation.h"

namespace f2 {

AnimationRange AnimationRange::still(double t, int sceneFps) {
    AnimationRange range;
    range.sceneFps = range.outputFps = sceneFps;
    range.timeOffset = t;
    return range;
}

std::int64_t AnimationRange::count() const {
    // Frames f in [0, n] with f = shardIndex (mod shardCount).
    auto upTo = [this](std::int64_t n) { return n < shardIndex ? 0 : (n - shardIndex) / shardCount + 1; };
    if (last < first) return 0;
    return upTo(last) - (first > 0 ? upTo(first - 1) : 0);
}

AnimationResult renderAnimation(const SceneDesc& scene, const AnimationRange& range, const Camera& camera,
                                FrameSink& sink, const std::atomic<bool>* cancel,
                                const std::function<void(const AnimationProgress&)>& progress,
                                const AnimationOptions& options) {
    AnimationResult result;
    result.total = range.count();
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
        if (progress) progress({result.done, result.skipped, result.total});
    };

    std::string error;
    if (!sink.begin({camera.width, camera.height, range.outputFps, result.total}, error)) return stop(error);
    Image image;
    // The shard's first frame at or after `first`, then every shardCount-th.
    std::int64_t start = range.first + ((range.shardIndex - range.first % range.shardCount) % range.shardCount +
                                        range.shardCount) % range.shardCount;
    for (std::int64_t f = start; f <= range.last; f += range.shardCount) {
        if (cancelled()) return stop("");
        if (sink.alreadyDone(f)) {
            ++result.skipped;
            report();
            continue;
        }
        const FrameTimings timings = renderer.render(scene, range.timeOf(f), camera, image, options.render, cancel);
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
