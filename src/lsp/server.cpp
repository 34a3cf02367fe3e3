#include "lsp/server.h"

#include <algorithm>
#include <limits>
#include <set>

#include "lsp/features.h"

namespace f2::lsp {

namespace {

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

Server::Server(std::function<void(std::string_view)> log, Options options)
    : log_(std::move(log)),
      options_(std::move(options)),
      workspace_(options_.beforeAnalysis),
      worker_([this] { work(); }) {}

Server::~Server() {
    {
        const std::lock_guard lock(mutex_);
        stop_ = true;
    }
    changed_.notify_all();
    worker_.join();
}

void Server::logProblem(std::string_view problem) const {
    const std::lock_guard lock(logMutex_);
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
            dispatchNotification(method, params);
        } catch (const std::exception& e) {
            logProblem("notification '" + method + "' ignored: " + e.what());
        }
        if (!options_.notify) {
            // Synchronous: what the worker sends for it is returned.
            waitUntilIdle();
            const std::lock_guard lock(mutex_);
            out = std::move(outbox_);
            outbox_.clear();
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
    if (method == "textDocument/formatting") {
        // From the newest text, not the newest analysis: the edits must apply to what the client has.
        const auto it = texts_.find(uriOf(params));
        if (it == texts_.end()) throw RequestError(kInvalidParams, "the document is not open");
        Analysis current;
        current.uri = it->first;
        current.document = TextDocument(it->second.text, it->second.version);
        return formatKeys(current);
    }
    static const std::set<std::string, std::less<>> kOnDocuments = {
        "textDocument/completion",     "textDocument/hover",         "textDocument/definition",
        "textDocument/references",     "textDocument/prepareRename", "textDocument/rename",
        "textDocument/documentSymbol", "textDocument/foldingRange"};
    if (!kOnDocuments.contains(method))
        throw RequestError(kMethodNotFound, "unknown method '" + method + "'");
    // Held while the feature reads it: the worker may make a newer one meanwhile.
    const std::shared_ptr<const Analysis> a = document(params);
    if (method == "textDocument/documentSymbol") return documentSymbols(*a);
    if (method == "textDocument/foldingRange") return foldingRanges(*a);
    const Position at = positionOf(params);
    if (method == "textDocument/completion") return completion(*a, at);
    if (method == "textDocument/hover") return hover(*a, at);
    if (method == "textDocument/definition") return definition(*a, at);
    if (method == "textDocument/references") {
        bool withDeclaration = true;
        if (params.contains("context")) withDeclaration = params["context"].value("includeDeclaration", true);
        return references(*a, at, withDeclaration);
    }
    if (method == "textDocument/prepareRename") return prepareRename(*a, at);
    return rename(*a, at, params.at("newName").get<std::string>());
}

void Server::dispatchNotification(const std::string& method, const Json& params) {
    if (method == "exit") {
        exited_ = true;
        return;
    }
    if (!initialized_) return;  // the protocol says: drop notifications before initialize
    if (method == "textDocument/didOpen") {
        const Json& doc = params.at("textDocument");
        std::string uri = doc.at("uri").get<std::string>();
        Text& t = texts_[uri];
        t = {doc.at("text").get<std::string>(), intMember(doc, "version")};
        queue({Job::Kind::Text, std::move(uri), t.text, t.version});
    } else if (method == "textDocument/didChange") {
        std::string uri = uriOf(params);
        const auto it = texts_.find(uri);
        if (it == texts_.end()) throw RequestError(kInvalidParams, "a change of a document that is not open");
        std::string text = it->second.text;
        for (const Json& change : params.at("contentChanges")) text = applyChange(text, change);
        const int version = intMember(params.at("textDocument"), "version");
        it->second = {std::move(text), version};
        queue({Job::Kind::Text, std::move(uri), it->second.text, version});
    } else if (method == "textDocument/didClose") {
        std::string uri = uriOf(params);
        if (texts_.erase(uri) == 0) return;
        {
            // Requests on it fail from now on, whatever the worker is doing.
            const std::lock_guard lock(mutex_);
            finished_.erase(uri);
        }
        queue({Job::Kind::Close, std::move(uri), {}, 0});
    } else if (method == "textDocument/didSave") {
        // An included file may have changed: every open scene is read again.
        queue({Job::Kind::RefreshAll, {}, {}, 0});
    } else if (!method.starts_with("$/") && method != "initialized" &&
               method != "workspace/didChangeConfiguration") {
        logProblem("unknown notification '" + method + "' ignored");
    }
}

std::shared_ptr<const Analysis> Server::document(const Json& params) {
    const std::string uri = uriOf(params);
    if (!texts_.contains(uri)) throw RequestError(kInvalidParams, "the document is not open");
    std::unique_lock lock(mutex_);
    // Only a document never analysed yet is waited for: until its text queued
    // (and any newer one) has been through the worker.
    changed_.wait(lock, [&] { return finished_.contains(uri) || (!busy_ && !queuedAt_.contains(uri)); });
    const auto it = finished_.find(uri);
    if (it == finished_.end()) throw RequestError(kInternalError, "the document could not be analysed");
    return it->second;
}

void Server::queue(Job job) {
    {
        const std::lock_guard lock(mutex_);
        if (job.kind == Job::Kind::RefreshAll) {
            // One queued refresh reads everything anyway.
            if (!queued_.empty() && queued_.back().kind == Job::Kind::RefreshAll) return;
            queued_.push_back(std::move(job));
        } else if (const auto at = queuedAt_.find(job.uri); at != queuedAt_.end() &&
                                                            queued_[at->second].kind == Job::Kind::Text &&
                                                            job.kind == Job::Kind::Text) {
            // A newer text replaces the one not analysed yet, in its place.
            queued_[at->second] = std::move(job);
        } else {
            queuedAt_[job.uri] = queued_.size();
            queued_.push_back(std::move(job));
        }
    }
    changed_.notify_all();
}

void Server::waitUntilIdle() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return queued_.empty() && !busy_; });
}

