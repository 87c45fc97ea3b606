// Where an estimator host writes one plugin's parameters (idl/component.idl, ComponentParameters):
// plumb/component/parameters/HOST/PLUGIN, each name with what a DDS topic name does not take
// (anything but letters, digits and '_') as '_'.
#pragma once

#include <string>

namespace plumb::components {

std::string parameters_topic(const std::string& host, const std::string& plugin);

}  // namespace plumb::components
