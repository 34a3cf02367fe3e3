#include "lsp/stdio_transport.h"

#include <unistd.h>

#include <array>
#include <cerrno>
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
    Server server([log](std::string_view line) {
        std::fprintf(log, "f2 lsp: %.*s\n", static_cast<int>(line.size()), line.data());
        std::fflush(log);
    });
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
                if (!writeAll(out, frameMessage(reply))) return server.exitCode();
            }
            if (server.exited()) return server.exitCode();
        }
    }
    return server.exitCode();
}

}  // namespace f2::lsp
