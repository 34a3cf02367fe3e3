#pragma once
/// The F2 language server: JSON-RPC messages in, messages out. Knows nothing
/// of standard input and output (stdio_transport.h runs it on them), so tests
/// and the fuzzer drive it directly.
#include <functional>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "lsp/analysis.h"
#include "lsp/protocol.h"

namespace f2::lsp {

class Server {
   public:
    /// Arrays and objects nested deeper than this make a message a parse
    /// error (-32700) before it is parsed: JSON values are copied, dumped and
    /// destroyed recursively, so a client's 1,000,000 `[` would overflow the
    /// stack. LSP messages nest about 10 deep; 256 leaves room for any
    /// client's settings and costs a few kilobytes of stack at most.
    static constexpr int kMaxJsonDepth = 256;

    /// `log` receives one line per problem that has no reply (a malformed
    /// notification, a framing error); default: none.
    explicit Server(std::function<void(std::string_view)> log = {});

    /// Handles one message body and returns the bodies to send, in order.
    /// Never throws: any problem becomes an error response or a log line.
    std::vector<std::string> handle(std::string_view body);

    /// Logs a problem of the transport (a bad header).
    void logProblem(std::string_view problem) const;

    /// True after the `exit` notification.
    bool exited() const { return exited_; }
    /// The process exit code the protocol asks for: 0 after `shutdown`, else 1.
    int exitCode() const { return shutdown_ ? 0 : 1; }

   private:
    Json dispatchRequest(const std::string& method, const Json& params);
    void dispatchNotification(const std::string& method, const Json& params, std::vector<std::string>& out);

    const Analysis& document(const Json& params) const;
    void publish(const Analysis& a, std::vector<std::string>& out);
    /// Clears the diagnostics a document published on other files (its includes).
    void unpublishOthers(const std::string& uri, const std::set<std::string>& keep,
                         std::vector<std::string>& out);
    void open(std::string uri, std::string text, int version, std::vector<std::string>& out);
    /// Analyses again the open documents whose scene reads the file `changed`
    /// (all of them when it is empty), each as part of the topmost open
    /// document that includes it, and publishes their diagnostics.
    void refresh(const std::string& changed, std::vector<std::string>& out);
    /// The open document whose scene a document belongs to: the topmost open
    /// document that includes it, or itself.
    std::string rootOf(const std::string& uri,
                       const std::map<std::string, std::set<std::string>>& closures) const;
    SourceOverlay openTexts() const;

    std::function<void(std::string_view)> log_;
    std::map<std::string, Analysis> documents_;  ///< open documents by URI
    std::map<std::string, std::string> roots_;   ///< URI -> the URI of the document parsed as its scene
    /// Other files (includes) each open document has published diagnostics on.
    std::map<std::string, std::set<std::string>> publishedOthers_;
    bool initialized_ = false;
    bool shutdown_ = false;
    bool exited_ = false;
};

/// Applies one `contentChanges` entry (a whole text, or a range and its new
/// text) to `text`; throws RequestError for an invalid change.
std::string applyChange(const std::string& text, const Json& change);

}  // namespace f2::lsp
