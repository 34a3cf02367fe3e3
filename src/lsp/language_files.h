#pragma once
/// Files generated from the language table (core/parse/language.h) for other
/// programs: the TextMate grammar of the editors and the fuzzer's dictionary
/// are written as templates whose word lists are `@f2:LIST@` placeholders,
/// filled here, so a new command or mode reaches them by regenerating
/// (scripts/generate-language-files.sh). `f2 language` prints them.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace f2::lsp {

/// The named word lists a template may use, e.g. "creating" = sphere, cylinder,
/// box, robot, human (commands without their '/'), "modes", "parts".
std::vector<std::string_view> languageListNames();
/// The words of list `name`, or nullopt if there is no such list.
std::optional<std::vector<std::string>> languageList(std::string_view name);

/// `text` with each `@f2:LIST@` replaced by the list's words as a regular
/// expression alternation (longest first, so `ease_in` is tried before `ease`)
/// and each line that is exactly `@f2:LIST:dict@` by one `"word"` line per
/// word (libFuzzer's dictionary format). An unknown list or an unclosed
/// placeholder is an error: `problem` says where ("LINE:COL: error: …"),
/// and the result is empty.
std::string fillLanguageTemplate(std::string_view text, std::string& problem);

/// Every command with its syntax and meaning, one block per command, for `f2 language`.
std::string languageSummary();

}  // namespace f2::lsp
