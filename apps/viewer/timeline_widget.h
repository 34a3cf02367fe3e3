#pragma once
/// Transport bar under the picture: play/pause, step, a frame slider, speed
/// and the current frame. It only reports what the user did; the Playback
/// clock owns the time.
#include <QWidget>

class QComboBox;
class QLabel;
class QSlider;
class QToolButton;

namespace f2::viewer {

class TimelineWidget : public QWidget {
    Q_OBJECT
   public:
    explicit TimelineWidget(QWidget* parent = nullptr);

    void setRange(int lastFrame, int fps);
    /// Shows `time` without emitting seekRequested.
    void setTime(double time);
    void setPlaying(bool playing);

    QSlider* slider() const { return slider_; }
    QComboBox* speedBox() const { return speed_; }

    static constexpr double kSpeeds[] = {0.25, 0.5, 1.0, 2.0, 4.0};

   signals:
    void playToggled();
    void stepRequested(int frames);
    void seekRequested(double time);
    void scrubStarted();
    void scrubFinished();
    void speedChanged(double speed);

   private:
    QToolButton* addButton(int standardIcon, const QString& tip);

    QToolButton* playButton_ = nullptr;
    QSlider* slider_ = nullptr;
    QComboBox* speed_ = nullptr;
    QLabel* frameLabel_ = nullptr;
    int lastFrame_ = 0;
    int fps_ = 24;
};

}  // namespace f2::viewer
