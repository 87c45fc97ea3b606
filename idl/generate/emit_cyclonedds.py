"""Cyclone DDS type support: conversions between plumb::topics types and the C structs idlc
generates (plumb_idl/<file>.h), and one CycloneTypeSupport entry per struct.

Outgoing sequences point into a per-write arena (transports/cyclonedds/convert.hpp) and are
never freed by Cyclone; incoming samples are loaned by Cyclone and only read.
"""

from emit_topics import BANNER


def c_name(scoped):
    return scoped.replace("::", "_")


def to_c(t, src, dst, path, depth=0):
    i = f"i{depth}"
    if t.kind == "primitive":
        return f"{dst} = {src};"
    if t.kind == "string":
        return f"put_string({src}, {dst}, \"{path}\");"
    if t.kind == "struct":
        return f"to_c({src}, {dst}, arena);"
    if t.kind == "array":
        inner = to_c(t.element, f"{src}[{i}]", f"{dst}[{i}]", path, depth + 1)
        return f"for (std::size_t {i} = 0; {i} < {t.bound}; ++{i}) {{ {inner} }}"
    s, b = f"s{depth}", f"b{depth}"
    inner = to_c(t.element, f"{s}[{i}]", f"{b}[{i}]", path, depth + 1)
    return (f"{{\n    const auto& {s} = {src};\n"
            f"    check_length({s}.size(), {t.bound}, \"{path}\");\n"
            f"    auto* {b} = arena.alloc<std::remove_pointer_t<decltype({dst}._buffer)>>({s}.size());\n"
            f"    for (std::size_t {i} = 0; {i} < {s}.size(); ++{i}) {{ {inner} }}\n"
            f"    set_sequence({dst}, {b}, {s}.size());\n  }}")


def from_c(t, src, dst, depth=0):
    i = f"i{depth}"
    if t.kind == "primitive":
        return f"{dst} = {src};"
    if t.kind == "string":
        return f"get_string({src}, {dst});"
    if t.kind == "struct":
        return f"from_c({src}, {dst});"
    if t.kind == "array":
        inner = from_c(t.element, f"{src}[{i}]", f"{dst}[{i}]", depth + 1)
        return f"for (std::size_t {i} = 0; {i} < {t.bound}; ++{i}) {{ {inner} }}"
    inner = from_c(t.element, f"{src}._buffer[{i}]", f"{dst}[{i}]", depth + 1)
    return (f"{dst}.resize({src}._length);\n"
            f"  for (std::uint32_t {i} = 0; {i} < {src}._length; ++{i}) {{ {inner} }}")


def source(f, structs):
    out = BANNER.format(source=f"{f.stem}.idl")
    out += (f"#include \"convert.hpp\"\n#include \"plumb/topics/{f.stem}.hpp\"\n#include \"plumb_idl/{f.stem}.h\"\n"
            "#include \"type_support.hpp\"\n\n"
            "namespace plumb::transport::cyclonedds::generated {\n\n")
    for s in f.structs:
        c = c_name(s.scoped)
        out += f"void to_c(const topics::{s.name}& m, {c}& c, Arena& arena);\n"
        out += f"void from_c(const {c}& c, topics::{s.name}& m);\n"
    out += "\n"
    for s in f.structs:
        c = c_name(s.scoped)
        uses_arena = any(_needs_arena(m.type, structs) for m in s.members)
        out += f"void to_c(const topics::{s.name}& m, {c}& c, Arena& {'arena' if uses_arena else '/*arena*/'}) {{\n"
        for m in s.members:
            out += "  " + to_c(m.type, f"m.{m.name}", f"c.{m.name}", f"{s.name}.{m.name}") + "\n"
        out += "}\n\n"
        out += f"void from_c(const {c}& c, topics::{s.name}& m) {{\n"
        for m in s.members:
            out += "  " + from_c(m.type, f"c.{m.name}", f"m.{m.name}") + "\n"
        out += "}\n\n"
    for s in f.structs:
        c = c_name(s.scoped)
        out += (f"extern const CycloneTypeSupport type_{c};\n"
                f"const CycloneTypeSupport type_{c}{{\n"
                f"    &topics::TypeSupportOf<topics::{s.name}>::value,\n"
                f"    &{c}_desc,\n"
                f"    [](dds_entity_t writer, const void* message) {{\n"
                f"      Arena arena;\n"
                f"      {c} c{{}};\n"
                f"      to_c(*static_cast<const topics::{s.name}*>(message), c, arena);\n"
                f"      return dds_write(writer, &c);\n"
                f"    }},\n"
                f"    [](const void* sample, void* message) {{\n"
                f"      from_c(*static_cast<const {c}*>(sample), *static_cast<topics::{s.name}*>(message));\n"
                f"    }}}};\n\n")
    out += "}  // namespace plumb::transport::cyclonedds::generated\n"
    return out


def _needs_arena(t, structs):
    if t.kind == "sequence":
        return True
    if t.kind == "array":
        return _needs_arena(t.element, structs)
    if t.kind == "struct":
        return True  # the nested to_c takes it either way
    return False


def registry(files):
    out = BANNER.format(source="*.idl")
    out += "#include \"type_support.hpp\"\n\nnamespace plumb::transport::cyclonedds {\n\nnamespace generated {\n"
    names = [c_name(s.scoped) for f in files for s in f.structs]
    out += "".join(f"extern const CycloneTypeSupport type_{n};\n" for n in names)
    out += "}  // namespace generated\n\nstd::span<const CycloneTypeSupport* const> generated_types() {\n"
    out += "  static const CycloneTypeSupport* const types[] = {\n"
    out += "".join(f"      &generated::type_{n},\n" for n in names)
    out += "  };\n  return types;\n}\n\n}  // namespace plumb::transport::cyclonedds\n"
    return out


def emit(files, structs):
    outputs = {f"{f.stem}.cpp": source(f, structs) for f in files}
    outputs["types.cpp"] = registry(files)
    return outputs
