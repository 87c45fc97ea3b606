// Resolving what type a topic carries, and calling generic code with that type.
#pragma once

#include <string>
#include <type_traits>

#include "plumb/transport/topic_names.hpp"
#include "plumb/transport/transport.hpp"
#include "plumb/transport/with_topic_type.hpp"

namespace plumb::cli {

// Any topic's type in generic code: plumb/transport/with_topic_type.hpp (shared with plumb-display).
using transport::with_topic_type;

// The type of `topic`: by the topic table of idl/, else from what discovery reports within
// `discovery_s` seconds. Throws transport::Error "unknown topic ..." listing what is known.
const transport::TypeSupport& resolve_topic_type(transport::Participant& participant, const std::string& topic,
                                                 double discovery_s);

}  // namespace plumb::cli
