#include "problems_dock.h"

#include <QCloseEvent>
#include <QFontDatabase>
#include <QLayout>
#include <QListWidget>
#include <QMainWindow>
#include <QScreen>
#include <QStyle>

namespace f2::viewer {

namespace {
// Where a problem list item points: file, line, column.
constexpr int kFileRole = Qt::UserRole;
constexpr int kLineRole = Qt::UserRole + 1;
constexpr int kColumnRole = Qt::UserRole + 2;
}  // namespace

ProblemsDock::ProblemsDock(QMainWindow* window)
    : QDockWidget(tr("Problems"), window), window_(window), list_(new QListWidget(this)) {
    setObjectName("problemsDock");
    // Under (or over) the picture only: the window grows by its height.
    setAllowedAreas(Qt::BottomDockWidgetArea | Qt::TopDockWidgetArea);
    list_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    list_->addItem(tr("No problems."));
    setWidget(list_);
    // Under the picture only, so the Scene dock beside it keeps its height and width.
    window->setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    window->setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    window->addDockWidget(Qt::BottomDockWidgetArea, this);
    hide();
    connect(list_, &QListWidget::itemClicked, this, &ProblemsDock::onItem);
    connect(list_, &QListWidget::itemActivated, this, &ProblemsDock::onItem);
    // View › Problems: the user's choice, which problems going away leaves alone.
    connect(toggleViewAction(), &QAction::triggered, this, [this](bool on) {
        openedItself_ = false;
        if (on)
            growWindow();
        else
            shrinkWindow();
    });
    // Floating, it takes nothing from the picture. (Docked again by the
    // user, it takes its room from the picture.)
    connect(this, &QDockWidget::topLevelChanged, this, [this](bool floating) {
        if (floating) shrinkWindow();
    });
}

void ProblemsDock::setProblems(const std::vector<Diagnostic>& problems, const QStringList& lines) {
    list_->clear();
    for (std::size_t i = 0; i < problems.size(); ++i) {
        const Diagnostic& d = problems[i];
        auto* item = new QListWidgetItem(lines[qsizetype(i)], list_);
        item->setData(kFileRole, QString::fromStdString(d.loc.file));
        item->setData(kLineRole, d.loc.line);
        item->setData(kColumnRole, d.loc.column);
        item->setForeground(d.severity == Severity::Error ? QColor(0xb0, 0x00, 0x20)
                                                          : QColor(0x90, 0x60, 0x00));
    }
    if (!problems.empty()) {
        openItself();
        raise();
        return;
    }
    list_->addItem(tr("No problems."));
    if (openedItself_ && isVisible()) {
        hide();
        shrinkWindow();
    }
    openedItself_ = false;
}

void ProblemsDock::openItself() {
    if (isVisible()) return;
    openedItself_ = true;
    show();
    // A few lines of messages.
    window_->resizeDocks({this}, {kHeight}, Qt::Vertical);
    growWindow();
}

bool ProblemsDock::takesRoom() const { return isVisible() && !isFloating(); }

void ProblemsDock::setVisible(bool visible) {
    // The sizes to keep, as they are before the dock takes room.
    if (visible && !isVisible() && !isFloating() && window_->centralWidget()) {
        pictureHeight_ = window_->centralWidget()->height();
        windowHeight_ = window_->height();
    }
    QDockWidget::setVisible(visible);
}

void ProblemsDock::growWindow() {
    if (grown_ || !takesRoom() || pictureHeight_ < 0) return;
    grown_ = true;
    const int heightBefore = window_->height();
    // Where the window's layout puts the dock, and what that leaves the picture.
    window_->layout()->activate();
    const int excess = window_->centralWidget()->height() - pictureHeight_;
    int grow = 0;
    if (excess > 0) {
        // The window had to grow to its new minimum size: the dock takes that.
        window_->resizeDocks({this}, {height() + excess}, Qt::Vertical);
    } else if (excess < 0 && !window_->isMaximized() && !window_->isFullScreen()) {
        grow = -excess;
        if (const QScreen* screen = window_->screen())
            grow = std::max(
                0, std::min(grow, screen->availableGeometry().bottom() - window_->frameGeometry().bottom()));
        if (grow > 0) window_->resize(window_->width(), window_->height() + grow);
    }
    grownBy_ = heightBefore - windowHeight_ + grow;
}

void ProblemsDock::shrinkWindow() {
    if (!grown_) return;
    grown_ = false;
    if (grownBy_ > 0 && !window_->isMaximized() && !window_->isFullScreen())
        window_->resize(window_->width(), window_->height() - grownBy_);
    grownBy_ = 0;
}

void ProblemsDock::closeEvent(QCloseEvent* event) {
    // The dock's close button: the user's choice.
    QDockWidget::closeEvent(event);
    if (!event->isAccepted()) return;
    openedItself_ = false;
    hide();
    shrinkWindow();
}

void ProblemsDock::onItem(QListWidgetItem* item) {
    if (!item->data(kLineRole).isValid()) return;
    emit problemClicked(item->data(kFileRole).toString(), item->data(kLineRole).toInt(),
                        item->data(kColumnRole).toInt());
}

}  // namespace f2::viewer
