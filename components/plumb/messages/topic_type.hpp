// Resolving what type a topic carries, and calling generic code with that type.
#pragma once

#include <string>
#include <type_traits>

#include "plumb/transport/topic_names.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::cli {

namespace detail {
template <class F, class First, class... Rest>
decltype(auto) with_type(const transport::TypeSupport& type, F&& f, topics::TypeList<First, Rest...>) {
  if (topics::type_support<First>() == type) return f(First{});
  if constexpr (sizeof...(Rest) > 0) {
    return with_type(type, std::forward<F>(f), topics::TypeList<Rest...>{});
  } else {
    throw transport::Error(std::string("no plumb::topics type for ") + type.type_name);
  }
}
}  // namespace detail

// Calls f(T{}) with the topics:: type of `type`: any struct of idl/, without a list to keep here.
template <class F> decltype(auto) with_topic_type(const transport::TypeSupport& type, F&& f) {
  return detail::with_type(type, std::forward<F>(f), topics::AllTypes{});
}

// The type of `topic`: by the topic table of idl/, else from what discovery reports within
// `discovery_s` seconds. Throws transport::Error "unknown topic ..." listing what is known.
const transport::TypeSupport& resolve_topic_type(transport::Participant& participant, const std::string& topic,
                                                 double discovery_s);

}  // namespace plumb::cli
