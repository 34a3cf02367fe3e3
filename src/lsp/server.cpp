#include "lsp/server.h"

#include <algorithm>
#include <limits>

#include "lsp/features.h"

namespace f2::lsp {

namespace {

std::string notification(std::string_view method, Json params) {
    return dumpJson({{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}});
}

std::string response(const Json& id, Json result) {
    return dumpJson({{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}});
}

std::string errorResponse(const Json& id, int code, std::string_view message) {
    return dumpJson({{"jsonrpc", "2.0"}, {"id", id}, {"error", {{"code", code}, {"message", message}}}});
}

/// True when arrays and objects in `json` nest deeper than `limit` (brackets
/// inside strings do not count). Linear and allocation-free, so it can run
/// before the parser on any body a client sends.
bool nestsDeeperThan(std::string_view json, int limit) {
    int depth = 0;
    bool inString = false;
    for (std::size_t i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (inString) {
            if (c == '\\') {
                ++i;  // the escaped character, a quote included
            } else if (c == '"') {
                inString = false;
            }
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > limit) return true;
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return false;
}

/// A member that must be an integer in the range of int (a float or a huge
/// number from a client is an invalid parameter, not undefined behaviour).
int intMember(const Json& object, std::string_view key) {
    const Json& v = object.at(key);
    if (v.is_number_unsigned()) {
        if (v.get<std::uint64_t>() > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
            throw RequestError(kInvalidParams, "'" + std::string(key) + "' is out of range");
        }
        return static_cast<int>(v.get<std::uint64_t>());
    }
    if (v.is_number_integer()) {
        const auto n = v.get<std::int64_t>();
        if (n < std::numeric_limits<int>::min() || n > std::numeric_limits<int>::max()) {
            throw RequestError(kInvalidParams, "'" + std::string(key) + "' is out of range");
        }
        return static_cast<int>(n);
    }
    throw RequestError(kInvalidParams, "'" + std::string(key) + "' must be an integer");
}

Position positionOf(const Json& params) {
    const Json& p = params.at("position");
    return {intMember(p, "line"), intMember(p, "character")};
}

std::string uriOf(const Json& params) { return params.at("textDocument").at("uri").get<std::string>(); }

Json capabilities() {
    return {
        {"positionEncoding", "utf-16"},
        {"textDocumentSync", {{"openClose", true}, {"change", 1}, {"save", {{"includeText", false}}}}},
        {"completionProvider", {{"triggerCharacters", {".", "/"}}}},
        {"hoverProvider", true},
        {"definitionProvider", true},
        {"referencesProvider", true},
        {"renameProvider", {{"prepareProvider", true}}},
        {"documentSymbolProvider", true},
        {"foldingRangeProvider", true},
        {"documentFormattingProvider", true},
    };
}

/// Byte offset in `text` of an LSP position (clamped to the text).
std::size_t offsetOf(const TextDocument& doc, const Position& p) {
    if (p.line < 0) return 0;
    if (p.line >= doc.lineCount()) return doc.text().size();
    const std::string_view line = doc.line(p.line);
    const auto lineStart = static_cast<std::size_t>(line.data() - doc.text().data());
    return lineStart + byteOffsetOfUtf16(line, std::max(p.character, 0));
}

}  // namespace

std::string applyChange(const std::string& text, const Json& change) {
    std::string newText = change.at("text").get<std::string>();
    if (!change.contains("range")) return newText;
    const Json& range = change.at("range");
    const TextDocument doc(text, 0);
    const Position start{intMember(range.at("start"), "line"), intMember(range.at("start"), "character")};
    const Position end{intMember(range.at("end"), "line"), intMember(range.at("end"), "character")};
    const std::size_t from = offsetOf(doc, start), to = offsetOf(doc, end);
    if (to < from) throw RequestError(kInvalidParams, "a change whose range ends before it starts");
    return text.substr(0, from) + newText + text.substr(to);
}

Server::Server(std::function<void(std::string_view)> log) : log_(std::move(log)) {}

void Server::logProblem(std::string_view problem) const {
    if (log_) log_(problem);
}

std::vector<std::string> Server::handle(std::string_view body) {
    std::vector<std::string> out;
    if (nestsDeeperThan(body, kMaxJsonDepth)) {
        out.push_back(errorResponse(
            nullptr, kParseError,
            "the message nests arrays and objects deeper than " + std::to_string(kMaxJsonDepth) + " levels"));
        return out;
    }
    const Json message = Json::parse(body, nullptr, /*allow_exceptions=*/false);
    if (message.is_discarded()) {
        out.push_back(errorResponse(nullptr, kParseError, "the message is not valid JSON"));
        return out;
    }
    if (!message.is_object() || !message.contains("method") || !message["method"].is_string()) {
        // A response to a request of ours (we send none) or garbage.
        if (message.is_object() && (message.contains("result") || message.contains("error"))) return out;
        out.push_back(errorResponse(message.is_object() && message.contains("id") ? message["id"] : Json(),
                                    kInvalidRequest, "not a JSON-RPC request or notification"));
        return out;
    }
    const std::string method = message["method"].get<std::string>();
    const Json params = message.contains("params") ? message["params"] : Json::object();

    if (!message.contains("id")) {
        try {
            dispatchNotification(method, params, out);
        } catch (const std::exception& e) {
            logProblem("notification '" + method + "' ignored: " + e.what());
        }
        return out;
    }
    const Json& id = message["id"];
    if (!id.is_string() && !id.is_number_integer()) {
        out.push_back(errorResponse(nullptr, kInvalidRequest, "a request id must be an integer or a string"));
        return out;
    }
    if (!initialized_ && method != "initialize") {
        out.push_back(errorResponse(id, kServerNotInitialized, "the server is not initialized yet"));
        return out;
    }
    if (shutdown_) {
        out.push_back(errorResponse(id, kInvalidRequest, "the server is shut down"));
        return out;
    }
    try {
        out.push_back(response(id, dispatchRequest(method, params)));
    } catch (const RequestError& e) {
        out.push_back(errorResponse(id, e.code, e.what()));
    } catch (const Json::exception& e) {
        out.push_back(errorResponse(id, kInvalidParams, std::string("invalid params: ") + e.what()));
    } catch (const std::exception& e) {
        out.push_back(errorResponse(id, kInternalError, e.what()));
    }
    return out;
}

Json Server::dispatchRequest(const std::string& method, const Json& params) {
    if (method == "initialize") {
        initialized_ = true;
        return {{"capabilities", capabilities()}, {"serverInfo", {{"name", "f2 lsp"}, {"version", "0.1.0"}}}};
    }
    if (method == "shutdown") {
        shutdown_ = true;
        return nullptr;
    }
    if (method == "textDocument/completion") return completion(document(params), positionOf(params));
    if (method == "textDocument/hover") return hover(document(params), positionOf(params));
    if (method == "textDocument/definition") return definition(document(params), positionOf(params));
    if (method == "textDocument/references") {
        bool withDeclaration = true;
        if (params.contains("context")) withDeclaration = params["context"].value("includeDeclaration", true);
        return references(document(params), positionOf(params), withDeclaration);
    }
    if (method == "textDocument/prepareRename") return prepareRename(document(params), positionOf(params));
    if (method == "textDocument/rename") {
        return rename(document(params), positionOf(params), params.at("newName").get<std::string>());
    }
    if (method == "textDocument/documentSymbol") return documentSymbols(document(params));
    if (method == "textDocument/foldingRange") return foldingRanges(document(params));
    if (method == "textDocument/formatting") return formatKeys(document(params));
    throw RequestError(kMethodNotFound, "unknown method '" + method + "'");
}

void Server::dispatchNotification(const std::string& method, const Json& params,
                                  std::vector<std::string>& out) {
    if (method == "exit") {
        exited_ = true;
        return;
    }
    if (!initialized_) return;  // the protocol says: drop notifications before initialize
    if (method == "textDocument/didOpen") {
        const Json& doc = params.at("textDocument");
        open(doc.at("uri").get<std::string>(), doc.at("text").get<std::string>(), intMember(doc, "version"),
             out);
    } else if (method == "textDocument/didChange") {
        const std::string uri = uriOf(params);
        const auto it = documents_.find(uri);
        if (it == documents_.end())
            throw RequestError(kInvalidParams, "a change of a document that is not open");
        std::string text = it->second.document.text();
        for (const Json& change : params.at("contentChanges")) text = applyChange(text, change);
        open(uri, std::move(text), intMember(params.at("textDocument"), "version"), out);
    } else if (method == "textDocument/didClose") {
        const std::string uri = uriOf(params);
        if (documents_.erase(uri) > 0) {
            roots_.erase(uri);
            out.push_back(notification("textDocument/publishDiagnostics",
                                       {{"uri", uri}, {"diagnostics", Json::array()}}));
            unpublishOthers(uri, {}, out);
            publishedOthers_.erase(uri);
            // Scenes that include it read it from disk again.
            refresh(pathFromUri(uri), out);
        }
    } else if (method == "textDocument/didSave") {
        // An included file may have changed: every open scene is read again.
        refresh({}, out);
    } else if (!method.starts_with("$/") && method != "initialized" &&
               method != "workspace/didChangeConfiguration") {
        logProblem("unknown notification '" + method + "' ignored");
    }
}

const Analysis& Server::document(const Json& params) const {
    const auto it = documents_.find(uriOf(params));
    if (it == documents_.end()) throw RequestError(kInvalidParams, "the document is not open");
    return it->second;
}

void Server::open(std::string uri, std::string text, int version, std::vector<std::string>& out) {
    const std::string path = pathFromUri(uri);
    documents_[uri].document = TextDocument(std::move(text), version);
    refresh(path, out);
}

SourceOverlay Server::openTexts() const {
    SourceOverlay texts;
    for (const auto& [uri, a] : documents_) texts[pathFromUri(uri)] = a.document.text();
    return texts;
}

std::string Server::rootOf(const std::string& uri,
                           const std::map<std::string, std::set<std::string>>& closures) const {
    // The documents that include it (and that it does not include: in a cycle
    // each is its own scene); of those, one that no other includes.
    const std::string path = pathFromUri(uri);
    const auto& own = closures.at(uri);
    std::vector<std::string> including;
    for (const auto& [other, files] : closures) {
        if (other != uri && files.contains(path) && !own.contains(pathFromUri(other)))
            including.push_back(other);
    }
    for (const std::string& candidate : including) {
        const std::string candidatePath = pathFromUri(candidate);
        const bool included = std::any_of(including.begin(), including.end(), [&](const std::string& o) {
            return o != candidate && closures.at(o).contains(candidatePath);
        });
        if (!included) return candidate;
    }
    return including.empty() ? uri : including.front();
}

void Server::refresh(const std::string& changed, std::vector<std::string>& out) {
    const SourceOverlay texts = openTexts();
    auto reanalyse = [&](const std::string& uri, const std::string& root) {
        Analysis& a = documents_[uri];
        a = analyze(uri, TextDocument(a.document.text(), a.document.version()), texts,
                    root == uri ? std::string() : pathFromUri(root));
        for (const auto& [other, unused] : documents_) a.openUris[pathFromUri(other)] = other;
        roots_[uri] = root;
    };
    std::set<std::string> done;
    // The changed document first, in its old scene: its includes may have changed.
    for (const auto& [uri, a] : documents_) {
        if (changed.empty() || pathFromUri(uri) != changed) continue;
        const auto old = roots_.find(uri);
        reanalyse(uri, old != roots_.end() && documents_.contains(old->second) ? old->second : uri);
        done.insert(uri);
    }
    // What each open document includes, followed through files on disk too.
    std::map<std::string, std::set<std::string>> closures;
    for (const auto& [uri, a] : documents_) {
        auto& files = closures[uri];
        for (std::size_t i = 0; i < a.sources.files.size(); ++i) {
            if (static_cast<int>(i) != a.self && a.sources.reaches(a.self, static_cast<int>(i)))
                files.insert(a.sources.files[i].path);
        }
    }
    std::vector<std::string> toPublish(done.begin(), done.end());
    for (const auto& [uri, a] : documents_) {
        const std::string root = rootOf(uri, closures);
        const auto old = roots_.find(uri);
        const bool moved = old == roots_.end() || old->second != root;
        const bool reads =
            changed.empty() || a.sources.find(changed) >= 0 ||
            std::find(a.result.files.begin(), a.result.files.end(), changed) != a.result.files.end();
        if (!moved && (!reads || done.contains(uri))) continue;
        reanalyse(uri, root);
        if (!done.contains(uri)) toPublish.push_back(uri);
    }
    for (const std::string& uri : toPublish) publish(documents_[uri], out);
}

void Server::publish(const Analysis& a, std::vector<std::string>& out) {
    std::set<std::string> others;
    for (Json& params : publishDiagnostics(a)) {
        const std::string uri = params["uri"].get<std::string>();
        if (uri != a.uri) {
            // An open document publishes its own (as the scene it belongs to reads it).
            if (documents_.contains(uri)) continue;
            others.insert(uri);
        }
        out.push_back(notification("textDocument/publishDiagnostics", std::move(params)));
    }
    unpublishOthers(a.uri, others, out);
    publishedOthers_[a.uri] = std::move(others);
}

void Server::unpublishOthers(const std::string& uri, const std::set<std::string>& keep,
                             std::vector<std::string>& out) {
    const auto it = publishedOthers_.find(uri);
    if (it == publishedOthers_.end()) return;
    // An include fixed or removed: its old errors must not stay on screen.
    for (const std::string& other : it->second) {
        if (keep.contains(other) || documents_.contains(other)) continue;
        out.push_back(notification("textDocument/publishDiagnostics",
                                   {{"uri", other}, {"diagnostics", Json::array()}}));
    }
}

}  // namespace f2::lsp
