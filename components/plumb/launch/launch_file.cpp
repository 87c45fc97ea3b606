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

std::vector<std::string> command(const std::string& path, const YAML::Node& node) {
  std::vector<std::string> words;
  if (node.IsSequence()) {
    for (const auto& word : node) words.push_back(scalar(path, word, "cmd"));
  } else {
    try {
      words = split_words(scalar(path, node, "cmd"));
    } catch (const std::invalid_argument& e) {
      refuse(path, node, std::string("cmd: ") + e.what());
    }
  }
  if (words.empty()) refuse(path, node, "'cmd' is empty: name the program and its options");
  return words;
}

void read_key(const std::string& path, const std::string& key, const YAML::Node& value, ProgramSpec& p) {
  if (key == "name") {
    p.name = scalar(path, value, key);
  } else if (key == "cmd") {
    p.argv = command(path, value);
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
    for (const auto& e : value) p.env[scalar(path, e.first, "env")] = scalar(path, e.second, e.first.Scalar());
  } else if (key == "cwd") {
    p.cwd = scalar(path, value, key);
  } else {
    throw std::invalid_argument(key);  // the caller names the line
  }
}

ProgramSpec read_program(const std::string& path, const YAML::Node& entry) {
  if (!entry.IsMap()) refuse(path, entry, "each entry of 'launch' is a program: cmd, and name, restart, ... below it");
  ProgramSpec p;
  p.where = at(path, entry);
  for (const auto& kv : entry) {
    const std::string key = scalar(path, kv.first, "key");
    try {
      read_key(path, key, kv.second, p);
    } catch (const std::invalid_argument& e) {
      if (std::string(e.what()) != key) throw;
      refuse(path, kv.first,
             "unknown key '" + key + "' (known: name, cmd, restart, restart_limit, restart_delay, on_exit, env, cwd)");
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

std::vector<ProgramSpec> read_launch_file(const std::string& path) {
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
    if (kv.first.Scalar() != "launch") refuse(path, kv.first, "unknown key '" + kv.first.Scalar() + "' (expected 'launch')");
  const YAML::Node list = root["launch"];
  if (!list.IsSequence() || list.size() == 0) refuse(path, list, "'launch' needs a list of programs ('- cmd: ...')");
  std::vector<ProgramSpec> programs;
  std::set<std::string> names;
  for (const auto& entry : list) {
    programs.push_back(read_program(path, entry));
    if (!names.insert(programs.back().name).second)
      throw std::invalid_argument(programs.back().where + ": the name '" + programs.back().name +
                                  "' is given twice (name: tells two runs of one program apart)");
  }
  return programs;
}

}  // namespace plumb::launch
