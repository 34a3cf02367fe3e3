#include "write_back.h"

#include <QCoreApplication>
#include <QStringList>
#include <cmath>

#include "core/anim/track.h"
#include "core/scene/models.h"
#include "include_origin.h"
#include "scene_locations.h"

namespace f2::viewer {

namespace {

QString tr(const char* text) { return QCoreApplication::translate("f2::viewer::WriteBack", text); }

/// Key times match within this many frames (a key at 2.5s is 60 at 24 fps, exactly or nearly).
constexpr double kSameTime = 1e-6;

QString toQString(std::string_view s) { return QString::fromUtf8(s.data(), qsizetype(s.size())); }

const KeyPropertySpec& specOf(KeyProperty property) {
    for (const KeyPropertySpec& spec : keyProperties())
        if (spec.property == property) return spec;
    return keyProperties().front();
}

/// What the request's target and property are in the parsed scene.
struct Resolved {
    const Track* track = nullptr;  ///< null: the scene has no such target or property
    std::optional<std::size_t> object;
    std::optional<std::size_t> light;  ///< lightMotions index
    bool part = false;
    bool camera = false;
};

const Track* targetTrack(const std::vector<TargetTrack>& tracks, FrameRef ref) {
    static const Track kNoKeys;
    for (const TargetTrack& t : tracks)
        if (t.target == ref && t.shape < 0) return &t.track;
    return &kNoKeys;
}

Resolved resolve(const SceneDesc& scene, const QString& target, std::optional<KeyProperty> property) {
    Resolved r;
    if (target == toQString(kCameraName)) {
        r.camera = true;
        if (!property) r.track = &scene.camera.track;
        if (property == KeyProperty::Zoom) r.track = &scene.camera.zoom;
        return r;
    }
    const QString name = target.section(u'.', 0, 0);
    const QString partName = target.section(u'.', 1);
    const std::string objectName = name.toStdString();
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        if (object.name != objectName) continue;
        r.object = i;
        int part = -1;
        if (!partName.isEmpty()) {
            part = object.model ? object.model->partIndex(partName.toStdString()) : -1;
            if (part < 0) return r;
            r.part = true;
        }
        if (!property) r.track = part < 0 ? &object.track : &object.partTracks[std::size_t(part)];
        const FrameRef ref{std::uint32_t(i), part};
        if (property == KeyProperty::Colour) r.track = targetTrack(scene.colourTracks, ref);
        if (property == KeyProperty::Visible) r.track = targetTrack(scene.visibilityTracks, ref);
        return r;
    }
    if (!partName.isEmpty()) return r;
    for (std::size_t i = 0; i < scene.lightMotions.size(); ++i) {
        const LightMotion& light = scene.lightMotions[i];
        if (light.name != objectName) continue;
        r.light = i;
        if (!property && !light.ambient) r.track = &light.track;
        if (property == KeyProperty::Intensity) r.track = &light.intensity;
    }
    return r;
}

bool startsWithWord(QStringView token) {
    return !token.isEmpty() && (token[0].isLetter() || token[0] == u'_');
}

/// Where the numbers of a key line are: the index of the first, or -1 when
/// it has none (a pose key without numbers, `/key 5 r1 ease`).
int keyNumbersAt(const SourceLine& line, std::optional<KeyProperty> property, int count) {
    const int first = property ? 4 : 3;
    if (int(line.tokens.size()) < first + count) return -1;
    return startsWithWord(line.tokens[std::size_t(first)].text) ? -1 : first;
}

QString numbersText(const std::vector<double>& values) {
    QStringList written;
    for (double v : values) written << shortestNumber(v);
    return written.join(u' ');
}

/// Edits giving tokens [first, first + values.size()) of `line` the new
/// values, only where the written value changes; values past the line's
/// last token are appended (a creating command without its rotation) unless
/// they are all 0, the value left out means. `old`: the parsed values, for
/// tokens that are expressions.
void writeNumbers(const SourceLine& line, int first, const std::vector<double>& values,
                  const std::vector<double>& old, std::vector<SpanEdit>& edits) {
    // The numbers written: up to the first word (an instance's parameters, `/lamp b 0 0 0 arm 60`).
    std::size_t written = std::size_t(first);
    while (written < line.tokens.size() && written < first + values.size() &&
           !startsWithWord(line.tokens[written].text))
        ++written;
    std::vector<double> missing;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const std::size_t at = std::size_t(first) + i;
        const QString now = shortestNumber(values[i]);
        if (at >= written) {
            missing.push_back(values[i]);
            continue;
        }
        const SourceToken& token = line.tokens[at];
        const auto plain = plainNumber(token.text);
        const QString before = plain            ? shortestNumber(*plain)
                               : i < old.size() ? shortestNumber(old[i])
                                                : QString();
        if (now != before) edits.push_back({token.begin, token.end, now});
    }
    if (std::any_of(missing.begin(), missing.end(), [](double v) { return shortestNumber(v) != u"0"; })) {
        const qsizetype end = line.tokens[written - 1].end;
        edits.push_back({end, end, u' ' + numbersText(missing)});
    }
}

