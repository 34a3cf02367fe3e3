#include "core/parse/suggest.h"

#include <algorithm>
#include <array>

#include "core/scene/models.h"

namespace f2 {

namespace {

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

bool equalIgnoringCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() &&
           std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) { return lower(x) == lower(y); });
}

/// Words people use for the robot's and the human's parts (SPEC 5), by the
/// part's index in the robot (whose names models.cpp defines), for any
/// model with a part of that name.
struct PartAlias {
    std::string_view word;
    int robotPart;
};

constexpr int kBody = 0, kLHand = 2, kRHand = 3;  // the robot's order of parts
constexpr std::array<PartAlias, 14> kPartAliases = {{
    {"torso", kBody},
    {"trunk", kBody},
    {"left", kLHand},
    {"larm", kLHand},
    {"leftarm", kLHand},
    {"left_arm", kLHand},
    {"lefthand", kLHand},
    {"left_hand", kLHand},
    {"right", kRHand},
    {"rarm", kRHand},
    {"rightarm", kRHand},
    {"right_arm", kRHand},
    {"righthand", kRHand},
    {"right_hand", kRHand},
}};

}  // namespace

std::size_t editDistance(std::string_view a, std::string_view b) {
    std::array<std::size_t, kMaxSuggestLength + 2> prev{}, cur{};
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t subst = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, subst});
        }
        prev = cur;
    }
    return prev[b.size()];
}

std::size_t ClosestWord::consider(std::string_view candidate) {
    if (word_.size() > kMaxSuggestLength || candidate.size() > kMaxSuggestLength) return 1;
    if (!best_.empty() && bestDistance_ == 0) return 1;  // nothing beats a case-only difference
    const std::size_t lengthGap =
        word_.size() > candidate.size() ? word_.size() - candidate.size() : candidate.size() - word_.size();
    // Edits in a short word soon make another word: "q" is not a typo of "s".
    const std::size_t allowed = word_.size() <= 1 ? 0 : word_.size() <= 3 ? 1 : 2;
    if (lengthGap > allowed) return 1;
    const std::size_t cost = 1 + word_.size() * candidate.size();
    const std::size_t distance = equalIgnoringCase(word_, candidate) ? 0 : editDistance(word_, candidate);
    if (distance <= allowed && (best_.empty() || distance < bestDistance_)) {
        best_ = candidate;
        bestDistance_ = distance;
    }
    return cost;
}

std::string_view suggestPart(std::string_view word, const ModelType& model) {
    for (const PartAlias& a : kPartAliases) {
        const std::string& part = robotModel()->parts[std::size_t(a.robotPart)].name;
        if (equalIgnoringCase(word, a.word) && model.partIndex(part) >= 0) return part;
    }
    ClosestWord closest(word);
    for (const ModelPart& part : model.parts) closest.consider(part.name);
    return closest.best();
}

}  // namespace f2
