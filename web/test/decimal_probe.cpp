// Prints what core/util/decimal_text.h gives for a fixed set of inputs: edge
// cases and values from a seeded std::mt19937_64 (the same sequence on every
// platform). Built natively (the standard library's from_chars/to_chars) and
// for WebAssembly (the portable versions on musl's strtod and snprintf);
// tests/web compares the two outputs line by line.
#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

#include "core/util/decimal_text.h"

namespace {

void read(const std::string& text) {
    double value = 1234.5;  // unchanged on an error
    const f2::DecimalRead r = f2::readDecimal(text.data(), text.data() + text.size(), value);
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    if (std::isnan(value)) bits = std::signbit(value) ? 1 : 0;  // any NaN payload
    // By name: errno values differ between glibc and musl.
    const char* error = r.ec == std::errc{}                      ? "ok"
                        : r.ec == std::errc::invalid_argument    ? "invalid"
                        : r.ec == std::errc::result_out_of_range ? "out of range"
                                                                 : "other";
    std::printf("read '%s': %d %s %016" PRIx64 "\n", text.c_str(), int(r.ptr - text.data()), error, bits);
}

double doubleFrom(std::uint64_t bits) {
    double d;
    std::memcpy(&d, &bits, sizeof d);
    return d;
}

}  // namespace

int main() {
    for (const char* text : {"",
                             "-",
                             "+1",
                             ".",
                             ".5",
                             "5.",
                             "-0",
                             "0012.500",
                             "1e",
                             "1e+",
                             "1E-5",
                             "1.5x",
                             "1,5",
                             "inf",
                             "-Infinity",
                             "infin",
                             "nan",
                             "-nan",
                             "nan(12)",
                             "nan(",
                             "1e400",
                             "-1e-400",
                             "1e-310",
                             "4.9406564584124654e-324",
                             "2.4703282292062327e-324",
                             "1.7976931348623158e308",
                             "9007199254740993",
                             "0.1",
                             "1e23",
                             "1e9999999999999"})
        read(text);
    std::mt19937_64 random(2025);
    for (int i = 0; i < 20000; ++i) {
        const double value = doubleFrom(random());
        if (std::isnan(value)) continue;
        const std::string shortest = f2::shortestText(value);
        std::printf("shortest %s; general9 %s; float %s\n", shortest.c_str(),
                    f2::generalText(value, 9).c_str(), f2::shortestText(float(value)).c_str());
        read(shortest);
        read(f2::generalText(value, 1 + int(random() % 17)));
        std::string digits = random() % 4 == 0 ? "-" : "";
        const int count = 1 + int(random() % 25), point = int(random() % std::uint64_t(count + 2)) - 1;
        for (int d = 0; d < count; ++d) {
            if (d == point) digits += '.';
            digits += char('0' + random() % 10);
        }
        if (random() % 2) digits += "e" + std::to_string(int(random() % 700) - 350);
        read(digits);
        const double simple = double(random() % 100000) / double(1 + random() % 1000);
        std::printf("simple %s %s\n", f2::shortestText(simple).c_str(),
                    f2::shortestText(float(simple)).c_str());
    }
    return 0;
}
