// Fuzzes the sensor CSV reader (plumb::csv::SensorReader, used by --replay) and the ASCII line
// parser: bad input may only ever come out as csv::Error naming a line, never as a crash.
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "plumb/bridge/line_parser.hpp"
#include "plumb/csv/files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  {
    std::istringstream in(text);
    try {
      plumb::csv::SensorReader reader(in, "fuzz.csv");
      plumb::Sample s;
      // The reader skips a bad row after throwing: keep reading, as the bridge's replay does.
      for (int rows = 0; rows < 100000; ++rows) {
        try {
          if (!reader.next(s)) break;
        } catch (const plumb::csv::Error& e) {
          if (e.line == 0) __builtin_trap();  // every row error names its line
        }
      }
    } catch (const plumb::csv::Error&) {
      // bad header: a clear error, fine
    }
  }
  plumb::bridge::Counters counters;
  plumb::bridge::LineParser lines(counters, "fuzz");
  std::vector<plumb::Sample> out;
  const std::size_t chunk = size ? 1 + data[0] % 64 : 1;
  for (std::size_t at = 0; at < size; at += chunk)
    lines.feed(std::span(data + at, std::min(chunk, size - at)), out);
  lines.finish(out);
  if (out.size() != counters.lines_ok) __builtin_trap();
  return 0;
}
