#include "app/run_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <exception>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "app/output_file.hpp"
#include "app/progress_line.hpp"
#include "app/setup_time.hpp"
#include "config/text_file.hpp"
#include "engine/distributed/distributed_run.hpp"
#include "engine/mesh/mesh_cache.hpp"
#include "engine/observe/history.hpp"
#include "engine/solver/explicit_integrator.hpp"
#include "engine/threads/thread_count.hpp"
#include "io/fields/field_recorder.hpp"
#include "records/content_hash.hpp"
#include "records/provenance/timestamp.hpp"
#include "records/provenance/version.hpp"
#include "run/parallel/rank_context.hpp"
#include "run/scene/scene_builder.hpp"
#include "run/scene/scene_file.hpp"
#include "run/scene/scene_run.hpp"

namespace ccm {
namespace {

// Why the run stopped, for people (TimeControl::end_after_separation).
std::string run_end_text(const RunSummary& s, const SceneTime& time) {
  if (s.ended_by == RunEnd::separated)
    return fmt::format(
        "the bodies separated: the contact open since {:.6g} s for the hold {:.6g} s",
        s.contact_opened_at, *time.end_after_separation);
  if (!time.end_after_separation) return "the end time";
  return s.touched ? fmt::format(
                         "the end time (the guard): the contact did not stay open for the "
                         "hold {:.6g} s",
                         *time.end_after_separation)
                   : "the end time (the guard): the bodies never touched";
}

namespace fs = std::filesystem;
using SystemClock = std::chrono::system_clock;

// An error met by every rank is told by rank 0 alone; the other ranks are quiet.
bool g_quiet_rank = false;
// Set once the ranks have agreed that each prepared the scene: an error after that may be one
// rank's alone, and ends the whole job (run_command).
bool g_stepping = false;

// Bad command-line input that is not about the scene file.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// ---------------------------------------------------------------------------------------------
// Small helpers: hashing, time stamps (TOML values and atomic files: output_file.hpp)

// ---------------------------------------------------------------------------------------------
// Preparation: everything that bad input can make fail, before anything is written

// The scene's text as read, and the scene assembled for its run (run/scene/scene_run.hpp).
struct Prepared : SceneRun {
  std::string text;
  double setup_seconds = 0.0;  // assembling the run: meshing, masses, surfaces, contact
  MeshCacheStats meshing;      // what the mesh cache did meanwhile
};

std::string setup_text(const Prepared& p) { return setup_time_text(p.setup_seconds, p.meshing); }

void check_out_dir(const fs::path& out) {
  std::error_code ec;
  if (out.empty()) throw UsageError("--out: the output directory must not be empty");
  if (fs::exists(out, ec) && !fs::is_directory(out, ec))
    throw UsageError(fmt::format("--out {}: exists and is not a directory", out.string()));
}

// The scene's text and the name it goes by: a file, or stdin for "-" (`ccm study scene ... |
// ccm run - --out DIR`; a relative mesh path is then taken from the working directory).
fs::path read_scene(const RunArgs& args, const std::string& piped, std::string& text) {
  if (args.scene != "-") {
    text = read_config_text(args.scene);
    return args.scene;
  }
  text = piped;
  return kStdinSceneName;
}

// The standard input, for a scene given as "-". Under mpirun only rank 0 has it: rank 0 reads
// it and passes it on, so that every rank prepares the same scene. A read that fails leaves
// rank 0's text empty and is reported by read_failed (rank 0's preparation then fails).
std::string piped_scene(const RunArgs& args, const study::RankContext& ranks, bool& read_failed) {
  std::string text;
  read_failed = false;
  if (args.scene != "-") return text;
  if (ranks.is_root()) {
    std::ostringstream all;  // (istreambuf_iterator here draws a GCC 12 -Wnull-dereference)
    all << std::cin.rdbuf();
    read_failed = std::cin.bad();
    text = all.str();
  }
  return ranks.broadcast_text(text);
}

void prepare(const RunArgs& args, const std::string& piped, Prepared& p) {
  try {
    set_default_threads(resolve_threads(args.threads, available_cores()));
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const fs::path source = read_scene(args, piped, p.text);
  Scene scene = parse_scene(p.text, source);
  if (args.fields) scene.output.fields = fields::all_fields();
  for (const std::string& w : scene.warnings) fmt::print(stderr, "ccm: warning: {}\n", w);
  check_out_dir(args.out);
  const MeshCacheStats before = mesh_cache_stats();
  const auto start = std::chrono::steady_clock::now();
  static_cast<SceneRun&>(p) = assemble_scene_run(std::move(scene));
  p.setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  p.meshing = mesh_cache_delta(before, mesh_cache_stats());
}

// ---------------------------------------------------------------------------------------------
// Reporting

struct RunRecord {
  const RunArgs& args;
  const Prepared& prepared;
  const RunSummary& summary;
  const distributed::PartitionReport& partition;  // ranks == 1: a serial run
  std::string started;
  std::string finished;
  int exit_code = 0;
  int field_frames = 0;  // frames in fields.xdmf (0: no field output)
};

std::string instability_text(const Instability& i) {
  std::string s = fmt::format("at t = {:.6g} s: {}", i.time, i.reason);
  if (i.element >= 0) s += fmt::format(" (element {})", i.element);
  if (i.node >= 0) s += fmt::format(" (node {})", i.node);
  return s;
}

double largest(const std::vector<double>& v) {
  return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
}

void print_partition(const distributed::PartitionReport& p) {
  if (p.ranks <= 1) return;
  fmt::print(
      "  {:<15}{} ranks (METIS), imbalance {:.2f} %, {} cut faces, {} contact region nodes\n",
      "partition", p.ranks, 100.0 * p.imbalance, p.cut_faces, p.contact_region_nodes);
  fmt::print("  {:<15}communication {:.3f} s, contact {:.3f} s (slowest rank)\n", "",
             largest(p.communication_seconds), largest(p.contact_seconds));
}

std::string partition_toml(const distributed::PartitionReport& p) {
  if (p.ranks <= 1) return {};
  std::string t = "\n[partition]  # mpirun -np N ccm run: METIS subdomains, one per rank\n";
  t += fmt::format("ranks = {}\nimbalance = {}  # max part cost / mean - 1\ncut_faces = {}\n",
                   p.ranks, toml_float(p.imbalance), p.cut_faces);
  t += fmt::format("contact_region_nodes = {}\n", p.contact_region_nodes);
  t += fmt::format("owned_nodes = [{}]\nhalo_nodes = [{}]\nneighbours = [{}]\nelements = [{}]\n",
                   fmt::join(p.owned_nodes, ", "), fmt::join(p.halo_nodes, ", "),
                   fmt::join(p.neighbours, ", "), fmt::join(p.elements, ", "));
  t += fmt::format("step_seconds = [{}]\ncommunication_seconds = [{}]\ncontact_seconds = [{}]\n",
                   fmt::join(p.step_seconds, ", "), fmt::join(p.communication_seconds, ", "),
                   fmt::join(p.contact_seconds, ", "));
  t += fmt::format(
      "step_cpu_seconds = [{}]\ncommunication_cpu_seconds = [{}]\ncontact_cpu_seconds = [{}]\n",
      fmt::join(p.step_cpu_seconds, ", "), fmt::join(p.communication_cpu_seconds, ", "),
      fmt::join(p.contact_cpu_seconds, ", "));
  t += fmt::format("messages = [{}]\nmessage_doubles = [{}]\ncollectives = [{}]\n",
                   fmt::join(p.messages, ", "), fmt::join(p.message_doubles, ", "),
                   fmt::join(p.collectives, ", "));
  return t;
}

void print_summary_table(const RunRecord& r) {
  const RunSummary& s = r.summary;
  const ModelMesh& mesh = r.prepared.model.mesh;
  fmt::print("ccm run {}{}\n", r.args.scene.string(),
             r.prepared.scene.title.empty() ? "" : "  (" + r.prepared.scene.title + ")");
  fmt::print("  {:<15}{}\n", "bodies", mesh.bodies.size());
  for (const Body& b : mesh.bodies)
    fmt::print("  {:<15}  {}: {} nodes, {} elements{}\n", "", b.name, b.n_nodes, b.n_elements,
               b.rigid ? " (rigid: its elements are not stepped)" : "");
  for (const RigidBodyModel& rb : r.prepared.model.rigid_bodies) {
    const MassProperties& m = rb.mass;
    fmt::print("  {:<15}{} ({}): mass {:.6g} kg, centre [{:.6g}, {:.6g}, {:.6g}] m\n", "rigid body",
               mesh.bodies[static_cast<size_t>(rb.body)].name, to_string(rb.motion), m.mass,
               m.center.x(), m.center.y(), m.center.z());
    fmt::print(
        "  {:<15}  inertia about the centre [kg m^2]: [[{:.6g}, {:.6g}, {:.6g}], [{:.6g}, "
        "{:.6g}, {:.6g}], [{:.6g}, {:.6g}, {:.6g}]]\n",
        "", m.inertia(0, 0), m.inertia(0, 1), m.inertia(0, 2), m.inertia(1, 0), m.inertia(1, 1),
        m.inertia(1, 2), m.inertia(2, 0), m.inertia(2, 1), m.inertia(2, 2));
  }
  fmt::print("  {:<15}{}\n", "nodes", s.n_nodes);
  fmt::print("  {:<15}{}\n", "elements", s.n_elements);
  const ContactSetup& contact = r.prepared.contact;
  fmt::print("  {:<15}{}\n", "contact", contact.model ? contact.description : "none");
  for (const auto& joint : r.prepared.joints)
    fmt::print("  {:<15}{} (work {:.6g} J)\n", "joint", joint->name(), joint->work());
  if (contact.model)
    fmt::print("  {:<15}{:.6g} J (work of the contact on the bodies)\n", "",
               contact.model->ledger().work);
  fmt::print("  {:<15}{}\n", "set-up", setup_text(r.prepared));
  fmt::print("  {:<15}{:.6g} s of {:.6g} s\n", "sim time", s.end_time, r.prepared.scene.time.end);
  fmt::print("  {:<15}{}\n", "ended by", run_end_text(s, r.prepared.scene.time));
  fmt::print("  {:<15}{}\n", "steps", s.steps);
  fmt::print("  {:<15}initial {:.4g} s, min {:.4g} s, max {:.4g} s\n", "dt", s.dt_initial, s.dt_min,
             s.dt_max);
  fmt::print("  {:<15}first {:.4g} s, mean {:.4g} s, smallest contact-limited {}\n", "", s.dt_first,
             s.dt_mean,
             s.limiters.contact > 0 ? fmt::format("{:.4g} s", s.dt_contact_min) : "none");
  fmt::print("  {:<15}structure {}, contact {}, max_dt {}, output/end landing {}\n", "dt set by",
             s.limiters.structure, s.limiters.contact, s.limiters.max_dt, s.limiters.landing);
  fmt::print("  {:<15}{:.3f} s (stepping: {:.3f} s wall, {:.3f} s thread CPU)\n", "wall time",
             s.wall_seconds, s.step_wall_seconds, s.step_cpu_seconds);
  fmt::print("  {:<15}{:.1f} ns\n", "per elem-step", s.ns_per_element_step);
  print_partition(r.partition);
  fmt::print("  {:<15}{:.3g} % (largest energy-balance error)\n", "energy error",
             100.0 * s.energy_balance_error);
  fmt::print("  {:<15}{}\n", "verdict", to_string(s.verdict));
  if (contact.solve_warning && !contact.solve_warning().empty())
    fmt::print("  {:<15}{}\n", "warning", contact.solve_warning());
  if (contact.search_summary && !contact.search_summary().empty())
    fmt::print("  {:<15}{}\n", "search", contact.search_summary());
  if (s.verdict == Verdict::unstable)
    fmt::print("  {:<15}{}\n", "instability", instability_text(s.instability));
  fmt::print("  {:<15}{}\n", "results", r.args.out.string());
  if (r.field_frames > 0)
    fmt::print("  {:<15}{} ({} frames; docs/fields.md)\n", "fields",
               (r.args.out / fields::kXdmfFile).string(), r.field_frames);
}

std::string summary_toml(const RunRecord& r) {
  const RunSummary& s = r.summary;
  const Scene& scene = r.prepared.scene;
  const ModelMesh& mesh = r.prepared.model.mesh;
  std::string t = "# ccm run summary\n";
  t += fmt::format("ccm_version = {}\n", toml_string(version_string()));
  const bool from_stdin = scene.source == kStdinSceneName;
  t +=
      fmt::format("scene = {}\n",
                  toml_string(from_stdin ? scene.source.string()
                                         : fs::absolute(scene.source).lexically_normal().string()));
  t += fmt::format("scene_fnv1a64 = {}\n", toml_string(study::fnv1a64(r.prepared.text)));
  t += fmt::format("title = {}\n", toml_string(scene.title));
  t += fmt::format("started = {}\nfinished = {}\n", r.started, r.finished);
  t +=
      fmt::format("verdict = {}\nexit_code = {}\n", toml_string(to_string(s.verdict)), r.exit_code);
  t += fmt::format("\n[model]\nbodies = {}\nnodes = {}\nelements = {}\n", mesh.bodies.size(),
                   s.n_nodes, s.n_elements);
  for (const RigidBodyModel& rb : r.prepared.model.rigid_bodies) {
    const MassProperties& m = rb.mass;
    t += fmt::format(
        "\n[[model.rigid_bodies]]  # docs/rigid-bodies.md\nbody = {}\nmotion = {}\nmass = {}  # "
        "kg\ncenter = [{}, {}, {}]  # m\ninertia = [[{}, {}, {}], [{}, {}, {}], [{}, {}, {}]]  # "
        "kg "
        "m^2, about the centre\n",
        toml_string(mesh.bodies[static_cast<size_t>(rb.body)].name),
        toml_string(to_string(rb.motion)), toml_float(m.mass), toml_float(m.center.x()),
        toml_float(m.center.y()), toml_float(m.center.z()), toml_float(m.inertia(0, 0)),
        toml_float(m.inertia(0, 1)), toml_float(m.inertia(0, 2)), toml_float(m.inertia(1, 0)),
        toml_float(m.inertia(1, 1)), toml_float(m.inertia(1, 2)), toml_float(m.inertia(2, 0)),
        toml_float(m.inertia(2, 1)), toml_float(m.inertia(2, 2)));
  }
  t += "\n[run]\n";
  t += fmt::format("end_time = {}\ntime_reached = {}\nsteps = {}\n", toml_float(scene.time.end),
                   toml_float(s.end_time), s.steps);
  t += fmt::format("ended_by = {}  # {}\ntouched = {}\n", toml_string(to_string(s.ended_by)),
                   run_end_text(s, scene.time), s.touched);
  if (s.ended_by == RunEnd::separated)
    t += fmt::format("contact_opened_at = {}\n", toml_float(s.contact_opened_at));
  t += fmt::format("dt_initial = {}\ndt_min = {}\ndt_max = {}\n", toml_float(s.dt_initial),
                   toml_float(s.dt_min), toml_float(s.dt_max));
  t += fmt::format("dt_first = {}\ndt_mean = {}\n", toml_float(s.dt_first), toml_float(s.dt_mean));
  if (s.limiters.contact > 0)
    t += fmt::format("dt_contact_min = {}\nfirst_contact_step_time = {}\n",
                     toml_float(s.dt_contact_min), toml_float(s.first_contact_step_time));
  t += fmt::format("setup_seconds = {}  # {}\nmeshes_made = {}\nmeshes_from_cache = {}\n",
                   toml_float(r.prepared.setup_seconds), setup_text(r.prepared),
                   r.prepared.meshing.misses, r.prepared.meshing.hits);
  t += fmt::format("wall_seconds = {}\nns_per_element_step = {}\n", toml_float(s.wall_seconds),
                   toml_float(s.ns_per_element_step));
  t += fmt::format(
      "step_wall_seconds = {}\nstep_cpu_seconds = {}  # CPU time of the step loop, all its "
      "threads\n",
      toml_float(s.step_wall_seconds), toml_float(s.step_cpu_seconds));
  t += fmt::format("threads = {}  # the result does not depend on it\n", s.threads);
  t += fmt::format("energy_balance_error = {}  # largest relative error (0.01 = 1 %)\n",
                   toml_float(s.energy_balance_error));
  t += fmt::format(
      "\n[run.steps_limited_by]  # each step once, by what set its length\n"
      "structure = {}\ncontact = {}\nmax_dt = {}\nlanding = {}  # output or end time\n",
      s.limiters.structure, s.limiters.contact, s.limiters.max_dt, s.limiters.landing);
  if (s.verdict == Verdict::unstable) {
    const Instability& i = s.instability;
    t += fmt::format("\n[instability]\ntime = {}\nreason = {}\nelement = {}\nnode = {}\n",
                     toml_float(i.time), toml_string(i.reason), i.element, i.node);
  }
  const ContactSetup& contact = r.prepared.contact;
  t += fmt::format("\n[contact]\nmodel = {}\n", toml_string(contact.model_name));
  if (contact.model)
    t += fmt::format("description = {}\nwork = {}  # J, of the contact on the bodies\n",
                     toml_string(contact.description), toml_float(contact.model->ledger().work));
  if (contact.solve_warning && !contact.solve_warning().empty())
    t += fmt::format("warning = {}\n", toml_string(contact.solve_warning()));
  if (contact.search_summary && !contact.search_summary().empty())
    t += fmt::format("search = {}\n", toml_string(contact.search_summary()));
  if (r.field_frames > 0)
    t += fmt::format("\n[fields]\nfile = {}\nframes = {}\n", toml_string(fields::kXdmfFile),
                     r.field_frames);
  t += partition_toml(r.partition);
  for (const Body& b : mesh.bodies)
    t += fmt::format("\n[[bodies]]\nname = {}\nnodes = {}\nelements = {}\n", toml_string(b.name),
                     b.n_nodes, b.n_elements);
  return t;
}

// ---------------------------------------------------------------------------------------------
// The command

RunSummary run_scene(const RunArgs& args, const Prepared& p, HistoryRecorder& history,
                     fields::FieldRecorder& fields, distributed::PartitionReport& partition) {
  RunOptions options = scene_run_options(p, &history);
  fields.attach(options);
  ProgressLine progress;
  options.progress = progress.on_terminal(args.quiet);
  const RunSummary summary = partition.ranks > 1
                                 ? distributed::run_partitioned(p.model, options, &partition)
                                 : run_explicit(p.model, options);
  progress.finish();
  return summary;
}

// Every rank prepares the scene alone. One that fails where the others do not (a file missing on
// one machine) would leave them waiting in the run's first collective, so the ranks agree
// first: a rank that failed rethrows its error (told by rank 0 if it failed too, else by the
// failing ranks themselves), and the others end with a usage error naming how many failed.
void agree_on_preparation(const study::RankContext& ranks, const std::exception_ptr& failure) {
  if (ranks.size() > 1) {
    const bool root_failed = ranks.broadcast_flag(failure != nullptr);
    const long failed = ranks.sum(failure ? 1 : 0);
    if (failure && !root_failed) g_quiet_rank = false;
    if (!failure && failed > 0)
      throw UsageError(
          fmt::format("{} of the {} MPI ranks could not prepare the scene", failed, ranks.size()));
  }
  if (failure) std::rethrow_exception(failure);
}

// Under mpirun with more than one rank, the scene's mesh is partitioned over the ranks (every
// rank prepares the whole scene, steps its subdomain); rank 0 alone writes and prints.
int run(const RunArgs& args, const study::RankContext& ranks) {
  const std::string started = utc_timestamp(SystemClock::now());
  bool read_failed = false;
  const std::string piped = piped_scene(args, ranks, read_failed);
  Prepared p;
  std::exception_ptr failure;
  try {
    if (read_failed) throw UsageError("cannot read the scene from stdin");
    prepare(args, piped, p);
    if (ranks.size() > 1 && !p.scene.output.fields.empty())
      throw UsageError(
          "field output (--fields, [output] fields) is not available in a run "
          "partitioned over MPI ranks: run it on one rank");
    if (ranks.size() > 1)
      if (auto why = distributed::partition_refusal(p.model)) throw UsageError(*why);
  } catch (...) {
    failure = std::current_exception();
  }
  agree_on_preparation(ranks, failure);
  g_stepping = true;
  if (ranks.is_root()) {
    fs::create_directories(args.out);
    write_atomic(args.out / "scene.toml", p.text);
  }
  RunArgs rank_args = args;
  rank_args.quiet = args.quiet || !ranks.is_root();
  HistoryRecorder history(p.model.mesh, p.output);
  const OutputSpec& out = p.scene.output;
  fields::FieldRecorder fields(p.model, {out.fields, out.field_interval, p.scene.title}, args.out);
  distributed::PartitionReport partition;
  partition.ranks = ranks.size();
  const RunSummary summary = run_scene(rank_args, p, history, fields, partition);
  fields.finish();
  const int code =
      summary.verdict == Verdict::completed ? exit_code::completed : exit_code::unstable;
  if (!ranks.is_root()) return code;
  write_history_csv(args.out / "history.csv", history);
  const RunRecord record{args,    p,
                         summary, partition,
                         started, utc_timestamp(SystemClock::now()),
                         code,    fields.frames_written()};
  write_atomic(args.out / "summary.toml", summary_toml(record));
  if (!args.quiet) print_summary_table(record);
  return code;
}

void report(std::string_view kind, std::string_view message) {
  if (g_quiet_rank) return;
  std::fflush(stdout);
  fmt::print(stderr, "ccm: {}: {}\n", kind, message);
}

// Reports an error and returns its exit code. Once the ranks have agreed on the preparation
// (g_stepping), an error may be one rank's alone while the others wait in a collective: that
// rank tells it with its number and ends the whole job with the code.
int fail(const study::RankContext& ranks, std::string_view kind, std::string_view message,
         int code) {
  if (g_stepping && ranks.size() > 1) {
    g_quiet_rank = false;
    report(kind, fmt::format("rank {}: {}", ranks.rank(), message));
    ranks.abort_all(code);
  }
  report(kind, message);
  return code;
}

}  // namespace

int resolve_threads(int requested, int automatic) {
  if (requested < 0)
    throw std::invalid_argument(fmt::format(
        "--threads {}: must be a positive number of threads (0: automatic)", requested));
  if (requested > 0) return requested;
  if (const std::optional<int> env = threads_from_environment()) return *env;
  return std::max(1, automatic);
}

int run_command(const RunArgs& args) {
  const study::RankContext ranks;  // MPI only when started by mpirun
  g_quiet_rank = !ranks.is_root();
  try {
    return run(args, ranks);
  } catch (const ConfigError& e) {
    return fail(ranks, "error", e.what(), exit_code::bad_input);
  } catch (const UsageError& e) {
    return fail(ranks, "error", e.what(), exit_code::bad_input);
  } catch (const std::exception& e) {
    return fail(ranks, "internal error", e.what(), exit_code::internal_error);
  } catch (const std::string& e) {  // Gmsh throws its messages as strings
    return fail(ranks, "internal error", e, exit_code::internal_error);
  } catch (...) {
    return fail(ranks, "internal error", "unknown exception", exit_code::internal_error);
  }
}

}  // namespace ccm
