// Evidence (contact): no node ends up inside a foreign tet, judged at every output sample by the
// independent brute-force checker (tests/support/penetration_checker.hpp), which shares no code
// with the DCR search. (a) an oblique impact of two bodies; (b) self-contact: the two prongs of
// a clamped U-shaped body (a tuning fork) clap together.
//
// Checker tolerance: a node counts as inside when all four barycentric coordinates exceed
// tol = 1e-6, i.e. when it is deeper than 1e-6 of the tet's altitude behind a face. The DCR
// keeps a node 1e-4 of the shortest surface edge outside a face (dcr_contact.cpp), and the
// altitudes here are at most ~3x that edge, so any real penetration past the projection
// (even 1 % of the kept separation) is flagged, while the node exactly on a shared face of its
// own body (barycentric 0 up to round-off, ~1e-16) never is.
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <vector>

#include "engine/contact/dcr/dcr_contact.hpp"
#include "tests/support/contact_scenes.hpp"
#include "tests/support/models.hpp"
#include "tests/support/penetration_checker.hpp"

using namespace ccm;

namespace {

constexpr double kCheckerTol = 1e-6;

struct PenetrationRun {
  RunSummary summary;
  int samples = 0;
  int max_active = 0;
  size_t worst_found = 0;  // most (node, tet) penetrations at any sample
  double first_bad_time = -1.0;
  double max_residual = 0.0;  // DCR's own max residual penetration [m]
  double wall = 0.0;
};

PenetrationRun run_checked(const Model& model, dcr::DcrContact& contact, double end_time,
                           double interval, const SampleFn& also = {}) {
  const auto start = std::chrono::steady_clock::now();
  PenetrationRun out;
  RunOptions opt;
  opt.contact = &contact;
  opt.time.end_time = end_time;
  opt.time.output_interval = interval;
  opt.on_sample = [&](const State& s) {
    ++out.samples;
    out.max_active = std::max(out.max_active, contact.active_contacts());
    out.max_residual = std::max(out.max_residual, contact.residual_penetration());
    const auto found = test::nodes_inside_foreign_tets(model.mesh, s.x, kCheckerTol);
    if (!found.empty() && out.first_bad_time < 0.0) out.first_bad_time = s.t;
    out.worst_found = std::max(out.worst_found, found.size());
    if (also) also(s);
  };
  out.summary = run_explicit(model, opt);
  out.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace

TEST_CASE("DCR: an oblique impact of two bodies leaves no node inside a foreign tet",
          "[dcr][no_penetration]") {
  // A soft sphere (R = 10 mm) fired obliquely at 3 m/s into a soft block clamped at its base:
  // it indents, slides and leaves, so node-face and edge-edge contacts both occur.
  const double R = 0.01, gap = 2e-4;
  const MaterialParams mat = test::neo_hookean(1e6, 0.3, 1000.0);
  ModelMesh mesh;
  add_body(mesh, "block", mat,
           test::translated(structured_box(Vec3(0.06, 0.04, 0.02), 12, 8, 4),
                            Vec3(-0.03, -0.02, -0.02)));
  add_body(mesh, "ball", mat, test::gmsh_sphere(R, 0.004, Vec3(-0.01, 0.0013, R + gap)));
  Model model = make_model(std::move(mesh));
  model.bcs.fix(nodes_on_plane(model.mesh, 0, Vec3(0, 0, -0.02), Vec3::UnitZ(), 1e-9));
  test::set_body_velocity(model, 1, Vec3(2.0, 0.0, -2.2));

  dcr::DcrSettings settings;
  settings.surfaces = {"block/boundary", "ball/boundary"};
  dcr::DcrContact contact(model.mesh, settings, model.bcs.fixed_nodes);
  const PenetrationRun r = run_checked(model, contact, 8e-3, 5e-5);
  INFO("verdict " << to_string(r.summary.verdict) << " " << r.summary.instability.reason);
  INFO("samples " << r.samples << ", max active " << r.max_active << ", penetrations "
                  << r.worst_found << " (first at " << r.first_bad_time << " s), DCR residual "
                  << r.max_residual << " m, steps " << r.summary.steps << ", wall " << r.wall
                  << " s");
  REQUIRE(r.summary.verdict == Verdict::completed);
  CHECK(r.max_active > 0);
  CHECK(r.worst_found == 0);
}

TEST_CASE("DCR self-contact: the prongs of a clamped fork clap without interpenetrating",
          "[dcr][no_penetration][self_contact]") {
  // One body: a 50 x 20 x 60 mm block with a 10 mm slot cut from the top down to z = 20 mm,
  // leaving two 20 mm prongs. The base is clamped; the prongs start with velocities toward each
  // other growing linearly from 0 at their root to 4 m/s at their tips, which is enough kinetic
  // energy to bend them the 5 mm each needs to touch (cantilever 3EI/l^3 ~ 600 N/m).
  const MaterialParams mat = test::neo_hookean(1e6, 0.3, 1000.0);
  const TetMesh fork = test::carved(structured_box(Vec3(0.05, 0.02, 0.06), 10, 4, 12),
                                    Vec3(0.02, -1.0, 0.02), Vec3(0.03, 1.0, 1.0));
  ModelMesh mesh;
  add_body(mesh, "fork", mat, fork);
  Model model = make_model(std::move(mesh));
  model.bcs.fix(nodes_on_plane(model.mesh, 0, Vec3(0, 0, 0), Vec3::UnitZ(), 1e-9));
  const double v_tip = 4.0;
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    const Vec3& X = model.mesh.X[static_cast<size_t>(n)];
    if (X.z() <= 0.02) continue;
    const double s = (X.z() - 0.02) / 0.04;
    model.initial_velocity[static_cast<size_t>(n)] =
        Vec3(X.x() < 0.025 ? v_tip * s : -v_tip * s, 0.0, 0.0);
  }

  dcr::DcrSettings settings;
  settings.surfaces = {"fork/boundary"};
  settings.self_contact = true;
  dcr::DcrContact contact(model.mesh, settings, model.bcs.fixed_nodes);
  // The slot's two faces (x = 20 mm and x = 30 mm above z = 20 mm): the smallest distance
  // along x between them shows that it is the prongs that meet.
  std::vector<int> left, right;
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    const Vec3& X = model.mesh.X[static_cast<size_t>(n)];
    if (X.z() <= 0.02 + 1e-9) continue;
    if (std::abs(X.x() - 0.02) < 1e-9) left.push_back(n);
    if (std::abs(X.x() - 0.03) < 1e-9) right.push_back(n);
  }
  double min_slot = 1.0;
  const PenetrationRun r = run_checked(model, contact, 10e-3, 5e-5, [&](const State& s) {
    double l = -1.0, rt = 1.0;
    for (int n : left) l = std::max(l, s.x[static_cast<size_t>(n)].x());
    for (int n : right) rt = std::min(rt, s.x[static_cast<size_t>(n)].x());
    min_slot = std::min(min_slot, rt - l);
  });
  INFO("verdict " << to_string(r.summary.verdict) << " " << r.summary.instability.reason);
  INFO("slot width: 10 mm at rest, smallest " << min_slot << " m");
  INFO("samples " << r.samples << ", max active " << r.max_active << ", penetrations "
                  << r.worst_found << " (first at " << r.first_bad_time << " s), DCR residual "
                  << r.max_residual << " m, steps " << r.summary.steps << ", wall " << r.wall
                  << " s");
  REQUIRE(r.summary.verdict == Verdict::completed);
  // The model has one body, so every contact seen is a contact within one body.
  CHECK(r.max_active > 0);
  // The prongs close the 10 mm slot to less than a tenth of a cell (0.5 mm; the x-extents of
  // the two slot faces, so bent prongs may even read below zero): they meet each other.
  CHECK(min_slot < 0.1 * 0.005);
  CHECK(r.worst_found == 0);
}
