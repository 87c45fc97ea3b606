"""What the generator knows about plumb's topic types, after parsing: plain data, no IDL syntax."""

from dataclasses import dataclass, field
from typing import Optional

# IDL primitive -> (C++ type of the vendor-neutral struct, zero value). Cyclone's C and Fast DDS's
# C++ use the same fixed-width types, so one table serves all three.
PRIMITIVES = {
    "boolean": ("bool", "false"),
    "octet": ("std::uint8_t", "0"),
    "char": ("char", "0"),
    "short": ("std::int16_t", "0"),
    "unsigned short": ("std::uint16_t", "0"),
    "long": ("std::int32_t", "0"),
    "unsigned long": ("std::uint32_t", "0"),
    "long long": ("std::int64_t", "0"),
    "unsigned long long": ("std::uint64_t", "0"),
    "float": ("float", "0"),
    "double": ("double", "0"),
}


@dataclass
class Type:
    """A member's type: kind is primitive, string, array, sequence or struct."""
    kind: str
    name: str = ""                      # primitive name, or the struct's scoped IDL name
    bound: int = 0                      # string<N>, sequence<T, N>, array length
    element: Optional["Type"] = None    # arrays and sequences

    def canonical(self, structs) -> str:
        """A text that changes whenever the wire layout or the C++ layout changes (for the layout hash)."""
        if self.kind == "primitive":
            return self.name
        if self.kind == "string":
            return f"string<{self.bound}>"
        if self.kind == "array":
            return f"{self.element.canonical(structs)}[{self.bound}]"
        if self.kind == "sequence":
            return f"sequence<{self.element.canonical(structs)},{self.bound}>"
        return structs[self.name].canonical(structs)


@dataclass
class Member:
    name: str          # without the IDL keyword escape ("_component" -> "component")
    type: Type
    comment: str
    line: int


@dataclass
class Struct:
    module: list       # ["plumb", "msg"]
    name: str
    members: list
    comment: str
    file: str          # IDL file stem ("attitude")
    line: int

    @property
    def scoped(self) -> str:
        return "::".join(self.module + [self.name])

    def canonical(self, structs) -> str:
        body = ";".join(f"{m.type.canonical(structs)} {m.name}" for m in self.members)
        return f"{self.scoped}{{{body}}}"

    def layout_hash(self, structs) -> int:
        # FNV-1a, 64 bit: stable across Python runs (unlike hash()).
        h = 0xcbf29ce484222325
        for byte in self.canonical(structs).encode():
            h = ((h ^ byte) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
        return h


@dataclass
class Const:
    name: str
    type: str          # IDL primitive name or "string"
    value: str         # C++ literal
    comment: str       # on the same line
    line: int
    leading: str = ""  # the comment lines directly above


@dataclass
class Topic:
    """One `// @topic` line: a topic name (or a prefix, "plumb/attitude/<estimator>") and its QoS."""
    pattern: str       # "plumb/attitude/" for a prefix, else the whole name
    placeholder: str   # "estimator" for a prefix, else ""
    struct: str        # scoped IDL name of the type it carries
    reliable: bool
    transient_local: bool
    keep_all: bool
    depth: int
    file: str
    line: int


@dataclass
class IdlFile:
    stem: str
    path: str
    consts: list = field(default_factory=list)
    structs: list = field(default_factory=list)
    topics: list = field(default_factory=list)
