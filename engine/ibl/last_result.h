// The last result of a costly function, kept for the next call with the
// same key: the rounds, frames and cells of one scene ask for the same
// environment data again and again, and one entry is all they need.
#pragma once

#include <memory>
#include <mutex>
#include <utility>

namespace facet::ibl {

template <class Key, class Value>
class LastResult {
 public:
  // compute() unless the last call's key equals `key`; a copy either way.
  template <class Compute>
  Value get(const Key& key, Compute&& compute) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (value_ && key_ == key) return *value_;
    }
    auto value = std::make_shared<const Value>(std::forward<Compute>(compute)());
    const std::lock_guard<std::mutex> lock(mutex_);
    key_ = key;
    value_ = value;
    return *value;
  }

 private:
  std::mutex mutex_;
  Key key_{};
  std::shared_ptr<const Value> value_;
};

}  // namespace facet::ibl
