"""Fast DDS type support: conversions between plumb::topics types and the classes fastddsgen
generates (plumb_idl/<file>.h, <file>PubSubTypes.h), and one FastTypeSupport entry per struct.

fastddsgen maps arrays to std::array and sequences to std::vector like plumb::topics does, so
those of primitives are assigned whole; bounded strings are fixed_string<N>, checked on the way.
"""

from emit_topics import BANNER


def _plain(t):
    """True when the neutral and the Fast DDS C++ types are the same (assignable whole)."""
    if t.kind == "primitive":
        return True
    if t.kind in ("array", "sequence"):
        return _plain(t.element)
    return False


def to_fast(t, src, dst, path, depth=0):
    i = f"i{depth}"
    if t.kind == "sequence":
        check = f"check_length({src}.size(), {t.bound}, \"{path}\");"
        if _plain(t.element):
            return f"{check} {dst} = {src};"
        s, d = f"s{depth}", f"d{depth}"
        inner = to_fast(t.element, f"{s}[{i}]", f"{d}[{i}]", path, depth + 1)
        return (f"{{\n    const auto& {s} = {src};\n    check_length({s}.size(), {t.bound}, \"{path}\");\n"
                f"    auto& {d} = {dst};\n    {d}.resize({s}.size());\n"
                f"    for (std::size_t {i} = 0; {i} < {s}.size(); ++{i}) {{ {inner} }}\n  }}")
    if _plain(t):
        return f"{dst} = {src};"
    if t.kind == "string":
        return f"put_string({src}, {dst}, \"{path}\");"
    if t.kind == "struct":
        return f"to_fast({src}, {dst});"
    s, d = f"s{depth}", f"d{depth}"
    inner = to_fast(t.element, f"{s}[{i}]", f"{d}[{i}]", path, depth + 1)
    return (f"{{\n    const auto& {s} = {src};\n    auto& {d} = {dst};\n"
            f"    for (std::size_t {i} = 0; {i} < {t.bound}; ++{i}) {{ {inner} }}\n  }}")


def from_fast(t, src, dst, depth=0):
    i = f"i{depth}"
    if _plain(t):
        return f"{dst} = {src};"
    if t.kind == "string":
        return f"get_string({src}, {dst});"
    if t.kind == "struct":
        return f"from_fast({src}, {dst});"
    s, d = f"s{depth}", f"d{depth}"
    inner = from_fast(t.element, f"{s}[{i}]", f"{d}[{i}]", depth + 1)
    size = f"{s}.size()" if t.kind == "sequence" else str(t.bound)
    resize = f"    {d}.resize({s}.size());\n" if t.kind == "sequence" else ""
    return (f"{{\n    const auto& {s} = {src};\n    auto& {d} = {dst};\n{resize}"
            f"    for (std::size_t {i} = 0; {i} < {size}; ++{i}) {{ {inner} }}\n  }}")


def fast_name(s):
    return s.scoped  # fastddsgen keeps the IDL modules as C++ namespaces


def source(f):
    out = BANNER.format(source=f"{f.stem}.idl")
    out += (f"#include \"convert.hpp\"\n#include \"plumb/topics/{f.stem}.hpp\"\n#include \"plumb_idl/{f.stem}.h\"\n"
            f"#include \"plumb_idl/{f.stem}PubSubTypes.h\"\n#include \"type_support.hpp\"\n\n"
            "namespace plumb::transport::fastdds::generated {\n\n")
    for s in f.structs:
        out += f"void to_fast(const topics::{s.name}& in, {fast_name(s)}& out);\n"
        out += f"void from_fast(const {fast_name(s)}& in, topics::{s.name}& out);\n"
    out += "\n"
    for s in f.structs:
        out += f"void to_fast(const topics::{s.name}& in, {fast_name(s)}& out) {{\n"
        for m in s.members:
            out += "  " + to_fast(m.type, f"in.{m.name}", f"out.{m.name}()", f"{s.name}.{m.name}") + "\n"
        out += "}\n\n"
        out += f"void from_fast(const {fast_name(s)}& in, topics::{s.name}& out) {{\n"
        for m in s.members:
            out += "  " + from_fast(m.type, f"in.{m.name}()", f"out.{m.name}") + "\n"
        out += "}\n\n"
    for s in f.structs:
        c = s.scoped.replace("::", "_")
        out += (f"extern const FastTypeSupport type_{c};\n"
                f"const FastTypeSupport type_{c}{{\n"
                f"    &topics::TypeSupportOf<topics::{s.name}>::value,\n"
                f"    []() -> eprosima::fastdds::dds::TopicDataType* {{ return new {fast_name(s)}PubSubType(); }},\n"
                f"    []() -> std::unique_ptr<SampleCodec> {{\n"
                f"      return std::make_unique<Codec<topics::{s.name}, {fast_name(s)}, &to_fast, &from_fast>>();\n"
                f"    }}}};\n\n")
    out += "}  // namespace plumb::transport::fastdds::generated\n"
    return out


def registry(files):
    out = BANNER.format(source="*.idl")
    out += "#include \"type_support.hpp\"\n\nnamespace plumb::transport::fastdds {\n\nnamespace generated {\n"
    names = [s.scoped.replace("::", "_") for f in files for s in f.structs]
    out += "".join(f"extern const FastTypeSupport type_{n};\n" for n in names)
    out += "}  // namespace generated\n\nstd::span<const FastTypeSupport* const> generated_types() {\n"
    out += "  static const FastTypeSupport* const types[] = {\n"
    out += "".join(f"      &generated::type_{n},\n" for n in names)
    out += "  };\n  return types;\n}\n\n}  // namespace plumb::transport::fastdds\n"
    return out


def emit(files, structs):
    outputs = {f"{f.stem}.cpp": source(f) for f in files}
    outputs["types.cpp"] = registry(files)
    return outputs
