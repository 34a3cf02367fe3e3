#pragma once
/// The *Problems* dock under the picture: every diagnostic of the latest parse
/// as `FILE:LINE:COL: error: message`, a click on one going there. It opens by
/// itself on the first problem and closes by itself when the last one goes, if
/// it opened itself (one the user opened stays, saying "No problems.").
/// The picture keeps its size: while the dock shows, the window is taller by
/// the dock's height (when the window is maximized, full screen or at the
/// bottom of the screen, it cannot grow and the picture gives up the rest).
#include <QDockWidget>
#include <QStringList>
#include <vector>

#include "core/parse/diagnostic.h"

class QListWidget;
class QListWidgetItem;
class QMainWindow;

namespace f2::viewer {

class ProblemsDock : public QDockWidget {
    Q_OBJECT
   public:
    /// Docked at the bottom of `window` (or the top: it takes height, never width), hidden.
    explicit ProblemsDock(QMainWindow* window);

    QListWidget* list() const { return list_; }
    /// Lists `problems` (`lines` are their formatted texts). Opens the dock
    /// when there are any, closes it when there are none if it opened itself.
    void setProblems(const std::vector<Diagnostic>& problems, const QStringList& lines);
    /// The dock is open because problems opened it (not the user).
    bool openedItself() const { return openedItself_; }
    /// Notes the window's and the picture's heights before the dock takes room.
    void setVisible(bool visible) override;

    /// The height the dock asks for when it opens: a few lines of messages.
    static constexpr int kHeight = 110;

   signals:
    /// The user clicked (or activated) a problem at `file`:`line`:`column`.
    void problemClicked(const QString& file, int line, int column);

   protected:
    void closeEvent(QCloseEvent* event) override;

   private:
    void openItself();
    /// Docked and shown: it takes height from the window.
    bool takesRoom() const;
    /// Gives the picture back the height it had without the dock: the window
    /// grows (where the screen lets it), or the dock takes what the window
    /// had to grow for its minimum size. Once per opening.
    void growWindow();
    /// The window gives back what it grew for the dock.
    void shrinkWindow();
    void onItem(QListWidgetItem* item);

    QMainWindow* window_;
    QListWidget* list_;
    bool openedItself_ = false;
    bool grown_ = false;      ///< growWindow() ran for this opening
    int grownBy_ = 0;         ///< pixels the window grew for the dock
    int pictureHeight_ = -1;  ///< the central widget's height without the dock
    int windowHeight_ = -1;   ///< the window's height without the dock
};

}  // namespace f2::viewer
