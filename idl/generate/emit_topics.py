"""The vendor-neutral C++ types (namespace plumb::topics) and the topic table, from the parsed IDL."""

import re

from idl_model import PRIMITIVES
from idl_parser import IdlError

BANNER = "// Generated from idl/{source} by idl/generate/generate.py at build time; do not edit.\n"


def camel(text):
    return "".join(part[:1].upper() + part[1:] for part in re.split(r"[_/]", text) if part)


def bound_name(member):
    return f"k{camel(member.name)}Max"


def cpp_type(t):
    if t.kind == "primitive":
        return PRIMITIVES[t.name][0]
    if t.kind == "string":
        return "std::string"
    if t.kind == "array":
        return f"std::array<{cpp_type(t.element)}, {t.bound}>"
    if t.kind == "sequence":
        return f"std::vector<{cpp_type(t.element)}>"
    return t.name.rsplit("::", 1)[-1]


def initializer(t):
    if t.kind == "primitive":
        return " = " + PRIMITIVES[t.name][1]
    if t.kind == "array":
        return "{}"
    return ""


def comment(text, indent=""):
    return f"{indent}// {text}\n" if text else ""


def const_line(c):
    leading = comment(c.leading)
    trailing = f"  // {c.comment}" if c.comment else ""
    if c.type == "string":
        return f"{leading}inline constexpr const char* {c.name} = {c.value};{trailing}\n"
    return f"{leading}inline constexpr {PRIMITIVES[c.type][0]} {c.name} = {c.value};{trailing}\n"


def struct_text(s, structs):
    out = comment(s.comment)
    out += f"struct {s.name} {{\n"
    bounded = [m for m in s.members if m.type.kind in ("string", "sequence")]
    for m in bounded:
        what = "characters" if m.type.kind == "string" else "elements"
        out += f"  static constexpr std::size_t {bound_name(m)} = {m.type.bound};  // {m.name}: at most this many {what}\n"
    if bounded:
        out += "\n"
    for m in s.members:
        trailing = f"  // {m.comment}" if m.comment else ""
        out += f"  {cpp_type(m.type)} {m.name}{initializer(m.type)};{trailing}\n"
    out += (f"\n  // The IDL bound of a string or sequence member by name; 0 for any other name.\n"
            f"  static constexpr std::size_t max_size(std::string_view member) {{\n")
    for m in bounded:
        out += f"    if (member == \"{m.name}\") return {bound_name(m)};\n"
    if not bounded:
        out += "    static_cast<void>(member);\n"
    out += "    return 0;\n  }\n"
    out += f"\n  bool operator==(const {s.name}&) const = default;\n}};\n\n"
    out += (f"template <class M, class V>\n"
            f"  requires std::is_same_v<std::remove_const_t<M>, {s.name}>\n"
            f"void visit_fields(M& m, V&& v) {{\n")
    for m in s.members:
        out += f"  v(\"{m.name}\", m.{m.name});\n"
    out += "}\n\n"
    out += (f"template <> struct TypeSupportOf<{s.name}> {{\n"
            f"  static constexpr TypeSupport value{{\"{s.scoped}\", 0x{s.layout_hash(structs):016x}ULL}};\n"
            f"}};\n\n")
    return out


def idl_dependencies(s, structs, seen):
    """The IDL files (stems) whose text a self-contained schema of `s` needs, dependencies first."""
    for m in s.members:
        t = m.type
        while t.kind in ("array", "sequence"):
            t = t.element
        if t.kind == "struct" and t.name in structs:
            idl_dependencies(structs[t.name], structs, seen)
    if s.file not in seen:
        seen.append(s.file)
    return seen


def idl_source_text(s, structs, texts):
    """The IDL of `s` and every type it uses, one file's text after another (no #include): what a
    recording stores as the type's schema (MCAP schema encoding `omgidl`)."""
    text = "".join(texts[stem] for stem in idl_dependencies(s, structs, []))
    if ")plumbidl\"" in text:
        raise IdlError(f"{s.file}.idl:{s.line}: error: the text ')plumbidl\"' cannot be embedded")
    return text


def idl_source_specialisation(s, structs, texts):
    return (f"template <> struct IdlSourceOf<{s.name}> {{\n"
            f"  static constexpr std::string_view text = R\"plumbidl({idl_source_text(s, structs, texts)})plumbidl\";\n"
            f"}};\n\n")


