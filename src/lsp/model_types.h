#pragma once
/// The model types a document can name (SPEC 10.1): the scene's own `/model`
/// blocks as the parser indexed them, the robot and the human; and the
/// `/model` block around a line, read from the text so that it is known while
/// the block is still being written (the parser indexes a block at its `/end`).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/parse/symbol_index.h"
#include "core/scene/models.h"
#include "lsp/analysis.h"

namespace f2::lsp {

/// A model type and, for the scene's own, where its block is written.
struct KnownModel {
    const ModelType* type = nullptr;
    const IndexedModel* indexed = nullptr;  ///< null for the robot and the human: no line defines them
};

/// The type called `name`: the scene's first `/model` of that name, or the robot or the human.
std::optional<KnownModel> findModel(const Analysis& a, std::string_view name);
/// Where `type` (an instance's model) is written, or null for the robot and the human.
const IndexedModel* indexedModelOf(const Analysis& a, const ModelType* type);

/// The `/model` block a line of the document stands in, as its text has it up to that line.
struct ModelBlock {
    std::string type;                 ///< the word after `/model`
    int line = 0;                     ///< 0-based line of the `/model`
    std::vector<std::string> parts;   ///< the `/part` names declared above the line
    std::vector<std::string> shapes;  ///< the `part.shape` names created above the line
};
std::optional<ModelBlock> modelBlockAt(const TextDocument& doc, int line);

}  // namespace f2::lsp
