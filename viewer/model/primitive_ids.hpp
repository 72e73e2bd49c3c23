#pragma once
// The primitive every pixel of a frame shows (pick_primitive for each pixel),
// computed on a thread of its own so that no frame waits for it: the viewer
// outlines the selected primitive with it.

#include "jtracer/pick.hpp"

#include <atomic>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace jt::view {

// Row by row from the bottom (Image8's order); -1 where no primitive is hit.
struct PrimitiveIdImage {
    int width = 0, height = 0;
    std::vector<int> ids;
    int at(int x, int y) const { return ids[static_cast<std::size_t>(y) * width + x]; }
};

class PrimitiveIds {
  public:
    PrimitiveIds() = default;
    ~PrimitiveIds();
    PrimitiveIds(const PrimitiveIds&) = delete;
    PrimitiveIds& operator=(const PrimitiveIds&) = delete;

    // Starts computing the ids of `frame` unless they are computed or under
    // way already; a computation for another frame is given up.
    void request(std::shared_ptr<const PreparedFrame> frame);
    // The ids of `frame`, or null while they are not ready.
    std::shared_ptr<const PrimitiveIdImage> ready(const PreparedFrame* frame) const;

  private:
    void stop();

    std::shared_ptr<const PreparedFrame> frame_;  // what the thread computes (UI thread only)
    std::thread thread_;
    std::atomic<bool> cancel_{false};
    mutable std::mutex mutex_;
    std::shared_ptr<const PrimitiveIdImage> done_;  // guarded by mutex_
    const PreparedFrame* done_for_ = nullptr;       // guarded by mutex_
};

}  // namespace jt::view
