#pragma once
/// What the language server says about each command: its syntax, meaning,
/// a completion snippet and what each argument is (to complete it).
#include <span>
#include <string_view>
#include <vector>

namespace f2::lsp {

/// What an argument of a command holds, for completion and hover.
enum class ArgKind {
    Number,         ///< any number (or an expression)
    NewName,        ///< a name the command creates
    Target,         ///< `name` or `name.part` (or `camera` where the language allows)
    Object,         ///< an existing object's name
    Part,           ///< body, head, lhand or rhand
    Mode,           ///< an interpolation mode
    Variable,       ///< a variable's name
    Path,           ///< a file path
    PointOrTarget,  ///< /look_at: x y z, or a target
};

struct CommandDoc {
    std::string_view name;          ///< "/robot"
    std::string_view syntax;        ///< "/robot <name> <px> <py> <pz> [<rx> <ry> <rz>]"
    std::string_view snippet;       ///< LSP snippet of the whole command
    std::string_view meaning;       ///< a short explanation (Markdown)
    std::span<const ArgKind> args;  ///< argument kinds; the last repeats for further arguments
};

/// Every command the server documents, including the second edition's
/// (SPEC 9); completion offers only those the parser knows (commandNames()).
std::span<const CommandDoc> commandDocs();

/// The doc of a command, or nullptr.
const CommandDoc* findCommandDoc(std::string_view name);

/// The kind of argument `index` (0-based) of a command.
ArgKind argumentKind(const CommandDoc& doc, int index);

}  // namespace f2::lsp
