#pragma once
/// JSON shapes of the Language Server Protocol used by the features, and the
/// error a request handler throws to answer with a JSON-RPC error.
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "lsp/text_document.h"

namespace f2::lsp {

using Json = nlohmann::json;

/// JSON-RPC and LSP error codes.
enum ErrorCode : int {
    kParseError = -32700,
    kInvalidRequest = -32600,
    kMethodNotFound = -32601,
    kInvalidParams = -32602,
    kInternalError = -32603,
    kServerNotInitialized = -32002,
    kRequestFailed = -32803,
};

/// Thrown by a request handler: the server answers with this error.
struct RequestError : std::runtime_error {
    RequestError(int code, const std::string& message) : std::runtime_error(message), code(code) {}
    int code;
};

inline Json toJson(const Position& p) { return {{"line", p.line}, {"character", p.character}}; }
inline Json toJson(const Range& r) { return {{"start", toJson(r.start)}, {"end", toJson(r.end)}}; }
inline Json location(const std::string& uri, const Range& r) { return {{"uri", uri}, {"range", toJson(r)}}; }

/// Serialises without throwing on invalid UTF-8 (it becomes U+FFFD).
inline std::string dumpJson(const Json& j) { return j.dump(-1, ' ', false, Json::error_handler_t::replace); }

// LSP enumerations used here.
inline constexpr int kSeverityError = 1, kSeverityWarning = 2;
inline constexpr int kCompletionKeyword = 14, kCompletionSnippet = 15, kCompletionVariable = 6,
                     kCompletionField = 5, kCompletionEnumMember = 20, kCompletionFile = 17,
                     kCompletionFunction = 3, kCompletionClass = 7, kCompletionProperty = 10;
inline constexpr int kSymbolFile = 1, kSymbolObject = 19, kSymbolField = 8, kSymbolEvent = 24,
                     kSymbolConstant = 14, kSymbolClass = 5;
inline constexpr int kInsertSnippet = 2;

}  // namespace f2::lsp
