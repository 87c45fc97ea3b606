// Survey rows and attitude/depth messages, between the survey library's types and the topics'.
#pragma once

#include "plumb/core/estimate.hpp"
#include "plumb/survey/station_detector.hpp"
#include "plumb/survey/survey.hpp"
#include "plumb/topics/all.hpp"

namespace plumb::survey_component {

topics::SurveyStation to_topic(const survey::SurveyRow& row);
survey::DepthReport from_topic(const topics::MeasuredDepth& d);

}  // namespace plumb::survey_component
