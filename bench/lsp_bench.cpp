// f2_lsp_bench: the language server with many open documents. For each N it
// opens N documents of about 40 bytes in one Server (as didOpen messages,
// the way `f2 lsp` gets them), then opens one more, changes one, and asks a
// hover, and prints the times and the peak memory (getrusage ru_maxrss). Each
// N runs in a child process, so each peak is its own.
//
//     build/release/bench/f2_lsp_bench [N ...]     (default: 1000 10000)
//
// With --include-lines L it measures instead what a hover costs while a
// document that includes an L-line file (`/let v 1` lines, in a temporary
// folder) is parsed: the server runs as `f2 lsp` runs it (parsing on its
// worker), and hovers on another open document are sent one after another
// (one a millisecond) until the including document's diagnostics arrive; it prints their count
// and latencies, and then the time a synchronous parse of the same document
// takes (what a hover waited for before the worker, when the parse ran on the
// message thread).
//
//     build/release/bench/f2_lsp_bench --include-lines 10000000
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string>
#include <thread>
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

std::string notificationOf(const std::string& method, const Json& params) {
    return Json({{"jsonrpc", "2.0"}, {"method", method}, {"params", params}}).dump();
}

std::string openDocument(const std::string& uri, const std::string& text) {
    return notificationOf("textDocument/didOpen",
                          {{"textDocument", {{"uri", uri}, {"version", 1}, {"text", text}}}});
}

int runBigInclude(long lines) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("f2_lsp_bench_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    {
        std::ofstream big(dir / "big.f2");
        const std::string chunk = [] {
            std::string c;
            for (int i = 0; i < 1000; ++i) c += "/let v 1\n";
            return c;
        }();
        for (long i = 0; i < lines / 1000; ++i) big << chunk;
        for (long i = 0; i < lines % 1000; ++i) big << "/let v 1\n";
    }
    const std::string other = "file://" + (dir / "other.f2").string();
    const std::string main = "file://" + (dir / "main.f2").string();
    const std::string mainText = "/include big.f2\n/amb_light 1\n/sphere t 1 0 0 0\n";
    const std::string hoverOther =
        Json(
            {{"jsonrpc", "2.0"},
             {"id", 2},
             {"method", "textDocument/hover"},
             {"params", {{"textDocument", {{"uri", other}}}, {"position", {{"line", 1}, {"character", 9}}}}}})
            .dump();
    int status = 0;
    {
        std::mutex mutex;
        std::condition_variable cv;
        bool otherPublished = false, mainPublished = false;
        f2::lsp::Server::Options options;
        options.notify = [&](std::vector<std::string> round) {
            const std::lock_guard lock(mutex);
            for (const std::string& m : round) {
                const Json j = Json::parse(m);
                if (j["params"]["uri"] == other) otherPublished = true;
                if (j["params"]["uri"] == main) mainPublished = true;
            }
            cv.notify_all();
        };
        f2::lsp::Server server({}, std::move(options));
        server.handle(R"({"jsonrpc":"2.0","id":1,"method":"initialize"})");
        server.handle(openDocument(other, "/amb_light 1\n/sphere s 1 0 0 0\n"));
        {
            std::unique_lock lock(mutex);
            cv.wait(lock, [&] { return otherPublished; });
        }
        const auto start = Clock::now();
        server.handle(openDocument(main, mainText));
        std::vector<double> latencies;
        bool answered = true;
        for (;;) {
            {
                const std::lock_guard lock(mutex);
                if (mainPublished) break;
            }
            const auto sent = Clock::now();
            const auto reply = server.handle(hoverOther);
            latencies.push_back(msSince(sent));
            std::this_thread::sleep_for(std::chrono::milliseconds(1));  // an eager client, not a busy loop
            answered = answered && reply.size() == 1 && Json::parse(reply[0])["result"].contains("contents");
        }
        const double parseMs = msSince(start);
        std::sort(latencies.begin(), latencies.end());
        const auto at = [&](double q) {
            return latencies.empty() ? 0.0 : latencies[static_cast<std::size_t>(q * (latencies.size() - 1))];
        };
        std::printf(
            "include of %ld lines: parsed on the worker in %.0f ms; meanwhile %zu hovers on another "
            "document%s, "
            "latency median %.3f ms, p99 %.3f ms, max %.3f ms\n",
            lines, parseMs, latencies.size(), answered ? "" : " (SOME NOT ANSWERED)", at(0.5), at(0.99),
            latencies.empty() ? 0.0 : latencies.back());
        if (!answered || latencies.empty()) status = 1;
    }
    {
        f2::lsp::Server server;  // synchronous: handle() returns when the parse is done
        server.handle(R"({"jsonrpc":"2.0","id":1,"method":"initialize"})");
        const auto start = Clock::now();
        server.handle(openDocument(main, mainText));
        std::printf(
            "the same didOpen parsed synchronously: %.0f ms (a hover sent after it waited that long when the "
            "message thread parsed)\n",
            msSince(start));
    }
    std::printf("peak RSS %.1f MB\n", peakMb());
    std::filesystem::remove_all(dir);
    return status;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 3 && std::strcmp(argv[1], "--include-lines") == 0) {
        const long lines = std::atol(argv[2]);
        if (lines < 1) {
            std::fprintf(stderr, "f2_lsp_bench: --include-lines needs a positive count, got '%s'\n", argv[2]);
            return 2;
        }
        return runBigInclude(lines);
    }
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
