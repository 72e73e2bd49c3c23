#include "text_checker.hpp"

#include "jtracer/scene_file.hpp"

#include <exception>

namespace jt::view {

CheckedText check_text(std::uint64_t id, std::string text, const std::filesystem::path& path) {
    LoadedScene loaded;
    loaded.path = path.string();
    loaded.parsed = parse_scene(text);
    loaded.parsed.scene.asset_folder = path.parent_path().string();
    loaded.text = std::move(text);
    CheckedText checked;
    checked.id = id;
    checked.diagnostics = check_scene(loaded);
    checked.ok = !has_errors(checked.diagnostics);
    checked.text = std::move(loaded.text);
    checked.parsed = std::move(loaded.parsed);
    return checked;
}

TextChecker::TextChecker() : worker_([this] { work(); }) {}

TextChecker::~TextChecker() {
    {
        std::lock_guard lock(mutex_);
        quit_ = true;
    }
    changed_.notify_all();
    worker_.join();
}

void TextChecker::check(std::uint64_t id, std::string text, const std::filesystem::path& path,
                        std::chrono::milliseconds pause) {
    {
        std::lock_guard lock(mutex_);
        next_ = Request{id, std::move(text), path, std::chrono::steady_clock::now() + pause};
        result_.reset();
    }
    changed_.notify_all();
}

void TextChecker::cancel() {
    std::lock_guard lock(mutex_);
    next_.reset();
    result_.reset();
}

std::optional<CheckedText> TextChecker::take() {
    std::lock_guard lock(mutex_);
    std::optional<CheckedText> result = std::move(result_);
    result_.reset();
    return result;
}

bool TextChecker::in_flight() const {
    std::lock_guard lock(mutex_);
    return next_ || checking_;
}

void TextChecker::set_wakeup(Wakeup* wakeup) {
    std::lock_guard lock(mutex_);
    wakeup_ = wakeup;
}

void TextChecker::wait() const {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return !next_ && !checking_; });
}

void TextChecker::work() {
    std::unique_lock lock(mutex_);
    for (;;) {
        changed_.wait(lock, [this] { return quit_ || next_; });
        if (quit_) return;
        // Wait out the pause; a newer text moves the deadline.
        if (std::chrono::steady_clock::now() < next_->due) {
            changed_.wait_until(lock, next_->due);
            continue;
        }
        Request request = std::move(*next_);
        next_.reset();
        checking_ = true;
        lock.unlock();
        CheckedText checked;
        try {
            checked = check_text(request.id, std::move(request.text), request.path);
        } catch (const std::exception& e) {  // out of memory, say
            checked = CheckedText{};
            checked.id = request.id;
            checked.diagnostics.push_back(Diagnostic{
                Severity::error, SourcePos{}, std::string("cannot check the text: ") + e.what()});
        }
        lock.lock();
        checking_ = false;
        const bool ready = !next_;
        if (ready) result_ = std::move(checked);
        changed_.notify_all();
        if (ready && wakeup_) {
            Wakeup* wakeup = wakeup_;
            lock.unlock();
            wakeup->notify();
            lock.lock();
        }
    }
}

}  // namespace jt::view
