#include "dope_sheet.h"

#include <QContextMenuEvent>
#include <QKeyEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>
#include <algorithm>
#include <cmath>

#include "key_marker_slider.h"

namespace f2::viewer {

namespace {

constexpr int kHalf = 4;  // a key's diamond: half its width
constexpr double kSameTime = 1e-6;

}  // namespace

DopeSheet::DopeSheet(KeyMarkerSlider* slider, QWidget* parent) : QWidget(parent), slider_(slider) {
    setFixedHeight(kVisibleRows * kRowHeight + 2);
    setFocusPolicy(Qt::ClickFocus);  // Delete and Esc reach it after a click
    setToolTip(
        tr("Keys of the selection: drag to move, Alt+drag to copy, Delete to remove, right-click for "
           "the mode"));
}

void DopeSheet::setRows(std::vector<DopeRow> rows, const QString& text, int fps) {
    text_ = text;
    fps_ = fps;
    if (rows == rows_) return;
    rows_ = std::move(rows);
    // A press under way named keys by their old places: it ends here.
    pressAt_.reset();
    pressKey_.reset();
    dragging_ = false;
    band_.reset();
    firstRow_ = std::clamp(firstRow_, 0, std::max(0, int(rows_.size()) - kVisibleRows));
    // Keys that are gone are no longer selected.
    std::erase_if(selected_, [&](const KeyId& id) {
        return std::none_of(rows_.begin(), rows_.end(), [&](const DopeRow& row) {
            return row.target == id.target && row.property == id.property &&
                   std::any_of(row.keys.begin(), row.keys.end(),
                               [&](const DopeKey& k) { return std::fabs(k.time - id.time) <= kSameTime; });
        });
    });
    update();
}

int DopeSheet::xOf(double frame) const {
    const int whole = int(std::lround(frame));  // the timeline's steps are whole frames
    return mapFromGlobal(slider_->mapToGlobal(QPoint(slider_->positionOf(whole), 0))).x();
}

int DopeSheet::frameAt(int x) const {
    return slider_->frameAtPosition(slider_->mapFromGlobal(mapToGlobal(QPoint(x, 0))).x());
}

QPoint DopeSheet::keyPoint(int row, int key) const {
    return {xOf(rows_[std::size_t(row)].keys[std::size_t(key)].time),
            (row - firstRow_) * kRowHeight + kRowHeight / 2 + 1};
}

bool DopeSheet::isSelected(int row, int key) const {
    const DopeRow& r = rows_[std::size_t(row)];
    const double time = r.keys[std::size_t(key)].time;
    return std::any_of(selected_.begin(), selected_.end(), [&](const KeyId& id) {
        return id.target == r.target && id.property == r.property && std::fabs(id.time - time) <= kSameTime;
    });
}

std::vector<std::pair<int, int>> DopeSheet::selectedKeys() const {
    std::vector<std::pair<int, int>> keys;
    for (int row = 0; row < int(rows_.size()); ++row)
        for (int key = 0; key < int(rows_[std::size_t(row)].keys.size()); ++key)
            if (isSelected(row, key)) keys.emplace_back(row, key);
    return keys;
}

std::vector<int> DopeSheet::selectedLines() const {
    std::vector<int> lines;
    for (const auto& [row, key] : selectedKeys())
        if (const int line = rows_[std::size_t(row)].keys[std::size_t(key)].line; line >= 0)
            lines.push_back(line);
    return lines;
}

std::optional<std::pair<int, int>> DopeSheet::keyAt(QPoint point) const {
    const int row = point.y() / kRowHeight + firstRow_;
    if (point.y() < 0 || row < 0 || row >= int(rows_.size())) return std::nullopt;
    const auto& keys = rows_[std::size_t(row)].keys;
    std::optional<std::pair<int, int>> nearest;
    int best = KeyMarkerSlider::kMarkerReach + 1;
    for (int key = 0; key < int(keys.size()); ++key) {
        const int distance = std::abs(xOf(keys[std::size_t(key)].time) - point.x());
        if (distance < best) {
            best = distance;
            nearest = std::pair(row, key);
        }
    }
    return nearest;
}

double DopeSheet::dragDelta() const {
    double delta = dragFrames_;
    for (const auto& [row, key] : selectedKeys())
        delta = std::max(delta, -rows_[std::size_t(row)].keys[std::size_t(key)].time);
    return delta;
}

void DopeSheet::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    const int labelsEnd = mapFromGlobal(slider_->mapToGlobal(QPoint(0, 0))).x() - 6;
    const double delta = dragging_ ? dragDelta() : 0;
    for (int row = firstRow_; row < int(rows_.size()) && row < firstRow_ + kVisibleRows; ++row) {
        const DopeRow& r = rows_[std::size_t(row)];
        const int top = (row - firstRow_) * kRowHeight + 1;
        if (row % 2) painter.fillRect(QRect(0, top, width(), kRowHeight), palette().alternateBase());
        painter.setPen(palette().color(QPalette::WindowText));
        QFont font = painter.font();
        font.setPixelSize(kRowHeight - 3);
        painter.setFont(font);
        painter.drawText(
            QRect(2, top, std::max(0, labelsEnd - 2), kRowHeight), Qt::AlignVCenter | Qt::AlignRight,
            painter.fontMetrics().elidedText(r.label, Qt::ElideLeft, std::max(0, labelsEnd - 2)));
        // The row's track over the slider's frames, as a groove for its keys.
        painter.setPen(palette().color(QPalette::Mid));
        painter.drawLine(xOf(slider_->minimum()), top + kRowHeight / 2, xOf(slider_->maximum()),
                         top + kRowHeight / 2);
        painter.setRenderHint(QPainter::Antialiasing, true);
        for (int key = 0; key < int(r.keys.size()); ++key) {
            const DopeKey& k = r.keys[std::size_t(key)];
            const bool selected = isSelected(row, key);
            // Dragged keys show at their new frame (a copy leaves the original too).
            const bool moves = selected && k.line >= 0 && delta != 0;
            const int y = top + kRowHeight / 2;
            for (int pass = 0; pass < (moves ? 2 : 1); ++pass) {
                const bool ghost = moves && pass == 0 && !copying_;
                const int x = xOf(k.time + (moves && pass == 1 ? delta : 0));
                const QPoint diamond[4] = {{x, y - kHalf}, {x + kHalf, y}, {x, y + kHalf}, {x - kHalf, y}};
                const QColor fill = selected ? QColor(255, 240, 120) : QColor(255, 170, 0);
                painter.setPen(QPen(selected ? QColor(120, 60, 0) : fill.darker(150), 1));
                painter.setBrush(k.line < 0 || ghost ? Qt::NoBrush : QBrush(fill));
                painter.drawPolygon(diamond, 4);
            }
        }
        painter.setRenderHint(QPainter::Antialiasing, false);
    }
    if (band_) {
        painter.setPen(QPen(palette().color(QPalette::Highlight), 1, Qt::DashLine));
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(band_->normalized());
    }
    // The frame shown, under the slider's handle.
    if (!rows_.empty()) {
        painter.setPen(QColor(40, 140, 255));
        const int x = xOf(slider_->value());
        painter.drawLine(x, 0, x, std::min(height(), (int(rows_.size()) - firstRow_) * kRowHeight + 1));
    }
}

