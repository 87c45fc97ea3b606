// The IDL text of a topic type, as the generator found it in idl/: IdlSourceOf<T>::text is the
// text of T's file (and of the files of the types it uses), self-contained, with no #include.
// A recording stores it as the type's schema (MCAP schema encoding "omgidl"), so a reader years
// later, or another tool, knows the layout of the CDR bytes without plumb's sources.
#pragma once

#include <string_view>

namespace plumb::topics {

// Specialised for every struct of idl/ in the generated headers.
template <class T> struct IdlSourceOf;

template <class T> constexpr std::string_view idl_source() { return IdlSourceOf<T>::text; }

}  // namespace plumb::topics
