// Names of the bits of a message's `flags` field, so that `plumb topic echo` prints
// "flags: 896 (HAS_GYRO, HAS_TEMPERATURE, CALIBRATED)" rather than a bare integer.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "plumb/topics/all.hpp"

namespace plumb::cli {

struct FlagName {
  std::uint32_t bit;
  const char* name;
};

// The bits of M::flags (the generated constants of idl/), empty for a type without named bits.
template <class M> std::span<const FlagName> flag_names() { return {}; }
template <> std::span<const FlagName> flag_names<topics::Attitude>();
template <> std::span<const FlagName> flag_names<topics::SensorSample>();
template <> std::span<const FlagName> flag_names<topics::Navigation>();

// "VALID, ROTATING", "none" for 0, unknown bits as hex ("0x8000").
std::string describe_flags(std::span<const FlagName> names, std::uint32_t flags);

}  // namespace plumb::cli
