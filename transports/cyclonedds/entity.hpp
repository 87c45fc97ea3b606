// Owns one Cyclone DDS entity handle and deletes it (and its children) when it goes away.
#pragma once

#include <dds/dds.h>

#include <utility>

namespace plumb::transport::cyclonedds {

class Entity {
 public:
  Entity() = default;
  explicit Entity(dds_entity_t handle) : handle_(handle) {}
  Entity(Entity&& other) noexcept : handle_(std::exchange(other.handle_, 0)) {}
  Entity& operator=(Entity&& other) noexcept {
    if (this != &other) {
      reset();
      handle_ = std::exchange(other.handle_, 0);
    }
    return *this;
  }
  Entity(const Entity&) = delete;
  Entity& operator=(const Entity&) = delete;
  ~Entity() { reset(); }

  dds_entity_t get() const { return handle_; }
  // Deleting an entity whose parent was deleted first only returns an error code: harmless.
  void reset() {
    if (handle_ > 0) dds_delete(handle_);
    handle_ = 0;
  }

 private:
  dds_entity_t handle_ = 0;
};

}  // namespace plumb::transport::cyclonedds
