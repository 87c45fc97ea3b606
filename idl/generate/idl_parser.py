"""Parser for the IDL subset plumb uses. Anything outside it is refused with file:line, so that a
type the generators cannot carry faithfully on both vendors never gets as far as the wire.

The subset: modules, `const` (integers and strings), @final structs, primitives, string<N>,
fixed arrays T x[N][M], sequence<T, N>, nested structs defined before use, // and /* */ comments,
the `_name` keyword escape, and `// @topic NAME [QOS...]` lines above a struct (see README.md).
"""

import re

from idl_model import PRIMITIVES, Const, IdlFile, Member, Struct, Topic, Type

# The interoperability rules of docs/architecture.md: every struct in module plumb::msg.
TYPE_MODULE = ["plumb", "msg"]

UNSUPPORTED_KEYWORDS = {
    "enum", "union", "typedef", "interface", "bitmask", "bitset", "exception", "native", "valuetype",
    "eventtype", "abstract", "local", "map", "fixed", "any", "wstring", "wchar", "long double", "include",
}

TOKEN = re.compile(r"""
    (?P<space>[ \t\r]+) |
    (?P<newline>\n) |
    (?P<line_comment>//[^\n]*) |
    (?P<block_comment>/\*.*?\*/) |
    (?P<directive>\#[^\n]*) |
    (?P<number>0[xX][0-9a-fA-F]+|\d+) |
    (?P<string>"(?:[^"\\\n]|\\.)*") |
    (?P<ident>[A-Za-z_][A-Za-z0-9_]*) |
    (?P<punct>::|[{};<>,\[\]()=@\-])
""", re.VERBOSE | re.DOTALL)

QOS_WORDS = {"reliable", "best_effort", "volatile", "transient_local", "keep_last", "keep_all"}


class IdlError(Exception):
    """A message in the form file:line: error: text."""


class Token:
    def __init__(self, kind, text, line):
        self.kind, self.text, self.line = kind, text, line

    def __repr__(self):
        return f"{self.text!r}@{self.line}"


