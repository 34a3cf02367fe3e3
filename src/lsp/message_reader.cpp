#include "lsp/message_reader.h"

#include <algorithm>
#include <charconv>
#include <optional>

namespace f2::lsp {

namespace {

constexpr std::string_view kHeaderEnd = "\r\n\r\n";
constexpr std::string_view kLengthField = "content-length:";
/// The header fields the protocol defines; a header block starts with one.
constexpr std::string_view kFields[] = {kLengthField, "content-type:"};

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const char x = a[i] >= 'A' && a[i] <= 'Z' ? char(a[i] - 'A' + 'a') : a[i];
        if (x != b[i]) return false;
    }
    return true;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

/// Whether `bytes` starts with a header field name the protocol defines
/// (`complete`), or is a beginning of one that more bytes may complete.
enum class FieldStart { No, Partial, Complete };
FieldStart fieldStart(std::string_view bytes) {
    for (const std::string_view field : kFields) {
        if (bytes.size() >= field.size()) {
            if (equalsIgnoringCase(bytes.substr(0, field.size()), field)) return FieldStart::Complete;
        } else if (equalsIgnoringCase(bytes, field.substr(0, bytes.size()))) {
            return FieldStart::Partial;
        }
    }
    return FieldStart::No;
}

/// Bytes before the first place where a header can start (every byte when there is none).
std::size_t bytesBeforeHeader(std::string_view bytes) {
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        if ((bytes[i] == 'c' || bytes[i] == 'C') && fieldStart(bytes.substr(i)) != FieldStart::No) return i;
    }
    return bytes.size();
}

}  // namespace

void MessageReader::feed(std::string_view bytes) {
    // Drop the consumed prefix before it grows large.
    if (start_ > 0 && start_ >= buffer_.size() / 2) {
        buffer_.erase(0, start_);
        start_ = 0;
    }
    if (skipBytes_ > 0) {
        const std::size_t dropped = std::min(skipBytes_, bytes.size());
        skipBytes_ -= dropped;
        bytes.remove_prefix(dropped);
    }
    buffer_.append(bytes);
}

bool MessageReader::next(Item& item) {
    for (;;) {
        if (skipBytes_ > 0) return false;
        const std::string_view pending = std::string_view(buffer_).substr(start_);
        if (inBody_) {
            if (pending.size() < bodyBytes_) return false;
            item = {Item::Kind::Body, std::string(pending.substr(0, bodyBytes_))};
            start_ += bodyBytes_;
            inBody_ = false;
            return true;
        }
        if (pending.empty()) return false;
        if (readHeader(item)) return true;  // a problem to report
        if (!inBody_) return false;         // the header is not complete yet
    }
}

/// Reads one header block. Returns true with a problem in `item`, or false
/// with inBody_ set (a body follows) or clear (more bytes are needed).
bool MessageReader::readHeader(Item& item) {
    std::string_view header;
    for (;;) {
        std::string_view pending = std::string_view(buffer_).substr(start_);
        // Resynchronise: bytes before a header field (a stray byte or line
        // after the last body) are garbage. They are counted, and reported once
        // the next header starts or when they reach kMaxHeaderBytes.
        const std::size_t garbage = bytesBeforeHeader(pending);
        start_ += garbage;
        garbageBytes_ += garbage;
        pending.remove_prefix(garbage);
        const bool complete = fieldStart(pending) == FieldStart::Complete;
        if (garbageBytes_ > 0 && (complete || garbageBytes_ >= kMaxHeaderBytes)) {
            item = {Item::Kind::Problem, "dropped " + std::to_string(garbageBytes_) +
                                             (garbageBytes_ == 1 ? " stray byte" : " stray bytes") +
                                             " (not a message header)"};
            garbageBytes_ = 0;
            return true;
        }
        if (!complete) return false;  // more bytes are needed
        const std::size_t end = pending.substr(0, kMaxHeaderBytes + kHeaderEnd.size()).find(kHeaderEnd);
        if (end != std::string_view::npos) {
            header = pending.substr(0, end);
            start_ += end + kHeaderEnd.size();
            break;
        }
        if (pending.size() < kMaxHeaderBytes + kHeaderEnd.size()) return false;  // it may still end
        // No end within the limit: not a header. Look for one after its first byte.
        ++start_;
        ++garbageBytes_;
    }
    std::optional<std::size_t> length;
    std::size_t lineStart = 0;
    while (lineStart <= header.size()) {
        std::size_t lineEnd = header.find("\r\n", lineStart);
        if (lineEnd == std::string_view::npos) lineEnd = header.size();
        const std::string_view line = header.substr(lineStart, lineEnd - lineStart);
        lineStart = lineEnd + 2;
        const std::size_t colon = line.find(':');
        if (colon == std::string_view::npos) continue;
        if (!equalsIgnoringCase(line.substr(0, colon + 1), kLengthField)) continue;
        const std::string_view value = trim(line.substr(colon + 1));
        std::size_t n = 0;
        const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
        if (ec != std::errc() || ptr != value.data() + value.size() || value.empty()) {
            item = {Item::Kind::Problem, "bad Content-Length '" + std::string(value.substr(0, 40)) + "'"};
            return true;
        }
        length = n;
    }
    if (!length) {
        item = {Item::Kind::Problem, "a message header without Content-Length"};
        return true;
    }
    if (*length > kMaxBodyBytes) {
        const std::size_t available = buffer_.size() - start_;
        const std::size_t dropped = std::min(available, *length);
        start_ += dropped;
        skipBytes_ = *length - dropped;
        item = {Item::Kind::Problem, "skipped a message of " + std::to_string(*length) +
                                         " bytes, more than the limit of " + std::to_string(kMaxBodyBytes)};
        return true;
    }
    bodyBytes_ = *length;
    inBody_ = true;
    return false;
}

std::string frameMessage(std::string_view body) {
    std::string out = "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n";
    out.append(body);
    return out;
}

}  // namespace f2::lsp
