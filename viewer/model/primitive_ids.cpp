#include "model/primitive_ids.hpp"

namespace jt::view {

PrimitiveIds::~PrimitiveIds() {
    stop();
}

void PrimitiveIds::stop() {
    cancel_ = true;
    if (thread_.joinable()) thread_.join();
    cancel_ = false;
}

void PrimitiveIds::request(std::shared_ptr<const PreparedFrame> frame) {
    if (!frame || frame == frame_) return;
    stop();
    {
        std::lock_guard lock(mutex_);
        done_.reset();
        done_for_ = nullptr;
    }
    frame_ = std::move(frame);
    thread_ = std::thread([this, frame = frame_] {
        auto image = std::make_shared<PrimitiveIdImage>();
        const PixelRect whole = frame_rect(*frame);
        image->width = whole.width();
        image->height = whole.height();
        image->ids.assign(static_cast<std::size_t>(image->width) * image->height, -1);
        for (int y = 0; y < image->height; ++y) {
            if (cancel_) return;
            for (int x = 0; x < image->width; ++x)
                if (const auto pick = pick_primitive(*frame, x, y))
                    image->ids[static_cast<std::size_t>(y) * image->width + x] = pick->primitive;
        }
        std::lock_guard lock(mutex_);
        done_ = std::move(image);
        done_for_ = frame.get();
    });
}

std::shared_ptr<const PrimitiveIdImage> PrimitiveIds::ready(const PreparedFrame* frame) const {
    std::lock_guard lock(mutex_);
    return frame && frame == done_for_ ? done_ : nullptr;
}

}  // namespace jt::view