class Parser:
    def __init__(self, path, stem, text, known_structs, known_consts):
        self.path = path
        self.result = IdlFile(stem=stem, path=path)
        self.structs = known_structs      # scoped name -> Struct, across files (defined before use)
        self.consts = known_consts        # name -> Const, across files
        self.tokens, self.comments, self.topic_lines = self._tokenize(text)
        self.pos = 0
        self.last_struct_line = 0

    # -- errors and tokens ---------------------------------------------------------------------
    def error(self, message, line=None):
        if line is None:
            line = self.peek().line if self.pos < len(self.tokens) else (self.tokens[-1].line if self.tokens else 1)
        raise IdlError(f"{self.path}:{line}: error: {message}")

    def _tokenize(self, text):
        tokens, comments, topic_lines = [], {}, []
        line, pos = 1, 0
        while pos < len(text):
            m = TOKEN.match(text, pos)
            if not m:
                raise IdlError(f"{self.path}:{line}: error: unexpected character {text[pos]!r}")
            kind, value = m.lastgroup, m.group()
            if kind == "line_comment":
                body = value[2:].strip()
                if body.startswith("@topic"):
                    topic_lines.append((line, body[len("@topic"):].strip()))
                else:
                    trailing = bool(tokens) and tokens[-1].line == line
                    comments.setdefault(line, []).append((body, trailing))
            elif kind == "directive":
                raise IdlError(f"{self.path}:{line}: error: preprocessor directive '{value.split()[0]}' is outside "
                               "plumb's IDL subset (keep each type's structs in one file, without #include)")
            elif kind in ("number", "string", "ident", "punct"):
                tokens.append(Token(kind, value, line))
            line += value.count("\n")
            pos = m.end()
        return tokens, comments, topic_lines

    def peek(self, offset=0):
        i = self.pos + offset
        return self.tokens[i] if i < len(self.tokens) else Token("eof", "<end of file>", self.tokens[-1].line if self.tokens else 1)

    def next(self):
        tok = self.peek()
        if tok.kind == "eof":
            self.error("unexpected end of file")
        self.pos += 1
        return tok

    def expect(self, text):
        tok = self.next()
        if tok.text != text:
            self.error(f"expected '{text}', found '{tok.text}'", tok.line)
        return tok

    def identifier(self, what):
        tok = self.next()
        if tok.kind != "ident":
            self.error(f"expected {what}, found '{tok.text}'", tok.line)
        if tok.text in UNSUPPORTED_KEYWORDS:
            self.error(f"'{tok.text}' is outside plumb's IDL subset", tok.line)
        return tok

    def trailing_comment(self, line):
        return " ".join(text for text, trailing in self.comments.get(line, []) if trailing)

    def leading_comment(self, line):
        """The comment lines directly above `line` (no blank line between)."""
        lines = []
        line -= 1
        while line in self.comments and not any(trailing for _, trailing in self.comments[line]):
            lines.insert(0, " ".join(text for text, _ in self.comments[line]))
            line -= 1
        return " ".join(lines)

    # -- file and module level -----------------------------------------------------------------
    def parse(self):
        self.definitions([], top=True)
        if self.topic_lines:
            self.error("'// @topic' must stand above the struct it names", self.topic_lines[0][0])
        return self.result

    def definitions(self, scope, top=False):
        while True:
            tok = self.peek()
            if tok.kind == "eof":
                if not top:
                    self.error("module is not closed with '};'")
                return
            if tok.text == "}" and not top:
                return
            self.definition(scope)

    def definition(self, scope):
        tok = self.peek()
        if tok.text == "module":
            self.next()
            name = self.identifier("a module name").text
            self.expect("{")
            self.definitions(scope + [name])
            self.expect("}")
            self.expect(";")
        elif tok.text == "const":
            self.const(scope)
        elif tok.text in ("@", "struct"):
            self.struct(scope)
        elif tok.kind == "ident" and tok.text in UNSUPPORTED_KEYWORDS:
            self.error(f"'{tok.text}' is outside plumb's IDL subset (modules, consts, @final structs)")
        else:
            self.error(f"expected a module, const or struct, found '{tok.text}'")

    def check_module(self, scope, what, line):
        if scope != TYPE_MODULE:
            self.error(f"{what} must be in module {'::'.join(TYPE_MODULE)} (docs/architecture.md), "
                       f"not in '{'::'.join(scope) or 'the global scope'}'", line)

    # -- const ---------------------------------------------------------------------------------
    def const(self, scope):
        start = self.expect("const")
        self.check_module(scope, "a const", start.line)
        if self.peek().text == "string":
            self.next()
            if self.peek().text == "<":
                self.next()
                self.integer()
                self.expect(">")
            type_name = "string"
        else:
            type_name = self.primitive_name()
            if type_name in ("float", "double", "boolean", "char"):
                self.error(f"const of type {type_name} is outside plumb's IDL subset (integers and strings)", start.line)
        name = self.identifier("a const name")
        self.expect("=")
        if type_name == "string":
            tok = self.next()
            if tok.kind != "string":
                self.error(f"const {name.text} needs a string literal", tok.line)
            value = tok.text
        else:
            value = str(self.integer())
        end = self.expect(";")
        if name.text in self.consts:
            self.error(f"const {name.text} is defined twice", name.line)
        const = Const(name.text, type_name, value, self.trailing_comment(end.line), start.line,
                      self.leading_comment(start.line))
        self.consts[name.text] = const
        self.result.consts.append(const)

    def integer(self):
        """An integer literal, optionally negative, or the name of an integer const."""
        negative = False
        if self.peek().text == "-":
            self.next()
            negative = True
        tok = self.next()
        if tok.kind == "number":
            value = int(tok.text, 0)
        elif tok.kind == "ident" and tok.text in self.consts and self.consts[tok.text].type != "string":
            value = int(self.consts[tok.text].value)
        else:
            self.error(f"expected an integer or an integer const, found '{tok.text}'", tok.line)
        return -value if negative else value

    def positive(self, what):
        line = self.peek().line
        value = self.integer()
        if value <= 0:
            self.error(f"{what} must be positive, is {value}", line)
        return value

    # -- struct --------------------------------------------------------------------------------
    def annotations(self):
        found = []
        while self.peek().text == "@":
            at = self.next()
            name = self.identifier("an annotation name").text
            if self.peek().text == "(":
                depth = 0
                while True:
                    tok = self.next()
                    depth += tok.text == "("
                    depth -= tok.text == ")"
                    if depth == 0:
                        break
            found.append((name, at.line))
        return found

    def struct(self, scope):
        first = self.peek()
        annotations = self.annotations()
        start = self.expect("struct")
        name = self.identifier("a struct name")
        self.check_module(scope, f"struct {name.text}", name.line)
        names = [a for a, _ in annotations]
        for annotation, line in annotations:
            if annotation != "final":
                self.error(f"annotation @{annotation} is outside plumb's IDL subset: every struct is @final, "
                           "keyless, without @optional (docs/architecture.md interoperability rules)", line)
        if "final" not in names:
            self.error(f"struct {name.text} must be @final (docs/architecture.md interoperability rules)", start.line)
        if self.peek().text == ":":
            self.error("struct inheritance is outside plumb's IDL subset")
        scoped = "::".join(scope + [name.text])
        if scoped in self.structs:
            self.error(f"struct {scoped} is defined twice", name.line)
        self.expect("{")
        members = []
        while self.peek().text != "}":
            members.extend(self.members(scope, name.text))
        self.expect("}")
        self.expect(";")
        if not members:
            self.error(f"struct {name.text} has no members", name.line)
        seen = {}
        for m in members:
            if m.name in seen:
                self.error(f"member '{m.name}' of {name.text} is declared twice", m.line)
            seen[m.name] = m
        struct = Struct(list(scope), name.text, members, self.leading_comment(first.line), self.result.stem, start.line)
        self.structs[scoped] = struct
        self.result.structs.append(struct)
        # Every `// @topic` line since the previous struct names this one.
        for line, text in self.topic_lines:
            if self.last_struct_line < line < first.line:
                self.result.topics.append(self.topic(line, text, scoped))
        self.last_struct_line = start.line
        self.topic_lines = [(l, t) for l, t in self.topic_lines if l > start.line]

    def members(self, scope, struct_name):
        annotations = self.annotations()
        if annotations:
            annotation, line = annotations[0]
            self.error(f"member annotation @{annotation} is outside plumb's IDL subset "
                       "(keyless types, no @optional: docs/architecture.md)", line)
        start = self.peek()
        base = self.type(scope)
        declarators = []
        while True:
            name = self.identifier("a member name")
            dims = []
            while self.peek().text == "[":
                self.next()
                dims.append(self.positive("an array size"))
                self.expect("]")
            member_type = base
            for n in reversed(dims):
                member_type = Type("array", bound=n, element=member_type)
            declarators.append((name, member_type))
            if self.peek().text != ",":
                break
            self.next()
        end = self.expect(";")
        comment = self.trailing_comment(end.line)
        result = []
        for name, member_type in declarators:
            # The IDL escape: "_component" is a member named "component" (what both vendors generate).
            plain = name.text[1:] if name.text.startswith("_") else name.text
            result.append(Member(plain, member_type, comment, start.line))
        return result

    def primitive_name(self):
        tok = self.next()
        words = [tok.text]
        if tok.text == "unsigned":
            nxt = self.next()
            words.append(nxt.text)
            if nxt.text == "long" and self.peek().text == "long":
                words.append(self.next().text)
        elif tok.text == "long":
            if self.peek().text in ("long", "double"):
                words.append(self.next().text)
        name = " ".join(words)
        if name not in PRIMITIVES:
            self.error(f"'{name}' is not a type of plumb's IDL subset", tok.line)
        return name

    def type(self, scope):
        tok = self.peek()
        if tok.text == "string":
            self.next()
            if self.peek().text != "<":
                self.error("unbounded string: give its bound, string<N> (plumb checks every string against it)")
            self.next()
            bound = self.positive("a string bound")
            self.expect(">")
            return Type("string", bound=bound)
        if tok.text == "sequence":
            self.next()
            self.expect("<")
            element = self.type(scope)
            if self.peek().text != ",":
                self.error("unbounded sequence: give its bound, sequence<T, N>")
            self.next()
            bound = self.positive("a sequence bound")
            self.expect(">")
            return Type("sequence", bound=bound, element=element)
        if tok.text in UNSUPPORTED_KEYWORDS or tok.text in ("wstring", "fixed", "map", "any"):
            self.error(f"'{tok.text}' is outside plumb's IDL subset")
        first_word = tok.text
        if first_word in ("unsigned", "long", "short", "float", "double", "boolean", "octet", "char"):
            name = self.primitive_name()
            if name == "long double":
                self.error("long double is outside plumb's IDL subset", tok.line)
            return Type("primitive", name=name)
        # A struct by (possibly scoped) name, looked up from the innermost module outwards.
        absolute = False
        if tok.text == "::":
            self.next()
            absolute = True
        parts = [self.identifier("a type").text]
        while self.peek().text == "::":
            self.next()
            parts.append(self.identifier("a type name").text)
        candidates = [parts] if absolute else [scope[:i] + parts for i in range(len(scope), -1, -1)]
        for candidate in candidates:
            scoped = "::".join(candidate)
            if scoped in self.structs:
                return Type("struct", name=scoped)
        self.error(f"unknown type '{'::'.join(parts)}' (structs must be defined before use, in the same file)", tok.line)

    # -- // @topic lines -----------------------------------------------------------------------
    def topic(self, line, text, scoped):
        words = text.split()
        if not words:
            self.error("'// @topic' needs a topic name, e.g. // @topic plumb/depth reliable keep_last 64", line)
        name = words[0]
        placeholder = ""
        m = re.fullmatch(r"([A-Za-z0-9_/]+/)<([A-Za-z_][A-Za-z0-9_]*)>", name)
        if m:
            name, placeholder = m.group(1), m.group(2)
        elif not re.fullmatch(r"[A-Za-z0-9_]+(/[A-Za-z0-9_]+)*", name):
            self.error(f"topic name '{name}': letters, digits, '_' and '/', optionally ending in '/<placeholder>'", line)
        reliable, transient_local, keep_all, depth = True, False, False, 64
        rest = words[1:]
        i = 0
        while i < len(rest):
            word = rest[i]
            if word not in QOS_WORDS:
                self.error(f"'{word}' is not a QoS word ({', '.join(sorted(QOS_WORDS))})", line)
            if word in ("reliable", "best_effort"):
                reliable = word == "reliable"
            elif word in ("volatile", "transient_local"):
                transient_local = word == "transient_local"
            elif word == "keep_all":
                keep_all = True
            else:
                keep_all = False
                if i + 1 >= len(rest) or not rest[i + 1].isdigit() or int(rest[i + 1]) <= 0:
                    self.error("keep_last needs a positive depth, e.g. keep_last 64", line)
                depth = int(rest[i + 1])
                i += 1
            i += 1
        return Topic(name, placeholder, scoped, reliable, transient_local, keep_all, depth, self.result.stem, line)


def parse_files(paths):
    """Parses the files in order; a struct may use structs of its own file defined above it."""
    structs, consts, files, topics = {}, {}, [], {}
    for path in paths:
        stem = path.rsplit("/", 1)[-1].removesuffix(".idl")
        with open(path, encoding="utf-8") as f:
            text = f.read()
        own_structs, own_consts = {}, {}
        parsed = Parser(path, stem, text, own_structs, own_consts).parse()
        for c in parsed.consts:
            if c.name in consts:
                raise IdlError(f"{path}:{c.line}: error: const {c.name} is also defined in another IDL file")
        consts.update(own_consts)
        for s in parsed.structs:
            if s.scoped in structs:
                raise IdlError(f"{path}:{s.line}: error: struct {s.scoped} is also defined in "
                               f"{structs[s.scoped].file}.idl")
        structs.update(own_structs)
        for t in parsed.topics:
            key = t.pattern + ("<>" if t.placeholder else "")
            if key in topics:
                other = topics[key]
                raise IdlError(f"{path}:{t.line}: error: topic '{t.pattern}' is also declared in {other.file}.idl:{other.line}")
            topics[key] = t
        files.append(parsed)
    return files, structs
