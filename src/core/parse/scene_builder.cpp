#include "core/parse/scene_builder.h"

#include <algorithm>
#include <cmath>

#include "core/parse/expression.h"
#include "core/parse/number.h"
#include "core/parse/quoted_text.h"
#include "core/parse/suggest.h"
#include "core/parse/unusual_char.h"

namespace f2::parsing {

namespace {

/// Total work (distance table cells) spent on "did you mean" for names, so
/// that a file with a million objects and many unknown names stays fast.
constexpr std::size_t kMaxNameSuggestWork = 50'000'000;

/// The command closest to a mistyped one, if it is close enough to be a typo.
std::string_view suggestCommand(std::string_view word) {
    if (word.size() > kMaxSuggestLength) return {};
    // A cut-short name ("/amb light" for "/amb_light") is a likely mistake too.
    if (word.size() >= 3) {
        for (const CommandSpec& c : commands()) {
            if (c.name.starts_with(word)) return c.name;
        }
    }
    std::string_view best;
    std::size_t bestDistance = 3;  // at most two edits
    for (const CommandSpec& c : commands()) {
        const std::size_t d = editDistance(word, c.name);
        if (d < bestDistance) {
            bestDistance = d;
            best = c.name;
        }
    }
    return best;
}

}  // namespace

ParseResult SceneBuilder::run(std::string_view text,
                              std::optional<std::pair<std::uint64_t, std::uint64_t>> identity) {
    const bool tooLarge = text.size() > limits_.maxSceneBytes;
    expander_.start(tooLarge ? std::string_view() : text, std::string(fileName_), identity);
    if (tooLarge) {
        error({1, 1}, "the scene is " + std::to_string(text.size()) + " bytes, more than the limit of " +
                          std::to_string(limits_.maxSceneBytes) + " bytes");
        return finish();
    }
    while (!stopped_ && expander_.next(tokens_)) parseLine();
    addCameraKeys();
    finishDrives();
    convertSecondsToFrames();
    checkAttachChanges();
    sortUnsortedTracks();
    applyInterpToPropertyTracks();
    orderColourTracks();
    orderAttachments();
    if (errors_ == 0) warnAboutTheWholeScene();
    return finish();
}

ParseResult SceneBuilder::finish() {
    ParseResult result = finishReading();
    if (errors_ == 0) result.scene = std::move(scene_);
    return result;
}

bool SceneBuilder::knowsCommand(std::string_view command) const {
    const CommandSpec* c = findCommand(command);
    return (c && c->group != CommandGroup::Source) || typeOfCommand(command) != nullptr;
}

const TypeBook* SceneBuilder::typeOfCommand(std::string_view command) const {
    if (!command.starts_with('/')) return nullptr;
    const auto it = types_.find(command.substr(1));
    return it == types_.end() ? nullptr : &it->second;
}

void SceneBuilder::parseLine() {
    const std::string_view head = commandText();
    if (!head.starts_with('/')) {
        std::string message = "expected a command starting with '/', got " + quoteToken(head);
        if (head.size() <= kMaxSuggestLength) {
            const std::string slashed = "/" + std::string(head);
            if (findCommand(slashed)) message += " (did you mean '" + slashed + "'?)";
        }
        error(commandPos(), noteCharacters(std::move(message), head, commandPos()));
        return;
    }
    if (building_) return parseModelLine(head);
    // The Source group never arrives here: the expander runs those lines.
    if (const CommandSpec* c = findCommand(head); c && c->group != CommandGroup::Source) {
        if (index_) index_->noteCommand(head, sourceLoc(commandPos()));
        dispatch(c->id);
        return;
    }
    if (const TypeBook* type = typeOfCommand(head)) {
        if (index_) index_->noteCommand(head, sourceLoc(commandPos()));
        command_ = CommandId::Robot;  // an instance is written as /robot is (SPEC 10.1)
        return parseObject(ObjectKind::Model, type);
    }
    unknownCommand(head);
}

void SceneBuilder::unknownCommand(std::string_view head) {
    std::string message = "unknown command " + quoteToken(head);
    if (const std::string_view guess = suggestCommand(head); !guess.empty()) {
        message += " (did you mean '" + std::string(guess) + "'?)";
    }
    error(commandPos(), noteCharacters(std::move(message), head, commandPos()));
}

void SceneBuilder::dispatch(CommandId command) {
    command_ = command;
    using enum CommandId;
    switch (command) {
        case Camera:
            return parseCamera();
        case AmbLight:
            return parseAmbLight();
        case PointLight:
            return parseLocalLight(LocalLightKind::Point);
        case SpotLight:
            return parseLocalLight(LocalLightKind::Spot);
        case DirLight:
            return parseDirLight();
        case Background:
            return parseBackground();
        case Material:
            return parseMaterial();
        case Sphere:
            return parseObject(ObjectKind::Sphere);
        case Cylinder:
            return parseObject(ObjectKind::Cylinder);
        case Box:
            return parseObject(ObjectKind::Box);
        case Paint:
            return parsePaint();
        case Robot:
            return parseObject(ObjectKind::Model, &types_.at("robot"));
        case Human:
            return parseObject(ObjectKind::Model, &types_.at("human"));
        case Anim:
            return parseAnim();
        case Key:
            return parseKey();
        case Interp:
            return parseInterp();
        case Fps:
            return parseFps();
        case LookAt:
            return parseLookAt();
        case Attach:
            return parseAttach();
        case Checker:
            return parseChecker();
        case Caption:
            return parseCaption();
        case NoShadow:
            return parseNoShadow();
        case Model:
            return openModel();
        case Part:
            error(commandPos(), "'/part' stands only inside a '/model' block");
            return;
        case Drive:
            return parseDrive();
#ifdef F2_SCRATCH_COMMAND
        case Scratch:
            return parseScratch();  // tests/scratch_command/scratch_builder.cpp
#endif
        case Let:
        case Repeat:
        case End:
        case Include:
            return;  // run by the SourceExpander
    }
}

bool SceneBuilder::newName(int i) {
    if (failed(i)) return false;
    const std::string_view name = arg(i);
    if (!isValidName(name)) {
        error(argPos(i), noteCharacters("invalid name " + quoteToken(name) +
                                            " (expected a letter or '_', then letters, digits or '_')",
                                        name, argPos(i)));
        return false;
    }
    if (name == kCameraName) {
        error(argPos(i), "'camera' is the name of the scene camera; an object cannot take it");
        return false;
    }
    std::optional<std::pair<Pos, std::uint32_t>> first;  // where, and its loop note
    if (auto it = names_.find(name); it != names_.end())
        first = {books_[it->second].defined, books_[it->second].loopNote};
    if (auto it = lightNames_.find(name); it != lightNames_.end())
        first = {lightBooks_[it->second].defined, lightBooks_[it->second].loopNote};
    if (first) {
        error(argPos(i), "duplicate name " + quoteToken(name) + " (first defined at " +
                             posText(first->first) +
                             (first->second == 0 ? "" : " " + loopNotes_[first->second - 1]) + ")");
        return false;
    }
    return true;
}

std::optional<int> SceneBuilder::lightNamed(std::string_view name) const {
    auto it = lightNames_.find(name);
    if (it == lightNames_.end()) return std::nullopt;
    return static_cast<int>(it->second);
}

void SceneBuilder::noteLightUse(int light, Pos pos, std::string_view name) {
    if (index_)
        index_->uses.push_back(
            {static_cast<std::size_t>(light), span(pos, name), std::string(commandText()), true});
}

std::string SceneBuilder::lightText(int light) const {
    const LightMotion& l = scene_.lightMotions[static_cast<std::size_t>(light)];
    return std::string(l.ambient ? "the ambient light " : "the light ") + quoteToken(l.name);
}

std::optional<std::size_t> SceneBuilder::existing(std::string_view name, std::string_view token, Pos pos,
                                                  bool cameraToo) {
    if (!isValidName(name)) {
        error(pos, noteCharacters("invalid target " + quoteToken(token) + " (expected a name or name.part)",
                                  token, pos));
        return std::nullopt;
    }
    auto it = names_.find(name);
    if (it == names_.end()) {
        std::string message = "unknown name " + quoteToken(name);
        if (const std::string_view guess = suggestName(name, cameraToo); !guess.empty()) {
            message += " (did you mean '" + std::string(guess) + "'?)";
        }
        error(pos, std::move(message));
        return std::nullopt;
    }
    if (index_) index_->uses.push_back({it->second, span(pos, name), std::string(commandText())});
    return it->second;
}

std::string_view SceneBuilder::suggestName(std::string_view name, bool cameraToo) {
    ClosestWord closest(name);
    for (const SceneObject& o : scene_.objects) {
        if (nameSuggestWork_ >= kMaxNameSuggestWork) break;
        nameSuggestWork_ += closest.consider(o.name);
    }
    for (const LightMotion& l : scene_.lightMotions) {
        if (nameSuggestWork_ >= kMaxNameSuggestWork) break;
        nameSuggestWork_ += closest.consider(l.name);
    }
    if (cameraToo) closest.consider(kCameraName);
    return closest.best();
}

std::string SceneBuilder::partList(const ModelType& model) {
    std::string list;
    for (std::size_t k = 0; k < model.parts.size(); ++k) {
        if (k > 0) list += k + 1 == model.parts.size() ? " or " : ", ";
        list += model.parts[k].name;
    }
    return list;
}

std::optional<int> SceneBuilder::partOf(std::size_t object, std::string_view part, Pos pos) {
    const SceneObject& o = scene_.objects[object];
    if (!o.model) {
        error(pos, quoteToken(commandText()) + " on a part of a primitive: " + quoteToken(o.name) + " is a " +
                       std::string(objectKindName(o.kind)) + "; only models have parts");
        return std::nullopt;
    }
    const int index = o.model->partIndex(part);
    if (index < 0) {
        const std::string_view guess = suggestPart(part, *o.model);
        error(pos, noteCharacters("unknown part " + quoteToken(part) +
                                      (guess.empty() ? " (expected " + partList(*o.model) + ")"
                                                     : " (did you mean '" + std::string(guess) + "'?)"),
                                  part, pos));
        return std::nullopt;
    }
    return index;
}

std::optional<int> SceneBuilder::shapeOf(std::size_t object, int part, std::string_view shape, Pos pos) {
    const ModelType& model = *scene_.objects[object].model;
    const int index = model.shapeIndex(part, shape);
    if (index >= 0) return index;
    std::string list;
    ClosestWord closest(shape);
    for (const ModelShape& s : model.shapes) {
        if (s.part != part) continue;
        list += (list.empty() ? "" : ", ") + s.name;
        closest.consider(s.name);
    }
    const std::string& partName = model.parts[std::size_t(part)].name;
    error(pos, noteCharacters(
                   "unknown shape " + quoteToken(shape) + " on the part " + quoteToken(partName) + " of '" +
                       model.name + "'" +
                       (!closest.best().empty() ? " (did you mean '" + std::string(closest.best()) + "'?)"
                        : list.empty()          ? " (it has no shapes)"
                                                : " (expected " + list + ")"),
                   shape, pos));
    return std::nullopt;
}

std::optional<Target> SceneBuilder::target(int i, CameraTarget cameraUse, LightTarget lightUse,
                                           ShapeTarget shapeUse) {
    if (failed(i)) return std::nullopt;
    const std::string_view text = arg(i);
    const Pos pos = argPos(i);
    const std::size_t dot = text.find('.');
    if (const std::optional<int> light = lightNamed(text.substr(0, dot))) {
        noteLightUse(*light, pos, text.substr(0, dot));
        if (lightUse == LightTarget::Refused) {
            error(pos, quoteToken(commandText()) +
                           " does not apply to lights: " + quoteToken(text.substr(0, dot)) + " is a light");
            return std::nullopt;
        }
        if (dot != std::string_view::npos) {
            Pos partPos = pos;
            partPos.column += static_cast<int>(dot) + 1;
            error(partPos, "a light has no parts");
            return std::nullopt;
        }
        Target t;
        t.light = *light;
        return t;
    }
    if (text.substr(0, dot) == kCameraName) {
        if (cameraUse == CameraTarget::Refused) {
            error(pos, quoteToken(commandText()) + " does not apply to the camera");
            return std::nullopt;
        }
        if (dot != std::string_view::npos) {
            Pos partPos = pos;  // the part itself, just after the dot
            partPos.column += static_cast<int>(dot) + 1;
            error(partPos, "the camera has no parts");
            return std::nullopt;
        }
        return Target{0, -1, true};
    }
    const std::optional<std::size_t> object =
        existing(text.substr(0, dot), text, pos, cameraUse != CameraTarget::Refused);
    if (!object) return std::nullopt;
    if (dot == std::string_view::npos) return Target{*object, -1};
    // Point at the part itself, just after the dot (of the token as written: "r{i}.head").
    const std::size_t writtenDot = argToken(i).written.find('.');
    Pos partPos = pos;
    partPos.column += static_cast<int>(writtenDot == std::string_view::npos ? dot : writtenDot) + 1;
    const std::string_view rest = text.substr(dot + 1);
    const std::size_t shapeDot = rest.find('.');
    const std::optional<int> part = partOf(*object, rest.substr(0, shapeDot), partPos);
    if (!part) return std::nullopt;
    if (shapeDot == std::string_view::npos) return Target{*object, *part};
    Pos shapePos = partPos;
    shapePos.column += static_cast<int>(shapeDot) + 1;
    shapePos.length = static_cast<int>(rest.size() - shapeDot - 1);
    const std::optional<int> shape = shapeOf(*object, *part, rest.substr(shapeDot + 1), shapePos);
    if (!shape) return std::nullopt;
    if (shapeUse == ShapeTarget::Refused) {
        error(shapePos, quoteToken(commandText()) + " does not apply to a shape: " + quoteToken(text) +
                            " is a shape, which takes looks and colour or visible keys only (its part is " +
                            quoteToken(text.substr(0, dot + 1 + shapeDot)) + ")");
        return std::nullopt;
    }
    Target t{*object, *part};
    t.shape = *shape;
    return t;
}

std::string SceneBuilder::targetName(Target t) const {
    if (t.camera) return std::string(kCameraName);
    if (t.light >= 0) return scene_.lightMotions[static_cast<std::size_t>(t.light)].name;
    const SceneObject& o = scene_.objects[t.object];
    std::string s = o.name;
    if (t.part >= 0) s += "." + o.model->parts[std::size_t(t.part)].name;
    if (t.shape >= 0) s += "." + o.model->shapes[std::size_t(t.shape)].name;
    return s;
}

Track& SceneBuilder::trackOf(Target t, TrackProperty property) {
    if (property == KeyProperty::Zoom) return scene_.camera.zoom;
    if (property == KeyProperty::Intensity) return lightMotion(t).intensity;
    if (property == KeyProperty::Colour) return scene_.colourTracks[targetTrackIndex(t, *property)].track;
    if (property == KeyProperty::Visible)
        return scene_.visibilityTracks[targetTrackIndex(t, *property)].track;
    if (t.camera) return scene_.camera.track;
    if (t.light >= 0) return lightMotion(t).track;
    SceneObject& o = scene_.objects[t.object];
    return t.part < 0 ? o.track : o.partTracks[static_cast<std::size_t>(t.part)];
}

std::size_t SceneBuilder::targetTrackIndex(Target t, KeyProperty property) {
    const bool visible = property == KeyProperty::Visible;
    auto [it, added] = (visible ? visibilityTrackIndex_ : colourTrackIndex_).try_emplace(slotOf(t), 0);
    if (added) {
        std::vector<TargetTrack>& tracks = visible ? scene_.visibilityTracks : scene_.colourTracks;
        it->second = tracks.size();
        Track track;
        if (visible) track.interpolation = Interpolation::Step;  // always a step (SPEC 10.7)
        tracks.push_back({FrameRef{static_cast<std::uint32_t>(t.object), t.part}, t.shape, track});
        (visible ? visibilityTrackBooks_ : colourTrackBooks_).push_back(-1);
    }
    return it->second;
}

}  // namespace f2::parsing
