// RenderJob::resume, which the viewer's pause/resume is built on: a job
// cancelled any number of times, at any moment, and resumed ends with exactly
// the image of a job that was never interrupted, and never runs a finished
// pass again.

#include "common/scenes.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/render_job.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

namespace jt {
namespace {

using test::showcase_at;

RenderOptions options_for(const Scene& scene, int samples) {
    RenderOptions options = render_options_for(scene);
    options.samples = samples;
    options.previews = true;
    return options;
}

TEST(RenderResume, CancelledAndResumedJobEndsWithTheUninterruptedImage) {
    const Scene scene = showcase_at(160, 96);
    const auto prepared = prepare_scene(scene).value();
    const RenderOptions options = options_for(scene, 8);
    RenderJob reference(prepared, options);
    reference.run();

    RenderJob job(prepared, options);
    // Cancel at staggered moments so that cancels land inside passes, sample
    // passes included, then resume each time.
    int cancels = 0;
    double fraction_before = 0.0;
    for (int delay_us = 300; !job.progress().finished; delay_us += 700) {
        std::thread worker([&] { job.run(); });
        std::this_thread::sleep_for(std::chrono::microseconds(delay_us));
        job.cancel();
        worker.join();
        const RenderProgress p = job.progress();
        if (!p.finished) {
            ++cancels;
            EXPECT_TRUE(p.cancelled);
            EXPECT_GE(p.fraction, fraction_before) << "work done is never given back";
            fraction_before = p.fraction;
        }
        job.resume();
        EXPECT_FALSE(job.progress().cancelled);
        ASSERT_LT(cancels, 10000);
    }
    EXPECT_GT(cancels, 0) << "the test never interrupted the job";
    EXPECT_EQ(job.progress().samples_done, 8);
    EXPECT_EQ(job.image(), reference.image());
}

TEST(RenderResume, ResumeRunsOnlyThePassesLeft) {
    const Scene scene = showcase_at(64, 36);
    RenderJob job(prepare_scene(scene).value(), options_for(scene, 4));
    ASSERT_TRUE(job.run_pass());  // preview 1/8
    ASSERT_TRUE(job.run_pass());  // preview 1/4
    job.cancel();
    EXPECT_FALSE(job.run_pass()) << "cancelled: nothing runs";
    job.resume();
    const RenderProgress at_resume = job.progress();
    EXPECT_EQ(at_resume.pass, 2);
    EXPECT_EQ(at_resume.pass_name, "preview 1/2");
    int passes_after_resume = 0;
    while (job.run_pass()) ++passes_after_resume;
    // preview 1/2, 1 sample, 2 samples, 4 samples.
    EXPECT_EQ(passes_after_resume, at_resume.pass_count - 2);
    EXPECT_TRUE(job.progress().finished);
    EXPECT_DOUBLE_EQ(job.progress().fraction, 1.0);
}

}  // namespace
}  // namespace jt