void Server::send(std::vector<std::string> messages) {
    if (messages.empty()) return;
    if (options_.notify) {
        options_.notify(std::move(messages));
        return;
    }
    const std::lock_guard lock(mutex_);
    for (std::string& m : messages) outbox_.push_back(std::move(m));
}

// The worker. Each round takes every queued job at once (so texts typed
// while the previous round ran are analysed together, each document's newest
// only), runs them through the workspace without the lock, then, under the
// lock, keeps the analyses whose document has no newer job queued by now:
// those become what requests see and are published; the others are stale and
// dropped (the newer job analyses them again next round). The message thread
// never touches the workspace; the worker never touches texts_; they share
// only the queue, finished_, the outbox and the flags, under mutex_, and the
// immutable analyses (shared_ptr<const Analysis>).
void Server::work() {
    std::unique_lock lock(mutex_);
    for (;;) {
        changed_.wait(lock, [&] { return stop_ || !queued_.empty(); });
        if (stop_) return;
        std::deque<Job> jobs;
        jobs.swap(queued_);
        queuedAt_.clear();
        busy_ = true;
        lock.unlock();

        std::vector<std::string> out, analysed;
        std::set<std::string> seen;
        for (Job& job : jobs) {
            try {
                std::vector<std::string> uris;
                switch (job.kind) {
                    case Job::Kind::Text:
                        uris = workspace_.open(std::move(job.uri), std::move(job.text), job.version);
                        break;
                    case Job::Kind::Close:
                        uris = workspace_.close(job.uri, out);
                        break;
                    case Job::Kind::RefreshAll:
                        uris = workspace_.refreshAll();
                        break;
                }
                for (std::string& uri : uris) {
                    if (seen.insert(uri).second) analysed.push_back(std::move(uri));
                }
            } catch (const std::exception& e) {
                // Its document keeps its last analysis (or, never analysed, answers requests with an error).
                logProblem(std::string("an analysis failed: ") + e.what());
            }
        }

        std::vector<std::string> current;
        lock.lock();
        for (std::string& uri : analysed) {
            if (queuedAt_.contains(uri)) continue;  // stale: a newer text (or its closing) is queued
            std::shared_ptr<const Analysis> a = workspace_.analysis(uri);
            if (!a) continue;  // closed since
            finished_[uri] = std::move(a);
            current.push_back(std::move(uri));
        }
        lock.unlock();
        // Requests may see the new analyses before their diagnostics are out: never the other way round.
        try {
            for (const std::string& uri : current) workspace_.publish(uri, out);
        } catch (const std::exception& e) {
            logProblem(std::string("publishing diagnostics failed: ") + e.what());
        }
        send(std::move(out));
        lock.lock();
        busy_ = false;
        changed_.notify_all();
    }
}
}  // namespace f2::lsp
