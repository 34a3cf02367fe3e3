#include "lsp/stdio_transport.h"

#include <unistd.h>

#include <array>
#include <cerrno>
#include <mutex>
#include <string>

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
    // one may be blocked in read(). Each whole framed message is written under
    // `outMutex`, so messages never interleave. Made before the server, which
    // joins its worker when destroyed: the worker never writes after this
    // function returns.
    std::mutex outMutex;
    bool outClosed = false;  // under outMutex: a write failed, the client is gone
    auto write = [&](std::string_view body) {
        const std::lock_guard lock(outMutex);
        if (!outClosed && !writeAll(out, frameMessage(body))) outClosed = true;
        return !outClosed;
    };
    Server::Options options;
    options.notify = [&](std::string body) { write(body); };
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
            for (const std::string& reply : server.handle(item.text)) {
                if (!write(reply)) return server.exitCode();
            }
            if (server.exited()) return server.exitCode();
        }
    }
    return server.exitCode();
}

}  // namespace f2::lsp
