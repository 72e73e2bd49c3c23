#pragma once
// Values read from files (models, decoded image maps), each held once and
// shared by all who use it. The few used last stay held after their last user
// lets go, so that validating a scene and then rendering it reads each file
// once. A file whose stamp (file_stamp.hpp) moved is read again.

#include "jtracer/error.hpp"
#include "jtracer/file_stamp.hpp"

#include <algorithm>
#include <cstddef>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <utility>

namespace jt {

template <class Key, class T>
class StampedCache {
  public:
    explicit StampedCache(std::size_t kept) : kept_(kept) {}

    // The value held for `key` when it was read from a file stamped `stamp`,
    // else read()'s (an Expected<T>), held from now on. Errors are not held.
    template <class Read>
    Expected<std::shared_ptr<const T>> get(const Key& key, const FileStamp& stamp, Read read) {
        {
            std::lock_guard lock(mutex_);
            auto found = entries_.find(key);
            if (found != entries_.end() && found->second.stamp == stamp)
                if (auto value = found->second.value.lock()) return value;
        }
        // Read outside the lock: two threads may read one file at once, and
        // the second result replaces the first; both are correct.
        Expected<T> fresh = read();
        if (!fresh) return fresh.error();
        auto value = std::make_shared<const T>(std::move(*fresh));
        std::lock_guard lock(mutex_);
        entries_[key] = Entry{stamp, value};
        recent_.push_back(value);
        if (recent_.size() > kept_) recent_.pop_front();
        std::erase_if(entries_, [](const auto& e) { return e.second.value.expired(); });
        return value;
    }

    // The value held for `key` when it was read from a file stamped `stamp`,
    // else null: a look that reads nothing.
    std::shared_ptr<const T> find(const Key& key, const FileStamp& stamp) {
        std::lock_guard lock(mutex_);
        auto found = entries_.find(key);
        if (found != entries_.end() && found->second.stamp == stamp)
            return found->second.value.lock();
        return nullptr;
    }

    // Drops every entry whose key `matches`: the next get reads its file again.
    // Values already shared stay as they are.
    template <class Matches>
    void forget(Matches matches) {
        std::lock_guard lock(mutex_);
        std::erase_if(entries_, [&](const auto& e) {
            if (!matches(e.first)) return false;
            if (auto value = e.second.value.lock()) std::erase(recent_, value);
            return true;
        });
    }

  private:
    struct Entry {
        FileStamp stamp;
        std::weak_ptr<const T> value;
    };
    std::size_t kept_;
    std::mutex mutex_;
    std::map<Key, Entry> entries_;
    std::deque<std::shared_ptr<const T>> recent_;  // most recent last
};

}  // namespace jt