def file_header(f, structs, texts=None):
    out = BANNER.format(source=f"{f.stem}.idl")
    out += ("#pragma once\n\n#include <array>\n#include <cstddef>\n#include <cstdint>\n#include <string>\n"
            "#include <string_view>\n#include <type_traits>\n#include <vector>\n\n#include \"plumb/topics/idl_source.hpp\"\n"
            "#include \"plumb/topics/type_support.hpp\"\n\n"
            "namespace plumb::topics {\n\n")
    for c in f.consts:
        out += const_line(c)
    if f.consts:
        out += "\n"
    for s in f.structs:
        out += struct_text(s, structs)
        if texts is not None:
            out += idl_source_specialisation(s, structs, texts)
    out += "}  // namespace plumb::topics\n"
    return out


def umbrella(files):
    out = BANNER.format(source="*.idl")
    out += "#pragma once\n\n#include <string_view>\n\n"
    for f in files:
        out += f"#include \"plumb/topics/{f.stem}.hpp\"\n"
    names = [s.name for f in files for s in f.structs]
    out += "\nnamespace plumb::topics {\n\n"
    out += "// Every struct of idl/, for code that goes through all of them (tests, tools).\n"
    out += f"using AllTypes = TypeList<{', '.join(names)}>;\n"
    out += "inline constexpr const TypeSupport* kAllTypes[] = {\n"
    out += "".join(f"    &TypeSupportOf<{n}>::value,\n" for n in names)
    out += "};\n\n"
    out += ("// The type support of the scoped IDL name (\"plumb::msg::Attitude\"); nullptr if idl/ has no such type.\n"
            "inline const TypeSupport* find_type_support(std::string_view type_name) {\n"
            "  for (const TypeSupport* t : kAllTypes) {\n"
            "    if (type_name == t->type_name) return t;\n"
            "  }\n"
            "  return nullptr;\n"
            "}\n\n}  // namespace plumb::topics\n")
    return out


def topic_constant(t):
    parts = t.pattern.removeprefix("plumb/").strip("/")
    return f"k{camel(parts)}" + ("Prefix" if t.placeholder else "")


def names_header(files, structs):
    topics = [t for f in files for t in f.topics]
    out = BANNER.format(source="*.idl (the // @topic lines)")
    out += "#pragma once\n\n#include <string>\n\n#include \"plumb/topics/all.hpp\"\n\n"
    out += "namespace plumb::topics::names {\n\n"
    seen = {}
    for t in topics:
        constant = topic_constant(t)
        if constant in seen:
            raise IdlError(f"{t.file}.idl:{t.line}: error: topic '{t.pattern}' gives the constant {constant}, "
                           f"as does {seen[constant].file}.idl:{seen[constant].line}")
        seen[constant] = t
        shown = t.pattern + (f"<{t.placeholder}>" if t.placeholder else "")
        out += f"inline constexpr const char* {constant} = \"{t.pattern}\";  // {shown}: {structs[t.struct].name}\n"
    out += "\n"
    functions = set()
    for t in topics:
        if not t.placeholder:
            continue
        function = t.pattern.strip("/").rsplit("/", 1)[-1]
        if function in functions:
            raise IdlError(f"{t.file}.idl:{t.line}: error: a second topic prefix ending in '{function}/'")
        functions.add(function)
        out += (f"// \"{t.pattern}<{t.placeholder}>\"\n"
                f"inline std::string {function}(const std::string& {t.placeholder}) {{ "
                f"return std::string({topic_constant(t)}) + {t.placeholder}; }}\n")
    out += "\n}  // namespace plumb::topics::names\n\nnamespace plumb::topics {\n\n"
    out += ("// Name (or prefix, followed by at least one character) -> type and default QoS. An exact name\n"
            "// wins over a prefix; the longest prefix wins over a shorter one.\n"
            "inline constexpr TopicEntry kTopicTable[] = {\n")
    for t in topics:
        name = structs[t.struct].name
        qos = (f"{{{str(t.reliable).lower()}, {str(t.transient_local).lower()}, "
               f"{str(t.keep_all).lower()}, {t.depth}}}")
        out += f"    {{\"{t.pattern}\", {str(bool(t.placeholder)).lower()}, &TypeSupportOf<{name}>::value, {qos}}},\n"
    out += "};\n\n"
    carried = []
    for t in topics:
        name = structs[t.struct].name
        if name not in carried:
            carried.append(name)
    out += "// The types carried by the topics above, once each.\n"
    out += f"using TopicTypes = TypeList<{', '.join(carried)}>;\n\n}}  // namespace plumb::topics\n"
    return out


def emit(files, structs):
    """{relative output path: text}"""
    texts = {}
    for f in files:
        with open(f.path, encoding="utf-8") as source:
            texts[f.stem] = source.read()
    outputs = {f"plumb/topics/{f.stem}.hpp": file_header(f, structs, texts) for f in files}
    outputs["plumb/topics/all.hpp"] = umbrella(files)
    outputs["plumb/topics/names.hpp"] = names_header(files, structs)
    return outputs
