// What an estimator host remembers across its own restarts: the last sequence number it took of
// each tool, kept in a small file on its computer and rewritten after every take. A host killed
// with -9 and started again reads its previous instance's record and counts the samples sent while
// it was down (lost_while_down on plumb/status).
//
// Why a file and not plumb/status: a transient-local writer keeps its last report only while it
// lives, and a killed host's writer is gone (there is no persistence service), so a restarted host
// could never read what its previous instance said on DDS. A status report is also up to a second
// old; the record is as old as the last take, which keeps the count within one batch.
// Pure logic and file I/O, no DDS: tested directly.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace plumb::estimator_component {

// One tool's place in its stream when the host last took samples of it.
struct ToolMark {
  std::uint64_t last_seq = 0;
  std::int64_t last_stamp_ns = 0;  // the sample's own time (board clock or simulation time)
  std::int64_t wall_ns = 0;        // this computer's clock (UTC) when the host took it
  bool operator==(const ToolMark&) const = default;
};
using ToolMarks = std::map<std::string, ToolMark>;  // tool id -> its mark

// The file's text: a header line, then one line per tool with fixed-width numbers, so that a
// rewrite in place never leaves the tail of a longer former content (tools are never dropped).
std::string format_marks(const ToolMarks& marks);
// Lines it does not understand are skipped: a damaged record counts nothing rather than a wrong number.
ToolMarks parse_marks(std::string_view text);

// What happened to a tool's stream between the previous instance's mark and this instance's first batch.
struct DownLoss {
  enum class Kind {
    Lost,             // the same stream went on: samples first..last were sent while the host was down (none if first > last)
    SourceRestarted,  // the sequence or the clock went back: a new source, nothing to count
    ClocksDisagree,   // the stream's clock and this computer's moved apart: another run, or a replay
  };
  Kind kind = Kind::Lost;
  std::uint64_t first = 0, last = 0;  // the lost sequence numbers (Lost)
  double stream_s = 0, wall_s = 0;    // how far the stream's clock and the wall clock moved since the mark
  std::uint64_t count() const { return kind == Kind::Lost && last >= first ? last - first + 1 : 0; }
};
// `first_seq`: the first sample of the tool's first batch; `batch_last_stamp_ns`: the last sample
// of that batch (a batch is sent when full, so its last sample is the one as old as its arrival);
// `wall_ns`: when it arrived.
DownLoss loss_while_down(const ToolMark& previous, std::uint64_t first_seq, std::int64_t batch_last_stamp_ns,
                         std::int64_t wall_ns);
// "2026-11-29 02:10:03.250 UTC"
std::string wall_time_text(std::int64_t wall_ns);

// The record file of one host. Several hosts on one computer reading the same topic and tool take
// one file each: the first of PATH, PATH.2, ... PATH.8 that no running host holds (an exclusive
// lock the kernel releases when the process ends, kill -9 included).
class ResumeFile {
 public:
  // Creates the folder and the file as needed; nullopt with `why` when it cannot.
  static std::optional<ResumeFile> open(const std::string& path, std::string& why);
  ResumeFile(ResumeFile&& other) noexcept;
  ResumeFile& operator=(ResumeFile&&) = delete;
  ResumeFile(const ResumeFile&) = delete;
  ~ResumeFile();

  const std::string& path() const { return path_; }
  const ToolMarks& previous() const { return previous_; }
  // Rewrites the record in place; false when the write failed (said once by the caller).
  bool save(const ToolMarks& marks);

 private:
  ResumeFile(int fd, std::string path, ToolMarks previous) : fd_(fd), path_(std::move(path)), previous_(std::move(previous)) {}
  int fd_ = -1;
  std::string path_;
  ToolMarks previous_;
  std::string text_;  // reused by every save
};

// The record's default place: $PLUMB_STATE_DIR, else $XDG_STATE_HOME/plumb, else
// ~/.local/state/plumb; the file names the domain, the topic and the selected tool, which
// is what makes two hosts' streams the same stream.
std::string default_state_dir();
std::string resume_file_name(int domain_id, const std::string& topic, const std::string& tool_id);

}  // namespace plumb::estimator_component
