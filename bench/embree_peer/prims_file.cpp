#include "prims_file.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace f2::peer {

namespace {

struct Token {
    std::string text;
    int column;  ///< 1-based
};

/// Splits a line at spaces and tabs, up to a `#` comment.
std::vector<Token> tokenize(const std::string& line) {
    std::vector<Token> tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        char c = line[i];
        if (c == '#') break;
        if (c == ' ' || c == '\t' || c == '\r') {
            ++i;
            continue;
        }
        std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r' && line[i] != '#') ++i;
        tokens.push_back({line.substr(start, i - start), int(start) + 1});
    }
    return tokens;
}

/// Reads one line's records; throws nothing, reports through `fail`.
class LineReader {
   public:
    LineReader(const std::string& name, int line, const std::vector<Token>& tokens)
        : name_(name), line_(line), tokens_(tokens) {}

    bool expectCount(std::size_t count, std::string& error) const {
        if (tokens_.size() == count) return true;
        error = where(tokens_[0].column) + "'" + tokens_[0].text + "' takes " + std::to_string(count - 1) +
                " numbers, got " + std::to_string(tokens_.size() - 1);
        return false;
    }

    /// A finite float at token `i`.
    bool number(std::size_t i, float& value, std::string& error) const {
        const std::string& text = tokens_[i].text;
        auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (ec == std::errc() && end == text.data() + text.size() && std::isfinite(value)) return true;
        error = where(tokens_[i].column) + "expected a finite number, got '" + text + "'";
        return false;
    }

    /// A whole number in [lo, hi] at token `i`.
    bool integer(std::size_t i, int lo, int hi, int& value, std::string& error) const {
        float v;
        if (!number(i, v, error)) return false;
        if (v == std::floor(v) && v >= float(lo) && v <= float(hi)) {
            value = int(v);
            return true;
        }
        error = where(tokens_[i].column) + "expected a whole number from " + std::to_string(lo) + " to " +
                std::to_string(hi) + ", got '" + tokens_[i].text + "'";
        return false;
    }

    /// 12 numbers of a 3x4 matrix from token `first`.
    bool affine(std::size_t first, Affine& a, std::string& error) const {
        for (int k = 0; k < 12; ++k)
            if (!number(first + std::size_t(k), a.m[k / 4][k % 4], error)) return false;
        return true;
    }

    bool colour(std::size_t first, std::uint8_t rgb[3], std::string& error) const {
        for (int k = 0; k < 3; ++k) {
            int v;
            if (!integer(first + std::size_t(k), 0, 255, v, error)) return false;
            rgb[k] = std::uint8_t(v);
        }
        return true;
    }

    bool positive(std::size_t i, float& value, std::string& error) const {
        if (!number(i, value, error)) return false;
        if (value > 0) return true;
        error = where(tokens_[i].column) + "expected a number > 0, got '" + tokens_[i].text + "'";
        return false;
    }

    std::string where(int column) const {
        return name_ + ":" + std::to_string(line_) + ":" + std::to_string(column) + ": error: ";
    }

   private:
    const std::string& name_;
    int line_;
    const std::vector<Token>& tokens_;
};

bool readPrimitive(const LineReader& in, ShapeKind kind, PrimRecord& p, std::string& error) {
    // KIND R H SX SY SZ m00 .. m23 CR CG CB KA KD KS N
    if (!in.expectCount(25, error)) return false;
    p.kind = kind;
    bool sizesOk = true;
    switch (kind) {
        case ShapeKind::Sphere:
            sizesOk = in.positive(1, p.radius, error);
            break;
        case ShapeKind::Cylinder:
            sizesOk = in.positive(1, p.radius, error) && in.positive(2, p.height, error);
            break;
        case ShapeKind::Box:
            sizesOk = in.positive(3, p.sides[0], error) && in.positive(4, p.sides[1], error) &&
                      in.positive(5, p.sides[2], error);
            break;
    }
    if (!sizesOk) return false;
    // The unused size fields are 0 by the format; their values do not matter.
    float unused;
    for (std::size_t i = 1; i <= 5; ++i)
        if (!in.number(i, unused, error)) return false;
    return in.affine(6, p.worldFromLocal, error) && in.colour(18, p.rgb, error) &&
           in.number(21, p.ka, error) && in.number(22, p.kd, error) && in.number(23, p.ks, error) &&
           in.positive(24, p.shininess, error);
}

}  // namespace

bool parsePrims(const std::string& text, const std::string& name, PrimsFrame& frame, std::string& error) {
    frame = PrimsFrame{};
    std::istringstream lines(text);
    std::string line;
    bool haveCamera = false;
    for (int number = 1; std::getline(lines, line); ++number) {
        const std::vector<Token> tokens = tokenize(line);
        if (tokens.empty()) continue;
        LineReader in(name, number, tokens);
        const std::string& word = tokens[0].text;
        bool ok = true;
        if (word == "camera") {
            // camera W H D m00 .. m23
            ok = in.expectCount(16, error) && in.integer(1, 1, 16384, frame.width, error) &&
                 in.integer(2, 1, 16384, frame.height, error) && in.positive(3, frame.distance, error) &&
                 in.affine(4, frame.worldFromCamera, error);
            haveCamera = true;
        } else if (word == "background") {
            ok = in.expectCount(4, error) && in.colour(1, frame.background, error);
        } else if (word == "amb") {
            float intensity;
            ok = in.expectCount(2, error) && in.number(1, intensity, error);
            frame.ambient += intensity;
        } else if (word == "dir") {
            DirLight light;
            ok = in.expectCount(5, error) && in.number(1, light.intensity, error) &&
                 in.number(2, light.direction[0], error) && in.number(3, light.direction[1], error) &&
                 in.number(4, light.direction[2], error);
            if (ok && light.direction[0] == 0 && light.direction[1] == 0 && light.direction[2] == 0) {
                error = in.where(tokens[2].column) + "a light direction must not be zero";
                ok = false;
            }
            frame.lights.push_back(light);
        } else if (word == "sphere" || word == "cylinder" || word == "box") {
            PrimRecord p;
            ShapeKind kind = word == "sphere"     ? ShapeKind::Sphere
                             : word == "cylinder" ? ShapeKind::Cylinder
                                                  : ShapeKind::Box;
            ok = readPrimitive(in, kind, p, error);
            frame.prims.push_back(p);
        } else {
            error = in.where(tokens[0].column) + "unknown record '" + word +
                    "' (expected camera, background, amb, dir, sphere, cylinder or box)";
            ok = false;
        }
        if (!ok) return false;
    }
    if (!haveCamera) {
        error = name + ":1:1: error: no 'camera' line";
        return false;
    }
    return true;
}

bool readPrimsFile(const std::string& path, PrimsFrame& frame, std::string& error) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        error = path + ":1:1: error: cannot read the file";
        return false;
    }
    std::ostringstream text;
    text << file.rdbuf();
    return parsePrims(text.str(), path, frame, error);
}

}  // namespace f2::peer