QString indentOf(const QString& text, const SourceLine& line) {
    qsizetype i = line.begin;
    while (i < line.end && (text[i] == u' ' || text[i] == u'\t')) ++i;
    return text.mid(line.begin, i - line.begin);
}

/// Where a target is made: on an editable line of the main file, inside a
/// loop of it, in an included file, or nowhere this text shows.
struct Origin {
    enum Where { Here, Loop, Included, Unknown, Stale } where = Unknown;
    int line = -1;       ///< Here: the creating line; Loop: the loop's /end; Included: the /include line
    int loopStart = -1;  ///< Loop: the /repeat line
    QString file;        ///< Included: the file's name as diagnostics give it
};

Origin originOf(const SceneSource& source, const std::vector<SourceLine>& lines, const Resolved& r,
                const QString& lightName) {
    auto at = [&](int index) -> Origin {
        if (index < 0 || index >= int(lines.size())) return {};
        const SourceLine& line = lines[std::size_t(index)];
        if (line.loopEnd >= 0) return {Origin::Loop, line.loopEnd, line.loopStart, {}};
        return {Origin::Here, index, -1, {}};
    };
    if (r.camera) {
        for (int i = 0; i < int(lines.size()); ++i)
            if (lines[std::size_t(i)].command() == u"/camera") return at(i);
        return {};
    }
    if (r.light) {
        for (int i = 0; i < int(lines.size()); ++i) {
            const auto& tokens = lines[std::size_t(i)].tokens;
            for (std::size_t t = 1; t + 1 < tokens.size(); ++t)
                if (tokens[t].text == u"name" && tokens[t + 1].text == lightName) return at(i);
        }
        return {};
    }
    const SceneObject& object = source.scene.objects[*r.object];
    const CreatedAt* created = source.locations.object(object.name);
    if (!created) return {};
    if (created->loc.file == source.sourceName) {
        // The text may have changed since the parse: the line must still hold the command.
        const int index = created->loc.line - 1;
        const std::string_view type = typeNameOf(object);
        if (index >= int(lines.size()) || lines[std::size_t(index)].command() !=
                                              u'/' + QString::fromUtf8(type.data(), qsizetype(type.size())))
            return {Origin::Stale, -1, -1, {}};
        Origin origin = at(index);
        // Several objects from one line (a loop) even where scanning saw no /repeat.
        if (origin.where == Origin::Here && created->sameLine > 1) origin.where = Origin::Loop;
        return origin;
    }
    Origin origin = at(includingLine(source.text, source.sourceName, created->loc, created->instance) - 1);
    if (origin.where == Origin::Here) origin.where = Origin::Included;
    origin.file = QString::fromStdString(created->loc.file);
    return origin;
}

/// The line a new line for the target goes after, when it has no key line to go next to.
int anchorLine(const Origin& origin, const std::vector<SourceLine>& lines) {
    return origin.where == Origin::Unknown || origin.where == Origin::Stale ? int(lines.size()) - 1
                                                                            : origin.line;
}

/// The written place of a loop, for messages: "lines 3–7".
QString loopPlace(const Origin& origin) {
    return tr("the /repeat loop of lines %1–%2").arg(origin.loopStart + 1).arg(origin.line + 1);
}

}  // namespace

std::optional<KeyProperty> keyLineProperty(const SourceLine& line) {
    if (line.tokens.size() < 4) return std::nullopt;
    const QByteArray word = line.tokens[3].text.toUtf8();
    const KeyPropertySpec* spec =
        findKeyProperty(std::string_view(word.constData(), std::size_t(word.size())));
    return spec ? std::optional(spec->property) : std::nullopt;
}

