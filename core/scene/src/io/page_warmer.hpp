#pragma once
// Faults in a large array's pages on another thread, just ahead of the code
// that fills it.
//
// Memory fresh from the kernel is zeroed at its first touch. On the team's VM
// that touch is cheap right after a process of our own, but costs ~2 ms a MB
// right after another program freed much memory (Tachyon or POV-Ray before it
// in a race): a million primitives (280 MB) then spent most of a second in
// the kernel on the parsing thread, while the other core idled. The warmer
// asks the kernel to fault the pages in (MADV_POPULATE_WRITE, which changes no
// byte) a bounded distance ahead of what the filler reported, so that cost is
// paid beside the parse. What it faulted past the array's final size is given
// back when it stops. Off Linux, or on a kernel without the advice, it does
// nothing.

#include <atomic>
#include <cstddef>
#include <thread>

namespace jt {

class PageWarmer {
  public:
    // How far past the filled part the pages are faulted in: enough that the
    // filler never waits for the warmer, little enough to give back at the end.
    static constexpr std::size_t lead_bytes = std::size_t{32} << 20;
    // Arrays smaller than this fill fast enough on their own.
    static constexpr std::size_t smallest_warmed_bytes = std::size_t{64} << 20;

    PageWarmer() = default;
    PageWarmer(const PageWarmer&) = delete;
    PageWarmer& operator=(const PageWarmer&) = delete;
    ~PageWarmer() { join(); }

    // Starts warming the reserved, unfilled [data, data + bytes).
    void start(void* data, std::size_t bytes);
    // Whether a thread is warming an array (start may decline: a small array,
    // no thread to be had, a system without the advice).
    bool warming() const { return thread_.joinable(); }
    // How many bytes from `data` the filler has written: cheap to call often.
    void filled(std::size_t bytes) {
        if (bytes < next_report_) return;
        next_report_ = bytes + report_step;
        report(bytes);
    }
    // Stops the thread and gives back the warmed pages wholly past the first
    // `used_bytes` of `data`, when `data` is still the array it warms (a filler
    // that outgrew its reservation has moved elsewhere, and the old place may
    // hold something else by now).
    void finish(const void* data, std::size_t used_bytes);

  private:
    static constexpr std::size_t report_step = std::size_t{1} << 20;
    void report(std::size_t bytes);
    void run();
    void join();

    std::byte* begin_ = nullptr;
    std::byte* end_ = nullptr;
    std::byte* warmed_ = nullptr;  // the thread's own until joined
    std::size_t next_report_ = 0;
    std::atomic<std::size_t> filled_{0};
    std::atomic<bool> stopping_{false};
    std::thread thread_;
};

}  // namespace jt
