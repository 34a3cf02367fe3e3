#include "timeline_widget.h"

#include <QBoxLayout>
#include <QComboBox>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QStyle>
#include <QToolButton>
#include <algorithm>
#include <cmath>

#include "core/anim/frame_time.h"

namespace f2::viewer {

TimelineWidget::TimelineWidget(QWidget* parent) : QWidget(parent) {
    auto* rows = new QVBoxLayout(this);
    rows->setContentsMargins(6, 2, 6, 2);
    rows->setSpacing(0);
    auto* layout = new QHBoxLayout;
    layout->setContentsMargins(0, 0, 0, 0);
    rows->addLayout(layout);

    // Standard style icons: they exist on every platform, unlike media glyphs in fonts.
    QToolButton* first = addButton(QStyle::SP_MediaSkipBackward, tr("First frame (Home)"));
    QToolButton* back = addButton(QStyle::SP_MediaSeekBackward, tr("Step back (Left)"));
    playButton_ = addButton(QStyle::SP_MediaPlay, tr("Play / pause (Space)"));
    QToolButton* forward = addButton(QStyle::SP_MediaSeekForward, tr("Step forward (Right)"));
    QToolButton* last = addButton(QStyle::SP_MediaSkipForward, tr("Last frame (End)"));
    for (QToolButton* b : {first, back, playButton_, forward, last}) layout->addWidget(b);
    setPlaying(false);

    slider_ = new KeyMarkerSlider(this);
    // Room for the loop flags above the groove and the key markers below it.
    slider_->setMinimumHeight(slider_->sizeHint().height() + 16);
    slider_->setTracking(true);            // the picture follows while dragging
    slider_->setFocusPolicy(Qt::NoFocus);  // keep Space/arrows for the window's shortcuts
    layout->addWidget(slider_, 1);
    dopeSheet_ = new DopeSheet(slider_, this);
    rows->addWidget(dopeSheet_);

    // The frame is a box to type into ("frame [116] / 240  4.84 s").
    layout->addWidget(new QLabel(tr("frame"), this));
    frameBox_ = new QSpinBox(this);
    frameBox_->setToolTip(tr("The frame shown; type a number and Enter to go there"));
    frameBox_->setKeyboardTracking(false);  // seek on Enter or leaving the box, not per digit
    frameBox_->setButtonSymbols(QAbstractSpinBox::NoButtons);
    frameBox_->setAlignment(Qt::AlignRight);
    layout->addWidget(frameBox_);
    frameLabel_ = new QLabel(this);
    frameLabel_->setMinimumWidth(frameLabel_->fontMetrics().horizontalAdvance("/ 00000  000.00 s"));
    layout->addWidget(frameLabel_);

    speed_ = new QComboBox(this);
    speed_->setFocusPolicy(Qt::NoFocus);
    speed_->setToolTip(tr("Playback speed"));
    for (double s : kSpeeds) speed_->addItem(QString::number(s) + QString::fromUtf8("×"), s);
    speed_->setCurrentIndex(2);
    layout->addWidget(speed_);

    connect(playButton_, &QToolButton::clicked, this, &TimelineWidget::playToggled);
    connect(back, &QToolButton::clicked, this, [this] { emit stepRequested(-1); });
    connect(forward, &QToolButton::clicked, this, [this] { emit stepRequested(1); });
    connect(first, &QToolButton::clicked, this, [this] { emit seekRequested(0); });
    connect(last, &QToolButton::clicked, this, [this] { emit seekRequested(lastFrame_); });
    connect(slider_, &QSlider::valueChanged, this, [this](int v) { emit seekRequested(v); });
    connect(slider_, &QSlider::sliderPressed, this, &TimelineWidget::scrubStarted);
    connect(slider_, &KeyMarkerSlider::markerClicked, this, [this](int frame) { emit seekRequested(frame); });
    connect(frameBox_, &QSpinBox::valueChanged, this, [this](int frame) { emit seekRequested(frame); });
    connect(dopeSheet_, &DopeSheet::seekRequested, this, &TimelineWidget::seekRequested);
    connect(slider_, &QSlider::sliderReleased, this, &TimelineWidget::scrubFinished);
    connect(slider_, &KeyMarkerSlider::loopInRequested, this, &TimelineWidget::loopInRequested);
    connect(slider_, &KeyMarkerSlider::loopOutRequested, this, &TimelineWidget::loopOutRequested);
    connect(slider_, &KeyMarkerSlider::loopClearRequested, this, &TimelineWidget::loopClearRequested);
    connect(speed_, &QComboBox::currentIndexChanged, this,
            [this](int i) { emit speedChanged(speed_->itemData(i).toDouble()); });
    setRange(0, 24);
}

QToolButton* TimelineWidget::addButton(int standardIcon, const QString& tip) {
    auto* button = new QToolButton(this);
    button->setIcon(style()->standardIcon(QStyle::StandardPixmap(standardIcon)));
    button->setToolTip(tip);
    button->setAutoRaise(true);
    button->setFocusPolicy(Qt::NoFocus);
    return button;
}

void TimelineWidget::setRange(int lastFrame, int fps) {
    lastFrame_ = std::max(0, lastFrame);
    fps_ = std::max(1, fps);
    const QSignalBlocker block(slider_);
    slider_->setRange(0, lastFrame_);
    const QSignalBlocker blockBox(frameBox_);
    frameBox_->setRange(0, lastFrame_);
    slider_->setPageStep(std::max(1, fps_));
}

void TimelineWidget::setTime(double time) {
    const int frame = int(std::clamp<std::int64_t>(frameAt(time), 0, lastFrame_));
    {
        const QSignalBlocker block(slider_);
        if (!slider_->isSliderDown()) slider_->setValue(frame);
    }
    dopeSheet_->update();          // its line at the frame shown
    if (!frameBox_->hasFocus()) {  // not while the user types a number
        const QSignalBlocker block(frameBox_);
        frameBox_->setValue(frame);
    }
    frameLabel_->setText(tr("/ %1  %2 s").arg(lastFrame_).arg(time / fps_, 0, 'f', 2));
}

void TimelineWidget::setKeyMarkers(QList<int> frames) { slider_->setMarkers(std::move(frames)); }

void TimelineWidget::setLoop(std::optional<std::pair<int, int>> loop) { slider_->setLoop(loop); }

void TimelineWidget::setPlaying(bool playing) {
    playButton_->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
}

}  // namespace f2::viewer
