// The anti-collision options, the same for `plumb clearance` (offline) and plumb-survey (live): the
// offset wells, the hole radii, the ISCWSA separation rule's constants and the warning and alarm
// levels (docs/surveys.md, "Anti-collision").
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "plumb/survey/clearance.hpp"

namespace plumb::components {

struct ClearanceCliOptions {
  std::vector<std::string> offsets;                               // offset wells' files
  // Offset wells that are sidetracks of the reference: each kicks off it at its own first station.
  std::vector<std::string> sidetracks;
  double reference_radius_m = 0.4572, offset_radius_m = 0.3048;  // 36 in and 24 in holes
  survey::SeparationRule rule;
  survey::ClearanceLevels levels;
};

// --offset and --sidetrack (repeated; one of them required where `offsets_required`),
// --reference-radius, --offset-radius, --k, --sigma-pa, --surface-margin, --warning, --alarm.
void add_clearance_options(CLI::App& app, ClearanceCliOptions& o, bool offsets_required);

// Throws std::invalid_argument (a usage error) for a rule, levels or radii that cannot work.
void check_clearance_options(const ClearanceCliOptions& o);

// A well's name: its file's name without the folder and the extensions (.wellpath.csv, .csv).
std::string clearance_well_name(const std::string& path);

// A number as the clearance lines print it: `decimals` places, fixed.
std::string clearance_number(double v, int decimals);

}  // namespace plumb::components
