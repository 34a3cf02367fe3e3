#include <algorithm>
#include <cmath>

#include "core/parse/expression.h"
#include "core/parse/number.h"
#include "core/parse/quoted_text.h"
#include "core/parse/scene_builder.h"
#include "core/parse/suggest.h"
#include "core/parse/unusual_char.h"

namespace f2::parsing {

int SceneBuilder::sizeArgCount(ObjectKind kind) {
    return kind == ObjectKind::Sphere     ? 1
           : kind == ObjectKind::Cylinder ? 2
           : kind == ObjectKind::Box      ? 3
                                          : 0;
}

Vec3 SceneBuilder::primitiveSize(ObjectKind kind, int first, bool& ok) {
    static constexpr std::array<std::string_view, 3> kBoxWhat = {"side sx", "side sy", "side sz"};
    static constexpr std::array<std::string_view, 2> kCylinderWhat = {"radius", "height"};
    Vec3 size;
    for (int k = 0; k < sizeArgCount(kind); ++k) {
        const std::string_view what = kind == ObjectKind::Box ? kBoxWhat[static_cast<std::size_t>(k)]
                                                              : kCylinderWhat[static_cast<std::size_t>(k)];
        size[k] = positive(first + k, what, ok);
    }
    return size;
}

void SceneBuilder::parseObject(ObjectKind kind, const TypeBook* type) {
    const int sizeArgs = sizeArgCount(kind);
    const int withoutRotation = command(command_).counts.front();  // name, sizes, centre
    SceneObject object;
    object.kind = kind;
    if (type) makeInstance(object, type->type);
    // An instance's parameters start at the first word after its position.
    int options = argCount();
    if (type) {
        for (int i = withoutRotation; i < std::min(argCount(), kMaxStoredTokens - 1); ++i) {
            if (isWordArgument(i)) {
                options = i;
                break;
            }
        }
    }
    // After an error about the whole line, a valid new name is still
    // registered with its kind, so later lines that use it do not add
    // "unknown name" errors. The error count caps how far this goes past
    // the object limit.
    const bool countOk = expectCounts(argCount() - options);
    const bool roomOk = scene_.objects.size() < limits_.maxObjects;
    if (countOk && !roomOk) {
        error(commandPos(), "too many objects: at most " + std::to_string(limits_.maxObjects) +
                                " allowed (a robot or human counts as one)");
    }
    if (!countOk || !roomOk) {
        if (argCount() >= 1 && isValidName(arg(0)) && !names_.contains(arg(0))) {
            addObject(std::move(object));
        }
        return;
    }

    bool ok = true;
    object.size = primitiveSize(kind, 1, ok);
    object.rest = pose(1 + sizeArgs, options == withoutRotation + 3, ok);
    const std::optional<std::vector<ModelParam>> params =
        type && options < argCount() ? instanceParams(*type->type, options) : std::nullopt;
    // A valid new name is registered even if other arguments are wrong, so
    // later lines that use it do not add "unknown name" errors.
    if (!newName(0)) return;
    ObjectLine line = objectLine();
    if (ok && params && !sameValues(*params, type->type->params)) {
        // The block read again with the instance's values; after an error in it, the type as defined.
        if (std::shared_ptr<const ModelType> own = readBlockFor(*type, *params, line))
            makeInstance(object, std::move(own));
    }
    addObject(std::move(object), std::move(line));
}

bool SceneBuilder::sameValues(const std::vector<ModelParam>& a, const std::vector<ModelParam>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const ModelParam& x, const ModelParam& y) { return x.value == y.value; });
}

std::uint32_t SceneBuilder::definitionLoopNote() {
    std::string note = expander_.loopNote();
    if (note.empty()) return 0;
    note = note.substr(2, note.size() - 3);  // " (in … )" -> "in …"
    if (loopNotes_.empty() || loopNotes_.back() != note) loopNotes_.push_back(std::move(note));
    return static_cast<std::uint32_t>(loopNotes_.size());
}

void SceneBuilder::addObject(SceneObject object, ObjectLine line) {
    object.name = std::move(line.name);
    names_.emplace(object.name, scene_.objects.size());
    if (index_) index_->objects.push_back({object, line.nameSpan, sourceLoc(line.command)});
    books_.push_back({line.namePos, std::nullopt, line.loopNote});
    scene_.objects.push_back(std::move(object));
}

void SceneBuilder::warnAboutTheWholeScene() {
    if (scene_.objects.empty()) {
        warning({1, 1}, "the scene has no objects: every frame shows only the background");
        return;
    }
    const auto keyedOn = [](const Track& t) {
        return std::any_of(t.keys.begin(), t.keys.end(), [](const Key& k) { return k.pose.position.x > 0; });
    };
    const bool lit = scene_.ambient > 0 ||
                     std::any_of(scene_.namedAmbients.begin(), scene_.namedAmbients.end(),
                                 [](const AmbientLight& l) { return l.intensity > 0; }) ||
                     std::any_of(scene_.lightMotions.begin(), scene_.lightMotions.end(),
                                 [&](const LightMotion& l) { return keyedOn(l.intensity); }) ||
                     std::any_of(scene_.lights.begin(), scene_.lights.end(),
                                 [](const DirectionalLight& l) { return l.intensity > 0; }) ||
                     std::any_of(scene_.localLights.begin(), scene_.localLights.end(),
                                 [](const LocalLight& l) { return l.intensity > 0; });
    if (!lit) {
        warning(books_.front().defined,
                "the scene has no light (no '/amb_light', '/dir_light', '/point_light' or "
                "'/spot_light' with an intensity > 0): every object renders black");
    }
}

