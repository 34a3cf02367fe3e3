#pragma once
/// The open documents as the language server analyses them: their texts, the
/// scene each belongs to (itself, or the topmost open document that includes
/// it), their analyses and the reverse indexes of what includes and reads
/// what. Owned and used by one thread, the server's worker (server.h); what
/// it hands out (analyses, notifications) is immutable or a copy.
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "lsp/analysis.h"
#include "lsp/protocol.h"

namespace f2::lsp {

/// A JSON-RPC notification body.
std::string notification(std::string_view method, Json params);

class Workspace {
   public:
    /// `beforeAnalysis`, if set, is called before each analysis with the
    /// document's URI and version (a test seam: a test blocks it to hold a parse).
    explicit Workspace(std::function<void(const std::string&, int)> beforeAnalysis = {});

    /// Opens a document or replaces its text, and analyses it and the open
    /// documents whose scene reads it. Returns the URIs analysed again, in the
    /// order to publish them (the changed document first).
    std::vector<std::string> open(std::string uri, std::string text, int version);
    /// Closes a document: appends to `out` the notifications that clear its
    /// diagnostics (and those it published on its includes), analyses again
    /// the documents that read it and returns their URIs.
    std::vector<std::string> close(const std::string& uri, std::vector<std::string>& out);
    /// Analyses every open document again (a file on disk may have changed).
    std::vector<std::string> refreshAll();

    /// The newest analysis of an open document; null when it is not open.
    std::shared_ptr<const Analysis> analysis(const std::string& uri) const;
    /// Appends the publishDiagnostics notifications of an open document's
    /// newest analysis (on it and on the files it includes that are not open)
    /// and clears those it published before on files it no longer has errors in.
    void publish(const std::string& uri, std::vector<std::string>& out);

   private:
    /// An open document: its newest text and its newest analysis.
    struct Document {
        TextDocument text;
        std::shared_ptr<const Analysis> analysis;  ///< never changed once made: readers may keep it
    };

    /// Clears the diagnostics a document published on other files (its includes).
    void unpublishOthers(const std::string& uri, const std::set<std::string>& keep,
                         std::vector<std::string>& out);
    /// Analyses again the open documents whose scene reads the file `changed`
    /// (all of them when it is empty), each as part of the topmost open
    /// document that includes it, and returns them in publishing order. The
    /// scene of a document can move only when the includes of the changed
    /// document reach it (before or after the change, `alsoMoved`): only those
    /// are looked at, so a change costs what it touches, not the open documents.
    std::vector<std::string> refresh(const std::string& changed, const std::set<std::string>& alsoMoved);
    /// Analyses a document again as part of the scene `root` and indexes it.
    void reanalyse(const std::string& uri, const std::string& root);
    /// The open document whose scene a document belongs to: the topmost open
    /// document that includes it, or itself.
    std::string rootOf(const std::string& uri) const;
    /// Records in the reverse indexes what a document includes and reads
    /// (`unindex`: forgets it), returning the files its includes reached before.
    std::set<std::string> index(const std::string& uri);
    std::set<std::string> unindex(const std::string& uri);
    /// The text and URI the scenes read for a path: the last open document
    /// with that path (in URI order), or none.
    void syncPath(const std::string& path);
    /// Adds the open documents of the files `paths` to `to`.
    void addDocumentsOf(const std::set<std::string>& paths, std::set<std::string>& to) const;

    /// What an open document's analysis links it to, by path.
    struct Links {
        std::set<std::string> includes;  ///< files its own includes reach, itself excluded
        std::set<std::string> reads;     ///< every file its scene read, itself excluded
    };

    std::function<void(const std::string&, int)> beforeAnalysis_;
    std::map<std::string, Document> documents_;  ///< open documents by URI
    std::map<std::string, std::string> roots_;   ///< URI -> the URI of the document parsed as its scene
    SourceOverlay texts_;                        ///< open documents' texts by path: what scenes read
    /// The URI of each open document's path, shared with their analyses.
    std::shared_ptr<OpenUris> openUris_;
    std::map<std::string, std::set<std::string>> urisByPath_;  ///< path -> open documents with it
    std::map<std::string, Links> links_;                       ///< URI -> its links
    std::map<std::string, std::set<std::string>> includedBy_;  ///< path -> documents whose includes reach it
    std::map<std::string, std::set<std::string>> readBy_;      ///< path -> documents whose scene read it
    /// Other files (includes) each open document has published diagnostics on.
    std::map<std::string, std::set<std::string>> publishedOthers_;
};

}  // namespace f2::lsp
