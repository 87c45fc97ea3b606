// What the generated topic headers (plumb/topics/*.hpp, built from idl/) share: the type-support
// entry that names a type to the transport, and the topic table's entries. The transport API
// takes a TypeSupport instead of a closed list of types, so a new IDL file needs no code here.
#pragma once

#include <cstdint>
#include <string_view>

namespace plumb::topics {

struct TypeSupport {
  // The scoped IDL name ("plumb::msg::Attitude"): both vendors register the type under it, so a
  // Fast DDS writer and a Cyclone DDS reader match, and a plugin finds its conversions by it.
  const char* type_name;
  // Changes whenever a member, its type or a bound changes: a plugin built from other IDL refuses
  // the type instead of misreading the message that a void* hands it.
  std::uint64_t layout_hash;

  friend bool operator==(const TypeSupport& a, const TypeSupport& b) {
    return a.layout_hash == b.layout_hash && std::string_view(a.type_name) == b.type_name;
  }
};

// Specialised for every struct of idl/ in the generated headers.
template <class T> struct TypeSupportOf;

template <class T> constexpr const TypeSupport& type_support() { return TypeSupportOf<T>::value; }

template <class... T> struct TypeList {};

// A topic's default QoS as declared by its `// @topic` line in idl/.
struct TopicQos {
  bool reliable;
  bool transient_local;
  bool keep_all;
  std::int32_t depth;  // keep-last depth
};

struct TopicEntry {
  const char* name;  // the whole name, or a prefix when `prefix`
  bool prefix;
  const TypeSupport* type;
  TopicQos qos;
};

}  // namespace plumb::topics
