#include "survey_store.hpp"

#include <filesystem>
#include <sstream>

namespace plumb::survey_component {

SurveyStore::SurveyStore(const std::string& path, survey::Survey& survey, const std::function<void(const std::string&)>& note)
    : path_(path), survey_(survey) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(path, ec) && fs::file_size(path, ec) > 0) {
    const survey::LoadedSurvey loaded = survey::read_survey_file(path);
    std::string problem = loaded.problem;
    for (const auto& s : loaded.stations) {
      try {
        survey.add(s);
      } catch (const survey::StationError& e) {
        // Rows that parse but cannot follow the ones before (edited by hand): the rest is not trusted.
        problem = path + ": " + e.what();
        break;
      }
    }
    resumed_ = survey.rows().size();
    if (!problem.empty()) {
      // Nothing is thrown away: the file as found is kept beside the repaired one.
      const std::string saved = path + ".damaged";
      fs::copy_file(path, saved, fs::copy_options::overwrite_existing, ec);
      note("survey file " + problem + "; resuming with the " + std::to_string(resumed_) + " valid station(s) before it" +
           (ec ? std::string(" (could not save the damaged file: ") + ec.message() + ")" : "; the file as found is in " + saved));
    } else {
      note("resuming the survey in " + path + " with " + std::to_string(resumed_) + " station(s)");
    }
  }
  // Always rewritten whole with the options in force (and without any damaged tail) before rows
  // are appended to it.
  survey::write_file_atomically(path, survey::survey_text(survey));
  appender_ = std::make_unique<survey::SurveyAppender>(path, survey.options());
}

void SurveyStore::append(const survey::SurveyRow& row) {
  if (survey_.section_azimuth_is_closure())
    rewrite();
  else
    appender_->append(row);
}

void SurveyStore::comment(const std::string& text) {
  std::string line = text;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  comments_.push_back(line);
  if (survey_.section_azimuth_is_closure())
    rewrite();
  else
    appender_->append_comment(text);
}

void SurveyStore::rewrite() {
  std::ostringstream out;
  survey::write_survey_header(out, survey_.options(), survey_.section_azimuth_deg());
  for (const auto& c : comments_) out << "# " << c << '\n';
  for (const auto& r : survey_.rows()) out << survey::survey_row_line(r);
  survey::write_file_atomically(path_, out.str());
}

}  // namespace plumb::survey_component
