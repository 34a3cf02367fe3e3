#pragma once
/// "Did you mean" hints for mistyped commands, names and parts.
#include <cstddef>
#include <string_view>

namespace f2 {

struct ModelType;  // scene/models.h

/// Only short words get a hint: the edit distance costs O(n·m).
inline constexpr std::size_t kMaxSuggestLength = 32;

/// Levenshtein distance of two words of at most kMaxSuggestLength bytes.
std::size_t editDistance(std::string_view a, std::string_view b);

/// Finds, among candidates given one by one, the one a mistyped word most
/// likely meant: the same word in other letter case, else the nearest within
/// two edits (one for words of two or three letters, none for one letter, so
/// that "q" is not taken for "s"). Ties go to the first candidate considered.
class ClosestWord {
   public:
    explicit ClosestWord(std::string_view word) : word_(word) {}

    /// Considers one candidate; returns the work done (distance table cells,
    /// at least 1) so that a caller can bound the work of a hostile file.
    std::size_t consider(std::string_view candidate);

    /// The best candidate so far, or empty if none is close enough.
    std::string_view best() const { return best_; }

   private:
    std::string_view word_;
    std::string_view best_;
    std::size_t bestDistance_ = 0;
};

/// The part a mistyped or guessed part name most likely means ("Head" →
/// "head", "left_arm" → "lhand", "torso" → "body"), or empty.
std::string_view suggestPart(std::string_view word, const ModelType& model);

}  // namespace f2
