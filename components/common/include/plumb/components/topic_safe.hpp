// Topic names made from names users give (a tool id, an estimator host's --name, a plugin): what a
// DDS topic name does not take (anything but letters, digits and '_') becomes '_'.
#pragma once

#include <string>

namespace plumb::components {

std::string topic_safe(std::string name);

// Where an estimator host writes one plugin's parameters (idl/component.idl, ComponentParameters):
// plumb/component/parameters/HOST/PLUGIN.
std::string parameters_topic(const std::string& host, const std::string& plugin);

}  // namespace plumb::components
