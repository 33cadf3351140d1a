#pragma once
// The sections of a report that set another run beside the program's: a second run of the
// same program (a dump of another machine, a trace) or the program re-optimised.
#include <nlohmann/json.hpp>

#include "isurface/base/progress.h"
#include "isurface/report/html_document.h"
#include "isurface/report/program_report.h"

namespace isurface::report {

void comparisonSection(HtmlDocument& doc, const OpenedRun& run, const OpenedRun& other, double gapLimit,
                       const ProgressCallback& progress,
                       nlohmann::json& out);

void optimisationSection(HtmlDocument& doc, const OpenedRun& run, const ReportOptions& options,
                         const ProgressCallback& progress, nlohmann::json& out);

}  // namespace isurface::report
