#include "io/sequence_sink.h"

#include <filesystem>

#include "io/output_target.h"
#include "io/png_writer.h"

namespace f2 {

namespace {
constexpr std::size_t kWritesInFlight = 2;
}

PngSequenceSink::PngSequenceSink(FramePattern pattern, bool resume)
    : pattern_(std::move(pattern)), resume_(resume) {}

PngSequenceSink::~PngSequenceSink() { abandon(); }

std::string PngSequenceSink::fileName(std::int64_t frame) const { return pattern_.format(frame); }

bool PngSequenceSink::begin(const FrameFormat&, std::string&) {
    return true;
}  // directories come with their frames

bool PngSequenceSink::makeDirectoryOf(const std::string& path, std::string& error) {
    const std::filesystem::path dir = std::filesystem::path(path).parent_path();
    if (dir.empty() || dir.string() == lastDirectory_) return true;
    if (!createDirectoryOf(path, error)) return false;
    lastDirectory_ = dir.string();
    return true;
}

void PngSequenceSink::removeLeftoverTemporaries(const std::string& path) {
    const std::filesystem::path file(path);
    const std::filesystem::path dir = file.parent_path().empty() ? "." : file.parent_path();
    std::error_code ec;
    if (dir.string() != scannedDirectory_) {
        // One listing per directory: leftovers are few, the frames many.
        scannedDirectory_ = dir.string();
        leftoverNames_.clear();
        for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
            std::string name = it->path().filename().string();
            if (looksLikeTemporary(name)) leftoverNames_.push_back(std::move(name));
        }
    }
    const std::string target = file.filename().string();
    for (const std::string& name : leftoverNames_)
        if (isTemporaryOf(name, target)) std::filesystem::remove(dir / name, ec);
}

bool PngSequenceSink::alreadyDone(std::int64_t frame) {
    if (!resume_) return false;
    // Only this run's own frames: another shard's worker may be writing its
    // temporaries in the same directory right now.
    removeLeftoverTemporaries(fileName(frame));
    // Files appear only complete (temporary file, then rename): one that exists is a finished frame.
    std::error_code ec;
    if (!std::filesystem::exists(fileName(frame), ec)) return false;
    ++completed_;
    return true;
}

bool PngSequenceSink::collectOldest() {
    std::string e = writes_.front().get();
    writes_.pop_front();
    if (e.empty()) ++completed_;
    if (error_.empty()) error_ = e;
    return error_.empty();
}

bool PngSequenceSink::write(const Image& image, std::int64_t frame, std::string& error,
                            const std::atomic<bool>*) {
    const std::string path = fileName(frame);
    if (!error_.empty() || !makeDirectoryOf(path, error_) ||
        (writes_.size() >= kWritesInFlight && !collectOldest())) {
        error = error_;
        return false;
    }
    writes_.push_back(std::async(std::launch::async, [image, path] {
        std::string e;
        writePng(image, path, e);
        return e;
    }));
    return true;
}

bool PngSequenceSink::finish(std::string& error, const std::atomic<bool>*) {
    bool ok = true;
    while (!writes_.empty()) ok = collectOldest() && ok;
    if (!ok) error = error_;
    return ok;
}

void PngSequenceSink::abandon() {
    while (!writes_.empty()) collectOldest();
}

}  // namespace f2
