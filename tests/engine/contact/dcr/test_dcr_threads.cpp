// Threads change the speed of the DCR contact's detection, never its result (docs/parallel.md,
// "Threads"): two DCR scenes with friction, an oblique impact of two bodies (node-face and
// edge-edge contacts, pair forces reported) and the self-contact of a clamped fork whose prongs
// clap, are run with the detection on 1, 2 and 3 threads, and the positions, velocities,
// energies, the contact's history and work are compared bit for bit. The loops' thread
// threshold is lowered to 16 items so that every detection loop of these small scenes runs
// threaded, and the contact's counter of threaded loops shows that they did.
#include <catch2/catch.hpp>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "engine/contact/dcr/broad_phase.hpp"
#include "engine/contact/dcr/dcr_contact.hpp"
#include "engine/contact/dcr/thread_chunks.hpp"
#include "engine/observe/history.hpp"
#include "tests/support/contact_scenes.hpp"
#include "tests/support/models.hpp"

using namespace ccm;

namespace {

// Loops of this many items or more run threaded in these tests (the default is 2,048).
constexpr std::size_t kTestMinItems = 16;

bool bits_equal(const void* a, const void* b, size_t bytes) {
  return std::memcmp(a, b, bytes) == 0;
}

struct DcrRun {
  std::vector<Vec3> x, v;                    // at the last sample
  std::vector<std::vector<double>> history;  // energies per body, then the contact's columns
  RunSummary summary;
  dcr::DcrContact::WorkParts work;
  int max_active = 0;
  long threaded_loops = 0;
};

DcrRun run_dcr(const Model& model, dcr::DcrSettings settings, int threads, double end_time) {
  settings.threads = {threads, kTestMinItems};
  dcr::DcrContact contact(model.mesh, settings, model.bcs.fixed_nodes);
  OutputRequest request;
  request.kinetic_energy = true;
  request.internal_energy = true;
  HistoryRecorder history(model.mesh, request);
  history.add_source(contact);
  RunOptions opt;
  opt.time.end_time = end_time;
  opt.time.output_interval = end_time / 40;
  opt.history = &history;
  opt.contact = &contact;
  opt.threads = threads;
  DcrRun r;
  opt.on_sample = [&](const State& s) {
    r.x = s.x;
    r.v = s.v;
    r.max_active = std::max(r.max_active, contact.active_contacts());
  };
  r.summary = run_explicit(model, opt);
  r.history = history.rows();
  r.work = contact.work_parts();
  r.threaded_loops = contact.threaded_loops();
  return r;
}

void require_identical(const DcrRun& a, const DcrRun& b) {
  REQUIRE(a.x.size() == b.x.size());
  CHECK(bits_equal(a.x.data(), b.x.data(), a.x.size() * sizeof(Vec3)));
  CHECK(bits_equal(a.v.data(), b.v.data(), a.v.size() * sizeof(Vec3)));
  REQUIRE(a.history.size() == b.history.size());
  for (size_t k = 0; k < a.history.size(); ++k) {
    REQUIRE(a.history[k].size() == b.history[k].size());
    CHECK(bits_equal(a.history[k].data(), b.history[k].data(), a.history[k].size() * 8));
  }
  CHECK(a.summary.steps == b.summary.steps);
  CHECK(bits_equal(&a.summary.dt_min, &b.summary.dt_min, 8));
  CHECK(bits_equal(&a.summary.energy_balance_error, &b.summary.energy_balance_error, 8));
  CHECK(bits_equal(&a.work, &b.work, sizeof(a.work)));
}

// Runs the scene on 1, 2 and 3 threads and compares; the single-thread run must have contacts.
void check_thread_independence(const Model& model, const dcr::DcrSettings& settings,
                               double end_time) {
  const DcrRun one = run_dcr(model, settings, 1, end_time);
  INFO("verdict " << to_string(one.summary.verdict) << " " << one.summary.instability.reason);
  REQUIRE(one.summary.verdict == Verdict::completed);
  REQUIRE(one.max_active > 0);
  CHECK(one.threaded_loops == 0);
  CHECK(one.work.impulses != 0.0);
  for (int threads : {2, 3}) {
    INFO(threads << " threads");
    const DcrRun r = run_dcr(model, settings, threads, end_time);
    // Every step's detection has loops over hundreds of nodes and candidates.
    CHECK(r.threaded_loops >= r.summary.steps);
    require_identical(one, r);
  }
}

}  // namespace

TEST_CASE("A loop is cut into chunks in item order whatever the thread count", "[threads][dcr]") {
  for (int threads : {1, 2, 3}) {
    dcr::ChunkedLoops loops({threads, kTestMinItems});
    loops.resolve_threads();
    INFO(threads << " threads");
    // 1,000 items: each chunk lists its items, and the chunks joined in order are 0, 1, ..., 999.
    const std::size_t n = 1000;
    const int chunks = loops.chunks(n);
    CHECK(chunks == (threads == 1 ? 1 : dcr::ChunkedLoops::kChunksPerThread * threads));
    dcr::ChunkLists<int> part;
    part.reset(chunks);
    loops.run(n, [&](std::size_t begin, std::size_t end, int chunk) {
      for (std::size_t i = begin; i < end; ++i) part[chunk].push_back(static_cast<int>(i));
    });
    std::vector<int> joined;
    part.append_to(joined);
    REQUIRE(joined.size() == n);
    for (std::size_t i = 0; i < n; ++i) CHECK(joined[i] == static_cast<int>(i));
    // Too few items: one chunk on the calling thread.
    CHECK(loops.chunks(kTestMinItems - 1) == 1);
    // Two items throw: the lower one's exception comes out, as from a loop on one thread.
    auto failing = [&] {
      loops.run(n, [](std::size_t begin, std::size_t end, int) {
        for (std::size_t i = begin; i < end; ++i)
          if (i == 700 || i == 300) throw std::runtime_error("item " + std::to_string(i));
      });
    };
    CHECK_THROWS_WITH(failing(), "item 300");
    CHECK(loops.threaded_loops() == (threads == 1 ? 0 : 2));
  }
}

