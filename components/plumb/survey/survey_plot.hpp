// The survey as an SVG: plan view (east right, north up, the horizontal 95 % ellipses) and vertical
// section (section distance right, TVD down), failed-QC stations in red.
#pragma once

#include <ostream>

#include "plumb/survey/survey.hpp"

namespace plumb::cli {

void write_survey_svg(std::ostream& out, const survey::Survey& survey);

}  // namespace plumb::cli
