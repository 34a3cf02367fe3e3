#include "playback.h"

#include <algorithm>
#include <cmath>

#include "core/anim/frame_time.h"

namespace f2::viewer {

namespace {
constexpr int kMaxTickHz = 60;  // no point asking for more pictures than a display shows
}

Playback::Playback(QObject* parent) : QObject(parent) {
    timer_.setTimerType(Qt::PreciseTimer);
    connect(&timer_, &QTimer::timeout, this, &Playback::tick);
}

void Playback::setRange(int lastFrame, int fps) {
    lastFrame_ = std::max(0, lastFrame);
    fps_ = std::max(1, fps);
    // One tick per scene frame: playback shows the scene at its own rate.
    timer_.setInterval(1000 / std::min(fps_, kMaxTickHz));
    setTime(std::clamp(time_, 0.0, double(lastFrame_)));
    if (loop_) setLoop(FrameRange{std::min(loop_->first, lastFrame_), std::min(loop_->last, lastFrame_)});
    restartClock();
}

int Playback::frame() const { return int(std::clamp<std::int64_t>(frameAt(time_), 0, lastFrame_)); }

void Playback::play() {
    if (isPlaying()) return;
    restartClock();
    timer_.start();
    emit playingChanged(true);
}

void Playback::pause() {
    if (!isPlaying()) return;
    timer_.stop();
    emit playingChanged(false);
}

void Playback::togglePlaying() { isPlaying() ? pause() : play(); }

void Playback::step(int frames) {
    pause();
    const int count = lastFrame_ + 1;
    const int target = ((frame() + frames) % count + count) % count;
    setTime(target);
}

void Playback::seek(double time) {
    setTime(std::clamp(time, 0.0, double(lastFrame_)));
    restartClock();
}

void Playback::setSpeed(double speed) {
    if (!(speed > 0)) return;
    speed_ = speed;
    restartClock();  // the new speed applies from now, without a jump
}

void Playback::setLoopIn(int frame) {
    frame = std::clamp(frame, 0, lastFrame_);
    const int out = loop_ ? loop_->last : lastFrame_;
    setLoop(FrameRange{frame, std::max(frame, out)});
}

void Playback::setLoopOut(int frame) {
    frame = std::clamp(frame, 0, lastFrame_);
    const int in = loop_ ? loop_->first : 0;
    setLoop(FrameRange{std::min(frame, in), frame});
}

void Playback::clearLoop() { setLoop(std::nullopt); }

void Playback::setLoop(std::optional<FrameRange> loop) {
    if (loop == loop_) return;
    loop_ = loop;
    restartClock();
    emit loopRangeChanged();
}

void Playback::beginScrub() {
    resumeAfterScrub_ = resumeAfterScrub_ || isPlaying();
    pause();
}

void Playback::endScrub() {
    if (resumeAfterScrub_) play();
    resumeAfterScrub_ = false;
}

void Playback::tick() {
    if (lastFrame_ == 0) return;  // a still scene: nothing moves, nothing to re-render
    // Time follows the wall clock, not the tick count, so a late tick or a
    // slow frame does not slow the animation down: frames get skipped instead.
    const double elapsed = double(clock_.nsecsElapsed()) * 1e-9;
    // Loop over [first, last + 1): the last frame is shown for one frame's
    // duration too. Playing from outside the loop starts at its in point.
    const FrameRange range = playRange();
    if (time_ < range.first || time_ >= range.last + 1.0) {
        setTime(range.first);
        restartClock();
        return;
    }
    const double period = double(range.last - range.first + 1);
    const double t = range.first + std::fmod(clockBase_ + elapsed * fps_ * speed_ - range.first, period);
    setTime(std::min(t, double(range.last) + 0.999));
}

void Playback::restartClock() {
    clockBase_ = time_;
    clock_.start();
}

void Playback::setTime(double time) {
    time_ = time;
    emit timeChanged(time_);
}

}  // namespace f2::viewer
