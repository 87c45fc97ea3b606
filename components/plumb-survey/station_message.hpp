// Survey rows, clearances and attitude/depth messages, between the survey library's types and the topics'.
#pragma once

#include "plumb/core/estimate.hpp"
#include "plumb/survey/station_detector.hpp"
#include "plumb/survey/survey.hpp"
#include "plumb/topics/all.hpp"
#include "clearance_watch.hpp"

namespace plumb::survey_component {

// section_azimuth_deg: the survey's when the row is published (Survey::section_azimuth_deg).
topics::SurveyStation to_topic(const survey::SurveyRow& row, double section_azimuth_deg);
// One reference station against one offset well, as plumb/clearance carries it.
topics::Clearance to_topic(const ClearanceWatch::Pair& pair, const survey::SurveyRow& row,
                           const survey::ClearanceLevels& levels);
survey::DepthReport from_topic(const topics::MeasuredDepth& d);

}  // namespace plumb::survey_component
