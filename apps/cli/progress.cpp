#include "progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "test_pause.h"

namespace f2::cli {

Progress::Progress(int total, bool live) : total_(total), live_(live) {}

bool Progress::isInteractive() {
    const char* term = std::getenv("TERM");
    return ::isatty(STDERR_FILENO) && !(term && std::strcmp(term, "dumb") == 0);
}

double Progress::elapsedSeconds() const {
    return std::chrono::duration<double>(Clock::now() - start_).count();
}

double Progress::framesPerSecond() const {
    double s = elapsedSeconds();
    int rendered = done_ - skipped_;
    return s > 0 && rendered > 0 ? rendered / s : 0;
}

void Progress::update(int done, double partial) {
    done_ = done;
    if (partial == 0) pauseForTestAfter(done);  // every finished frame passes here, once
    if (!live_) return;
    auto now = Clock::now();
    // At most ~10 redraws a second: a terminal is slower than a small frame.
    if (done < total_ && now - lastDraw_ < std::chrono::milliseconds(100)) return;
    lastDraw_ = now;

    constexpr int kBarWidth = 24;
    const double progressed = done + partial;
    int filled = total_ > 0 ? int(std::lround(double(kBarWidth) * progressed / total_)) : kBarWidth;
    std::string bar(std::size_t(filled), '#');
    bar.resize(kBarWidth, '-');
    double fps = framesPerSecond();
    const double rate = elapsedSeconds() > 0 ? (progressed - skipped_) / elapsedSeconds() : 0;
    std::string left = rate > 0 ? formatDuration((total_ - progressed) / rate) + " left" : "";
    char line[160];
    int n = std::snprintf(line, sizeof line, "\r[%s] %d/%d frames  %.1f fps  %s", bar.c_str(), done, total_,
                          fps, left.c_str());
    std::size_t width = n > 0 ? std::size_t(n) : 0;
    // Blank out what is left of a longer previous line.
    std::string pad(drawnWidth_ > width ? drawnWidth_ - width : 0, ' ');
    std::fprintf(stderr, "%s%s", line, pad.c_str());
    std::fflush(stderr);
    drawnWidth_ = width;
}

void Progress::clear() {
    if (!live_ || drawnWidth_ == 0) return;
    std::fprintf(stderr, "\r%*s\r", int(drawnWidth_), "");
    std::fflush(stderr);
    drawnWidth_ = 0;
}

std::string Progress::summary() const {
    return formatMilliseconds(elapsedSeconds() * 1000) + ", " + threeSignificantDigits(framesPerSecond()) +
           " frames/s";
}

std::string formatDuration(double seconds) {
    long s = std::lround(std::max(0.0, seconds));
    char text[32];
    if (s >= 3600)
        std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    else
        std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
    return text;
}

std::string threeSignificantDigits(double value) {
    char text[64];
    // Rounded first, so that 9.996 counts as 10.0, not 10.00; beyond 100 a whole number, never 1.23e+04.
    std::snprintf(text, sizeof text, "%.3g", value);
    const double rounded = std::strtod(text, nullptr);
    const int decimals =
        rounded > 0 && rounded < 100 ? std::min(6, 2 - int(std::floor(std::log10(rounded)))) : 0;
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

std::string formatMilliseconds(double ms) {
    return ms >= 999.5 ? threeSignificantDigits(ms / 1000) + " s" : threeSignificantDigits(ms) + " ms";
}

}  // namespace f2::cli
