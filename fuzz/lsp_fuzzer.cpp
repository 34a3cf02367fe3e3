// libFuzzer target over the language server's message handling (`f2 lsp`).
// The first byte picks a mode:
//  - even: the rest is a byte stream of JSON-RPC frames (random, truncated,
//    with bad headers), cut into chunks and fed to the framing reader; every
//    body goes to an initialized server;
//  - odd: the rest is a scene (up to the first NUL byte) opened as two
//    documents (scene.f2 and part.f2, so includes between open documents
//    and include cycles are exercised), then each of up to 8 following byte pairs is a position at which
//    every feature is asked (completion, hover, definition, references, rename, symbols, folding, formatting)
//    and an edit is applied there.
//
// Invariants checked (a violation aborts, so libFuzzer keeps the input):
//  - Server::handle never throws;
//  - every reply is a JSON object with "jsonrpc": "2.0" and either an id with
//    a result or an error, or a method (a notification);
//  - a request with an integer id gets exactly one reply with that id.
//
// Build: cmake --preset fuzz && cmake --build --preset fuzz --target f2_lsp_fuzzer
// Run:   F2_FUZZ_TARGET=lsp fuzz/run.sh SECONDS
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "lsp/message_reader.h"
#include "lsp/protocol.h"
#include "lsp/server.h"

namespace {

using f2::lsp::Json;

[[noreturn]] void fail(const char* what, const std::string& detail) {
    std::fprintf(stderr, "f2 lsp fuzz invariant broken: %s\n%.2000s\n", what, detail.c_str());
    std::abort();
}

/// Checks the replies to one message; returns how many carry `id`.
int checkReplies(const std::vector<std::string>& replies, long long id) {
    int withId = 0;
    for (const std::string& reply : replies) {
        const Json j = Json::parse(reply, nullptr, false);
        if (j.is_discarded() || !j.is_object()) fail("a reply is not a JSON object", reply);
        if (j.value("jsonrpc", "") != "2.0") fail("a reply without jsonrpc 2.0", reply);
        const bool isResponse = j.contains("id") && (j.contains("result") || j.contains("error"));
        if (!isResponse && !j.contains("method"))
            fail("a reply that is neither a response nor a notification", reply);
        if (isResponse && j["id"].is_number_integer() && j["id"].get<long long>() == id) ++withId;
    }
    return withId;
}

std::vector<std::string> handle(f2::lsp::Server& server, std::string_view body) {
    try {
        return server.handle(body);
    } catch (const std::exception& e) {
        fail("Server::handle threw", e.what());
    } catch (...) {
        fail("Server::handle threw a non-standard exception", std::string(body));
    }
}

void request(f2::lsp::Server& server, long long id, const std::string& method, Json params) {
    const Json message = {{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", std::move(params)}};
    if (checkReplies(handle(server, f2::lsp::dumpJson(message)), id) != 1) {
        fail("a request did not get exactly one reply", message.dump());
    }
}

void notify(f2::lsp::Server& server, const std::string& method, Json params) {
    const Json message = {{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}};
    checkReplies(handle(server, f2::lsp::dumpJson(message)), -1);
}

void streamMode(f2::lsp::Server& server, std::string_view bytes) {
    f2::lsp::MessageReader reader;
    // Chunk sizes come from the bytes themselves, so frames are cut anywhere.
    std::size_t i = 0;
    while (i < bytes.size()) {
        const std::size_t chunk = 1 + static_cast<unsigned char>(bytes[i]) % 97;
        reader.feed(bytes.substr(i, chunk));
        i += chunk;
        f2::lsp::MessageReader::Item item;
        while (reader.next(item)) {
            if (item.kind == f2::lsp::MessageReader::Item::Kind::Body)
                checkReplies(handle(server, item.text), -1);
        }
    }
}

void documentMode(f2::lsp::Server& server, std::string_view bytes) {
    const std::size_t nul = bytes.find('\0');
    // JSON strings must be UTF-8: invalid bytes become U+FFFD, as an editor sends them.
    const std::string text =
        Json(std::string(bytes.substr(0, nul))).dump(-1, ' ', false, Json::error_handler_t::replace);
    const Json textJson = Json::parse(text);
    const std::string uri = "file:///fuzz/scene.f2";
    // The same text open a second time as part.f2 (not on disk): `/include
    // part.f2` then reads an open document, which includes itself (a cycle
    // through the server's open texts) and makes scene.f2 its scene.
    for (const char* name : {"file:///fuzz/part.f2", "file:///fuzz/scene.f2"}) {
        notify(server, "textDocument/didOpen",
               {{"textDocument", {{"uri", name}, {"languageId", "f2"}, {"version", 1}, {"text", textJson}}}});
    }
    if (nul == std::string_view::npos) return;
    const std::string_view positions = bytes.substr(nul + 1);
    long long id = 10;
    for (std::size_t k = 0; k + 1 < positions.size() && k < 16; k += 2) {
        // Lines and characters around and beyond the text, negative ones included.
        const int line = static_cast<signed char>(positions[k]) / 4;
        const int character = static_cast<signed char>(positions[k + 1]);
        const Json at = {{"textDocument", {{"uri", uri}}},
                         {"position", {{"line", line}, {"character", character}}}};
        for (const char* method : {"textDocument/completion", "textDocument/hover", "textDocument/definition",
                                   "textDocument/references", "textDocument/prepareRename"}) {
            request(server, ++id, method, at);
        }
        Json renameParams = at;
        renameParams["newName"] = "x" + std::to_string(k);
        request(server, ++id, "textDocument/rename", renameParams);
        // An edit at that place, then the whole-document features.
        const Json range = {{"start", {{"line", line}, {"character", character}}},
                            {"end", {{"line", line + (character & 1)}, {"character", 0}}}};
        notify(server, "textDocument/didChange",
               {{"textDocument", {{"uri", uri}, {"version", 2 + static_cast<int>(k)}}},
                {"contentChanges",
                 Json::array({{{"range", range}, {"text", std::string(1, positions[k] & 0x7F)}}})}});
        const Json doc = {{"textDocument", {{"uri", uri}}}};
        for (const char* method :
             {"textDocument/documentSymbol", "textDocument/foldingRange", "textDocument/formatting"}) {
            request(server, ++id, method, doc);
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
    f2::lsp::Server server;
    request(server, 1, "initialize", Json::object());
    if (data[0] % 2 == 0) {
        streamMode(server, bytes);
    } else {
        documentMode(server, bytes);
    }
    return 0;
}