void DopeSheet::mousePressEvent(QMouseEvent* event) {
    const QPoint at = event->position().toPoint();
    const auto key = keyAt(at);
    const bool adding = event->modifiers() & (Qt::ShiftModifier | Qt::ControlModifier);
    if (event->button() != Qt::LeftButton && event->button() != Qt::RightButton) return;
    const int named = at.y() / kRowHeight + firstRow_;
    if (!key && at.x() < xOf(slider_->minimum()) - kHalf && named < int(rows_.size()) &&
        event->button() == Qt::LeftButton) {
        // A click on a row's name selects all its keys.
        if (!adding) selected_.clear();
        const DopeRow& r = rows_[std::size_t(named)];
        for (int k = 0; k < int(r.keys.size()); ++k)
            if (!isSelected(named, k))
                selected_.push_back({r.target, r.property, r.keys[std::size_t(k)].time});
        return update();
    }
    if (!key) {
        if (!adding) selected_.clear();
        // A drag from an empty place selects the keys in its rectangle.
        if (event->button() == Qt::LeftButton) band_ = QRect(at, at);
        update();
        return;
    }
    const DopeRow& row = rows_[std::size_t(key->first)];
    const KeyId id{row.target, row.property, row.keys[std::size_t(key->second)].time};
    if (!isSelected(key->first, key->second)) {
        if (!adding) selected_.clear();
        selected_.push_back(id);
    } else if (adding && event->button() == Qt::LeftButton) {
        std::erase_if(selected_, [&](const KeyId& s) {
            return s.target == id.target && s.property == id.property &&
                   std::fabs(s.time - id.time) <= kSameTime;
        });
    }
    if (event->button() == Qt::LeftButton) {
        pressAt_ = at;
        pressKey_ = key;
        dragging_ = false;
        copying_ = event->modifiers() & Qt::AltModifier;
        dragFrames_ = 0;
    }
    update();
}

void DopeSheet::mouseMoveEvent(QMouseEvent* event) {
    const QPoint at = event->position().toPoint();
    if (band_) {
        band_->setBottomRight(at);
        return update();
    }
    if (!pressAt_) return;
    if (!dragging_ && std::abs(at.x() - pressAt_->x()) < 3) return;
    dragging_ = true;
    dragFrames_ = frameAt(at.x()) - frameAt(pressAt_->x());
    update();
}

