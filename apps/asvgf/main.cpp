// asvgf: command-line entry point. Parses the subcommand and its options, runs it, maps errors to
// exit codes: 0 success, 1 runtime failure (message on stderr), 2 bad command line.
#include <cstdio>
#include <exception>
#include <functional>
#include <stdexcept>
#include <vector>

#include "commands.hpp"
#include "hal/error.hpp"
#include "io/atomic_file.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "asvgf: real-time A-SVGF denoising of path-traced frames on a thin HAL (Vulkan, OpenGL and OpenGL ES backends)",
      "asvgf"};
  app.set_version_flag("--version", std::string("asvgf ") + ASVGF_VERSION);
  app.require_subcommand(0, 1);
  app.fallthrough(false);

  std::vector<std::pair<CLI::App*, std::function<int()>>> commands;
  auto info = asvgf::cli::add_info_command(app);
  commands.emplace_back(app.get_subcommand("info"), info);
  auto render = asvgf::cli::add_render_command(app);
  commands.emplace_back(app.get_subcommand("render"), render);
  auto denoise = asvgf::cli::add_denoise_command(app);
  commands.emplace_back(app.get_subcommand("denoise"), denoise);
  auto bench = asvgf::cli::add_bench_command(app);
  commands.emplace_back(app.get_subcommand("bench"), bench);
  auto graph = asvgf::cli::add_graph_command(app);
  commands.emplace_back(app.get_subcommand("graph"), graph);
  auto report = asvgf::cli::add_report_command(app);
  commands.emplace_back(app.get_subcommand("report"), report);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "asvgf: error: %s\nRun 'asvgf --help' for the subcommands and options.\n", e.what());
    return 2;
  }

  try {
    asvgf::render::check_file_fault_environment();
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "asvgf: error: %s\n", e.what());
    return 2;
  }
  for (auto& [sub, run] : commands) {
    if (!sub->parsed()) continue;
    try {
      return run();
    } catch (const CLI::ValidationError& e) {
      std::fprintf(stderr, "asvgf %s: error: %s\n", sub->get_name().c_str(), e.what());
      return 2;
    } catch (const hal::Error& e) {
      std::fprintf(stderr, "asvgf %s: %s\n", sub->get_name().c_str(), e.what());
      return 1;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "asvgf %s: error: %s\n", sub->get_name().c_str(), e.what());
      return 1;
    }
  }
  std::fprintf(stderr, "asvgf: error: no subcommand given\n%s", app.help().c_str());
  return 2;
}
