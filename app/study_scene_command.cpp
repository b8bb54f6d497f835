// `ccm study scene GRID --point N [--model ccm|rigid]`: the scene file of one run of a grid, on
// stdout, exactly as `ccm study run` runs it (run/runner/study_scene.hpp). With it one run of a
// study can be repeated, changed or looked at alone: `ccm run` it and open its output.
#include <fmt/format.h>

#include <vector>

#include "app/run_command.hpp"
#include "app/study_commands.hpp"
#include "run/runner/study_scene.hpp"
#include "run/scene/scene.hpp"
#include "study/grid/grid_file.hpp"

namespace ccm {

int study_scene_command(const StudySceneArgs& args) {
  try {
    const study::GridSpec spec = study::parse_grid_file(args.grid);
    const study::ImpactModel model =
        args.model == "rigid" ? study::ImpactModel::rigid : study::ImpactModel::ccm;
    const study::StudyPoints all = study::study_points(spec);
    std::vector<study::GridPoint> points = all.grid;
    points.insert(points.end(), all.convergence.begin(), all.convergence.end());
    for (const study::GridPoint& p : points)
      if (p.index == args.point) {
        fmt::print("{}", study::study_scene_text(spec, p, model));
        return exit_code::completed;
      }
    fmt::print(stderr, "ccm: error: {}: no point {} (the grid has points 0 to {})\n",
               args.grid.string(), args.point, points.empty() ? -1 : points.back().index);
    return exit_code::bad_input;
  } catch (const ConfigError& e) {
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return exit_code::bad_input;
  } catch (const std::exception& e) {
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return exit_code::internal_error;
  }
}

}  // namespace ccm
