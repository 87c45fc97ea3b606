#include "idl_parser.hpp"

#include <cctype>
#include <stdexcept>

namespace plumb::test {

namespace {

std::string strip_comments(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text.compare(i, 2, "//") == 0) {
      while (i < text.size() && text[i] != '\n') ++i;
      out += '\n';
    } else if (text.compare(i, 2, "/*") == 0) {
      const auto end = text.find("*/", i + 2);
      if (end == std::string::npos) throw std::runtime_error("unterminated comment");
      i = end + 1;
      out += ' ';
    } else {
      out += text[i];
    }
  }
  return out;
}

std::vector<std::string> tokenize(const std::string& text) {
  std::vector<std::string> tokens;
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (std::isspace(c)) {
      ++i;
    } else if (std::isalnum(c) || c == '_') {
      std::size_t j = i;
      while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_')) ++j;
      tokens.push_back(text.substr(i, j - i));
      i = j;
    } else if (text.compare(i, 2, "::") == 0) {
      tokens.emplace_back("::");
      i += 2;
    } else {
      tokens.emplace_back(1, text[i]);
      ++i;
    }
  }
  return tokens;
}

class Parser {
 public:
  explicit Parser(std::vector<std::string> tokens) : tokens_(std::move(tokens)) {}

  IdlFile parse() {
    IdlFile file;
    while (!done()) {
      const std::string t = next();
      if (t == "module") {
        next();  // name
        expect("{");
      } else if (t == "}") {
        expect(";");
      } else if (t == "@") {
        next();  // annotation name (final, ...)
      } else if (t == "const") {
        parse_const(file);
      } else if (t == "struct") {
        file.structs.push_back(parse_struct());
      } else {
        throw std::runtime_error("unexpected '" + t + "'");
      }
    }
    return file;
  }

 private:
  bool done() const { return pos_ >= tokens_.size(); }
  const std::string& peek() const {
    if (done()) throw std::runtime_error("unexpected end of file");
    return tokens_[pos_];
  }
  std::string next() {
    const std::string t = peek();
    ++pos_;
    return t;
  }
  void expect(const std::string& t) {
    const std::string got = next();
    if (got != t) throw std::runtime_error("expected '" + t + "', got '" + got + "'");
  }
  std::size_t number() { return std::stoul(next()); }

  // unsigned long long / long long / unsigned long / double / string<N> / sequence<T, N> / Name
  IdlMember parse_type() {
    IdlMember m;
    std::string t = next();
    if (t == "unsigned") {
      expect("long");
      if (peek() == "long") {
        next();
        m.type = "uint64";
      } else {
        m.type = "uint32";
      }
    } else if (t == "long") {
      if (peek() == "long") {
        next();
        m.type = "int64";
      } else {
        m.type = "int32";
      }
    } else if (t == "string") {
      m.type = "string";
      if (peek() == "<") {
        next();
        m.bound = number();
        expect(">");
      }
    } else if (t == "sequence") {
      m.type = "sequence";
      expect("<");
      m.element = parse_type().type;
      if (peek() == ",") {
        next();
        m.bound = number();
      }
      expect(">");
    } else {
      m.type = t;  // double, boolean, or a struct name
    }
    return m;
  }

  void parse_const(IdlFile& file) {
    parse_type();
    const std::string name = next();
    expect("=");
    file.constants[name] = std::stoll(next());
    expect(";");
  }

  IdlStruct parse_struct() {
    IdlStruct s;
    s.name = next();
    expect("{");
    while (peek() != "}") {
      IdlMember m = parse_type();
      m.name = next();
      // A leading underscore escapes an IDL keyword ("_component" is the field "component").
      if (m.name.size() > 1 && m.name[0] == '_') m.name.erase(0, 1);
      if (peek() == "[") {
        next();
        m.array = number();
        expect("]");
      }
      expect(";");
      s.members.push_back(m);
    }
    expect("}");
    expect(";");
    return s;
  }

  std::vector<std::string> tokens_;
  std::size_t pos_ = 0;
};

}  // namespace

IdlFile parse_idl(const std::string& text) { return Parser(tokenize(strip_comments(text))).parse(); }

}  // namespace plumb::test
