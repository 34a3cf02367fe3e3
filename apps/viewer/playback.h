#pragma once
/// The animation clock: current time, play/pause, speed and looping. Time is
/// in frames and may be fractional (SPEC 6), so slow motion stays smooth.
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace f2::viewer {

class Playback : public QObject {
    Q_OBJECT
   public:
    explicit Playback(QObject* parent = nullptr);

    /// The animation runs over frames 0..lastFrame at `fps`; the time is clamped into it.
    void setRange(int lastFrame, int fps);
    int lastFrame() const { return lastFrame_; }
    int fps() const { return fps_; }

    double time() const { return time_; }
    /// The whole frame the current time falls in.
    int frame() const;
    bool isPlaying() const { return timer_.isActive(); }
    double speed() const { return speed_; }
    /// Milliseconds between the clock's ticks while playing: one scene frame, at most 60 a second.
    int tickIntervalMs() const { return timer_.interval(); }

   public slots:
    void play();
    void pause();
    void togglePlaying();
    /// Pauses and moves `frames` whole frames from frame() (the frame shown), wrapping around.
    void step(int frames);
    /// Moves to `time` (clamped); keeps playing from there if playing.
    void seek(double time);
    void seekToStart() { seek(0); }
    void seekToEnd() { seek(lastFrame_); }
    void setSpeed(double speed);
    /// Scrubbing pauses the clock while the slider is held and resumes after.
    void beginScrub();
    void endScrub();

   signals:
    void timeChanged(double time);
    void playingChanged(bool playing);

   private:
    void tick();
    void restartClock();
    void setTime(double time);

    QTimer timer_;
    QElapsedTimer clock_;
    double clockBase_ = 0;  // time at the moment clock_ started
    double time_ = 0;
    double speed_ = 1;
    int lastFrame_ = 0;
    int fps_ = 24;
    bool resumeAfterScrub_ = false;
};

}  // namespace f2::viewer
