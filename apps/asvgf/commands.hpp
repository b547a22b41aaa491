// Subcommands of the `asvgf` tool: each registers its options on the CLI and runs when chosen.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace asvgf::cli {

// Registers `info` on the app; the returned function runs it and gives the exit code.
std::function<int()> add_info_command(CLI::App& app);
// Registers `graph`.
std::function<int()> add_graph_command(CLI::App& app);
// Registers `render`.
std::function<int()> add_render_command(CLI::App& app);
// Registers `report`.
std::function<int()> add_report_command(CLI::App& app);
// Registers `denoise`.
std::function<int()> add_denoise_command(CLI::App& app);
// Registers `bench`.
std::function<int()> add_bench_command(CLI::App& app);

}  // namespace asvgf::cli
