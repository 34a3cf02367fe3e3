#pragma once
/// The timeline as a dope sheet: the key tracks of the selection (its pose,
/// each keyed part, colour and visible; the camera's pose and d without a
/// selection) with each key's `/key` line, and the edits of the gestures on
/// them — move (or copy) keys in time, delete them, set their mode. Pure
/// functions of the text, so the widget (dope_sheet.h) only draws and asks.
#include <QString>
#include <optional>
#include <vector>

#include "core/parse/language.h"
#include "core/scene/scene_desc.h"
#include "selection.h"
#include "source_edit.h"

namespace f2::viewer {

struct DopeKey {
    double time = 0;  ///< frames
    /// Its `/key` line (index into scanSource(text)), or -1 when no line of
    /// this file can be edited for it (a loop, an include, a computed time).
    int line = -1;
    std::optional<Easing> mode;  ///< its own mode word
};

struct DopeRow {
    QString label;   ///< "pose", "head", "colour"…
    QString target;  ///< as /key writes it: `ball`, `r1.head`, `camera`
    std::optional<KeyProperty> property;
    std::vector<DopeKey> keys;  ///< by time
    friend bool operator==(const DopeRow& a, const DopeRow& b) {
        return a.label == b.label && a.target == b.target && a.property == b.property &&
               a.keys.size() == b.keys.size() &&
               std::equal(a.keys.begin(), a.keys.end(), b.keys.begin(),
                          [](const DopeKey& x, const DopeKey& y) {
                              return x.time == y.time && x.line == y.line && x.mode == y.mode;
                          });
    }
};

/// The rows of `selection` (none: the camera) in `scene`, whose text is `text`.
std::vector<DopeRow> dopeSheetRows(const QString& text, const SceneDesc& scene,
                                   const std::optional<Selection>& selection);

/// Moves the keys on `lines` (scanSource indices of `/key` lines) by `delta`
/// frames (a key would go before 0: the move stops at 0), or with `copy`
/// writes a copy of each at its new time after it. A time in seconds stays
/// in seconds when a short one says the new frame exactly, else it becomes frames. A key of the same track
/// already at a new time is removed (it would be replaced, with a warning).
std::vector<SpanEdit> moveKeyEdits(const QString& text, int fps, const std::vector<int>& lines, double delta,
                                   bool copy);
/// Removes the `/key` lines `lines`.
std::vector<SpanEdit> deleteKeyEdits(const QString& text, const std::vector<int>& lines);
/// Gives the keys on `lines` the mode `mode` (none: no mode word, the
/// track's `/interp` holds), replacing the mode word (and bezier numbers)
/// they have. `visible` keys take no mode and are left alone.
std::vector<SpanEdit> keyModeEdits(const QString& text, const std::vector<int>& lines,
                                   const std::optional<Easing>& mode);

}  // namespace f2::viewer
