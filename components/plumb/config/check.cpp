// plumb config check FILE...: checks a DDS configuration file for applications that are not plumb
// (transports/config/*.xml, edited for a computer's interface) before a stock application meets
// it: the vendors report a broken file in many log lines, or ignore a wrong interface until
// nothing matches. One line per problem, "FILE:LINE: what", exit 1; one line per good file.
#include <arpa/inet.h>
#include <ifaddrs.h>
#include <netinet/in.h>
#include <tinyxml2.h>

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "verbs.hpp"

namespace plumb::cli {
namespace {

struct Interface {
  std::string name;
  std::string address;
};

std::vector<Interface> ipv4_interfaces() {
  std::vector<Interface> result;
  ifaddrs* list = nullptr;
  if (getifaddrs(&list) != 0) return result;
  for (const ifaddrs* i = list; i != nullptr; i = i->ifa_next) {
    if (i->ifa_addr == nullptr || i->ifa_addr->sa_family != AF_INET) continue;
    char text[INET_ADDRSTRLEN] = {};
    inet_ntop(AF_INET, &reinterpret_cast<const sockaddr_in*>(i->ifa_addr)->sin_addr, text, sizeof text);
    result.push_back({i->ifa_name, text});
  }
  freeifaddrs(list);
  return result;
}

// "" when `wanted` (a name or an IPv4 address) is an interface of this host, else why not.
std::string interface_problem(const std::string& wanted) {
  std::string available;
  for (const auto& i : ipv4_interfaces()) {
    if (i.name == wanted || i.address == wanted) return "";
    available += (available.empty() ? "" : ", ") + i.name + " (" + i.address + ")";
  }
  return "network interface '" + wanted + "' is not on this computer (available: " + available + ")";
}

// Depth-first: every element named `name` below `parent`.
void collect(const tinyxml2::XMLElement* parent, const char* name, std::vector<const tinyxml2::XMLElement*>& out) {
  for (const auto* e = parent->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
    if (std::string(e->Name()) == name) out.push_back(e);
    collect(e, name, out);
  }
}

// Problems of one file, each "FILE:LINE: what"; the good-file summary in `summary`.
std::vector<std::string> check_file(const std::string& file, std::string& summary) {
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(file.c_str()) != tinyxml2::XML_SUCCESS) {
    if (doc.ErrorID() == tinyxml2::XML_ERROR_FILE_NOT_FOUND || doc.ErrorID() == tinyxml2::XML_ERROR_FILE_COULD_NOT_BE_OPENED)
      return {file + ": cannot be read"};
    // tinyxml2's text repeats the line; the name says what is wrong.
    return {file + ":" + std::to_string(doc.ErrorLineNum()) + ": not well-formed XML (" + doc.ErrorName() + ")"};
  }
  const auto* root = doc.RootElement();
  const std::string kind = root->Name();
  std::vector<std::string> problems;
  auto at = [&](const tinyxml2::XMLElement* e, const std::string& what) {
    problems.push_back(file + ":" + std::to_string(e->GetLineNum()) + ": " + what);
  };
  std::vector<std::string> used;
  if (kind == "CycloneDDS") {
    std::vector<const tinyxml2::XMLElement*> interfaces;
    collect(root, "NetworkInterface", interfaces);
    for (const auto* e : interfaces) {
      const char* name = e->Attribute("name");
      const char* address = e->Attribute("address");
      if (name == nullptr && address == nullptr) {
        at(e, "<NetworkInterface> names no interface (name=\"eth1\" or address=\"192.168.10.2\")");
        continue;
      }
      const std::string wanted = name != nullptr ? name : address;
      if (auto why = interface_problem(wanted); !why.empty()) at(e, why); else used.push_back(wanted);
    }
    summary = "Cyclone DDS configuration (CYCLONEDDS_URI=file://" + file + ")";
  } else if (kind == "dds" || kind == "profiles") {
    std::vector<const tinyxml2::XMLElement*> lists;
    collect(root, "interfaceWhiteList", lists);
    for (const auto* list : lists) {
      for (const auto* e = list->FirstChildElement("address"); e != nullptr; e = e->NextSiblingElement("address")) {
        const std::string wanted = e->GetText() != nullptr ? e->GetText() : "";
        if (auto why = interface_problem(wanted); !why.empty()) at(e, why); else used.push_back(wanted);
      }
    }
    summary = "Fast DDS profile (FASTRTPS_DEFAULT_PROFILES_FILE=" + file + ")";
  } else {
    at(root, "<" + kind + "> is neither a Cyclone DDS configuration (<CycloneDDS>) nor a Fast DDS profile (<dds>)");
  }
  std::string list;
  for (const auto& u : used) list += (list.empty() ? "" : ", ") + u;
  summary += ", interfaces: " + (list.empty() ? std::string("vendor default") : list);
  return problems;
}

}  // namespace

void add_config_verbs(CLI::App& app, Verbs& verbs) {
  auto* config = app.add_subcommand("config", "Check DDS configuration files for applications that are not plumb");
  config->require_subcommand(1);
  auto* check = config->add_subcommand("check", "Check Cyclone DDS / Fast DDS XML files: well-formed, interfaces on this computer");
  auto files = std::make_shared<std::vector<std::string>>();
  check->add_option("file", *files, "XML files (share/plumb/config/*.xml, as edited)")->required();
  verbs.add(check, [files] {
    int status = 0;
    for (const auto& file : *files) {
      std::string summary;
      const auto problems = check_file(file, summary);
      for (const auto& p : problems) std::cerr << p << std::endl;
      if (problems.empty()) std::cout << file << ": ok, " << summary << std::endl;
      else status = 1;
    }
    return status;
  });
}

}  // namespace plumb::cli
