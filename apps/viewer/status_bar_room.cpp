#include "status_bar_room.h"

#include <QEvent>
#include <QFontMetrics>
#include <QLayout>
#include <QStatusBar>
#include <QStyle>

namespace f2::viewer {

namespace {
// QStatusBar's own margins round a message and between widgets (qstatusbar.cpp).
constexpr int kMessageMargin = 8;
constexpr int kWidgetSpacing = 6;
}  // namespace

StatusBarRoom::StatusBarRoom(QStatusBar* bar, QList<QWidget*> yielding) : QObject(bar), bar_(bar) {
    for (QWidget* w : yielding) yielding_ << w;
    connect(bar, &QStatusBar::messageChanged, this, [this](const QString& message) {
        bar_->setToolTip(message);
        fit();
    });
    bar->installEventFilter(this);
}

bool StatusBarRoom::eventFilter(QObject* watched, QEvent* event) {
    if (watched == bar_ && event->type() == QEvent::Resize) fit();
    return QObject::eventFilter(watched, event);
}

void StatusBarRoom::fit() {
    const QString message = bar_->currentMessage();
    for (const auto& w : yielding_)
        if (w) w->setVisible(true);
    if (message.isEmpty()) return;
    const int needed = bar_->fontMetrics().horizontalAdvance(message) + 2 * kMessageMargin;
    // The width the permanent widgets leave: each one visible takes its size
    // hint and the spacing; the size grip takes its own.
    auto taken = [this] {
        int width = bar_->isSizeGripEnabled() ? bar_->style()->pixelMetric(QStyle::PM_SizeGripSize) : 0;
        for (QWidget* w : bar_->findChildren<QWidget*>(Qt::FindDirectChildrenOnly))
            if (!w->isHidden() && !w->isWindow() && w->metaObject()->className() != QByteArray("QSizeGrip"))
                width += w->sizeHint().width() + kWidgetSpacing;
        return width;
    };
    for (const auto& w : yielding_) {
        if (bar_->width() - taken() >= needed) break;
        if (w) w->setVisible(false);
    }
}

}  // namespace f2::viewer
