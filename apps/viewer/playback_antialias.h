#pragma once
/// How many samples per pixel the frames rendered while the animation plays
/// get (View › Playback Anti-aliasing): Off (one), On (2x2 always) or Auto,
/// which picks the most the frame budget allows from the measured frame times.
#include <functional>
#include <optional>

#include "core/render/renderer.h"

namespace f2::viewer {

enum class PlaybackAntialiasMode { Off, Auto, On };

class PlaybackAntialias {
   public:
    /// N of the N x N samples that On uses.
    static constexpr int kOnLevel = 2;
    /// Auto goes up to what the paused picture refines to (`f2 render --aa 4`).
    static constexpr int kMaxAutoLevel = 4;
    /// Share of the budget a frame's render may take: converting, handing over
    /// and painting the picture and the GUI's own work need the rest.
    static constexpr double kHeadroom = 0.75;
    /// Auto steps up only when the higher level is predicted to take at most
    /// this share of what it may take, so that it does not flip back and forth
    /// between two levels on noise; it steps down as soon as a frame would not fit.
    static constexpr double kStepUpMargin = 0.8;
    /// Weight of the newest frame in the running estimates (smooths one slow frame).
    static constexpr double kSmoothing = 0.3;

    /// A frame's cost in milliseconds, split as the estimate models it: the
    /// part that does not depend on the samples (evaluate, build) and the
    /// trace, which grows with N x N.
    struct Cost {
        double fixedMs = 0, traceMs = 0;
    };
    /// Stands in for the measurement (tests): the cost of a frame at N x N.
    using CostModel = std::function<Cost(int antialias)>;

    void setMode(PlaybackAntialiasMode mode) { mode_ = mode; }
    PlaybackAntialiasMode mode() const { return mode_; }

    /// The time one frame may take, in milliseconds: the playback clock's tick.
    void setBudgetMs(double ms) { budgetMs_ = ms; }
    double budgetMs() const { return budgetMs_; }

    /// Learns from a delivered frame rendered with `antialias` x `antialias` samples.
    void observe(int antialias, const FrameTimings& timings);
    /// Replaces the measured timings by `model` (tests: no real timing); empty = measure.
    void setCostModel(CostModel model) { costModel_ = std::move(model); }

    /// N of the N x N samples for the next frame while playing.
    int level() const;
    /// Forgets the estimates (another scene: its cost is unknown) and starts Auto at one sample.
    void reset();

   private:
    /// Predicted milliseconds of a frame at N x N from the estimates.
    double predictedMs(int n) const;

    PlaybackAntialiasMode mode_ = PlaybackAntialiasMode::Auto;
    double budgetMs_ = 1000.0 / 60;
    CostModel costModel_;
    std::optional<double> fixedMs_, perSampleMs_;  // running estimates
    int autoLevel_ = 1;
};

}  // namespace f2::viewer
