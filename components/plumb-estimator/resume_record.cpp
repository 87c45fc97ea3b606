#include "resume_record.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cinttypes>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <sstream>
#include <utility>

namespace plumb::estimator_component {
namespace {

constexpr std::string_view kResumeHeader = "plumb-estimator resume record 1";
constexpr int kResumeFilesPerName = 8;  // hosts on one computer reading the same stream
// How far the stream's clock and the wall clock may move apart over a restart and still be taken
// for the same stream: delivery and scheduling jitter, plus a board clock's drift.
constexpr double kResumeClockSlackS = 2.0;
constexpr double kResumeClockSlackFraction = 0.1;

bool resume_read_whole_file(int fd, std::string& out) {
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0) return false;
    if (n == 0) return true;
    out.append(buffer, static_cast<std::size_t>(n));
  }
}

std::string resume_sanitised(const std::string& text) {
  std::string out;
  for (char c : text) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.') ? c : '_';
  return out;
}

}  // namespace

std::string format_marks(const ToolMarks& marks) {
  std::string out(kResumeHeader);
  out += '\n';
  char numbers[96];
  for (const auto& [tool, m] : marks) {
    std::snprintf(numbers, sizeof numbers, "%020" PRIu64 " %+020" PRId64 " %+020" PRId64 " ", m.last_seq,
                  m.last_stamp_ns, m.wall_ns);
    out += numbers;
    out += tool;  // last on the line: a tool id may hold spaces
    out += '\n';
  }
  return out;
}

ToolMarks parse_marks(std::string_view text) {
  ToolMarks marks;
  std::istringstream in{std::string(text)};
  std::string line;
  if (!std::getline(in, line) || line != kResumeHeader) return marks;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    ToolMark m;
    if (!(fields >> m.last_seq >> m.last_stamp_ns >> m.wall_ns)) continue;
    if (fields.get() != ' ') continue;
    std::string tool;
    std::getline(fields, tool);
    marks[tool] = m;
  }
  return marks;
}

DownLoss loss_while_down(const ToolMark& previous, std::uint64_t first_seq, std::int64_t batch_last_stamp_ns,
                         std::int64_t wall_ns) {
  DownLoss d;
  d.stream_s = static_cast<double>(batch_last_stamp_ns - previous.last_stamp_ns) * 1e-9;
  d.wall_s = static_cast<double>(wall_ns - previous.wall_ns) * 1e-9;
  if (first_seq <= previous.last_seq || d.stream_s < 0) {
    d.kind = DownLoss::Kind::SourceRestarted;
    return d;
  }
  if (std::abs(d.stream_s - d.wall_s) > kResumeClockSlackS + kResumeClockSlackFraction * std::abs(d.wall_s)) {
    d.kind = DownLoss::Kind::ClocksDisagree;
    return d;
  }
  d.first = previous.last_seq + 1;
  d.last = first_seq - 1;  // first > last when nothing was lost
  return d;
}

std::string wall_time_text(std::int64_t wall_ns) {
  const std::time_t seconds = static_cast<std::time_t>(wall_ns / 1000000000);
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char text[64];
  const std::size_t n = std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S", &utc);
  std::snprintf(text + n, sizeof text - n, ".%03d UTC", static_cast<int>((wall_ns / 1000000) % 1000));
  return text;
}

std::optional<ResumeFile> ResumeFile::open(const std::string& path, std::string& why) {
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  if (ec) {
    why = "cannot create " + std::filesystem::path(path).parent_path().string() + ": " + ec.message();
    return std::nullopt;
  }
  for (int i = 1; i <= kResumeFilesPerName; ++i) {
    const std::string candidate = i == 1 ? path : path + "." + std::to_string(i);
    const int fd = ::open(candidate.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) {
      why = "cannot open " + candidate + ": " + std::strerror(errno);
      return std::nullopt;
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {  // a running host keeps this one
      ::close(fd);
      continue;
    }
    std::string text;
    if (!resume_read_whole_file(fd, text)) {
      why = "cannot read " + candidate + ": " + std::strerror(errno);
      ::close(fd);
      return std::nullopt;
    }
    return ResumeFile(fd, candidate, parse_marks(text));
  }
  why = std::to_string(kResumeFilesPerName) + " hosts already keep a record at " + path;
  return std::nullopt;
}

ResumeFile::ResumeFile(ResumeFile&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)),
      path_(std::move(other.path_)),
      previous_(std::move(other.previous_)),
      text_(std::move(other.text_)) {}

ResumeFile::~ResumeFile() {
  if (fd_ >= 0) ::close(fd_);
}

bool ResumeFile::save(const ToolMarks& marks) {
  text_ = format_marks(marks);
  // One write at offset 0: a process killed with -9 ends between system calls, never inside one,
  // so the file always holds a whole record.
  const ssize_t n = ::pwrite(fd_, text_.data(), text_.size(), 0);
  return n == static_cast<ssize_t>(text_.size());
}

std::string default_state_dir() {
  if (const char* dir = std::getenv("PLUMB_STATE_DIR"); dir && *dir) return dir;
  if (const char* dir = std::getenv("XDG_STATE_HOME"); dir && *dir) return std::string(dir) + "/plumb";
  if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.local/state/plumb";
  return "/tmp/plumb-state";
}

std::string resume_file_name(int domain_id, const std::string& topic, const std::string& tool_id) {
  std::string name = "plumb-estimator-domain" + std::to_string(domain_id) + "-" + resume_sanitised(topic);
  if (!tool_id.empty()) name += "-tool-" + resume_sanitised(tool_id);
  return name + ".resume";
}

}  // namespace plumb::estimator_component
