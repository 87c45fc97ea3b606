#include "launch_file.hpp"

#include <fstream>
#include <set>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

namespace plumb::launch {
namespace {

std::string at(const std::string& path, const YAML::Node& node) {
  return path + ":" + std::to_string(node.Mark().line + 1);
}

[[noreturn]] void refuse(const std::string& path, const YAML::Node& node, const std::string& what) {
  throw std::invalid_argument(at(path, node) + ": " + what);
}

std::string scalar(const std::string& path, const YAML::Node& node, const std::string& key) {
  if (!node.IsScalar()) refuse(path, node, "'" + key + "' needs one value");
  return node.Scalar();
}

double number(const std::string& path, const YAML::Node& node, const std::string& key, double min) {
  const std::string text = scalar(path, node, key);
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size() && v >= min) return v;
  } catch (const std::logic_error&) {
  }
  refuse(path, node, "'" + key + "' must be a number >= " + std::to_string(static_cast<int>(min)) + ", got '" + text + "'");
}

std::string names_of(const Arguments& arguments) {
  std::string names;
  for (const auto& [name, value] : arguments) names += (names.empty() ? "" : ", ") + name;
  return names.empty() ? "none" : names;
}

// `$(var NAME)` replaced by the argument's value.
std::string substitute(const std::string& path, const YAML::Node& node, std::string text, const Arguments& arguments) {
  for (std::size_t pos = text.find("$("); pos != std::string::npos; pos = text.find("$(", pos)) {
    const std::size_t end = text.find(')', pos);
    const std::string inside = text.substr(pos + 2, end == std::string::npos ? std::string::npos : end - pos - 2);
    if (end == std::string::npos || inside.rfind("var ", 0) != 0)
      refuse(path, node, "'$(' starts a substitution: $(var NAME), got '" + text.substr(pos) + "'");
    const std::string name = inside.substr(4);
    const auto it = arguments.find(name);
    if (it == arguments.end())
      refuse(path, node, "$(var " + name + "): no launch argument '" + name + "' (declared under 'arguments:': " +
                             names_of(arguments) + ")");
    text.replace(pos, end + 1 - pos, it->second);
    pos += it->second.size();
  }
  return text;
}

std::string value(const std::string& path, const YAML::Node& node, const std::string& key, const Arguments& arguments) {
  return substitute(path, node, scalar(path, node, key), arguments);
}

std::vector<std::string> command(const std::string& path, const YAML::Node& node, const Arguments& arguments) {
  std::vector<std::string> words;
  if (node.IsSequence()) {
    for (const auto& word : node) words.push_back(value(path, word, "cmd", arguments));
  } else {
    const std::string line = value(path, node, "cmd", arguments);
    try {
      words = split_words(line);
    } catch (const std::invalid_argument& e) {
      refuse(path, node, std::string("cmd: ") + e.what());
    }
  }
  if (words.empty()) refuse(path, node, "'cmd' is empty: name the program and its options");
  return words;
}

void read_key(const std::string& path, const std::string& key, const YAML::Node& value, ProgramSpec& p,
              const Arguments& arguments) {
  if (key == "name") {
    p.name = scalar(path, value, key);
  } else if (key == "cmd") {
    p.argv = command(path, value, arguments);
    p.cmd_where = at(path, value);
  } else if (key == "required") {
    const std::string v = scalar(path, value, key);
    if (v != "true" && v != "false") refuse(path, value, "'required' is true or false, got '" + v + "'");
    p.required = v == "true";
  } else if (key == "restart") {
    const std::string v = scalar(path, value, key);
    if (v != "never" && v != "on-failure") refuse(path, value, "'restart' is never or on-failure, got '" + v + "'");
    p.restart = v == "never" ? Restart::Never : Restart::OnFailure;
  } else if (key == "restart_limit") {
    p.restart_limit = static_cast<int>(number(path, value, key, 0));
  } else if (key == "restart_delay") {
    p.restart_delay_s = number(path, value, key, 0);
  } else if (key == "on_exit") {
    const std::string v = scalar(path, value, key);
    if (v != "shutdown" && v != "continue") refuse(path, value, "'on_exit' is shutdown or continue, got '" + v + "'");
    p.shutdown_on_exit = v == "shutdown";
  } else if (key == "env") {
    if (!value.IsMap()) refuse(path, value, "'env' holds NAME: VALUE lines");
    for (const auto& e : value)
      p.env[scalar(path, e.first, "env")] = substitute(path, e.second, scalar(path, e.second, e.first.Scalar()), arguments);
  } else if (key == "cwd") {
    p.cwd = substitute(path, value, scalar(path, value, key), arguments);
  } else {
    throw std::invalid_argument(key);  // the caller names the line
  }
}

