// A double-ended queue on one power-of-two ring buffer, for the stillness detector's sliding
// windows and monotonic queues: they push and pop a few elements at every reading, and a ring that
// has reached the window's size does so without allocating or walking std::deque's blocks.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace plumb::strapdown {

template <typename T>
class RingQueue {
 public:
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  void clear() { head_ = size_ = 0; }
  T& front() { return buffer_[head_]; }
  const T& front() const { return buffer_[head_]; }
  T& back() { return buffer_[(head_ + size_ - 1) & mask_]; }
  const T& back() const { return buffer_[(head_ + size_ - 1) & mask_]; }
  const T& operator[](std::size_t i) const { return buffer_[(head_ + i) & mask_]; }
  T& operator[](std::size_t i) { return buffer_[(head_ + i) & mask_]; }
  void push_back(const T& value) {
    if (size_ == buffer_.size()) grow();
    buffer_[(head_ + size_) & mask_] = value;
    ++size_;
  }
  template <typename... Args>
  void emplace_back(Args&&... args) {
    push_back(T{std::forward<Args>(args)...});
  }
  void pop_front() {
    head_ = (head_ + 1) & mask_;
    --size_;
  }
  void pop_back() { --size_; }

  class const_iterator {
   public:
    const_iterator(const RingQueue* q, std::size_t i) : q_(q), i_(i) {}
    const T& operator*() const { return (*q_)[i_]; }
    const_iterator& operator++() {
      ++i_;
      return *this;
    }
    bool operator!=(const const_iterator& o) const { return i_ != o.i_; }

   private:
    const RingQueue* q_;
    std::size_t i_;
  };
  const_iterator begin() const { return {this, 0}; }
  const_iterator end() const { return {this, size_}; }

 private:
  // Doubles the capacity, the elements in order from index 0.
  void grow() {
    std::vector<T> bigger(buffer_.empty() ? 16 : 2 * buffer_.size());
    for (std::size_t i = 0; i < size_; ++i) bigger[i] = (*this)[i];
    buffer_.swap(bigger);
    head_ = 0;
    mask_ = buffer_.size() - 1;
  }
  std::vector<T> buffer_;
  std::size_t head_ = 0, size_ = 0, mask_ = 0;
};

}  // namespace plumb::strapdown
