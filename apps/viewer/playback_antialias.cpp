#include "playback_antialias.h"

namespace f2::viewer {

void PlaybackAntialias::observe(int antialias, const FrameTimings& timings) {
    const int n = antialias < 1 ? 1 : antialias;
    const Cost cost =
        costModel_ ? costModel_(n) : Cost{timings.evaluateMs + timings.buildMs, timings.traceMs};
    const double perSample = cost.traceMs / double(n * n);
    auto blend = [](std::optional<double>& estimate, double value) {
        estimate = estimate ? *estimate + kSmoothing * (value - *estimate) : value;
    };
    blend(fixedMs_, cost.fixedMs);
    blend(perSampleMs_, perSample);

    // Auto: down at once when the current level no longer fits; up while the next one fits with a margin.
    const double allowed = kHeadroom * budgetMs_;
    while (autoLevel_ > 1 && predictedMs(autoLevel_) > allowed) --autoLevel_;
    while (autoLevel_ < kMaxAutoLevel && predictedMs(autoLevel_ + 1) <= kStepUpMargin * allowed) ++autoLevel_;
}

double PlaybackAntialias::predictedMs(int n) const {
    return fixedMs_.value_or(0) + perSampleMs_.value_or(0) * double(n * n);
}

int PlaybackAntialias::level() const {
    switch (mode_) {
        case PlaybackAntialiasMode::Off:
            return 1;
        case PlaybackAntialiasMode::On:
            return kOnLevel;
        case PlaybackAntialiasMode::Auto:
            return autoLevel_;
    }
    return 1;
}

void PlaybackAntialias::reset() {
    fixedMs_.reset();
    perSampleMs_.reset();
    autoLevel_ = 1;
}

}  // namespace f2::viewer
