// A trade-study grid as read from a grid file (docs/grid-file.md): the axes swept (thesis 2.8,
// Table 2.2) and every fixed parameter of the impact scene both models run. Plain typed
// aggregates, validated by the parser (study/grid/grid_file.hpp).
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/penalty_mode.hpp"
#include "engine/core/step_safety.hpp"

namespace ccm::study {

// How the artifact plate is held.
enum class ArtifactSupport {
  base,  // the bottom face z = 0 fixed: a block on a rigid floor
  edges  // the two faces x = 0 and x = L_A clamped: a plate spanning a gap
};

struct ArtifactSpec {
  double length = 1.0;      // L_A [m]: the plate is L_A x L_A x thickness
  double thickness = 0.25;  // [m]
  double E = 1000.0;        // E_A [Pa]
  double nu = 0.49;
  double rho = 1000.0;     // [kg/m^3]
  double mesh_size = 0.1;  // [m], target tet edge (Gmsh)
  // A finer mesh within contact_radius of the impact point (the middle of the top face), when
  // contact_mesh_size > 0 [m]; a mesh_scale scales it with mesh_size.
  double contact_mesh_size = 0.0;
  double contact_radius = 0.0;
  ArtifactSupport support = ArtifactSupport::base;
};

// The impactor sphere: D_I = RLS L_A (eq. 2.33), E_I = ER E_A (eq. 2.32).
struct ImpactorSpec {
  double nu = 0.49;
  double rho = 1000.0;            // [kg/m^3]
  double mesh_size_ratio = 0.25;  // tet edge / D_I, in (0, 0.5]
  // A finer mesh within contact_radius of the sphere's lowest point, when contact_mesh_size > 0
  // [m] (never coarser than D_I mesh_size_ratio); a mesh_scale scales it too.
  double contact_mesh_size = 0.0;
  double contact_radius = 0.0;
};

struct GridTime {
  double contact_time = 0.1;      // t_c [s]: the gap is speed * t_c
  double end = 0.15;              // t_f [s]
  double output_interval = 1e-3;  // [s], the same for both models
  double dt_safety = kDefaultDtSafety;
  long max_steps = 0;  // 0: no limit
  // Whole impacts: each run ends one hold [s] after its bodies separate (end is then the guard),
  // and a point's two runs end together (docs/grid-file.md, "Whole impacts"). Empty: at end.
  std::optional<double> end_after_separation;
};

struct GridContact {
  // The rigid model's springs: per_point (K_P = penalty, thesis 2.8) or element
  // (k = penalty_scale K A^2 / V per surface triangle); see docs/grid-file.md.
  PenaltyMode penalty_mode = PenaltyMode::per_point;
  double penalty =
      kDefaultPointPenalty;  // K_P [N/m] per quadrature point (rigid model, thesis 2.8)
  double penalty_scale = kDefaultElementPenaltyScale;  // s (rigid model, element mode)
  double damping = 0.0;      // zeta, fraction of critical per point (rigid model)
  double restitution = 0.0;  // e (ccm model, DCR)
  double friction = 0.0;     // mu (ccm model, DCR)
  // The rigid model's impactor: the analytic sphere (the thesis's) or the ccm model's meshed
  // sphere made a rigid body (docs/rigid-bodies.md), on the same per-point springs.
  bool meshed_rigid_impactor = false;
  // The meshed impactor's crease angle [degrees]: it stands for a sphere, so its surface is
  // smoothed (docs/rigid-bodies.md, "The curved surface"; the coarsest grid mesh, five edges per
  // diameter, turns by about 25 degrees at an edge).
  double crease_angle = kMeshedImpactorCreaseAngle;
};

// A point named in [convergence]: the three main axes, the other axes at their fixed values.
struct ConvergencePoint {
  double modulus_ratio = 1.0;
  double length_ratio = 1.0;
  double kinetic_energy = 0.0;
};

struct ConvergenceSpec {
  std::vector<ConvergencePoint> points;
  std::vector<double> mesh_scales;  // 2-3 distinct factors on both mesh sizes
};

// A grid over a scene file of the user's (docs/grid-file.md, "Grids over your own scene"): the
// axes are paths into the scene, the "ccm" model runs the scene as written and the "rigid" model
// with the `rigid` bodies made rigid (as `ccm compare --rigid`). A point's ER, RLS and KE are
// derived from its scene (run/template/template_points.hpp); they are the fits' coordinates.
struct TemplateAxis {
  std::string path;  // into the scene: "bodies.shell.material.E", "contact.pairs[0].friction"
  std::vector<double> values;
  int line = 0;  // the axis's line in the grid file
};

// The artifact whose histories give the metrics is the one body that stays deformable in the
// "rigid" model (as for `ccm compare`'s groups, run/compare/scene_groups.hpp).
struct SceneTemplate {
  std::filesystem::path scene;         // the scene file, resolved against the grid file's folder
  std::vector<std::string> rigid;      // the bodies rigid in the "rigid" model
  std::vector<TemplateAxis> axes;      // coordinates: their values move ER, RLS or KE
  std::vector<TemplateAxis> levels;    // each value selects its own set of fits
  int scene_line = 0, rigid_line = 0;  // of those keys in the grid file
};

// How a template axis is named in GridPoint::other_axes (and so in the store): "axes.<path>" for
// a coordinate (not a fit level: it reaches the fits through ER, RLS and KE), "levels.<path>".
inline constexpr std::string_view kTemplateAxisPrefix = "axes.";
inline constexpr std::string_view kTemplateLevelPrefix = "levels.";

struct GridSpec {
  std::filesystem::path source;  // the grid file, as given
  std::string title;
  std::vector<double> modulus_ratios;    // ER
  std::vector<double> length_ratios;     // RLS
  std::vector<double> kinetic_energies;  // KE_I [J]
  std::map<std::string, std::vector<double>>
      other_axes;  // by name (kGridAxisNames, study/grid/grid_axis.hpp)
  GridTime time;
  ArtifactSpec artifact;
  ImpactorSpec impactor;
  GridContact contact;
  ConvergenceSpec convergence;  // empty: no convergence runs
  // Set for a grid over a scene: then the axes above are empty and time, artifact, impactor and
  // contact unused (the scene has its own).
  std::optional<SceneTemplate> scene_template;
};

}  // namespace ccm::study
