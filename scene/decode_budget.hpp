// Memory for decoding images, shared by every load in a process: a decoded 8192^2 texture
// is 256 MiB (and its PNG's inflated rows as much again) from a file of a few hundred
// kilobytes, so loads decoding at once must not each take what they like. A load holds a
// lease for its image's decoding bytes while it decodes; one that cannot get them within its
// wait gives up (the server answers 503).
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>

namespace scene {

class DecodeBudget {
 public:
  explicit DecodeBudget(std::uint64_t bytes) : capacity_(bytes) {}
  DecodeBudget(const DecodeBudget&) = delete;
  DecodeBudget& operator=(const DecodeBudget&) = delete;

  // Returns its bytes when destroyed.
  class Lease {
   public:
    Lease(Lease&& other) noexcept : budget_(other.budget_), bytes_(other.bytes_) { other.budget_ = nullptr; }
    Lease& operator=(Lease&&) = delete;
    ~Lease();

   private:
    friend class DecodeBudget;
    Lease(DecodeBudget* budget, std::uint64_t bytes) : budget_(budget), bytes_(bytes) {}
    DecodeBudget* budget_;
    std::uint64_t bytes_;
  };

  // `bytes` (at most the whole budget: one image larger than it may still decode alone),
  // waiting up to `wait` for others to return theirs; empty when they did not.
  std::optional<Lease> acquire(std::uint64_t bytes, std::chrono::milliseconds wait);

  std::uint64_t capacity() const { return capacity_; }
  std::uint64_t in_use() const;

 private:
  void release(std::uint64_t bytes);

  const std::uint64_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable returned_;
  std::uint64_t in_use_ = 0;
};

}  // namespace scene
