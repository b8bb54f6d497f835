// The ccm command line: `ccm --version`, `ccm run SCENE --out DIR [--quiet]`.
#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include "study/cli/run_command.hpp"
#include "study/provenance/version.hpp"

int main(int argc, char** argv) {
  CLI::App app{"ccm: explicit finite-element simulations of soft bodies", "ccm"};
  app.set_version_flag("--version", "ccm " + ccm::version_string());
  app.require_subcommand(1);

  ccm::RunArgs args;
  CLI::App* run = app.add_subcommand("run", "Run a scene file and write its results into a folder");
  run->add_option("SCENE", args.scene, "Scene file (TOML; see docs/scene-file.md)")->required();
  run->add_option("--out,-o", args.out,
                  "Output folder for history.csv, summary.toml and scene.toml (created only "
                  "once the scene has been read and meshed)")
      ->required();
  run->add_flag("--quiet,-q", args.quiet, "No progress line and no summary table");
  run->footer(
      "Exit codes: 0 completed, 1 internal error, 2 bad input (nothing written), 3 unstable "
      "(results up to the instability written).");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    fmt::print(stderr, "ccm: error: {}\nRun 'ccm --help' for usage.\n", e.what());
    return ccm::exit_code::bad_input;
  }
  return ccm::run_command(args);
}
