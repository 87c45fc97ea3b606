// Calling generic code with the plumb::topics type a TypeSupport names: what lets a tool handle any
// topic of idl/ (record, echo, play, the display's Foxglove channels) without a list of types to keep.
#pragma once

#include <string>
#include <utility>

#include "plumb/transport/transport.hpp"

namespace plumb::transport {

namespace detail {
template <class F, class First, class... Rest>
decltype(auto) with_type(const TypeSupport& type, F&& f, topics::TypeList<First, Rest...>) {
  if (topics::type_support<First>() == type) return f(First{});
  if constexpr (sizeof...(Rest) > 0) {
    return with_type(type, std::forward<F>(f), topics::TypeList<Rest...>{});
  } else {
    throw Error(std::string("no plumb::topics type for ") + type.type_name);
  }
}
}  // namespace detail

// Calls f(T{}) with the topics:: type of `type`: any struct of idl/. Error for a type plumb does not know.
template <class F> decltype(auto) with_topic_type(const TypeSupport& type, F&& f) {
  return detail::with_type(type, std::forward<F>(f), topics::AllTypes{});
}

}  // namespace plumb::transport
