#include "lsp/workspace.h"

#include <algorithm>

#include "lsp/features.h"

namespace f2::lsp {

std::string notification(std::string_view method, Json params) {
    return dumpJson({{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}});
}

Workspace::Workspace(std::function<void(const std::string&, int)> beforeAnalysis)
    : beforeAnalysis_(std::move(beforeAnalysis)), openUris_(std::make_shared<OpenUris>()) {}

std::vector<std::string> Workspace::open(std::string uri, std::string text, int version) {
    const std::string path = pathFromUri(uri);
    documents_[uri].text = TextDocument(std::move(text), version);
    urisByPath_[path].insert(uri);
    syncPath(path);
    return refresh(path, {});
}

std::vector<std::string> Workspace::refreshAll() { return refresh({}, {}); }

std::shared_ptr<const Analysis> Workspace::analysis(const std::string& uri) const {
    const auto it = documents_.find(uri);
    return it == documents_.end() ? nullptr : it->second.analysis;
}

std::vector<std::string> Workspace::close(const std::string& uri, std::vector<std::string>& out) {
    if (documents_.erase(uri) == 0) return {};
    const std::string path = pathFromUri(uri);
    roots_.erase(uri);
    // The documents its includes reached may belong to another scene now.
    const std::set<std::string> reached = unindex(uri);
    links_.erase(uri);
    if (auto it = urisByPath_.find(path); it != urisByPath_.end()) {
        it->second.erase(uri);
        if (it->second.empty()) urisByPath_.erase(it);
    }
    syncPath(path);
    out.push_back(
        notification("textDocument/publishDiagnostics", {{"uri", uri}, {"diagnostics", Json::array()}}));
    unpublishOthers(uri, {}, out);
    publishedOthers_.erase(uri);
    // Scenes that include it read it from disk again.
    return refresh(path, reached);
}

void Workspace::syncPath(const std::string& path) {
    const auto it = urisByPath_.find(path);
    if (it == urisByPath_.end()) {
        texts_.erase(path);
        openUris_->erase(path);
        return;
    }
    const std::string& uri = *it->second.rbegin();
    texts_[path] = documents_.at(uri).text.text();
    openUris_->set(path, uri);
}

void Workspace::addDocumentsOf(const std::set<std::string>& paths, std::set<std::string>& to) const {
    for (const std::string& path : paths) {
        if (const auto it = urisByPath_.find(path); it != urisByPath_.end())
            to.insert(it->second.begin(), it->second.end());
    }
}

std::set<std::string> Workspace::unindex(const std::string& uri) {
    const auto it = links_.find(uri);
    if (it == links_.end()) return {};
    auto forget = [&](std::map<std::string, std::set<std::string>>& reverse,
                      const std::set<std::string>& paths) {
        for (const std::string& path : paths) {
            const auto entry = reverse.find(path);
            if (entry == reverse.end()) continue;
            entry->second.erase(uri);
            if (entry->second.empty()) reverse.erase(entry);
        }
    };
    forget(includedBy_, it->second.includes);
    forget(readBy_, it->second.reads);
    Links old = std::move(it->second);
    it->second = {};
    return std::move(old.includes);
}

std::set<std::string> Workspace::index(const std::string& uri) {
    std::set<std::string> before = unindex(uri);
    const Analysis& a = *documents_.at(uri).analysis;
    Links& links = links_[uri];
    const std::vector<bool> reached = a.sources.reachableFrom(a.self);
    for (std::size_t i = 0; i < a.sources.files.size(); ++i) {
        const std::string& file = a.sources.files[i].path;
        if (file == a.path) continue;
        links.reads.insert(file);
        if (reached[i]) links.includes.insert(file);
    }
    for (const std::string& file : a.result.files) {
        if (file != a.path) links.reads.insert(file);
    }
    for (const std::string& file : links.includes) includedBy_[file].insert(uri);
    for (const std::string& file : links.reads) readBy_[file].insert(uri);
    return before;
}

void Workspace::reanalyse(const std::string& uri, const std::string& root) {
    Document& d = documents_.at(uri);
    if (beforeAnalysis_) beforeAnalysis_(uri, d.text.version());
    // A new analysis, never the old one changed: a reader may still hold that.
    auto a = std::make_shared<Analysis>(
        analyze(uri, d.text, texts_, root == uri ? std::string() : pathFromUri(root)));
    a->openUris = openUris_;
    d.analysis = std::move(a);
    roots_[uri] = root;
}

std::string Workspace::rootOf(const std::string& uri) const {
    // The documents that include it (and that it does not include: in a cycle
    // each is its own scene); of those, one that no other includes.
    const auto reaching = includedBy_.find(pathFromUri(uri));
    if (reaching == includedBy_.end()) return uri;
    const auto ownLinks = links_.find(uri);
    const std::set<std::string> none;
    const std::set<std::string>& own = ownLinks != links_.end() ? ownLinks->second.includes : none;
    std::vector<std::string> including;
    for (const std::string& other : reaching->second) {
        if (other != uri && !own.contains(pathFromUri(other))) including.push_back(other);
    }
    for (const std::string& candidate : including) {
        const std::string candidatePath = pathFromUri(candidate);
        const bool included = std::any_of(including.begin(), including.end(), [&](const std::string& o) {
            return o != candidate && links_.at(o).includes.contains(candidatePath);
        });
        if (!included) return candidate;
    }
    return including.empty() ? uri : including.front();
}

std::vector<std::string> Workspace::refresh(const std::string& changed,
                                            const std::set<std::string>& alsoMoved) {
    std::vector<std::string> first;  // the changed documents: published first
    std::set<std::string> done, check;
    // The documents whose scene read the changed file are read again.
    std::set<std::string> reading;
    if (changed.empty()) {
        for (const auto& [uri, a] : documents_) reading.insert(uri);
    } else if (const auto it = readBy_.find(changed); it != readBy_.end()) {
        reading = it->second;
    }
    check = reading;
    addDocumentsOf(alsoMoved, check);
    // The changed document first, in its old scene: its includes may have changed.
    if (const auto it = urisByPath_.find(changed); !changed.empty() && it != urisByPath_.end()) {
        for (const std::string& uri : it->second) {
            const auto old = roots_.find(uri);
            reanalyse(uri, old != roots_.end() && documents_.contains(old->second) ? old->second : uri);
            const std::set<std::string> before = index(uri);
            // The documents its includes reach, before and after, may move to or from its scene.
            addDocumentsOf(before, check);
            addDocumentsOf(links_.at(uri).includes, check);
            check.insert(uri);
            done.insert(uri);
            first.push_back(uri);
        }
    }
    // Then the scenes of the documents looked at, from the index as it is; a
    // document whose includes change on the way (a file it reaches changed)
    // is looked at again with those it reaches, for a few rounds at most.
    constexpr int kMaxRounds = 4;
    std::set<std::string> toPublish;
    for (int round = 0; round < kMaxRounds && !check.empty(); ++round) {
        std::vector<std::pair<std::string, std::string>> work;  // URI, its scene
        for (const std::string& uri : check) {
            if (!documents_.contains(uri)) continue;
            std::string root = rootOf(uri);
            const auto old = roots_.find(uri);
            const bool moved = old == roots_.end() || old->second != root;
            if (!moved && (!reading.contains(uri) || done.contains(uri))) continue;
            work.emplace_back(uri, std::move(root));
        }
        check.clear();
        for (const auto& [uri, root] : work) {
            reanalyse(uri, root);
            const std::set<std::string> before = index(uri);
            if (before != links_.at(uri).includes) {
                // Its own scene too: a cycle through it may be gone.
                check.insert(uri);
                addDocumentsOf(before, check);
                addDocumentsOf(links_.at(uri).includes, check);
            }
            done.insert(uri);
            toPublish.insert(uri);
        }
    }
    for (const std::string& uri : first) toPublish.erase(uri);
    first.insert(first.end(), toPublish.begin(), toPublish.end());
    return first;
}

void Workspace::publish(const std::string& uri, std::vector<std::string>& out) {
    const Analysis& a = *documents_.at(uri).analysis;
    std::set<std::string> others;
    for (Json& params : publishDiagnostics(a)) {
        std::string file = params["uri"].get<std::string>();
        if (file != a.uri) {
            // An open document publishes its own (as the scene it belongs to reads it).
            if (documents_.contains(file)) continue;
            others.insert(std::move(file));
        }
        out.push_back(notification("textDocument/publishDiagnostics", std::move(params)));
    }
    unpublishOthers(a.uri, others, out);
    publishedOthers_[a.uri] = std::move(others);
}

void Workspace::unpublishOthers(const std::string& uri, const std::set<std::string>& keep,
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
