// Reads an MCAP file: the summary through the footer when the file was closed, and the data
// section by a linear scan that needs neither (a recording cut short by kill -9 or a full disk
// is read up to its last whole chunk). A damaged part is reported with its byte offset and
// skipped where the record framing allows, so the readable rest is still used.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "plumb/mcap/records.hpp"

namespace plumb::mcap {

struct Header {
  std::string profile;
  std::string library;
};

class Reader {
 public:
  // Maps `path`; Error when it cannot be opened or does not start with the MCAP magic.
  explicit Reader(const std::string& path);
  ~Reader();
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  using MessageCallback = std::function<void(const Channel&, const MessageView&)>;
  // Calls `on_message` for every readable message in file order (the order they were recorded),
  // registering schemas, channels and metadata on the way. Never throws for damage: see problems().
  // Scanning again starts over.
  void scan(const MessageCallback& on_message = {});

  // True when the footer and summary were found and their CRC holds: statistics() is then
  // known without a scan.
  bool has_summary() const;
  // From the summary, else from the last scan().
  const Statistics& statistics() const;
  const std::map<std::uint16_t, Schema>& schemas() const;
  const std::map<std::uint16_t, Channel>& channels() const;
  const std::vector<Metadata>& metadata() const;
  const Header& header() const;
  std::uint64_t file_size() const;
  const std::string& path() const;

  // What was found damaged, each "byte N: what" (empty for a whole file); a missing summary is a
  // note, not a problem: see has_summary().
  const std::vector<std::string>& problems() const;
  // Where the last scan stopped reading (the file size for a whole file).
  std::uint64_t readable_bytes() const;

 private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace plumb::mcap
