#pragma once
/// View › Mode: the tracer's view modes (core/render/view_mode.h) as a
/// submenu of checkable actions, exactly one checked. No shortcuts: the
/// letters are taken by playback and the stage.
#include <QObject>
#include <QString>
#include <array>

#include "core/render/view_mode.h"

class QAction;
class QMenu;

namespace f2::viewer {

class ViewModeMenu : public QObject {
    Q_OBJECT
   public:
    /// Adds the "Mode" submenu to `parent`, Shaded checked.
    explicit ViewModeMenu(QMenu* parent);

    ViewMode mode() const { return mode_; }
    /// Checks `mode`'s action and emits modeChanged if it is a change.
    void setMode(ViewMode mode);
    /// The action of `mode` (tests trigger it as a user would).
    QAction* action(ViewMode mode) const { return actions_[std::size_t(mode)]; }
    /// "Shaded", "Normals", ..., as the menu and the status bar name them.
    static QString label(ViewMode mode);

   signals:
    void modeChanged(f2::ViewMode mode);

   private:
    ViewMode mode_ = ViewMode::Shaded;
    std::array<QAction*, kViewModes.size()> actions_{};
};

}  // namespace f2::viewer
