// Fuzzes the MCAP reader (plumb::mcap::Reader: summary through the footer, linear scan, chunk
// decompression, record decoding): damage may only come out as problems() naming a byte or as
// mcap::Error from the constructor, never as a crash or a read outside the file.
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <string>

#include "plumb/mcap/reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The reader maps a file: hand it the input as an in-memory one.
  const int fd = memfd_create("fuzz.mcap", 0);
  if (fd < 0) return 0;
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd, data + done, size - done);
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  try {
    plumb::mcap::Reader reader("/proc/self/fd/" + std::to_string(fd));
    std::size_t bytes = 0;
    reader.scan([&](const plumb::mcap::Channel& c, const plumb::mcap::MessageView& m) {
      bytes += m.size + c.topic.size();
      if (m.size > 0) bytes += m.data[m.size - 1];  // the message's bytes are readable
    });
    for (const auto& p : reader.problems()) {
      if (p.rfind("byte ", 0) != 0) __builtin_trap();  // every problem names its offset
    }
    if (reader.readable_bytes() > reader.file_size()) __builtin_trap();
    static_cast<void>(reader.statistics());
  } catch (const plumb::mcap::Error&) {
    // not an MCAP file at all: a clear error, fine
  }
  ::close(fd);
  return 0;
}
