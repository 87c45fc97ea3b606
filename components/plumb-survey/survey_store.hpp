// The survey kept in a file so that a restarted plumb-survey resumes with every station: read at
// start (a truncated or damaged tail is reported, the whole old file saved beside it, the valid
// part kept), rewritten whole through a temporary file, then grown one fsync'ed row per station
// (or, when the vertical section follows the closure, rewritten whole at each station).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "plumb/survey/survey.hpp"
#include "plumb/survey/survey_file.hpp"

namespace plumb::survey_component {

class SurveyStore {
 public:
  // Loads `path` into `survey` (which must be empty). Messages for the operator go to `note`.
  // Throws std::runtime_error when the file exists but is not a survey file (never overwritten).
  SurveyStore(const std::string& path, survey::Survey& survey, const std::function<void(const std::string&)>& note);
  // Without a given section azimuth every row's vertical section follows the newest station's
  // closure: the file is then rewritten whole (atomically) at each station, its comments after the
  // header, instead of growing by one row.
  void append(const survey::SurveyRow& row);
  void comment(const std::string& text);
  std::size_t resumed() const { return resumed_; }

 private:
  void rewrite();
  std::string path_;
  const survey::Survey& survey_;
  std::vector<std::string> comments_;  // the comment lines written since the start, for rewrite()
  std::unique_ptr<survey::SurveyAppender> appender_;
  std::size_t resumed_ = 0;
};

}  // namespace plumb::survey_component
