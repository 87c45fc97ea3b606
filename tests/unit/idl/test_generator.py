"""idl/generate/generate.py: the generated plumb::topics types follow idl/ member by member, and
IDL outside plumb's subset stops the build with file:line: error: ..."""

import glob
import os
import re
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
IDL_DIR = os.environ.get("PLUMB_IDL_DIR", os.path.join(HERE, "..", "..", "..", "idl"))
GENERATOR = os.environ.get("PLUMB_IDL_GENERATOR", os.path.join(IDL_DIR, "generate", "generate.py"))


def run(language, out_dir, *paths):
    return subprocess.run([sys.executable, GENERATOR, language, out_dir, *paths], capture_output=True, text=True)


def scan_idl(text):
    """A deliberately naive reading of the IDL, independent of the generator's parser:
    {struct: [(member, kind, bound)]} and {const: value}."""
    text = re.sub(r"//[^\n]*|/\*.*?\*/", "", text, flags=re.S)
    structs = {}
    for name, body in re.findall(r"struct\s+(\w+)\s*\{(.*?)\};", text, flags=re.S):
        members = []
        for decl in body.split(";"):
            decl = " ".join(decl.split())
            if not decl:
                continue
            member = re.search(r"(\w+)\s*(\[[^\]]*\]\s*)*$", decl).group(1).lstrip("_")
            bound = re.match(r"(string|sequence)\s*<(?:.*,)?\s*(\d+)\s*>", decl)
            members.append((member, bound.group(1) if bound else "", int(bound.group(2)) if bound else 0))
        structs[name] = members
    consts = dict(re.findall(r"const\s+[\w ]+?\s+(\w+)\s*=\s*(-?\w+)\s*;", text))
    return structs, consts