void DopeSheet::mouseReleaseEvent(QMouseEvent* event) {
    if (band_ && event->button() == Qt::LeftButton) {
        const QRect band = band_->normalized().adjusted(-kHalf, -kHalf, kHalf, kHalf);
        band_.reset();
        for (int row = firstRow_; row < int(rows_.size()); ++row)
            for (int key = 0; key < int(rows_[std::size_t(row)].keys.size()); ++key)
                if (band.contains(keyPoint(row, key)) && !isSelected(row, key))
                    selected_.push_back({rows_[std::size_t(row)].target, rows_[std::size_t(row)].property,
                                         rows_[std::size_t(row)].keys[std::size_t(key)].time});
        return update();
    }
    if (!pressAt_ || event->button() != Qt::LeftButton) return;
    const auto key = pressKey_;
    const bool dragged = dragging_;
    const double delta = dragDelta();
    pressAt_.reset();
    pressKey_.reset();
    dragging_ = false;
    if (!dragged) {
        if (key) emit seekRequested(rows_[std::size_t(key->first)].keys[std::size_t(key->second)].time);
        update();
        return;
    }
    if (delta == 0) return update();
    const std::vector<int> lines = selectedLines();
    const std::vector<SpanEdit> edits = moveKeyEdits(text_, fps_, lines, delta, copying_);
    // The moved (or copied) keys stay selected at their new times.
    for (KeyId& id : selected_) id.time += delta;
    request(edits);
    update();
}

void DopeSheet::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Escape && (pressAt_ || band_)) {
        // Cancel the drag: nothing was written.
        band_.reset();
        pressAt_.reset();
        pressKey_.reset();
        dragging_ = false;
        update();
        return;
    }
    if ((event->key() == Qt::Key_Delete || event->key() == Qt::Key_Backspace) && !selected_.empty()) {
        request(deleteKeyEdits(text_, selectedLines()));
        selected_.clear();
        update();
        return;
    }
    QWidget::keyPressEvent(event);
}

std::unique_ptr<QMenu> DopeSheet::modeMenu() {
    auto menu = std::make_unique<QMenu>(this);
    const auto keys = selectedKeys();
    const bool visible = std::any_of(keys.begin(), keys.end(), [&](const auto& k) {
        return rows_[std::size_t(k.first)].property == KeyProperty::Visible;
    });
    auto add = [&](const QString& label, std::optional<Easing> mode) {
        QAction* action = menu->addAction(
            label, this, [this, mode] { request(keyModeEdits(text_, selectedLines(), mode)); });
        action->setCheckable(true);
        action->setChecked(!keys.empty() && std::all_of(keys.begin(), keys.end(), [&](const auto& k) {
            const auto& own = rows_[std::size_t(k.first)].keys[std::size_t(k.second)].mode;
            return mode ? own && own->mode == mode->mode : !own;
        }));
        action->setEnabled(!keys.empty() && !visible);
    };
    add(tr("No Mode Word (the Track's /interp)"), std::nullopt);
    menu->addSeparator();
    // The modes of the language table, in its order; bezier with CSS's `ease` curve to start from.
    for (Interpolation mode : interpolationModes())
        add(QString::fromStdString(easingText(Easing(mode, {0.25f, 0.1f, 0.25f, 1.0f}))),
            Easing(mode,
                   mode == Interpolation::Bezier ? BezierCurve{0.25f, 0.1f, 0.25f, 1.0f} : BezierCurve{}));
    return menu;
}

void DopeSheet::contextMenuEvent(QContextMenuEvent* event) {
    if (!keyAt(event->pos())) return;
    modeMenu()->exec(event->globalPos());
}

bool DopeSheet::event(QEvent* event) {
    if (event->type() != QEvent::ToolTip) return QWidget::event(event);
    // A key's tooltip: its line as written, or why it cannot be edited here.
    auto* help = static_cast<QHelpEvent*>(event);
    const auto key = keyAt(help->pos());
    if (!key) return QWidget::event(event);
    const DopeKey& k = rows_[std::size_t(key->first)].keys[std::size_t(key->second)];
    QToolTip::showText(
        help->globalPos(),
        k.line >= 0 ? tr("line %1: %2").arg(k.line + 1).arg(text_.section(u'\n', k.line, k.line).trimmed())
                    : tr("frame %1: written in a loop, an included file or with a computed time; "
                         "not edited here")
                          .arg(k.time),
        this);
    return true;
}

void DopeSheet::wheelEvent(QWheelEvent* event) {
    const int step = event->angleDelta().y() > 0 ? -1 : 1;
    firstRow_ = std::clamp(firstRow_ + step, 0, std::max(0, int(rows_.size()) - kVisibleRows));
    update();
}

void DopeSheet::request(const std::vector<SpanEdit>& edits) {
    if (!edits.empty()) emit editsRequested(edits, text_);
}

}  // namespace f2::viewer
