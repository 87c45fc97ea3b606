// The page's files, embedded at build time (embed_web.cmake writes web_assets.cpp from web/).
#pragma once

#include <string>
#include <string_view>

namespace plumb::display_component {

// The embedded file called `name` ("index.html"), or nullptr.
const std::string_view* web_asset(const std::string& name);

}  // namespace plumb::display_component