class GeneratedTypesFollowTheIdl(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.idl_files = sorted(glob.glob(os.path.join(IDL_DIR, "*.idl")))
        result = run("topics", cls.tmp.name, *cls.idl_files)
        assert result.returncode == 0, result.stderr

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def header(self, idl_path):
        stem = os.path.basename(idl_path)[:-4]
        with open(os.path.join(self.tmp.name, "plumb", "topics", stem + ".hpp"), encoding="utf-8") as f:
            return f.read()

    def test_visit_fields_names_every_member_in_idl_order(self):
        self.assertGreaterEqual(len(self.idl_files), 7)
        for path in self.idl_files:
            with open(path, encoding="utf-8") as f:
                structs, _ = scan_idl(f.read())
            header = self.header(path)
            for struct, members in structs.items():
                block = re.search(r"std::remove_const_t<M>, " + struct + r">\nvoid visit_fields.*?\n}\n", header, re.S)
                self.assertIsNotNone(block, f"{struct}: no visit_fields")
                visited = re.findall(r'v\("(\w+)", m\.(\w+)\);', block.group(0))
                self.assertEqual([a for a, _ in visited], [b for _, b in visited])
                self.assertEqual([a for a, _ in visited], [m for m, _, _ in members], f"{os.path.basename(path)}: {struct}")

    def test_string_and_sequence_bounds_are_constants(self):
        for path in self.idl_files:
            with open(path, encoding="utf-8") as f:
                structs, _ = scan_idl(f.read())
            header = self.header(path)
            for struct, members in structs.items():
                for member, kind, bound in members:
                    if not kind:
                        continue
                    camel = "".join(p[:1].upper() + p[1:] for p in member.split("_"))
                    self.assertIn(f"static constexpr std::size_t k{camel}Max = {bound};", header, f"{struct}.{member}")

    def test_consts_keep_their_idl_names_and_values(self):
        for path in self.idl_files:
            with open(path, encoding="utf-8") as f:
                _, consts = scan_idl(f.read())
            header = self.header(path)
            for name, value in consts.items():
                self.assertRegex(header, rf"inline constexpr [\w:]+ {name} = {value};")

    def test_every_topic_struct_has_type_support_under_its_scoped_name(self):
        for path in self.idl_files:
            with open(path, encoding="utf-8") as f:
                structs, _ = scan_idl(f.read())
            for struct in structs:
                self.assertIn(f'TypeSupport value{{"plumb::msg::{struct}", 0x', self.header(path))

    def test_the_navigator_topics_are_in_the_table(self):
        with open(os.path.join(self.tmp.name, "plumb", "topics", "names.hpp"), encoding="utf-8") as f:
            names = f.read()
        self.assertIn('{"plumb/navigation/", true, &TypeSupportOf<Navigation>::value, {true, false, false, 64}}', names)
        self.assertIn('{"plumb/depth", false, &TypeSupportOf<MeasuredDepth>::value, {true, false, false, 64}}', names)


GOOD = """// A type using every construct of the subset.
module plumb {
module msg {
const unsigned long N = 4;
const string NAME = "x";
@final
struct Inner {
  octet o; char c; boolean b; short s; unsigned short us; long l; unsigned long ul;
  long long ll; unsigned long long ull; float f; double d;
};
// @topic plumb/good/<which> best_effort keep_last 8
@final
struct Outer {
  string<7> _component;              // keyword escape
  double grid[2][3];
  string<5> names[N];
  sequence<Inner, N> inners;
  sequence<string<3>, 2> tags;
  sequence<double, 16> values;
  Inner single;
};
};
};
"""


class GeneratorAcceptsTheSubset(unittest.TestCase):
    def test_every_construct_of_the_subset_generates_for_every_language(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "good.idl")
            with open(path, "w", encoding="utf-8") as f:
                f.write(GOOD)
            for language in ("topics", "cyclonedds", "fastdds"):
                result = run(language, os.path.join(tmp, language), path)
                self.assertEqual(result.returncode, 0, f"{language}: {result.stderr}")
            with open(os.path.join(tmp, "topics", "plumb", "topics", "good.hpp"), encoding="utf-8") as f:
                header = f.read()
            self.assertIn("std::string component;", header)
            self.assertIn("std::array<std::array<double, 3>, 2> grid{};", header)
            self.assertIn("std::array<std::string, 4> names{};", header)
            self.assertIn("static constexpr std::size_t kInnersMax = 4;", header)

    def test_layout_hash_follows_the_layout_not_the_comments(self):
        def hash_of(text):
            with tempfile.TemporaryDirectory() as tmp:
                path = os.path.join(tmp, "good.idl")
                with open(path, "w", encoding="utf-8") as f:
                    f.write(text)
                self.assertEqual(run("topics", tmp, path).returncode, 0)
                with open(os.path.join(tmp, "plumb", "topics", "good.hpp"), encoding="utf-8") as f:
                    return re.search(r'"plumb::msg::Outer", (0x[0-9a-f]+)ULL', f.read()).group(1)
        base = hash_of(GOOD)
        self.assertEqual(base, hash_of(GOOD.replace("// keyword escape", "// another comment")))
        self.assertNotEqual(base, hash_of(GOOD.replace("string<7> _component", "string<8> _component")))
        self.assertNotEqual(base, hash_of(GOOD.replace("float f;", "double f;")))


BAD = [
    # (what, IDL text, line, message pattern)
    ("not @final", "module plumb { module msg {\nstruct A {\n double x; }; }; };", 2, "must be @final"),
    ("@appendable", "module plumb { module msg {\n@appendable\nstruct A { double x; }; }; };", 2, "@appendable"),
    ("unbounded string", "module plumb { module msg {\n@final struct A {\n  string name; }; }; };", 3, "unbounded string"),
    ("unbounded sequence", "module plumb { module msg {\n@final struct A {\n\n  sequence<double> v; }; }; };", 4, "unbounded sequence"),
    ("a key", "module plumb { module msg {\n@final struct A {\n  @key long id; }; }; };", 3, "@key"),
    ("@optional", "module plumb { module msg {\n@final struct A {\n  @optional double x; }; }; };", 3, "@optional"),
    ("enum", "module plumb { module msg {\nenum Color { RED };\n}; };", 2, "enum"),
    ("#include", "#include \"other.idl\"\nmodule plumb { };", 1, "#include"),
    ("unknown type", "module plumb { module msg {\n@final struct A {\n  Missing m; }; }; };", 3, "unknown type 'Missing'"),
    ("other module", "module other {\n@final struct A { double x; }; };", 2, "module plumb::msg"),
    ("bad QoS word", "module plumb { module msg {\n// @topic plumb/a reliabel\n@final struct A { double x; }; }; };", 2, "reliabel"),
    ("duplicate member", "module plumb { module msg {\n@final struct A {\n double x;\n double x; }; }; };", 4, "declared twice"),
    ("@topic on nothing", "module plumb { module msg {\n@final struct A { double x; };\n// @topic plumb/a\n}; };", 3, "@topic"),
    ("long double", "module plumb { module msg {\n@final struct A {\n  long double x; }; }; };", 3, "long double"),
]


class GeneratorRefusesWhatIsOutsideTheSubset(unittest.TestCase):
    def test_each_refusal_names_file_and_line(self):
        with tempfile.TemporaryDirectory() as tmp:
            for what, text, line, pattern in BAD:
                with self.subTest(what):
                    path = os.path.join(tmp, "bad.idl")
                    with open(path, "w", encoding="utf-8") as f:
                        f.write(text)
                    result = run("topics", os.path.join(tmp, "out"), path)
                    self.assertEqual(result.returncode, 1, result.stderr)
                    self.assertRegex(result.stderr.strip(), rf"^{re.escape(path)}:{line}: error: .*{re.escape(pattern)}")


if __name__ == "__main__":
    unittest.main()
