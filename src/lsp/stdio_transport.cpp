#include "lsp/stdio_transport.h"

#include <unistd.h>

#include <array>
#include <cerrno>
#include <mutex>
#include <string>
#include <vector>

#include "lsp/message_reader.h"
#include "lsp/server.h"

namespace f2::lsp {

namespace {

/// Writes all of `bytes`; false when the other end is gone.
bool writeAll(int fd, std::string_view bytes) {
    while (!bytes.empty()) {
        const ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        bytes.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
}

}  // namespace

int runServer(int in, int out, std::FILE* log) {
    // Two threads write to `out`: this one its replies, the server's worker
    // its notifications (publishDiagnostics) as analyses finish, while this
    // one may be blocked in read(). Whole framed messages are written under
    // `outMutex` (a reply's, or a round's notifications, together), so
    // messages never interleave. Made before the server, which
    // joins its worker when destroyed: the worker never writes after this
    // function returns.
    std::mutex outMutex;
    bool outClosed = false;  // under outMutex: a write failed, the client is gone
    auto write = [&](const std::vector<std::string>& bodies) {
        const std::lock_guard lock(outMutex);
        for (const std::string& body : bodies) {
            if (!outClosed && !writeAll(out, frameMessage(body))) outClosed = true;
        }
        return !outClosed;
    };
    Server::Options options;
    // A round's notifications in one go: a client that has read one has them all.
    options.notify = [&](std::vector<std::string> bodies) { write(bodies); };
    Server server(
        [log](std::string_view line) {
            std::fprintf(log, "f2 lsp: %.*s\n", static_cast<int>(line.size()), line.data());
            std::fflush(log);
        },
        std::move(options));
    MessageReader reader;
    std::array<char, 1 << 16> buffer;
    for (;;) {
        const ssize_t got = ::read(in, buffer.data(), buffer.size());
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) break;  // end of input or a read error: the client is gone
        reader.feed({buffer.data(), static_cast<std::size_t>(got)});
        MessageReader::Item item;
        while (reader.next(item)) {
            if (item.kind == MessageReader::Item::Kind::Problem) {
                server.logProblem(item.text);
                continue;
            }
            if (!write(server.handle(item.text))) return server.exitCode();
            if (server.exited()) return server.exitCode();
        }
    }
    return server.exitCode();
}

}  // namespace f2::lsp