int keyLineModeAt(const SourceLine& line) {
    const auto property = keyLineProperty(line);
    const int count = property ? specOf(*property).numbers : 6;
    const int numbers = keyNumbersAt(line, property, count);
    const int at = numbers >= 0 ? numbers + count : property ? 4 : 3;
    return std::min(at, int(line.tokens.size()));
}

std::optional<double> keyTime(QStringView token, int fps) {
    if (token.endsWith(u's')) {
        const auto seconds = plainNumber(token.chopped(1));
        return seconds ? std::optional(*seconds * fps) : std::nullopt;
    }
    return plainNumber(token);
}

std::vector<KeyLine> keyLines(const std::vector<SourceLine>& lines, int fps, const QString& target,
                              std::optional<KeyProperty> property) {
    std::vector<KeyLine> found;
    for (int i = 0; i < int(lines.size()); ++i) {
        const SourceLine& line = lines[std::size_t(i)];
        if (line.command() != u"/key" || line.tokens.size() < 3 || line.tokens[2].text != target) continue;
        if (keyLineProperty(line) != property) continue;
        found.push_back({i, keyTime(line.tokens[1].text, fps), line.loopEnd < 0 && !line.inModel});
    }
    return found;
}

WriteBack writeBack(const SceneSource& source, const WriteRequest& request) {
    const std::vector<SourceLine> lines = scanSource(source.text);
    const Resolved r = resolve(source.scene, request.target, request.property);
    const int count = request.property ? specOf(*request.property).numbers : 6;
    WriteBack out;
    if (!r.track || int(request.values.size()) != count) {
        const bool known = r.camera || r.light || (r.object && (r.part || request.target.indexOf(u'.') < 0));
        out.refusal =
            known && request.property
                ? tr("%1 has no %2 to key.").arg(request.target, toQString(specOf(*request.property).word))
            : known ? tr("%1 has no pose to key.").arg(request.target)
                    : tr("%1 is not in the scene as it was last read (renamed or deleted since?)")
                          .arg(request.target);
        return out;
    }
    const QString keyText =
        QStringLiteral("/key %1 %2%3 %4")
            .arg(request.frame)
            .arg(request.target,
                 request.property ? u' ' + toQString(specOf(*request.property).word) : QString(),
                 numbersText(request.values));
    const Origin origin = originOf(source, lines, r, request.target);
    const std::vector<KeyLine> keyed = keyLines(lines, source.scene.fps, request.target, request.property);

    // The parsed key at the frame: its values, for numbers written as expressions.
    std::vector<double> old;
    for (const Key& key : r.track->keys) {
        if (std::fabs(key.time - request.frame) > kSameTime) continue;
        for (int c = 0; c < count; ++c)
            old.push_back(request.property ? key.pose.position[c] : poseChannel(key.pose, c));
    }
    if (!r.track->keys.empty() || !keyed.empty()) {
        // The last line keying that frame is the one that counts (a later one replaces an earlier one).
        const KeyLine* atFrame = nullptr;
        for (const KeyLine& key : keyed)
            if (key.time && std::fabs(*key.time - request.frame) <= kSameTime) atFrame = &key;
        if (atFrame && atFrame->editable) {
            const SourceLine& line = lines[std::size_t(atFrame->line)];
            const int first = keyNumbersAt(line, request.property, count);
            if (first >= 0)
                writeNumbers(line, first, request.values, old, out.edits);
            else
                out.edits.push_back({line.tokens[request.property ? 3 : 2].end,
                                     line.tokens[request.property ? 3 : 2].end,
                                     u' ' + numbersText(request.values)});
            return out;
        }
        if (atFrame || !old.empty()) {
            // Written where an edit would change more than this key, or not in this file.
            const SourceLine* line = atFrame ? &lines[std::size_t(atFrame->line)] : nullptr;
            const int after = line && line->loopEnd >= 0 ? line->loopEnd : int(lines.size()) - 1;
            out.refusal =
                line && line->loopEnd >= 0
                    ? tr("The key of %1 at frame %2 is written inside the /repeat loop of lines %3–%4: "
                         "changing it there would change every pass.")
                          .arg(request.target)
                          .arg(request.frame)
                          .arg(line->loopStart + 1)
                          .arg(line->loopEnd + 1)
                    : tr("The key of %1 at frame %2 is not written on a line of this file the studio can "
                         "edit "
                         "(an included file, a /model block or a computed time).")
                          .arg(request.target)
                          .arg(request.frame);
            out.offer = {insertLineAfter(source.text, lines, after, keyText)};
            out.offerLabel = tr("Add a key at line %1 instead (it replaces that key)").arg(after + 2);
            return out;
        }
        // A new key, in time order among the target's key lines.
        const KeyLine* before = nullptr;
        const KeyLine* later = nullptr;
        for (const KeyLine& key : keyed) {
            if (!key.editable || !key.time) continue;
            if (*key.time < request.frame && (!before || *key.time >= *before->time)) before = &key;
            if (*key.time > request.frame && (!later || *key.time < *later->time)) later = &key;
        }
        if (before) {
            const SourceLine& line = lines[std::size_t(before->line)];
            out.edits = {
                insertLineAfter(source.text, lines, before->line, indentOf(source.text, line) + keyText)};
        } else if (later) {
            const SourceLine& line = lines[std::size_t(later->line)];
            out.edits = {{line.begin, line.begin, indentOf(source.text, line) + keyText + u'\n'}};
        } else {
            out.edits = {insertLineAfter(source.text, lines, anchorLine(origin, lines), keyText)};
        }
        return out;
    }

    // No keys: the creating command's numbers, where it has them.
    int first = -1;
    std::vector<double> rest;
    if (r.camera && !request.property) {
        first = 4;
        for (int c = 0; c < 6; ++c) rest.push_back(poseChannel(source.scene.camera.pose, c));
    } else if (r.camera) {
        first = 3;
        rest = {source.scene.camera.distance};
    } else if (r.light && request.property == KeyProperty::Intensity) {
        first = 1;
    } else if (r.object && !r.part && !request.property) {
        const SceneObject& object = source.scene.objects[*r.object];
        first = object.kind == ObjectKind::Sphere     ? 3
                : object.kind == ObjectKind::Cylinder ? 4
                : object.kind == ObjectKind::Box      ? 5
                                                      : 2;
        for (int c = 0; c < 6; ++c) rest.push_back(poseChannel(object.rest, c));
    }
    if (first < 0) {
        // A part, a colour, a light's pose, visibility: the first key goes after the creating line.
        out.edits = {insertLineAfter(source.text, lines, anchorLine(origin, lines), keyText)};
        return out;
    }
    if (origin.where == Origin::Here) {
        writeNumbers(lines[std::size_t(origin.line)], first, request.values, rest, out.edits);
        return out;
    }
    const QString what = r.camera ? tr("The /camera line") : request.target;
    switch (origin.where) {
        case Origin::Loop:
            out.refusal =
                tr("%1 is made inside %2: changing its numbers there would change every object the loop "
                   "makes.")
                    .arg(what, loopPlace(origin));
            out.offerLabel = tr("Add a key after the loop (line %1) instead").arg(origin.line + 2);
            break;
        case Origin::Included:
            out.refusal = tr("%1 is made in the included file %2: the studio edits only this file.")
                              .arg(what, origin.file);
            out.offerLabel = tr("Add a key after its /include (line %1) instead").arg(origin.line + 2);
            break;
        case Origin::Stale:
            out.refusal =
                tr("The text has changed at the line that makes %1 since it was last read; try again "
                   "once the picture has caught up.")
                    .arg(request.target);
            return out;
        default:
            out.refusal = r.camera ? tr("This file has no /camera line.")
                                   : tr("%1 is not made on a line of this file.").arg(what);
            out.offerLabel = tr("Add a key at the end of the file instead");
            break;
    }
    out.offer = {insertLineAfter(source.text, lines, anchorLine(origin, lines), keyText)};
    return out;
}

WriteBack writePose(const SceneSource& source, const QString& target, int frame, const Pose& pose) {
    std::vector<double> values;
    for (int c = 0; c < 6; ++c) values.push_back(poseChannel(pose, c));
    return writeBack(source, {target, std::nullopt, frame, std::move(values)});
}

}  // namespace f2::viewer
