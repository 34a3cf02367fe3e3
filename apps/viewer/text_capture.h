#pragma once
/// Capture into the text: the lines *Set Camera from View*, *Key Camera Here*
/// and *Key Selection Here* write, and where they go. Pure functions of the text, so the exact
/// lines are unit-tested; the window applies an edit as one undo step.
#include <QString>
#include <vector>

#include "core/scene/scene_desc.h"

class QPlainTextEdit;

namespace f2::viewer {

/// Replace line `line` (1-based) with `text`, or insert `text` before it
/// (`line` may be one past the last line).
struct TextEdit {
    int line = 1;
    bool replace = false;
    QString text;
};

/// A number as the scene text writes it: at most two decimals, no trailing zeros.
QString formatNumber(double value);

/// The `/camera` edit for a view at `pose`: the scene's `/camera` line keeps
/// its size and `d` as written (and its comment), the eye and rotation become
/// `pose`; without one, a line with the scene's size and `d` goes first.
TextEdit cameraEdit(const QString& text, const CameraDesc& camera, const Pose& pose);

/// The `/key` edit for `target` (`name`, `name.part` or `camera`) at `frame`
/// with `pose`: replaces that target's key at that frame, else goes after the
/// last key of the target, else after line `createdAt` (1-based: the line that
/// creates the object, or the `/camera` line), else (0) at the end.
TextEdit keyEdit(const QString& text, const QString& target, int frame, const Pose& pose, int createdAt);

/// The 1-based line of the `/camera` command in `text`, or 0.
int cameraLine(const QString& text);

/// `text` with `edit` applied, as applyEdit() leaves the editor's text.
QString withEdit(const QString& text, const TextEdit& edit);

/// Applies `edit` to `editor` as one undo step and selects the written line.
void applyEdit(QPlainTextEdit* editor, const TextEdit& edit);
/// Applies `edits` in order (each one's line counts in the text the ones
/// before it left) as one undo step and selects the line the last one wrote.
void applyEdits(QPlainTextEdit* editor, const std::vector<TextEdit>& edits);

}  // namespace f2::viewer
