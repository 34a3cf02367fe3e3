#pragma once
/// The dope sheet under the timeline's slider: one row per key track of the
/// selection (dope_sheet_model.h), each key a diamond at its frame, aligned
/// with the slider. Click a key to go to it (Shift/Ctrl+click adds to the
/// selection, a click on a row's name selects its keys, a drag from an
/// empty place selects a rectangle's keys), drag
/// a key to move the selected keys, Alt+drag to copy them, Delete
/// removes them, right-click sets their mode; Esc during a drag cancels it.
/// Each gesture asks for its edits as one request (editsRequested), which
/// the window applies as one undo step. Keys no line of this file can edit
/// (a loop, an include) are drawn hollow and stay put.
#include <QRect>
#include <QString>
#include <QWidget>
#include <optional>
#include <vector>

#include "dope_sheet_model.h"

class QMenu;

namespace f2::viewer {

class KeyMarkerSlider;

class DopeSheet : public QWidget {
    Q_OBJECT
   public:
    /// Frames are placed where `slider` puts them.
    DopeSheet(KeyMarkerSlider* slider, QWidget* parent = nullptr);

    /// The rows to show, made from `text` (the lines their keys name) at `fps`.
    void setRows(std::vector<DopeRow> rows, const QString& text, int fps);
    const std::vector<DopeRow>& rows() const { return rows_; }
    /// Where key `key` of row `row` is drawn (widget pixels), for tests and menus.
    QPoint keyPoint(int row, int key) const;
    /// The frame drawn at widget x.
    int frameAt(int x) const;
    /// The selected keys' rows and indices.
    std::vector<std::pair<int, int>> selectedKeys() const;
    /// The mode menu of the selected keys (right-click).
    std::unique_ptr<QMenu> modeMenu();

    static constexpr int kRowHeight = 13;
    static constexpr int kVisibleRows = 4;

   signals:
    /// Apply `edits` to the text, if it is still `base`, as one undo step.
    void editsRequested(const std::vector<f2::viewer::SpanEdit>& edits, const QString& base);
    void seekRequested(double frame);

   protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    bool event(QEvent* event) override;

   private:
    /// A key by what survives an edit: its track and time.
    struct KeyId {
        QString target;
        std::optional<KeyProperty> property;
        double time = 0;
    };
    bool isSelected(int row, int key) const;
    std::optional<std::pair<int, int>> keyAt(QPoint point) const;
    int xOf(double frame) const;
    /// The `/key` lines of the selected keys that can be edited.
    std::vector<int> selectedLines() const;
    /// The drag's offset in frames, kept from taking a key before 0.
    double dragDelta() const;
    void request(const std::vector<SpanEdit>& edits);

    KeyMarkerSlider* slider_;
    std::vector<DopeRow> rows_;
    QString text_;
    int fps_ = 24;
    int firstRow_ = 0;  // scrolled by the wheel
    std::vector<KeyId> selected_;
    // A press on a key: where, and whether it became a drag.
    std::optional<QPoint> pressAt_;
    std::optional<std::pair<int, int>> pressKey_;
    bool dragging_ = false;
    std::optional<QRect> band_;  // a drag from an empty place: the rectangle that selects
    bool copying_ = false;
    int dragFrames_ = 0;
};

}  // namespace f2::viewer
