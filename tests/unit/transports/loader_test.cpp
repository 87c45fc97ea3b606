// The loader: search path, names, errors that list what was found, the PLUMB_TRANSPORT default.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>

#include <unistd.h>

#include "plumb/transport/loader.hpp"

namespace {

using namespace plumb::transport;

// Restores an environment variable when the test ends.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value) setenv(name, value, 1);
    else unsetenv(name);
  }
  ~ScopedEnv() {
    if (old_) setenv(name_, old_->c_str(), 1);
    else unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

std::string error_of(const std::string& name) {
  try {
    load_transport(name);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

bool found(const std::string& name) {
  for (const auto& t : find_transports()) if (t.name == name) return true;
  return false;
}

TEST(Loader, FindsTheBuiltPluginsNextToTheLibrary) {
  const ScopedEnv path("PLUMB_TRANSPORT_PATH", nullptr);
  for (const std::string name : {PLUMB_BUILT_TRANSPORTS}) EXPECT_TRUE(found(name)) << name;
}

TEST(Loader, UnknownNameIsAOneLineErrorListingTheTransportsFound) {
  const ScopedEnv path("PLUMB_TRANSPORT_PATH", nullptr);
  const std::string message = error_of("foo");
  EXPECT_NE(message.find("unknown transport 'foo'"), std::string::npos) << message;
  for (const std::string name : {PLUMB_BUILT_TRANSPORTS}) EXPECT_NE(message.find(name), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(Loader, AMisspelledNameIsAUsageErrorNamingTheCloseMatches) {
  const ScopedEnv path("PLUMB_TRANSPORT_PATH", nullptr);
  for (const std::string name : {PLUMB_BUILT_TRANSPORTS}) {
    const std::string typo = name.substr(0, name.size() - 1);  // "fastdd"
    try {
      load_transport(typo);
      FAIL() << typo << " loaded";
    } catch (const std::invalid_argument& e) {  // every plumb program: exit status 2
      const std::string message = e.what();
      EXPECT_NE(message.find("did you mean " + name + "?"), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
  // Nothing close: no guess, but still the list of what exists.
  const std::string message = error_of("zzzzzzzzzz");
  EXPECT_EQ(message.find("did you mean"), std::string::npos) << message;
  EXPECT_NE(message.find("found: "), std::string::npos) << message;
}

TEST(Loader, PathLikeNamesAreUnknownNotOpened) {
  EXPECT_NE(error_of("../lib/cyclonedds").find("unknown transport"), std::string::npos);
}

TEST(Loader, ResolvesEmptyNameThroughTheEnvironmentThenTheDefault) {
  {
    const ScopedEnv env(kTransportEnv, nullptr);
    EXPECT_EQ(resolve_transport_name(""), "cyclonedds");
    EXPECT_EQ(resolve_transport_name("fastdds"), "fastdds");
  }
  {
    const ScopedEnv env(kTransportEnv, "fastdds");
    EXPECT_EQ(resolve_transport_name(""), "fastdds");
    EXPECT_EQ(resolve_transport_name("cyclonedds"), "cyclonedds");  // an explicit name wins
  }
}

TEST(Loader, HonoursPlumbTransportWhenLoading) {
  const ScopedEnv env(kTransportEnv, "nosuchvendor");
  EXPECT_NE(error_of("").find("unknown transport 'nosuchvendor'"), std::string::npos);
  const ScopedEnv env2(kTransportEnv, "cyclonedds");
  EXPECT_EQ(load_transport("")->name(), "cyclonedds");
}

TEST(Loader, SearchesPlumbTransportPathFirst) {
  const ScopedEnv path("PLUMB_TRANSPORT_PATH", "/nonexistent-dir:" PLUMB_FAKE_PLUGIN_DIR);
  EXPECT_TRUE(found("wrongabi"));
  EXPECT_TRUE(found("noentry"));
  EXPECT_TRUE(found("cyclonedds"));  // still found next to the library
}

TEST(Loader, RefusesAPluginOfAnotherAbiVersion) {
  const ScopedEnv path("PLUMB_TRANSPORT_PATH", PLUMB_FAKE_PLUGIN_DIR);
  const std::string message = error_of("wrongabi");
  EXPECT_NE(message.find("ABI version"), std::string::npos) << message;
  EXPECT_NE(message.find("found: "), std::string::npos) << message;
}

TEST(Loader, RefusesALibraryWithoutTheEntryPoint) {
  const ScopedEnv path("PLUMB_TRANSPORT_PATH", PLUMB_FAKE_PLUGIN_DIR);
  const std::string message = error_of("noentry");
  EXPECT_NE(message.find("no plumb_transport_plugin entry point"), std::string::npos) << message;
}

TEST(Loader, ReportsALibraryThatIsNotLoadable) {
  const auto dir = std::filesystem::temp_directory_path() / ("plumb_loader_test_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "libplumb_transport_broken.so") << "not an ELF file";
  const ScopedEnv path("PLUMB_TRANSPORT_PATH", dir.c_str());
  const std::string message = error_of("broken");
  std::filesystem::remove_all(dir);
  EXPECT_NE(message.find("could not be loaded"), std::string::npos) << message;
  EXPECT_NE(message.find("broken"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

}  // namespace
