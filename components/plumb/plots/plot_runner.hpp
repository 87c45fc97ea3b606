// Runs plumb-plot (the matplotlib script installed beside plumb) on a file plumb wrote: the plots of
// `plumb survey --plot` and `plumb compare --plots`.
#pragma once

#include <string>

namespace plumb::cli {

// Runs `plumb-plot KIND INPUT -o OUTPUT`, the script found next to this executable. Throws
// std::runtime_error with the script's own message when it fails (e.g. matplotlib missing).
void run_plot(const std::string& kind, const std::string& input, const std::string& output);

}  // namespace plumb::cli
