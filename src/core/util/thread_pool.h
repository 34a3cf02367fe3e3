#pragma once
/// A small persistent pool: workers live as long as the pool and run one
/// parallel loop at a time; the calling thread takes part in it. A frame runs
/// several loops a millisecond apart (evaluate, refit, trace), so workers and
/// the caller spin briefly before sleeping: waking a thread through the
/// kernel costs tens of microseconds on a virtual machine.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace f2 {

class ThreadPool {
   public:
    /// `threads` counts the caller: 1 means no worker threads. 0 = all cores.
    explicit ThreadPool(int threads = 0);
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    int threadCount() const { return int(workers_.size()) + 1; }

    /// Calls body(i) for every i in [0, count), items handed out by an atomic
    /// counter. Returns when all are done. Not reentrant.
    template <class Body>
    void parallelFor(std::uint32_t count, Body&& body) {
        using Fn = std::remove_reference_t<Body>;
        run(
            count, [](void* ctx, std::uint32_t i) { (*static_cast<Fn*>(ctx))(i); },
            const_cast<void*>(static_cast<const void*>(&body)));
    }

    static int hardwareThreads();

   private:
    using ItemFn = void (*)(void*, std::uint32_t);
    void run(std::uint32_t count, ItemFn fn, void* ctx);
    void workerLoop();
    void drain();

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    std::atomic<std::uint64_t> generation_{0};  ///< bumped (under mutex_) for each loop
    std::atomic<int> busy_{0};                  ///< workers still inside the current loop
    bool stop_ = false;
    // Current loop.
    ItemFn fn_ = nullptr;
    void* ctx_ = nullptr;
    std::uint32_t count_ = 0;
    std::atomic<std::uint32_t> next_{0};
};

}  // namespace f2
