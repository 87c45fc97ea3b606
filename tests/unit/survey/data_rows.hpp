// The published examples' tables (tests/data) as rows of cells: '#' lines are notes, the first
// other line is the header.
#pragma once

#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/csv/files.hpp"

namespace plumb::survey::test {

inline std::vector<std::vector<std::string>> data_rows(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  std::vector<std::vector<std::string>> out;
  bool header = true;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    out.push_back(csv::split_line(line));
  }
  return out;
}

}  // namespace plumb::survey::test
