// A small parser for the subset of IDL plumb uses (modules, consts, @final structs with basic,
// bounded string, array, sequence and struct members), enough to compare idl/ with messages.hpp.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace plumb::test {

struct IdlMember {
  std::string name;
  std::string type;          // double, int64, uint64, uint32, string, sequence, or a struct name
  std::size_t bound = 0;     // string<N> / sequence<T, N>; 0 when unbounded
  std::size_t array = 0;     // name[N]; 0 when not an array
  std::string element;       // sequence element type
};

struct IdlStruct {
  std::string name;
  std::vector<IdlMember> members;
};

struct IdlFile {
  std::vector<IdlStruct> structs;
  std::map<std::string, long long> constants;
};

// Throws std::runtime_error naming the token where the text leaves the subset.
IdlFile parse_idl(const std::string& text);

}  // namespace plumb::test
