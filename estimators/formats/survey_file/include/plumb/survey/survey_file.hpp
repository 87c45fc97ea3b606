// The survey CSV (docs/surveys.md lists the columns): one header line, '#' comment lines naming the
// format and the survey's references, one row per station with its inputs, QC, path point and
// uncertainty. A file is written whole to a temporary name and renamed (never half-written), or
// grown one fsync'ed row at a time by a live survey; reading it back rebuilds the survey from each
// row's inputs, so the derived columns always follow the options in force.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "plumb/survey/survey.hpp"

namespace plumb::survey {

inline constexpr const char* kSurveyFormatLine = "# plumb survey 2";
// Version 1 (no toolface, no random and total sigmas, no reference field columns) is still read.
inline constexpr const char* kSurveyFormatLineV1 = "# plumb survey 1";

// Without a given section azimuth the header says `section_azimuth_deg A (closure)`, A the closure
// azimuth of the survey's last station (`closure_azimuth_deg`).
void write_survey_header(std::ostream& out, const SurveyOptions& options, double closure_azimuth_deg = 0);
void write_survey_row(std::ostream& out, const SurveyRow& row);
std::string survey_row_line(const SurveyRow& row);  // with its '\n'
std::string survey_text(const Survey& survey);     // header and every row

// Writes `text` to `path` through `path.tmp` + fsync + rename + fsync of the folder: readers see
// the old file or the new one, never a part. Throws std::runtime_error naming the file.
void write_file_atomically(const std::string& path, const std::string& text);

// What read_survey_file found.
struct LoadedSurvey {
  std::vector<Station> stations;  // the valid rows, in order
  std::size_t valid_lines = 0;    // header and comments included: where the valid part ends
  std::string problem;            // empty when the whole file is good; else what is wrong and where
};

// Reads a survey file's stations. A truncated last row (no newline: the writer died in the middle)
// or a damaged row stops the reading there; what was read before is kept and `problem` says what
// was wrong at which line. A file without the format line or header is an error (std::runtime_error).
LoadedSurvey read_survey_file(const std::string& path);

// Appends rows to a survey file, each written with one write() and fsync'ed before add() returns.
class SurveyAppender {
 public:
  // Opens (creating with the header when missing or empty) `path` for appending.
  SurveyAppender(const std::string& path, const SurveyOptions& options);
  ~SurveyAppender();
  SurveyAppender(const SurveyAppender&) = delete;
  SurveyAppender& operator=(const SurveyAppender&) = delete;
  void append(const SurveyRow& row);
  // A `# ` comment line (readers skip it), fsync'ed like a row: what the file's rows depend on that
  // was learnt after its header (the depth clock's alignment).
  void append_comment(const std::string& text);

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace plumb::survey
