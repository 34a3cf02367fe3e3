// f2_lsp_bench: the language server with many open documents. For each N it
// opens N documents of about 40 bytes in one Server (as didOpen messages,
// the way `f2 lsp` gets them), then opens one more, changes one, and asks a
// hover, and prints the times and the peak memory (getrusage ru_maxrss). Each
// N runs in a child process, so each peak is its own.
//
//     build/release/bench/f2_lsp_bench [N ...]     (default: 1000 10000)
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "lsp/protocol.h"
#include "lsp/server.h"

namespace {

using f2::lsp::Json;
using Clock = std::chrono::steady_clock;

std::string uriOf(int i) { return "file:///bench/doc" + std::to_string(i) + ".f2"; }

/// About 40 bytes: an object, its colour and a key.
std::string textOf(int i) {
    const std::string name = "s" + std::to_string(i);
    return "/sphere " + name + " 1 0 0 0\n/paint " + name + " 9 9 9\n/key 0 " + name + "\n";
}

std::string didOpen(int i) {
    return Json({{"jsonrpc", "2.0"},
                 {"method", "textDocument/didOpen"},
                 {"params", {{"textDocument", {{"uri", uriOf(i)}, {"version", 1}, {"text", textOf(i)}}}}}})
        .dump();
}

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double peakMb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

void run(int n) {
    const double baseMb = peakMb();
    f2::lsp::Server server;
    server.handle(R"({"jsonrpc":"2.0","id":1,"method":"initialize"})");
    std::size_t replies = 0;
    auto start = Clock::now();
    for (int i = 0; i < n; ++i) replies += server.handle(didOpen(i)).size();
    const double openMs = msSince(start);

    start = Clock::now();
    replies += server.handle(didOpen(n)).size();
    const double oneMoreMs = msSince(start);

    start = Clock::now();
    replies += server
                   .handle(Json({{"jsonrpc", "2.0"},
                                 {"method", "textDocument/didChange"},
                                 {"params",
                                  {{"textDocument", {{"uri", uriOf(n / 2)}, {"version", 2}}},
                                   {"contentChanges", Json::array({{{"text", textOf(n / 2) + "# x\n"}}})}}}})
                               .dump())
                   .size();
    const double changeMs = msSince(start);

    start = Clock::now();
    const auto hover = server.handle(
        Json({{"jsonrpc", "2.0"},
              {"id", 2},
              {"method", "textDocument/hover"},
              {"params",
               {{"textDocument", {{"uri", uriOf(n / 2)}}}, {"position", {{"line", 0}, {"character", 9}}}}}})
            .dump());
    const double hoverMs = msSince(start);
    const bool answered = hover.size() == 1 && Json::parse(hover[0])["result"].contains("contents");

    std::printf(
        "N=%-6d open N: %9.1f ms (%.3f ms each)  open one more: %8.3f ms  change one: %8.3f ms  "
        "hover: %6.3f ms%s  peak RSS %.1f MB (%.1f MB before)  %zu notifications\n",
        n, openMs, openMs / n, oneMoreMs, changeMs, hoverMs, answered ? "" : " (NO ANSWER)", peakMb(), baseMb,
        replies);
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<int> counts;
    for (int i = 1; i < argc; ++i) counts.push_back(std::atoi(argv[i]));
    if (counts.empty()) counts = {1000, 10000};
    int status = 0;
    for (const int n : counts) {
        if (n < 1) {
            std::fprintf(stderr, "f2_lsp_bench: N must be a positive count, got '%d'\n", n);
            return 2;
        }
        const pid_t child = fork();
        if (child == 0) {
            run(n);
            std::_Exit(0);
        }
        int childStatus = 0;
        waitpid(child, &childStatus, 0);
        if (!WIFEXITED(childStatus) || WEXITSTATUS(childStatus) != 0) status = 1;
    }
    return status;
}
