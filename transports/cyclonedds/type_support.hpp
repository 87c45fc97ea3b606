// What the Cyclone plugin needs per topic type, generated from idl/ at build time
// (idl/generate/emit_cyclonedds.py): idlc's topic descriptor and the conversions between the
// plumb::topics struct and idlc's C struct. The endpoints are written once against this.
#pragma once

#include <dds/dds.h>

#include <span>

#include "plumb/transport/transport.hpp"

namespace plumb::transport::cyclonedds {

struct CycloneTypeSupport {
  const TypeSupport* type;
  const dds_topic_descriptor_t* descriptor;
  // Converts the plumb::topics message and writes it; throws Error when it exceeds an IDL bound.
  dds_return_t (*write)(dds_entity_t writer, const void* message);
  // Copies a sample (idlc's C struct, loaned from the reader) into the plumb::topics message.
  void (*read)(const void* sample, void* message);
};

// Every struct of idl/ (generated).
std::span<const CycloneTypeSupport* const> generated_types();

// The entry of `type`; Error when this plugin was built from IDL without it, or with another layout.
const CycloneTypeSupport& find_type(const TypeSupport& type);

}  // namespace plumb::transport::cyclonedds
