// --column, --units and --axes: the same options, help and refusals in every tool that reads a
// sensor CSV from another logger (docs/import.md).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "plumb/csv/import.hpp"

namespace plumb::components {

struct ImportOptions {
  std::vector<std::string> columns;
  std::vector<std::string> units;
  std::string axes;
  // Throws std::invalid_argument with one line naming the option at fault.
  csv::Import make() const { return csv::make_import(columns, units, axes); }
};

void add_import_options(CLI::App& app, ImportOptions& o);

}  // namespace plumb::components
