#pragma once
/// The F2 language server: JSON-RPC messages in, messages out. Knows nothing
/// of standard input and output (stdio_transport.h runs it on them), so tests
/// and the fuzzer drive it directly.
#include <condition_variable>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "lsp/analysis.h"
#include "lsp/protocol.h"
#include "lsp/workspace.h"

namespace f2::lsp {

/// The server reads messages on one thread (the caller's: the message
/// thread) and analyses documents on another (the worker), so a huge document
/// or include never holds up a request:
///
/// - didOpen, didChange, didClose and didSave only queue work for the worker:
///   the newest text of each document, keyed by URI. A change replaces the
///   queued text of its document that the worker has not started yet
///   (changes typed while an analysis runs are coalesced into one).
/// - The worker takes everything queued at once, analyses it with the open
///   documents whose scene reads it (workspace.h), then publishes. An analysis
///   of a document that has a newer text queued by then is stale: it is
///   dropped, neither published nor seen by requests; the newer text is
///   analysed next.
/// - Requests (hover, completion, definition, …) are answered at once on the
///   message thread from the newest finished analysis of their document: the
///   last good one while a newer parse runs (its ranges are those of the text
///   it read), as most servers do. Only a document that has no finished
///   analysis yet (just opened) is waited for. Formatting reads the newest
///   text itself, so its edits always apply.
class Server {
   public:
    /// Arrays and objects nested deeper than this make a message a parse
    /// error (-32700) before it is parsed: JSON values are copied, dumped and
    /// destroyed recursively, so a client's 1,000,000 `[` would overflow the
    /// stack. LSP messages nest about 10 deep; 256 leaves room for any
    /// client's settings and costs a few kilobytes of stack at most.
    static constexpr int kMaxJsonDepth = 256;

    struct Options {
        /// Receives the notifications the worker sends (publishDiagnostics),
        /// on the worker's thread, as analyses finish: those of one round
        /// together, in order, to be written together (a client that has read
        /// one of them has the others before any later reply). Unset: the
        /// server is synchronous: handle() waits after each notification until
        /// the worker is idle and returns what it sent (tests, the fuzzer).
        std::function<void(std::vector<std::string>)> notify;
        /// A test seam: called on the worker before each analysis with the
        /// document's URI and version (a test blocks it to hold a parse).
        std::function<void(const std::string&, int)> beforeAnalysis;
    };

    /// `log` receives one line per problem that has no reply (a malformed
    /// notification, a framing error); default: none. It may be called on
    /// the worker's thread too, never on two threads at once.
    explicit Server(std::function<void(std::string_view)> log = {}, Options options = {});
    /// Stops the worker: it finishes the analysis it is in (if any), drops
    /// what is queued, and is joined.
    ~Server();
    Server(const Server&) = delete;
    Server& operator=(const Server&) = delete;

    /// Handles one message body and returns the bodies to send, in order.
    /// Never throws: any problem becomes an error response or a log line.
    std::vector<std::string> handle(std::string_view body);

    /// Waits until the worker has analysed and published everything queued.
    void waitUntilIdle();

    /// Logs a problem of the transport (a bad header).
    void logProblem(std::string_view problem) const;

    /// True after the `exit` notification.
    bool exited() const { return exited_; }
    /// The process exit code the protocol asks for: 0 after `shutdown`, else 1.
    int exitCode() const { return shutdown_ ? 0 : 1; }

   private:
    /// Work for the worker: a document's newest text, its closing, or every
    /// open document again (didSave).
    struct Job {
        enum class Kind { Text, Close, RefreshAll } kind = Kind::Text;
        std::string uri;
        std::string text;
        int version = 0;
    };
    /// An open document's newest text as the client sent it.
    struct Text {
        std::string text;
        int version = 0;
    };

    Json dispatchRequest(const std::string& method, const Json& params);
    void dispatchNotification(const std::string& method, const Json& params);
    /// The newest finished analysis of the document of a request.
    std::shared_ptr<const Analysis> document(const Json& params);
    /// Queues a job, replacing a queued one of the same document.
    void queue(Job job);
    /// The worker's loop.
    void work();
    /// Sends notifications from the worker.
    void send(std::vector<std::string> messages);

    std::function<void(std::string_view)> log_;
    Options options_;
    mutable std::mutex logMutex_;

    // The message thread's own.
    std::map<std::string, Text> texts_;  ///< open documents by URI
    bool initialized_ = false;
    bool shutdown_ = false;
    bool exited_ = false;

    // The worker's own (and made before it starts).
    Workspace workspace_;

    // Shared, under mutex_.
    std::mutex mutex_;
    std::condition_variable changed_;  ///< a job queued, a round finished, or stop
    std::deque<Job> queued_;
    std::map<std::string, std::size_t> queuedAt_;  ///< URI -> its job in queued_
    bool busy_ = false;                            ///< the worker is in a round
    bool stop_ = false;
    /// The newest analysis published of each open document.
    std::map<std::string, std::shared_ptr<const Analysis>> finished_;
    std::vector<std::string> outbox_;  ///< synchronous mode: what the worker sent

    std::thread worker_;  ///< last: started when everything else is made
};

/// Applies one `contentChanges` entry (a whole text, or a range and its new
/// text) to `text`; throws RequestError for an invalid change.
std::string applyChange(const std::string& text, const Json& change);

}  // namespace f2::lsp
