// report/summary.hpp: `asvgf report --scenes`: one table over the reports of several scenes
// (summary.md, summary.csv), each scene's full report in its own folder.
#pragma once

#include <string>
#include <vector>

#include "report/report.hpp"

namespace asvgf::report {

struct SceneReport {
  ReportData data;
  Headline headline;
  std::string folder;  // relative to the summary, where the scene's report.md is
};

// The plain-accumulation spp whose mean relMSE equals `relmse` in this report's accumulation runs
// (log-log interpolation; below_range: lower than every accumulation's error).
CurveHit matching_accumulation(const ReportData& data, double relmse);

// The runs the summary table shows: the methods, the built-in variants flagged `summarised` and every
// --run (accumulation enters as K).
bool summary_run(const RunSpec& spec);

std::string summary_markdown(const std::vector<SceneReport>& scenes);
// One row per scene and run, accumulation included.
std::string summary_csv(const std::vector<SceneReport>& scenes);

}  // namespace asvgf::report
