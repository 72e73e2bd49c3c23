#include "model/prepared_ahead.hpp"

#include <exception>
#include <string>
#include <utility>

namespace jt::view {

AheadPreparer::~AheadPreparer() {
    if (thread_.joinable()) thread_.join();
}

PreparedAhead AheadPreparer::start(std::shared_ptr<const Scene> scene) {
    if (thread_.joinable()) thread_.join();
    std::promise<Expected<std::shared_ptr<const PreparedScene>>> promise;
    PreparedAhead ahead{scene, promise.get_future().share()};
    thread_ = std::thread([scene = std::move(scene), promise = std::move(promise)]() mutable {
        try {
            promise.set_value(prepare_scene(scene));
        } catch (const std::exception& e) {  // out of memory, say
            promise.set_value(Error{std::string("the render failed: ") + e.what()});
        }
    });
    return ahead;
}

}  // namespace jt::view
