// The bytes of a cache file's payload: values and arrays of trivially
// copyable types, written in order and read back in that order with every
// read checked against the bounds (a cache file is input like any other).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace facet::ibl::cache_format {

class Writer {
 public:
  template <class T>
  void put(const T& value) {
    const auto* bytes = reinterpret_cast<const char*>(&value);
    data_.insert(data_.end(), bytes, bytes + sizeof(T));
  }
  template <class T>
  void putArray(const std::vector<T>& values) {
    put(std::uint64_t(values.size()));
    const auto* bytes = reinterpret_cast<const char*>(values.data());
    data_.insert(data_.end(), bytes, bytes + values.size() * sizeof(T));
  }
  void putBytes(const char* bytes, std::size_t size) { data_.insert(data_.end(), bytes, bytes + size); }
  void putText(const std::string& text) { putArray(std::vector<char>(text.begin(), text.end())); }
  const std::vector<char>& data() const { return data_; }

 private:
  std::vector<char> data_;
};

// Reads what Writer wrote; every read checks the bounds, and a failed one
// leaves ok() false for good.
class Reader {
 public:
  explicit Reader(const std::vector<char>& data) : data_(data) {}
  template <class T>
  T get() {
    T value{};
    if (take(sizeof(T))) std::memcpy(&value, data_.data() + position_ - sizeof(T), sizeof(T));
    return value;
  }
  template <class T>
  std::vector<T> getArray(std::uint64_t expectedCount) {
    const auto count = get<std::uint64_t>();
    // Compared by division: a crafted count times sizeof(T) could wrap.
    if (count != expectedCount || count > (data_.size() - position_) / sizeof(T) || !take(count * sizeof(T))) {
      ok_ = false;
      return {};
    }
    std::vector<T> values(count);
    // An empty vector's data() may be null, which memcpy may not be handed even for 0 bytes.
    if (count > 0) std::memcpy(values.data(), data_.data() + position_ - count * sizeof(T), count * sizeof(T));
    return values;
  }
  // What putText wrote, of whatever length the bytes back.
  std::string getText() {
    const auto count = get<std::uint64_t>();
    if (!take(count)) return {};
    return std::string(data_.data() + position_ - std::size_t(count), std::size_t(count));
  }
  bool matches(const char* bytes, std::size_t size) {
    return take(size) && std::memcmp(data_.data() + position_ - size, bytes, size) == 0;
  }
  bool ok() const { return ok_; }
  bool atEnd() const { return position_ == data_.size(); }
  std::size_t position() const { return position_; }

 private:
  bool take(std::uint64_t size) {
    if (!ok_ || size > data_.size() - position_) return ok_ = false;
    position_ += size;
    return true;
  }
  const std::vector<char>& data_;
  std::size_t position_ = 0;
  bool ok_ = true;
};

}  // namespace facet::ibl::cache_format
