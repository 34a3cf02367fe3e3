#include "status_readouts.h"

#include <QLabel>
#include <QStatusBar>

#include "core/anim/frame_time.h"
#include "playback.h"
#include "status_bar_room.h"
#include "studio_session.h"
#include "view_mode_menu.h"

namespace f2::viewer {

StatusReadouts::StatusReadouts(QStatusBar* bar, const StudioSession* session)
    : QObject(bar),
      session_(session),
      frame_(new QLabel(bar)),
      time_(new QLabel(bar)),
      fps_(new QLabel(bar)),
      size_(new QLabel(bar)),
      selection_(new QLabel(bar)),
      refine_(new QLabel(bar)),
      view_(new QLabel(bar)),
      playbackAntialias_(new QLabel(bar)) {
    for (QLabel* label : {selection_, view_, refine_, playbackAntialias_, frame_, time_, fps_, size_})
        bar->addPermanentWidget(label);
    // A message (a pick, an error) shows whole: the readouts make room for it.
    new StatusBarRoom(bar, {fps_, time_, refine_, playbackAntialias_, size_, view_, selection_});
    refresh_.setInterval(kRefreshMs);
    connect(&refresh_, &QTimer::timeout, this, &StatusReadouts::update);
    refresh_.start();
}

void StatusReadouts::setSelection(const QString& text) { selection_->setText(text); }

QString StatusReadouts::selection() const { return selection_->text(); }

QString StatusReadouts::playbackAntialias() const { return playbackAntialias_->text(); }

void StatusReadouts::update() {
    const FrameInfo& shown = session_->shownFrame();
    const Playback* playback = session_->playback();
    const int last = playback->lastFrame();
    if (shown.serial == 0) {
        frame_->setText(tr("frame –/%1").arg(last));
        time_->setText(tr("– ms/frame"));
        size_->setText(tr("–"));
    } else {
        frame_->setText(tr("frame %1/%2").arg(frameAt(shown.time)).arg(last));
        time_->setText(tr("%1 ms/frame").arg(shown.timings.totalMs(), 0, 'f', 1));
        size_->setText(tr("%1×%2").arg(shown.size.width()).arg(shown.size.height()));
    }
    fps_->setText(tr("%1 fps").arg(session_->renderController()->achievedFps(), 0, 'f', 1));
    view_->setText(tr("view: %1").arg(ViewModeMenu::label(shown.view)));
    const int n = shown.antialias;
    refine_->setText(shown.serial == 0 || playback->isPlaying() || !session_->refinement() ||
                             shown.view != ViewMode::Shaded
                         ? QString()
                     : session_->isRefining() ? tr("refining: %1×%1 samples…").arg(n)
                                              : tr("refined: %1×%1 samples").arg(n));
    const char* const modeNames[] = {"off", "auto", "on"};
    playbackAntialias_->setText(shown.serial != 0 && playback->isPlaying() && shown.view == ViewMode::Shaded
                                    ? tr("playing: %1×%1 samples (%2)")
                                          .arg(n)
                                          .arg(tr(modeNames[int(session_->playbackAntialias().mode())]))
                                    : QString());
}

}  // namespace f2::viewer