ProgramSpec read_program(const std::string& path, const YAML::Node& entry, const Arguments& arguments) {
  if (!entry.IsMap()) refuse(path, entry, "each entry of 'launch' is a program: cmd, and name, restart, ... below it");
  ProgramSpec p;
  p.where = at(path, entry);
  for (const auto& kv : entry) {
    const std::string key = scalar(path, kv.first, "key");
    try {
      read_key(path, key, kv.second, p, arguments);
    } catch (const std::invalid_argument& e) {
      if (std::string(e.what()) != key) throw;
      refuse(path, kv.first,
             "unknown key '" + key + "' (known: name, cmd, restart, restart_limit, restart_delay, required, on_exit, env, cwd)");
    }
  }
  if (p.argv.empty()) refuse(path, entry, "a program without 'cmd'");
  if (p.name.empty()) p.name = p.argv[0].substr(p.argv[0].rfind('/') + 1);
  return p;
}

}  // namespace

std::vector<std::string> split_words(const std::string& line) {
  std::vector<std::string> words;
  std::string word;
  bool in_word = false;
  char quote = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote) {
      if (c == quote) quote = 0;
      else if (c == '\\' && quote == '"' && i + 1 < line.size()) word += line[++i];
      else word += c;
    } else if (c == '\'' || c == '"') {
      quote = c;
      in_word = true;
    } else if (c == '\\' && i + 1 < line.size()) {
      word += line[++i];
      in_word = true;
    } else if (c == ' ' || c == '\t') {
      if (in_word) words.push_back(word);
      word.clear();
      in_word = false;
    } else {
      word += c;
      in_word = true;
    }
  }
  if (quote) throw std::invalid_argument(std::string("unterminated ") + quote + " quote");
  if (in_word) words.push_back(word);
  return words;
}

Arguments parse_arguments(const std::vector<std::string>& words) {
  Arguments given;
  for (const auto& w : words) {
    const auto sep = w.find(":=");
    if (sep == std::string::npos || sep == 0)
      throw std::invalid_argument("'" + w + "': a launch argument is NAME:=VALUE (e.g. port:=8081)");
    given[w.substr(0, sep)] = w.substr(sep + 2);
  }
  return given;
}

std::vector<ProgramSpec> read_launch_file(const std::string& path, const Arguments& given) {
  if (!std::ifstream(path)) throw std::invalid_argument("cannot read launch file '" + path + "'");
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw std::invalid_argument(path + ":" + std::to_string(e.mark.line + 1) + ": not YAML: " + e.msg);
  }
  if (!root.IsMap() || !root["launch"])
    throw std::invalid_argument(path + ": expected 'launch:' and below it a list of programs ('- cmd: ...')");
  for (const auto& kv : root)
    if (kv.first.Scalar() != "launch" && kv.first.Scalar() != "arguments")
      refuse(path, kv.first, "unknown key '" + kv.first.Scalar() + "' (expected 'arguments' and 'launch')");
  // The declared arguments with their defaults, then the command line's values.
  Arguments arguments;
  if (const YAML::Node declared = root["arguments"]) {
    if (!declared.IsMap()) refuse(path, declared, "'arguments' holds NAME: DEFAULT lines");
    for (const auto& kv : declared) arguments[scalar(path, kv.first, "arguments")] = scalar(path, kv.second, kv.first.Scalar());
  }
  for (const auto& [name, v] : given) {
    if (!arguments.count(name))
      throw std::invalid_argument("launch argument '" + name + "' is not declared in " + path + " (declared: " +
                                  names_of(arguments) + ")");
    arguments[name] = v;
  }
  const YAML::Node list = root["launch"];
  if (!list.IsSequence() || list.size() == 0) refuse(path, list, "'launch' needs a list of programs ('- cmd: ...')");
  std::vector<ProgramSpec> programs;
  std::set<std::string> names;
  for (const auto& entry : list) {
    programs.push_back(read_program(path, entry, arguments));
    if (!names.insert(programs.back().name).second)
      throw std::invalid_argument(programs.back().where + ": the name '" + programs.back().name +
                                  "' is given twice (name: tells two runs of one program apart)");
  }
  return programs;
}

}  // namespace plumb::launch
