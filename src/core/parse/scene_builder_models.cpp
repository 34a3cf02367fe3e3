#include <algorithm>
#include <cmath>

#include "core/parse/expression.h"
#include "core/parse/number.h"
#include "core/parse/quoted_text.h"
#include "core/parse/scene_builder.h"
#include "core/parse/suggest.h"
#include "core/parse/unusual_char.h"

namespace f2::parsing {

void SceneBuilder::openModel() {
    building_.emplace();
    building_->type = std::make_shared<ModelType>();
    building_->defined = commandPos();
    readModelHeader(*building_);
    // Errors from here on are in the block's lines ("no shapes" may follow from them).
    building_->errorsBefore = errors_;
}

void SceneBuilder::readModelHeader(ModelBuild& build) {
    // `/model <type> [<param> <default>]…` (SPEC 10.6): each default is
    // the parameter's value while the block is read here.
    if (argCount() == 0) {
        expectArgs({1});
        return;
    }
    // A parameter without its default is left out; the type is still defined.
    // (A line longer than the stored tokens is reported by modelParams.)
    if (argCount() % 2 == 0 && argCount() < kMaxStoredTokens) {
        error(argPos(argCount() - 1), "the parameter " + quoteToken(arg(argCount() - 1)) +
                                          " needs a default value: '/model <type> [<param> <default>]…'");
    }
    build.type->params = modelParams();
    if (failed(0)) return;
    const std::string_view name = arg(0);
    const Pos pos = argPos(0);
    if (!isValidName(name)) {
        error(pos, noteCharacters("invalid model type " + quoteToken(name) +
                                      " (expected a letter or '_', then letters, digits or '_')",
                                  name, pos));
        return;
    }
    const std::string slashed = "/" + std::string(name);
    if (const auto it = types_.find(name); it != types_.end()) {
        error(pos, it->second.defined ? "model type " + quoteToken(name) + " is already defined (at " +
                                            posText(*it->second.defined) + ")"
                                      : quoteToken(name) + " is a built-in model type ('" + slashed +
                                            "' makes one); choose another name");
        return;
    }
    if (findCommand(slashed) || name == kRootName || name == kCameraName) {
        error(pos, quoteToken(name) + " cannot name a model type: " +
                       (findCommand(slashed) ? "'" + slashed + "' is a command" : "it is a reserved word"));
        return;
    }
    if (types_.size() >= std::size_t(kMaxModelTypes)) {
        error(pos, "too many model types: at most " + std::to_string(kMaxModelTypes) +
                       " allowed (the robot and the human count)");
        return;
    }
    build.type->name = std::string(name);
    build.namePos = pos;
    build.named = true;
    start_ = expander_.lastModelBlock();
    build.indexed.name = span(pos, name);
    build.indexed.command = sourceLoc(commandPos());
}

std::vector<ModelParam> SceneBuilder::modelParams() {
    std::vector<ModelParam> params;
    // Only so many tokens of a line are stored (kMaxStoredTokens): the rest is an error.
    if (argCount() >= kMaxStoredTokens) {
        error(commandPos(), "too many parameters on one '/model' line: at most " +
                                std::to_string((kMaxStoredTokens - 2) / 2));
        return {};
    }
    for (int i = 1; i + 1 < argCount(); i += 2) {
        if (failed(i)) continue;
        const std::string_view name = arg(i);
        bool ok = true;
        const double value = real(i + 1, ok);
        if (!isValidName(name) || Variables::isPredefined(name)) {
            error(argPos(i),
                  noteCharacters(Variables::isPredefined(name)
                                     ? quoteToken(name) + " is a constant; a parameter cannot take "
                                                          "its name"
                                     : "invalid parameter name " + quoteToken(name) +
                                           " (expected a letter or '_', then letters, digits or "
                                           "'_')",
                                 name, argPos(i)));
            continue;
        }
        if (std::any_of(params.begin(), params.end(), [&](const ModelParam& p) { return p.name == name; })) {
            error(argPos(i), "the parameter " + quoteToken(name) + " is given twice");
            continue;
        }
        if (!ok) continue;
        params.push_back({std::string(name), value});
        expander_.setVariable(name, value);
    }
    return params;
}

std::optional<std::vector<ModelParam>> SceneBuilder::instanceParams(const ModelType& type, int first) {
    std::vector<ModelParam> values = type.params;
    std::vector<bool> given(values.size(), false);
    if (argCount() >= kMaxStoredTokens) {
        error(commandPos(), "too many arguments: an instance's line holds at most " +
                                std::to_string(kMaxStoredTokens - 1) + " (its parameters included)");
        return std::nullopt;
    }
    bool ok = true;
    for (int i = first; i < argCount(); i += 2) {
        if (failed(i)) {
            ok = false;
            continue;
        }
        const std::string_view word = arg(i);
        const auto it =
            std::find_if(values.begin(), values.end(), [&](const ModelParam& p) { return p.name == word; });
        if (it == values.end()) {
            std::string names;
            for (std::size_t k = 0; k < type.params.size(); ++k)
                names += (k > 0 ? (k + 1 == type.params.size() ? " and " : ", ") : "") + type.params[k].name;
            error(argPos(i), "unknown parameter " + quoteToken(word) + " of '" + type.name + "' (" +
                                 (names.empty() ? "it has no parameters" : "its parameters: " + names) + ")");
            ok = false;
            continue;
        }
        const std::size_t k = std::size_t(it - values.begin());
        if (given[k]) {
            error(argPos(i), "the parameter " + quoteToken(word) + " is given twice");
            ok = false;
            continue;
        }
        given[k] = true;
        if (i + 1 >= argCount()) {
            error(argPos(i), "the parameter " + quoteToken(word) + " needs a value");
            ok = false;
            continue;
        }
        it->value = real(i + 1, ok);
    }
    if (!ok) return std::nullopt;
    return values;
}

std::shared_ptr<const ModelType> SceneBuilder::readBlockFor(const TypeBook& book,
                                                            const std::vector<ModelParam>& values,
                                                            const ObjectLine& line) {
    expander_.replayModelBlock(book.start);
    for (const ModelParam& p : values) expander_.setVariable(p.name, p.value);
    building_.emplace();
    ModelBuild& build = *building_;
    build.type = std::make_shared<ModelType>();
    build.type->name = book.type->name;
    build.type->params = values;
    build.defined = build.namePos = *book.defined;
    build.errorsBefore = errors_;
    build.named = true;
    build.readFor = book.type;
    const std::string outerNote = std::move(instanceNote_);
    instanceNote_ = " (in /" + book.type->name + " " + line.name + ")";
    std::shared_ptr<const ModelType> read = build.type;
    const std::size_t errorsBefore = errors_;
    while (!stopped_ && building_ && expander_.next(tokens_)) parseLine();
    instanceNote_ = outerNote;
    return errors_ == errorsBefore ? read : nullptr;
}

bool SceneBuilder::sameNames(const ModelType& a, const ModelType& b) {
    if (a.parts.size() != b.parts.size() || a.shapes.size() != b.shapes.size()) return false;
    for (std::size_t k = 0; k < a.parts.size(); ++k)
        if (a.parts[k].name != b.parts[k].name || a.parts[k].parent != b.parts[k].parent) return false;
    for (std::size_t k = 0; k < a.shapes.size(); ++k)
        if (a.shapes[k].name != b.shapes[k].name || a.shapes[k].part != b.shapes[k].part) return false;
    return true;
}

void SceneBuilder::parseModelLine(std::string_view head) {
    ModelBuild& build = *building_;
    const CommandSpec* c = findCommand(head);
    if (c && c->id == CommandId::End) {
        if (build.nested > 0) {
            --build.nested;
            return;
        }
        return closeModel();
    }
    if (c && c->id == CommandId::Model) {
        error(commandPos(), "a '/model' cannot stand inside another (the block of " + modelText(build) +
                                " is open until its '/end')");
        ++build.nested;
        return;
    }
    if (build.nested > 0) return;  // the lines of a refused block
    if (!c) return unknownCommand(head);
    command_ = c->id;
    using enum CommandId;
    switch (c->id) {
        case Part:
            return parsePart();
        case Sphere:
            return parseModelShape(ShapeKind::Sphere, ObjectKind::Sphere);
        case Cylinder:
            return parseModelShape(ShapeKind::Cylinder, ObjectKind::Cylinder);
        case Box:
            return parseModelShape(ShapeKind::Box, ObjectKind::Box);
        case Paint:
            return parsePaint();
        case Material:
            return parseMaterial();
        case Checker:
            return parseChecker();
        default:
            error(commandPos(), quoteToken(head) +
                                    " cannot stand inside a '/model' block (only /part, "
                                    "/sphere, /cylinder, /box, /paint, /material, /checker, "
                                    "/let, /repeat and /include; the block of " +
                                    modelText(build) + " ends with '/end')");
    }
}

void SceneBuilder::parsePart() {
    ModelType& type = *building_->type;
    if (!expectCounts()) return;
    bool ok = true;
    ModelPart part;
    part.pivot = vec3(2, ok);
    const Vec3 rest = argCount() == 8 ? vec3(5, ok) : Vec3{};
    setRestRotation(part, rest);
    if (failed(0) || failed(1)) return;
    const std::string_view name = arg(0), parent = arg(1);
    if (!isValidName(name)) {
        error(argPos(0), noteCharacters("invalid part name " + quoteToken(name) +
                                            " (expected a letter or '_', then letters, digits or '_')",
                                        name, argPos(0)));
        return;
    }
    if (name == kRootName) {
        error(argPos(0),
              "'root' is the model's own frame, the parent of its first parts; a part cannot "
              "take the name");
        return;
    }
    if (type.partIndex(name) >= 0) {
        error(argPos(0), "duplicate part " + quoteToken(name) + " in " + modelText(*building_));
        return;
    }
    if (parent == kRootName) {
        part.parent = -1;
    } else if (const int index = type.partIndex(parent); index >= 0) {
        part.parent = index;
    } else {
        error(argPos(1), "unknown parent " + quoteToken(parent) +
                             " (expected 'root' or a part declared before this one" +
                             (type.parts.empty() ? std::string(")") : ": " + partList(type) + ")"));
        // Still declared (on the root), so that its shapes add no errors.
    }
    if (type.parts.size() >= std::size_t(kMaxModelParts)) {
        error(commandPos(), "too many parts: at most " + std::to_string(kMaxModelParts) + " in a model");
        return;
    }
    part.name = std::string(name);
    type.parts.push_back(std::move(part));
    building_->indexed.parts.push_back(span(argPos(0), name));
}

std::string SceneBuilder::unknownBlockPart(std::string_view part) const {
    const ModelType& type = *building_->type;
    return "unknown part " + quoteToken(part) + " of " + modelText(*building_) +
           (type.parts.empty() ? std::string(" (declare it with '/part' first)")
                               : " (expected " + partList(type) + ")");
}

std::optional<int> SceneBuilder::modelShapeArgument(int i) {
    if (failed(i)) return std::nullopt;
    const ModelType& type = *building_->type;
    const std::string_view text = arg(i);
    const std::size_t dot = text.find('.');
    if (dot == std::string_view::npos) {
        error(argPos(i), "inside '/model' " + quoteToken(commandText()) +
                             " takes a shape of the model, '<part>.<shape>', got " + quoteToken(text));
        return std::nullopt;
    }
    const int part = type.partIndex(text.substr(0, dot));
    if (part < 0) {
        error(argPos(i), unknownBlockPart(text.substr(0, dot)));
        return std::nullopt;
    }
    const int shape = type.shapeIndex(part, text.substr(dot + 1));
    if (shape < 0) {
        Pos shapePos = argPos(i);
        shapePos.column += static_cast<int>(dot) + 1;
        shapePos.length = static_cast<int>(text.size() - dot - 1);
        error(shapePos, "unknown shape " + quoteToken(text.substr(dot + 1)) + " on the part " +
                            quoteToken(text.substr(0, dot)) + " of " + modelText(*building_));
    }
    return shape < 0 ? std::nullopt : std::optional<int>(shape);
}

void SceneBuilder::parseModelShape(ShapeKind kind, ObjectKind sized) {
    ModelType& type = *building_->type;
    const int sizeArgs = sizeArgCount(sized), withoutRotation = command(command_).counts.front();
    if (!expectCounts()) return;
    bool ok = true;
    ModelShape shape;
    shape.kind = kind;
    shape.size = primitiveSize(sized, 1, ok);
    shape.centre = vec3(1 + sizeArgs, ok);
    setShapeRotation(shape, argCount() == withoutRotation + 3 ? vec3(4 + sizeArgs, ok) : Vec3{});
    if (failed(0)) return;
    const std::string_view text = arg(0);
    const std::size_t dot = text.find('.');
    const std::string_view partName = text.substr(0, dot);
    if (dot == std::string_view::npos || !isValidName(partName) || !isValidName(text.substr(dot + 1))) {
        error(argPos(0),
              noteCharacters("a shape of a model is named '<part>.<shape>', got " + quoteToken(text), text,
                             argPos(0)));
        return;
    }
    const std::string_view shapeName = text.substr(dot + 1);
    shape.part = type.partIndex(partName);
    if (shape.part < 0) {
        error(argPos(0), unknownBlockPart(partName));
        return;
    }
    if (type.shapeIndex(shape.part, shapeName) >= 0) {
        error(argPos(0), "duplicate shape " + quoteToken(text) + " in " + modelText(*building_));
        return;
    }
    if (type.shapes.size() >= std::size_t(kMaxModelShapes)) {
        error(commandPos(), "too many shapes: at most " + std::to_string(kMaxModelShapes) + " in a model");
        return;
    }
    if (!ok) return;
    shape.name = std::string(shapeName);
    type.shapes.push_back(std::move(shape));
    building_->indexed.shapes.push_back(span(argPos(0), text));
}

void SceneBuilder::closeModel() {
    ModelBuild build = std::move(*building_);
    building_.reset();
    if (argCount() > 0) error(argPos(0), "'/end' takes no arguments");
    if (build.readFor) {
        // (A line that failed already names fewer shapes: not said twice.)
        if (errors_ == build.errorsBefore && !sameNames(*build.type, *build.readFor)) {
            error(build.defined, "the parts and shapes of '" + build.type->name +
                                     "' must not depend on its parameters: with these values the "
                                     "block names other parts or shapes than with its defaults");
        }
        return;
    }
    if (build.type->shapes.empty() && errors_ == build.errorsBefore) {
        // "model 'm' has no shapes", or "the model has no shapes" when its name was refused.
        error(build.defined, (build.named ? "model " : "") + modelText(build) +
                                 " has no shapes (put a '/sphere', '/cylinder' or '/box' named "
                                 "'<part>.<shape>' on one of its parts)");
    }
    if (!build.named) return;
    // Registered even with an error inside, so its instances do not add
    // "unknown command" errors.
    const std::shared_ptr<const ModelType> type = build.type;
    types_.emplace(type->name, TypeBook{type, build.namePos, start_});
    scene_.models.push_back(type);
    if (index_) {
        build.indexed.type = type;
        index_->models.push_back(std::move(build.indexed));
    }
}

}  // namespace f2::parsing