TEST_CASE("The broad phase lists the same candidates on 1, 2 and 3 threads", "[threads][dcr]") {
  // Two 6 x 6 x 3 boxes, one above the other, the upper one sheared: a rebuild (grid search),
  // then a cached step.
  ModelMesh mesh;
  add_body(mesh, "a", test::neo_hookean(1e6, 0.3, 1000.0),
           structured_box(Vec3(0.03, 0.03, 0.015), 6, 6, 3));
  add_body(mesh, "b", test::neo_hookean(1e6, 0.3, 1000.0),
           test::translated(structured_box(Vec3(0.03, 0.03, 0.015), 6, 6, 3),
                            Vec3(0.004, 0.002, 0.0155)));
  const dcr::SurfaceFeatures f = dcr::make_surface_features(mesh, {"a/boundary", "b/boundary"});
  std::vector<Vec3> x_end = mesh.X;
  for (Vec3& p : x_end) p += Vec3(1e-4 * p.z(), -2e-4 * p.x(), -6e-4 * p.z() / 0.03);
  auto search = [&](int threads, bool self_contact) {
    dcr::ChunkedLoops loops({threads, kTestMinItems});
    loops.resolve_threads();
    dcr::BroadPhase bp;
    bp.use_loops(loops);
    std::vector<dcr::Candidates> out(2);
    bp.find(f, mesh.X, x_end, 5e-4, self_contact, out[0]);  // rebuild
    bp.find(f, mesh.X, x_end, 5e-4, self_contact, out[1]);  // from the cache
    CHECK((threads == 1 ? loops.threaded_loops() == 0 : loops.threaded_loops() > 0));
    return std::make_pair(out, bp.stats());
  };
  for (bool self_contact : {false, true}) {
    INFO("self_contact " << self_contact);
    const auto [one, stats_one] = search(1, self_contact);
    REQUIRE(!one[0].node_face.empty());
    REQUIRE(!one[0].edge_edge.empty());
    for (int threads : {2, 3}) {
      INFO(threads << " threads");
      const auto [r, stats] = search(threads, self_contact);
      for (size_t k = 0; k < 2; ++k) {
        CHECK(r[k].node_face == one[k].node_face);
        CHECK(r[k].edge_edge == one[k].edge_edge);
      }
      CHECK(stats.cell_visits == stats_one.cell_visits);
      CHECK(stats.box_tests == stats_one.box_tests);
      CHECK(stats.cached_pairs == stats_one.cached_pairs);
    }
  }
}

TEST_CASE("A DCR impact with friction is bitwise the same on 1, 2 and 3 threads",
          "[threads][dcr]") {
  // A soft sphere (R = 10 mm) fired obliquely at 3 m/s into a soft block clamped at its base
  // (as the no-penetration test): it indents and slides, node-face and edge-edge contacts both
  // occur; friction 0.3, restitution 0.5, pair forces along z reported.
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
  settings.friction = 0.3;
  settings.restitution = 0.5;
  settings.output.force_axis = Vec3::UnitZ();
  check_thread_independence(model, settings, 3e-3);
}

TEST_CASE("DCR self-contact with friction is bitwise the same on 1, 2 and 3 threads",
          "[threads][dcr]") {
  // The clamped fork of the no-penetration test: its prongs, started towards each other, clap.
  const MaterialParams mat = test::neo_hookean(1e6, 0.3, 1000.0);
  const TetMesh fork = test::carved(structured_box(Vec3(0.05, 0.02, 0.06), 10, 4, 12),
                                    Vec3(0.02, -1.0, 0.02), Vec3(0.03, 1.0, 1.0));
  ModelMesh mesh;
  add_body(mesh, "fork", mat, fork);
  Model model = make_model(std::move(mesh));
  model.bcs.fix(nodes_on_plane(model.mesh, 0, Vec3(0, 0, 0), Vec3::UnitZ(), 1e-9));
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    const Vec3& X = model.mesh.X[static_cast<size_t>(n)];
    if (X.z() <= 0.02) continue;
    const double s = (X.z() - 0.02) / 0.04;  // 0 at the prongs' root, 1 at their tips
    model.initial_velocity[static_cast<size_t>(n)] =
        Vec3(X.x() < 0.025 ? 4.0 * s : -4.0 * s, 0.5 * s, 0.0);
  }
  dcr::DcrSettings settings;
  settings.surfaces = {"fork/boundary"};
  settings.self_contact = true;
  settings.friction = 0.3;
  check_thread_independence(model, settings, 6e-3);
}
