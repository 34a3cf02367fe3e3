// textDocument/hover: a command's syntax and meaning; an object's kind, where
// it is created, its keys, its model's part tree and its pose at frame 0; a
// part's shapes and pivot; a shape; a model type's part tree; the camera's
// line, keys, look-at, attachment and pose at frame 0; a named light's line,
// mount, keys and place at frame 0; a `/drive`'s value at frame 0; a
// variable's definition; an include's file.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <utility>

#include "core/anim/camera_motion.h"
#include "core/anim/light_evaluation.h"
#include "core/anim/track.h"
#include "core/parse/expression.h"
#include "core/parse/language.h"
#include "core/parse/lexer.h"
#include "core/scene/models.h"
#include "lsp/features.h"
#include "lsp/model_types.h"

namespace f2::lsp {

namespace {

std::string number(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
}

std::string vec(const Vec3& v) { return "(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ")"; }

/// "sphere r 6", "cylinder r 10, h 100", "box 60 × 50 × 50".
std::string shapeText(ShapeKind kind, const Vec3& size) {
    switch (kind) {
        case ShapeKind::Sphere:
            return "sphere r " + number(size.x);
        case ShapeKind::Cylinder:
            return "cylinder r " + number(size.x) + ", h " + number(size.y);
        case ShapeKind::Box:
            return "box " + number(size.x) + " × " + number(size.y) + " × " + number(size.z);
    }
    return {};
}

/// "cylinder r 4, h 120 centred at (0, 60, 0)", its turn and whether it keeps its colour.
std::string shapeLine(const ModelShape& s) {
    std::string text = shapeText(s.kind, s.size) + " centred at " + vec(s.centre);
    if (s.turn) text += ", turned " + vec(s.rotation);
    return s.ownColor ? text + " (keeps its colour)" : text;
}

/// A model's parts as a Markdown tree: each part with its pivot and rest
/// rotation, then its shapes and its children, `indent` spaces in.
void addPartTree(std::string& text, const ModelType& model, int parent, std::size_t indent) {
    for (std::size_t i = 0; i < model.parts.size(); ++i) {
        const ModelPart& part = model.parts[i];
        if (part.parent != parent) continue;
        text += std::string(indent, ' ') + "- `" + part.name + "`" + (parent < 0 ? " on the root" : "") +
                ", pivot " + vec(part.pivot);
        if (part.rest) text += ", rest rotation " + vec(part.restRotation);
        text += "\n";
        for (const ModelShape& s : model.shapes) {
            if (s.part != static_cast<int>(i)) continue;
            text +=
                std::string(indent + 2, ' ') + "- `" + part.name + "." + s.name + "`: " + shapeLine(s) + "\n";
        }
        addPartTree(text, model, static_cast<int>(i), indent + 2);
    }
}

std::string placeText(const Analysis& a, const SourceLoc& loc) {
    std::string place = "line " + std::to_string(loc.line);
    if (!a.inDocument(loc)) place += " of " + loc.file;
    return place;
}

Json markdown(std::string text, const Range& range) {
    return {{"contents", {{"kind", "markdown"}, {"value", std::move(text)}}}, {"range", toJson(range)}};
}

std::string objectHover(const Analysis& a, std::size_t index) {
    const IndexedObject& entry = a.index.objects[index];
    const SceneObject& o = entry.object;
    std::string text =
        "**" + std::string(typeNameOf(o)) + "** `" + o.name + "`, created at " + placeText(a, entry.command);
    if (a.inDocument(entry.command)) {
        text += ":\n```f2\n" + std::string(a.document.line(entry.command.line - 1)) + "\n```\n";
    } else {
        text += "\n\n";
    }
    if (!o.model) text += "- " + shapeText(shapeKindOf(o.kind), o.size) + "\n";
    const auto keys = keyCounts(a, index);
    text += "- keys: " + std::to_string(keys[0]);
    if (o.model) {
        text += " (own)";
        for (std::size_t i = 0; i < o.model->parts.size(); ++i)
            text += ", " + o.model->parts[i].name + " " + std::to_string(keys[i + 1]);
    }
    text += "\n";
    if (o.model) {
        text += "- parts of " + o.model->name + ":\n";
        addPartTree(text, *o.model, -1, 2);
    }
    // The pose at frame 0 needs the keys, which only a scene without errors has.
    if (a.result.ok() && index < a.result.scene->objects.size()) {
        const SceneObject& parsed = a.result.scene->objects[index];
        const Pose pose = evaluateTrack(parsed.track, 0.0, parsed.rest);
        text += "- at frame 0: position " + vec(pose.position) + ", rotation " + vec(pose.rotation) + "\n";
    } else {
        text += "- as created: position " + vec(o.rest.position) + ", rotation " + vec(o.rest.rotation) +
                " (the scene has errors, so keys are not evaluated)\n";
    }
    return text;
}

/// A part of a model: its pivot and rest rotation, its shapes.
std::string partFacts(const ModelType& model, int part) {
    const ModelPart& mp = model.parts[static_cast<std::size_t>(part)];
    const std::string parent =
        mp.parent < 0 ? "the root" : model.parts[static_cast<std::size_t>(mp.parent)].name;
    std::string text = "- pivot " + vec(mp.pivot) + " in " + parent + "'s frame";
    if (mp.rest) text += ", rest rotation " + vec(mp.restRotation);
    text += "\n";
    for (const ModelShape& s : model.shapes) {
        if (s.part == part) text += "- `" + s.name + "`: " + shapeLine(s) + "\n";
    }
    return text;
}

/// Where a part (or, with `shape`, a shape) of a model the scene defines is written.
std::string memberPlace(const Analysis& a, const ModelType& model, int member, bool shape) {
    const IndexedModel* m = indexedModelOf(a, &model);
    if (!m) return {};
    const auto& spans = shape ? m->shapes : m->parts;
    if (member < 0 || std::size_t(member) >= spans.size()) return {};
    return (shape ? "- created at " : "- declared at ") + placeText(a, spans[std::size_t(member)].loc) + "\n";
}

std::string partHover(const Analysis& a, std::size_t index, int part) {
    const SceneObject& o = a.index.objects[index].object;
    if (!o.model) return "**part** of `" + o.name + "`\n";
    const ModelType& model = *o.model;
    const ModelPart& mp = model.parts[static_cast<std::size_t>(part)];
    std::string text = "**part** `" + o.name + "." + mp.name + "` of " + model.name + " `" + o.name + "`\n";
    text += partFacts(model, part);
    const auto keys = keyCounts(a, index);
    text += "- keys: " + std::to_string(keys[static_cast<std::size_t>(part + 1)]) + "\n";
    return text + memberPlace(a, model, part, false);
}

/// `name.part.shape` (SPEC 10.1): its kind, size and place on its part.
std::string shapeHover(const Analysis& a, std::size_t index, int shape) {
    const SceneObject& o = a.index.objects[index].object;
    const ModelType& model = *o.model;
    const ModelShape& s = model.shapes[static_cast<std::size_t>(shape)];
    const std::string& part = model.parts[static_cast<std::size_t>(s.part)].name;
    return "**shape** `" + o.name + "." + part + "." + s.name + "` of " + model.name + " `" + o.name +
           "`\n- " + shapeLine(s) + " in " + part + "'s frame\n" + memberPlace(a, model, shape, true);
}

/// A part or a shape named inside its `/model` block.
std::string modelMemberHover(const Analysis& a, const SymbolAt& at) {
    const auto known = findModel(a, at.text);
    if (!known) return {};
    const ModelType& model = *known->type;
    if (at.kind == SymbolAt::Kind::ModelPart) {
        return "**part** `" + model.parts[std::size_t(at.part)].name + "` of the model `" + model.name +
               "`\n" + partFacts(model, at.part) + memberPlace(a, model, at.part, false);
    }
    const ModelShape& s = model.shapes[std::size_t(at.shape)];
    const std::string& part = model.parts[std::size_t(s.part)].name;
    return "**shape** `" + part + "." + s.name + "` of the model `" + model.name + "`\n- " + shapeLine(s) +
           " in " + part + "'s frame\n" + memberPlace(a, model, at.shape, true);
}

/// A model type (SPEC 10.1): where it is defined and its part tree.
std::string modelHover(const Analysis& a, const std::string& name) {
    const auto known = findModel(a, name);
    if (!known) return "**model** `" + name + "`: its block has no `/end` yet, or errors\n";
    std::string text = "**model** `" + name + "`";
    text += known->indexed ? ", defined at " + placeText(a, known->indexed->command) + "\n"
                           : ", built in (SPEC 5)\n";
    text += "- " + std::to_string(known->type->parts.size()) + " parts, " +
            std::to_string(known->type->shapes.size()) + " shapes:\n";
    addPartTree(text, *known->type, -1, 2);
    return text;
}

/// The first argument after a `/let` or `/repeat` variable: a number, a word or a `( … )`.
std::string_view valueText(std::string_view line, std::size_t nameEnd) {
    std::size_t b = line.find_first_not_of(" \t", nameEnd);
    if (b == std::string_view::npos) return {};
    if (line[b] != '(') return line.substr(b, line.find_first_of(" \t#", b) - b);
    int depth = 0;
    for (std::size_t i = b; i < line.size(); ++i) {
        if (line[i] == '(') ++depth;
        if (line[i] == ')' && --depth == 0) return line.substr(b, i + 1 - b);
    }
    return {};
}

/// The value a definition gives when the `/let` and `/repeat` lines before it
/// run in reading order, each loop at its first pass; nullopt when one fails.
std::optional<double> definedValue(const Analysis& a, const VariableOccurrence& def) {
    Variables values;
    for (const VariableOccurrence& v : a.sources.variables) {
        if (!v.definition) continue;
        const std::string_view text =
            valueText(a.sources.files[static_cast<std::size_t>(v.file)].document.line(v.line), v.end);
        const ExpressionResult r =
            text.starts_with('(') ? evaluateParenthesized(text, values) : evaluateExpression(text, values);
        if (r.ok) values.set(v.name, r.value);
        if (v.file == def.file && v.line == def.line && v.order == def.order) return values.find(def.name);
    }
    return std::nullopt;
}

std::string variableHover(const Analysis& a, const std::string& name, int line) {
    const auto def = definitionOf(a.sources.variables, name, a.sources.orderOf(a.self, line));
    // In a /drive's expression, frame and time are the drive's inputs (SPEC 10.7).
    if (!def && (name == kDriveInputs[0] || name == kDriveInputs[1]) &&
        a.document.line(line).find(command(CommandId::Drive).name) != std::string_view::npos) {
        return "**" + name + "** in a `/drive`: " +
               (name == kDriveInputs[0] ? "the frame drawn (fractional in motion blur and playback)"
                                        : "the time in seconds, frame / fps");
    }
    if (!def) return "**variable** `" + name + "`: not defined in this scene";
    const SceneFile& file = a.sources.files[static_cast<std::size_t>(def->file)];
    const SourceLoc loc{file.path, def->line + 1, 1};
    std::string text = "**" + std::string(def->loop ? "loop variable" : "variable") + "** `" + name + "`";
    if (const auto value = definedValue(a, *def)) {
        text +=
            def->loop ? " = " + formatNumber(*value) + " on the first pass" : " = " + formatNumber(*value);
    }
    return text + ", defined at " + placeText(a, loc) + ":\n```f2\n" +
           std::string(file.document.line(def->line)) + "\n```";
}

/// The first line of the scene's files whose command is `command` (and, if
/// given, whose first argument is `firstArgument`): "line N[ of FILE]" and its text.
std::optional<std::pair<std::string, std::string>> findCommandLine(const Analysis& a,
                                                                   std::string_view command,
                                                                   std::string_view firstArgument = {}) {
    for (const SceneFile& file : a.sources.files) {
        for (int i = 0; i < file.document.lineCount(); ++i) {
            LineTokens tokens;
            tokenizeLine(file.document.line(i), tokens);
            if (tokens.count < 1 || tokens.tokens[0].text != command) continue;
            if (!firstArgument.empty() && (tokens.count < 2 || tokens.tokens[1].text != firstArgument))
                continue;
            return std::pair{placeText(a, {file.path, i + 1, 1}), std::string(file.document.line(i))};
        }
    }
    return std::nullopt;
}

std::string frameRefText(const SceneDesc& scene, const FrameRef& ref) {
    std::string text = "`" + scene.objects[ref.object].name;
    if (ref.part >= 0)
        text += "." + scene.objects[ref.object].model->parts[static_cast<std::size_t>(ref.part)].name;
    return text + "`";
}

/// `camera`: its `/camera` line, keys, what it looks at and rides on, its pose at frame 0.
std::string cameraHover(const Analysis& a) {
    std::string text = "**camera**, the scene camera";
    if (const auto line = findCommandLine(a, "/camera")) {
        text += ", set at " + line->first + ":\n```f2\n" + line->second + "\n```\n";
    } else {
        text += " (no `/camera` line: 800 × 600, d 0.5, at the origin looking along +z)\n\n";
    }
    const auto lookAt = findCommandLine(a, "/look_at");
    const auto attach = findCommandLine(a, "/attach", "camera");
    if (!a.result.ok()) {
        if (lookAt) text += "- looks at: `" + lookAt->second + "` (" + lookAt->first + ")\n";
        if (attach) text += "- rides on: `" + attach->second + "` (" + attach->first + ")\n";
        return text + "- the scene has errors, so its keys and pose are not evaluated\n";
    }
    const SceneDesc& scene = *a.result.scene;
    const CameraDesc& camera = scene.camera;
    text += "- image " + std::to_string(camera.width) + " × " + std::to_string(camera.height) + ", d " +
            number(camera.distance) + "\n";
    text += "- keys: " + std::to_string(camera.track.keys.size()) + "\n";
    text += "- looks at: ";
    if (!camera.lookAt) {
        text += "nothing (its keys turn it)\n";
    } else {
        text += camera.lookAt->target ? frameRefText(scene, *camera.lookAt->target)
                                      : "the point " + vec(camera.lookAt->point);
        text += lookAt ? " (" + lookAt->first + ")\n" : "\n";
    }
    text += "- rides on: ";
    if (!camera.attachedTo) {
        text += "nothing\n";
    } else {
        text += frameRefText(scene, *camera.attachedTo) + (attach ? " (" + attach->first + ")\n" : "\n");
    }
    const Transform frame = cameraFrameAt(scene, 0.0);
    const Vec3 forward = frame.linear.column(2);
    text += "- at frame 0: eye " + vec(frame.translation);
    if (!camera.attachedTo && !camera.lookAt) {
        text += ", rotation " + vec(evaluateTrack(camera.track, 0.0, camera.pose).rotation);
    }
    return text + ", looking along " + vec(forward) + "\n";
}

/// A named light (SPEC 10.2): its line, what it rides on, its keys, and where
/// it is and how bright at frame 0.
std::string lightHover(const Analysis& a, std::size_t index) {
    const IndexedLight& entry = a.index.lights[index];
    std::string text = "**light** `" + entry.name + "` (`" + entry.command + "`), created at " +
                       placeText(a, entry.commandLoc);
    if (a.inDocument(entry.commandLoc)) {
        text += ":\n```f2\n" + std::string(a.document.line(entry.commandLoc.line - 1)) + "\n```\n";
    } else {
        text += "\n\n";
    }
    if (!a.result.ok() || index >= a.result.scene->lightMotions.size()) {
        return text + "- the scene has errors, so its keys and pose are not evaluated\n";
    }
    const SceneDesc& scene = *a.result.scene;
    const LightMotion& motion = scene.lightMotions[index];
    if (!motion.ambient) {
        text +=
            "- rides on: " + (motion.attachedTo ? frameRefText(scene, *motion.attachedTo) : "nothing") + "\n";
        text += "- pose keys: " + std::to_string(motion.track.keys.size()) + "\n";
    }
    text += "- intensity keys: " + std::to_string(motion.intensity.keys.size()) + "\n";
    const auto motionIndex = static_cast<std::int32_t>(index);
    for (const LocalLight& l : scene.localLights) {
        if (l.motion != motionIndex) continue;
        text += "- at frame 0: position " +
                vec(placeLight(scene, l.motion, l.position, l.direction, 0.0).position) + ", intensity " +
                number(lightIntensityAt(scene, l.motion, l.intensity, 0.0)) + "\n";
    }
    for (const DirectionalLight& l : scene.lights) {
        if (l.motion != motionIndex) continue;
        text += "- at frame 0: travels along " +
                vec(placeLight(scene, l.motion, {}, l.direction, 0.0).direction) + ", intensity " +
                number(lightIntensityAt(scene, l.motion, l.intensity, 0.0)) + "\n";
    }
    for (const AmbientLight& l : scene.namedAmbients) {
        if (l.motion != index) continue;
        text += "- at frame 0: intensity " + number(lightIntensityAt(scene, motionIndex, l.intensity, 0.0)) +
                "\n";
    }
    return text;
}

std::string includeHover(const Analysis& a, const std::string& path) {
    const std::string file = resolveInclude(a.path, path);
    std::error_code ec;
    const bool exists = std::filesystem::is_regular_file(file, ec);
    return "**include** `" + file + "`" + (exists ? "" : " (not a readable file)");
}

/// A `/drive` on line `line` (1-based) of the document: its value at frame
/// 0, as the other hovers give a pose (the server has no current frame).
std::string driveHover(const Analysis& a, int line) {
    if (!a.result.ok()) return "\n\n(the scene has errors, so the drive is not evaluated)";
    for (const std::shared_ptr<const Drive>& drive : a.result.scene->drives) {
        if (drive->line != line || !a.inDocument({drive->file, drive->line, drive->column})) continue;
        ExpressionFailure failure;
        const double v = drive->valueAt(0.0, &failure);
        return "\n\n`" + drive->target + " " + std::string(driveChannelName(drive->channel)) +
               "` at frame 0: " +
               (std::isfinite(v) ? formatNumber(v) : "no finite value (" + failure.message + ")");
    }
    return {};
}

}  // namespace

Json hover(const Analysis& a, Position p) {
    const SymbolAt at = symbolAt(a, p);
    switch (at.kind) {
        case SymbolAt::Kind::None:
            return nullptr;
        case SymbolAt::Kind::Command: {
            const CommandSpec* doc = findCommand(at.command);
            if (!doc) return nullptr;
            std::string text = "```f2\n" + std::string(doc->syntax) + "\n```\n" + std::string(doc->meaning);
            if (doc->id == CommandId::Drive) text += driveHover(a, p.line + 1);
            // The robot and the human are models too (SPEC 10.1): their trees.
            if (doc->id == CommandId::Robot || doc->id == CommandId::Human)
                text += "\n\n" + modelHover(a, std::string(doc->name.substr(1)));
            return markdown(std::move(text), at.range);
        }
        case SymbolAt::Kind::Object:
            return markdown(objectHover(a, at.object), at.range);
        case SymbolAt::Kind::Part:
            return markdown(partHover(a, at.object, at.part), at.range);
        case SymbolAt::Kind::Shape:
            return markdown(shapeHover(a, at.object, at.shape), at.range);
        case SymbolAt::Kind::Model:
            return markdown(modelHover(a, at.text), at.range);
        case SymbolAt::Kind::ModelPart:
        case SymbolAt::Kind::ModelShape:
            return markdown(modelMemberHover(a, at), at.range);
        case SymbolAt::Kind::Variable:
            return markdown(variableHover(a, at.text, p.line), at.range);
        case SymbolAt::Kind::Include:
            return markdown(includeHover(a, at.text), at.range);
        case SymbolAt::Kind::Camera:
            return markdown(cameraHover(a), at.range);
        case SymbolAt::Kind::Light:
            return markdown(lightHover(a, at.object), at.range);
    }
    return nullptr;
}

}  // namespace f2::lsp
