#pragma once
// A scene's render preparation (the BVH build, for 100,000 objects the
// largest step before the first preview) started on a thread of its own as
// soon as the loader has validated the scene, so that it runs while the loader
// copies the scene for the document, instead of after it; the loader hands the
// open over once it is done (scene_loader.hpp: prepared_ahead_hold). The
// render controller adopts it (RenderController::adopt_prepared) and its first
// run waits for it rather than preparing the same scene again.

#include "jtracer/error.hpp"
#include "jtracer/render_job.hpp"
#include "jtracer/scene.hpp"

#include <future>
#include <memory>
#include <thread>

namespace jt::view {

struct PreparedAhead {
    std::shared_ptr<const Scene> scene;  // what is prepared: render exactly this to use it
    std::shared_future<Expected<std::shared_ptr<const PreparedScene>>> prepared;
};

// Runs one preparation at a time on a thread it owns; the thread is joined
// before the next one starts and when the preparer goes (a preparation
// cannot be interrupted: at most one waits).
class AheadPreparer {
  public:
    AheadPreparer() = default;
    ~AheadPreparer();
    AheadPreparer(const AheadPreparer&) = delete;
    AheadPreparer& operator=(const AheadPreparer&) = delete;

    // Starts preparing `scene` and returns at once.
    PreparedAhead start(std::shared_ptr<const Scene> scene);

  private:
    std::thread thread_;
};

}  // namespace jt::view