SceneBuilder::LookTarget SceneBuilder::lookTarget(int i) {
    if (!building_) return {target(i, CameraTarget::Refused, LightTarget::Refused, ShapeTarget::Accepted)};
    const std::optional<int> shape = modelShapeArgument(i);
    return {std::nullopt, shape ? &building_->type->shapes[std::size_t(*shape)] : nullptr};
}

void SceneBuilder::parsePaint() {
    if (!expectCounts()) return;
    bool ok = true;
    const LookTarget t = lookTarget(0);
    const Color8 c = color(1, ok);
    if (!t || !ok) return;
    setLook(t, LookPart::Colour, [&](Appearance& a) { a.color = c; });
}

void SceneBuilder::parseMaterial() {
    // `emit e` (SPEC 10.8) ends the line when it is there. Only a line of
    // 7 or 8 arguments can hold it (and only so long a line has its
    // tokens stored: kMaxStoredTokens).
    const int n = argCount();
    const bool emits = (n == 7 || n == 8) && isWordArgument(n - 2) && arg(n - 2) == kEmitWord;
    if (n == 6 && isWordArgument(5) && arg(5) == kEmitWord) {
        error(argPos(5), "'emit' takes a number (the emission e >= 0)");
        return;
    }
    if (!expectCounts(emits ? 2 : 0)) return;
    bool ok = true;
    const LookTarget t = lookTarget(0);
    Material m;
    m.ka = nonNegative(1, "ka", ok);
    m.kd = nonNegative(2, "kd", ok);
    m.ks = nonNegative(3, "ks", ok);
    m.n = positive(4, "n", ok);
    if (n - (emits ? 2 : 0) == 6) m.reflection = nonNegative(5, "reflection", ok);
    if (emits) m.emission = nonNegative(n - 1, "emission", ok);
    if (!t || !ok) return;
    setLook(t, LookPart::Other, [&](Appearance& a) { a.material = m; });
}

void SceneBuilder::parseNoShadow() {
    if (!expectCounts()) return;
    const std::optional<Target> t =
        target(0, CameraTarget::Refused, LightTarget::Refused, ShapeTarget::Accepted);
    if (!t) return;
    setAppearance(*t, LookPart::Other, [](Appearance& a) { a.castsShadow = false; });
}

void SceneBuilder::parseChecker() {
    if (!expectCounts()) return;
    bool ok = true;
    const LookTarget t = lookTarget(0);
    Checker checker;
    checker.color = color(1, ok);
    checker.size = positive(4, "cell size", ok);
    if (!t || !ok) return;
    // A chequered colour is a colour: a shape painted in its model keeps its own.
    setLook(t, LookPart::Colour, [&](Appearance& a) { a.checker = checker; });
}

void SceneBuilder::parseCaption() {
    const int n = argCount();
    if (n != 6 && n != 10) {
        error(commandPos(), noteCharacters("'/caption' takes 6 or 10 arguments (from, to, x, y, size, "
                                           "\"text\", then optionally colour r g b), got " +
                                               std::to_string(n),
                                           commandLine(), commandPos()));
        return;
    }
    bool ok = true;
    const KeyTime from = keyTime(0, ok), to = keyTime(1, ok);
    Caption caption;
    caption.x = real(2, ok);
    caption.y = real(3, ok);
    caption.size = positive(4, "caption size", ok);
    if (ok && caption.size > 1) {
        error(argPos(4),
              "caption size is a fraction of the image height, at most 1, got " + printable(arg(4)));
        ok = false;
    }
    if (!failed(5)) {
        QuotedText text = readQuotedText(arg(5));
        if (text.ok) {
            caption.text = std::move(text.text);
        } else {
            // Columns inside the token hold as written unless `{ … }` changed it.
            const bool asWritten = argToken(5).written == argToken(5).text;
            Pos at = argPos(5);
            if (asWritten) at.column += static_cast<int>(text.offset);
            error(at, text.message);
            ok = false;
        }
    } else {
        ok = false;
    }
    if (n == 10) {
        if (arg(6) != "colour") {
            error(argPos(6), "expected 'colour' after the caption's text, got " + quoteToken(arg(6)));
            ok = false;
        } else {
            caption.colour = color(7, ok);
        }
    }
    if (!ok) return;
    caption.from = from.value;
    caption.to = to.value;
    scene_.captions.push_back(std::move(caption));
    captionBooks_.push_back({argPos(0), argPos(1), from.seconds, to.seconds});
}

}  // namespace f2::parsing
