#pragma once
/// JSON-RPC framing of the Language Server Protocol: `Content-Length: N`
/// headers, a blank line, then N bytes of JSON. Push-based, so the same code
/// reads standard input, test strings and fuzzer input.
#include <cstddef>
#include <string>
#include <string_view>

namespace f2::lsp {

/// Splits a byte stream into message bodies. A header block starts with a
/// field the protocol defines (`Content-Length:` or `Content-Type:`, in any
/// case); bytes before one (a stray byte or line between messages) are
/// dropped with a problem reported, so the reader resynchronises on the next
/// header. A header block that is invalid is dropped with a problem too.
class MessageReader {
   public:
    /// A body larger than this is skipped (its bytes are read and dropped).
    static constexpr std::size_t kMaxBodyBytes = std::size_t{64} << 20;
    /// A header block longer than this is garbage.
    static constexpr std::size_t kMaxHeaderBytes = 8192;

    struct Item {
        enum class Kind { Body, Problem } kind = Kind::Body;
        std::string text;  ///< the JSON body, or what was wrong
    };

    /// Appends bytes from the stream.
    void feed(std::string_view bytes);
    /// Takes the next complete body or problem; false when more bytes are needed.
    bool next(Item& item);

   private:
    bool readHeader(Item& item);

    std::string buffer_;
    std::size_t start_ = 0;      ///< consumed prefix of buffer_
    std::size_t bodyBytes_ = 0;  ///< length of the body being read
    bool inBody_ = false;
    std::size_t skipBytes_ = 0;     ///< bytes of an oversized body still to drop
    std::size_t garbageBytes_ = 0;  ///< bytes dropped before a header, not reported yet
};

/// A body with its header, ready to write.
std::string frameMessage(std::string_view body);

}  // namespace f2::lsp
