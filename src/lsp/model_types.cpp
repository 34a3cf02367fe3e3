#include "lsp/model_types.h"

#include "core/parse/language.h"
#include "core/parse/lexer.h"

namespace f2::lsp {

std::optional<KnownModel> findModel(const Analysis& a, std::string_view name) {
    for (const IndexedModel& m : a.index.models) {
        if (m.type && m.type->name == name) return KnownModel{m.type.get(), &m};
    }
    for (const auto* builtIn : {&robotModel(), &humanModel()}) {
        if ((*builtIn)->name == name) return KnownModel{builtIn->get(), nullptr};
    }
    return std::nullopt;
}

const IndexedModel* indexedModelOf(const Analysis& a, const ModelType* type) {
    for (const IndexedModel& m : a.index.models) {
        if (m.type.get() == type) return &m;
    }
    return nullptr;
}

std::optional<ModelBlock> modelBlockAt(const TextDocument& doc, int line) {
    // Blocks open at `/model` and `/repeat` and close at `/end`: a `/repeat`
    // inside a model must not end it.
    std::vector<bool> open;  // true: a model
    std::optional<ModelBlock> block;
    LineTokens tokens;
    for (int i = 0; i < line && i < doc.lineCount(); ++i) {
        const std::string_view text = doc.line(i);
        if (text.find('/') == std::string_view::npos) continue;
        tokenizeLine(text, tokens);
        if (tokens.count == 0) continue;
        const CommandSpec* command = findCommand(tokens.tokens[0].text);
        if (!command) continue;
        const std::string_view first = tokens.count > 1 ? tokens.tokens[1].text : std::string_view{};
        if (command->id == CommandId::Model) {
            open.push_back(true);
            block = ModelBlock{std::string(first), i, {}, {}};
        } else if (command->id == CommandId::Repeat) {
            open.push_back(false);
        } else if (command->id == CommandId::End) {
            if (!open.empty() && open.back()) block.reset();
            if (!open.empty()) open.pop_back();
        } else if (block && command->id == CommandId::Part && !first.empty()) {
            block->parts.emplace_back(first);
        } else if (block && createsModelShape(command->id) && first.find('.') != std::string_view::npos) {
            block->shapes.emplace_back(first);
        }
    }
    return block;
}

}  // namespace f2::lsp
