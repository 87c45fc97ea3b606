// The survey kept in a file so that a restarted plumb-survey resumes with every station: read at
// start (a truncated or damaged tail is reported, the whole old file saved beside it, the valid
// part kept), rewritten whole through a temporary file, then grown one fsync'ed row per station.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "plumb/survey/survey.hpp"
#include "plumb/survey/survey_file.hpp"

namespace plumb::survey_component {

class SurveyStore {
 public:
  // Loads `path` into `survey` (which must be empty). Messages for the operator go to `note`.
  // Throws std::runtime_error when the file exists but is not a survey file (never overwritten).
  SurveyStore(const std::string& path, survey::Survey& survey, const std::function<void(const std::string&)>& note);
  void append(const survey::SurveyRow& row) { appender_->append(row); }
  void comment(const std::string& text) { appender_->append_comment(text); }
  std::size_t resumed() const { return resumed_; }

 private:
  std::unique_ptr<survey::SurveyAppender> appender_;
  std::size_t resumed_ = 0;
};

}  // namespace plumb::survey_component
