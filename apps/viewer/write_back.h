#pragma once
/// Write-back: what a gesture in the picture (or a value typed in a dialog)
/// changes in the scene text, as span edits (source_edit.h) the window applies
/// as one undo step. Pure functions of the text and its last parse, so every
/// rule is unit-tested without widgets:
///
/// - the target has keys (of that track): its `/key` line at the frame gets
///   the new numbers in place (only numbers whose written value changes; the
///   time, mode word, spacing and comment stay), else a new `/key` line goes
///   in time order among the target's key lines (after the last key before
///   the frame, else before the first after it);
/// - it has none: the numbers of its creating command change in place
///   (`/sphere`…, `/camera`, a light's intensity); a part, a colour or
///   `visible` has no such numbers and gets its first `/key` line after the
///   line that created its object;
/// - a creating command or key inside a `/repeat` loop or in an included
///   file is never edited: the answer is a refusal saying why, with the
///   edits that add a key after the loop (or the `/include` line) in the main
///   file instead, for the window to offer.
#include <QString>
#include <optional>
#include <string>
#include <vector>

#include "core/parse/language.h"
#include "core/scene/scene_desc.h"
#include "source_edit.h"

namespace f2::viewer {

class SceneLocations;

/// The text and what its last parse made of it.
struct SceneSource {
    const QString& text;
    const SceneDesc& scene;
    const SceneLocations& locations;
    std::string sourceName;  ///< the main file's name as diagnostics give it
};

/// One value written back: `target`'s pose or property at `frame`.
struct WriteRequest {
    QString target;                       ///< `name`, `name.part`, a named light or `camera`
    std::optional<KeyProperty> property;  ///< none: the pose
    int frame = 0;
    /// x y z rx ry rz for a pose, else the property's numbers (r g b; i; d;
    /// 0 or 1), as the key's numbers mean them (capture_pose.h): an attached
    /// target's pose in the frame it rides on, a part's offset and rotation
    /// about its pivot, a light's pose in its own frame.
    std::vector<double> values;
};

struct WriteBack {
    std::vector<SpanEdit> edits;  ///< empty when refused (or nothing changes)
    QString refusal;              ///< why the text is not edited; empty: it is
    std::vector<SpanEdit> offer;  ///< refused: the edits of the alternative
    QString offerLabel;           ///< what the offer does, for its button
    bool refused() const { return !refusal.isEmpty(); }
};

/// What writing `request` into `source.text` takes (see the rules above).
/// Its edits' offsets are in `source.text`: apply them with applySourceEdits()
/// (or applyWriteBack(), write_back_prompt.h) to an editor holding that text.
WriteBack writeBack(const SceneSource& source, const WriteRequest& request);
/// writeBack() of a pose.
WriteBack writePose(const SceneSource& source, const QString& target, int frame, const Pose& pose);

/// The `/key` lines of `target`'s track (`property`: none for the pose) in
/// `text`, in text order, with the time each is at (nothing for a computed time).
struct KeyLine {
    int line = 0;  ///< 0-based index into scanSource(text)
    std::optional<double> time;
    bool editable = true;  ///< not inside a loop or a `/model` block
};
std::vector<KeyLine> keyLines(const std::vector<SourceLine>& lines, int fps, const QString& target,
                              std::optional<KeyProperty> property);
/// The property a `/key` line keys (none: the pose).
std::optional<KeyProperty> keyLineProperty(const SourceLine& line);
/// The index of a `/key` line's mode word (after its numbers), or its token count without one.
int keyLineModeAt(const SourceLine& line);
/// A key line's time token read as frames (`2.5s` with `fps`); nothing for an expression.
std::optional<double> keyTime(QStringView token, int fps);

}  // namespace f2::viewer
