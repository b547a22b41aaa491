// The runs `asvgf report` renders: its built-in list (every method and the settings the record
// compares), --methods restricting it, and --run adding runs of the user's own settings.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "report/report.hpp"

namespace asvgf::cli {

// raw, ema-0.2, ema-0.05, svgf, asvgf and its variants, accum-1spp .. accum-<max>spp.
std::vector<report::RunSpec> builtin_runs(std::uint32_t max_accumulation_spp);

// --methods: a comma list of method names (raw, ema, svgf, asvgf, reference or accum) or run
// names; empty keeps every run. Throws CLI::ValidationError naming an entry that matches no run.
std::vector<report::RunSpec> select_runs(std::vector<report::RunSpec> runs, const std::string& list);

// --run 'NAME=METHOD [OPTIONS]': a run named NAME of METHOD (raw, ema, svgf or asvgf) with the
// denoiser options `asvgf render` takes (--sigma-l 8 --history-tap 1 ...), checked as it checks
// them. `taken` are the names already in use. Throws CLI::ValidationError naming the problem.
report::RunSpec parse_run(const std::string& text, const std::vector<report::RunSpec>& taken);

}  // namespace asvgf::cli
