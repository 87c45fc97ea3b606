#include "type_support.hpp"

#include <string_view>

namespace plumb::transport::fastdds {

const FastTypeSupport& find_type(const TypeSupport& type) {
  for (const FastTypeSupport* t : generated_types()) {
    if (std::string_view(t->type->type_name) != type.type_name) continue;
    if (t->type->layout_hash != type.layout_hash) {
      throw Error(std::string("type ") + type.type_name +
                  " differs between this program and the fastdds plugin: they were built from different idl/");
    }
    return *t;
  }
  throw Error(std::string("the fastdds plugin has no type ") + type.type_name + ": it was built from an idl/ without it");
}

}  // namespace plumb::transport::fastdds
