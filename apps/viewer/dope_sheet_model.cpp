#include "dope_sheet_model.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/scene/models.h"
#include "write_back.h"

namespace f2::viewer {

namespace {

constexpr double kSameTime = 1e-6;

QString toQString(std::string_view s) { return QString::fromUtf8(s.data(), qsizetype(s.size())); }

/// The text cut into lines, once and only if a row has keys (a large scene
/// without keys on the selection is not scanned on every parse).
class LazyLines {
   public:
    explicit LazyLines(const QString& text) : text_(text) {}
    const std::vector<SourceLine>& get() {
        if (!lines_) lines_ = scanSource(text_);
        return *lines_;
    }

   private:
    const QString& text_;
    std::optional<std::vector<SourceLine>> lines_;
};

/// A row for `track` (if `always` or it has keys), its keys matched to their lines.
void addRow(std::vector<DopeRow>& rows, LazyLines& lines, int fps, QString label, QString target,
            std::optional<KeyProperty> property, const Track* track, bool always) {
    if (!track || (track->keys.empty() && !always)) return;
    DopeRow row{std::move(label), std::move(target), property, {}};
    if (track->keys.empty()) return rows.push_back(std::move(row));
    const std::vector<KeyLine> written = keyLines(lines.get(), fps, row.target, property);
    for (const Key& key : track->keys) {
        DopeKey dope{key.time, -1, key.mode};
        // The last line at that time is the one the key comes from.
        for (const KeyLine& line : written)
            if (line.time && std::fabs(*line.time - key.time) <= kSameTime)
                dope.line = line.editable ? line.line : -1;
        row.keys.push_back(dope);
    }
    rows.push_back(std::move(row));
}

const Track* targetTrack(const std::vector<TargetTrack>& tracks, FrameRef ref) {
    for (const TargetTrack& t : tracks)
        if (t.target == ref && t.shape < 0) return &t.track;
    return nullptr;
}

QString word(KeyProperty property) {
    for (const KeyPropertySpec& spec : keyProperties())
        if (spec.property == property) return toQString(spec.word);
    return {};
}

}  // namespace

std::vector<DopeRow> dopeSheetRows(const QString& text, const SceneDesc& scene,
                                   const std::optional<Selection>& selection) {
    LazyLines lines(text);
    std::vector<DopeRow> rows;
    if (!selection || selection->kind == Selection::Kind::Camera) {
        const QString camera = toQString(kCameraName);
        addRow(rows, lines, scene.fps, camera, camera, std::nullopt, &scene.camera.track, true);
        addRow(rows, lines, scene.fps, camera + u' ' + word(KeyProperty::Zoom), camera, KeyProperty::Zoom,
               &scene.camera.zoom, false);
        return rows;
    }
    if (selection->kind == Selection::Kind::Light) {
        // A named light (selected by its marker in the picture): its pose and intensity.
        for (const LightMotion& light : scene.lightMotions) {
            if (light.name != selection->object) continue;
            const QString name = QString::fromStdString(light.name);
            if (!light.ambient) addRow(rows, lines, scene.fps, name, name, std::nullopt, &light.track, true);
            addRow(rows, lines, scene.fps, name + u' ' + word(KeyProperty::Intensity), name,
                   KeyProperty::Intensity, &light.intensity, false);
        }
        return rows;
    }
    const auto index = findObject(scene, *selection);
    if (!index) return rows;
    const SceneObject& object = scene.objects[*index];
    const QString name = QString::fromStdString(object.name);
    // Pose rows first (the object's, then its keyed parts'), then properties.
    addRow(rows, lines, scene.fps, name, name, std::nullopt, &object.track, true);
    const int parts = object.model ? int(object.model->parts.size()) : 0;
    auto partTarget = [&](int part) {
        return name + u'.' + QString::fromStdString(object.model->parts[std::size_t(part)].name);
    };
    for (int part = 0; part < parts; ++part)
        addRow(rows, lines, scene.fps, partTarget(part), partTarget(part), std::nullopt,
               &object.partTracks[std::size_t(part)], selection->part == part);
    for (KeyProperty property : {KeyProperty::Colour, KeyProperty::Visible}) {
        const auto& tracks = property == KeyProperty::Colour ? scene.colourTracks : scene.visibilityTracks;
        for (int part = -1; part < parts; ++part) {
            const QString target = part < 0 ? name : partTarget(part);
            addRow(rows, lines, scene.fps, target + u' ' + word(property), target, property,
                   targetTrack(tracks, {std::uint32_t(*index), part}), false);
        }
    }
    return rows;
}

std::vector<SpanEdit> moveKeyEdits(const QString& text, int fps, const std::vector<int>& keyLinesMoved,
                                   double delta, bool copy) {
    const std::vector<SourceLine> lines = scanSource(text);
    struct Moved {
        int line;
        double time;
    };
    std::vector<Moved> moved;
    for (int index : keyLinesMoved) {
        if (index < 0 || index >= int(lines.size()) || lines[std::size_t(index)].tokens.size() < 3) continue;
        if (const auto time = keyTime(lines[std::size_t(index)].tokens[1].text, fps)) {
            moved.push_back({index, *time});
            delta = std::max(delta, -*time);  // no key before frame 0
        }
    }
    std::vector<SpanEdit> edits, removals;
    if (delta == 0) return edits;
    auto sameTrack = [&](const SourceLine& a, const SourceLine& b) {
        return a.tokens[2].text == b.tokens[2].text && keyLineProperty(a) == keyLineProperty(b);
    };
    for (const Moved& key : moved) {
        const SourceLine& line = lines[std::size_t(key.line)];
        const SourceToken& time = line.tokens[1];
        const double to = key.time + delta;
        // Seconds stay seconds when they say the frame exactly (2.5s at 24 fps), else frames.
        const QString seconds = shortestNumber(to / fps) + u's';
        const auto secondsAt = keyTime(seconds, fps);
        const QString written =
            time.text.endsWith(u's') && secondsAt && std::fabs(*secondsAt - to) <= kSameTime
                ? seconds
                : shortestNumber(to);
        if (copy) {
            QString copied = text.mid(line.begin, line.end - line.begin);
            if (copied.endsWith(u'\r')) copied.chop(1);
            copied.replace(time.begin - line.begin, time.end - time.begin, written);
            edits.push_back(insertLineAfter(text, lines, key.line, copied));
        } else {
            edits.push_back({time.begin, time.end, written});
        }
        // A key of that track already there would be replaced: remove it.
        for (int other = 0; other < int(lines.size()); ++other) {
            const SourceLine& there = lines[std::size_t(other)];
            if (there.command() != u"/key" || there.tokens.size() < 3 || !sameTrack(there, line)) continue;
            if (std::any_of(moved.begin(), moved.end(), [&](const Moved& m) { return m.line == other; }))
                continue;
            const auto at = keyTime(there.tokens[1].text, fps);
            if (at && std::fabs(*at - to) <= kSameTime) removals.push_back(removeLine(text, lines, other));
        }
    }
    // Removals last: at an offset where a copy is inserted they apply first (withEdits' order).
    edits.insert(edits.end(), removals.begin(), removals.end());
    return edits;
}

std::vector<SpanEdit> deleteKeyEdits(const QString& text, const std::vector<int>& keyLinesRemoved) {
    const std::vector<SourceLine> lines = scanSource(text);
    std::vector<SpanEdit> edits;
    for (int index : keyLinesRemoved)
        if (index >= 0 && index < int(lines.size()) && lines[std::size_t(index)].command() == u"/key")
            edits.push_back(removeLine(text, lines, index));
    return edits;
}

std::vector<SpanEdit> keyModeEdits(const QString& text, const std::vector<int>& keyLinesSet,
                                   const std::optional<Easing>& mode) {
    const std::vector<SourceLine> lines = scanSource(text);
    std::vector<SpanEdit> edits;
    const QString written = mode ? QString::fromStdString(easingText(*mode)) : QString();
    for (int index : keyLinesSet) {
        if (index < 0 || index >= int(lines.size())) continue;
        const SourceLine& line = lines[std::size_t(index)];
        if (line.command() != u"/key" || line.tokens.size() < 3 ||
            keyLineProperty(line) == KeyProperty::Visible)
            continue;
        const int at = keyLineModeAt(line);
        if (at < int(line.tokens.size())) {
            // Replace the mode word and its numbers; removing it takes the space before it too.
            const qsizetype begin =
                written.isEmpty() ? line.tokens[std::size_t(at - 1)].end : line.tokens[std::size_t(at)].begin;
            edits.push_back({begin, line.tokens.back().end, written});
        } else if (!written.isEmpty()) {
            edits.push_back({line.tokens.back().end, line.tokens.back().end, u' ' + written});
        }
    }
    return edits;
}

}  // namespace f2::viewer
