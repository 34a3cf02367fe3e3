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
    // Loop over [0, lastFrame + 1): the last frame is shown for one frame's duration too.
    const double period = double(lastFrame_ + 1);
    double t = std::fmod(clockBase_ + elapsed * fps_ * speed_, period);
    setTime(std::min(t, double(lastFrame_) + 0.999));
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
