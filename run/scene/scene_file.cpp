#include "run/scene/scene_file.hpp"

#include <toml++/toml.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <sstream>
#include <type_traits>

#include "config/did_you_mean.hpp"
#include "config/strict_table.hpp"
#include "config/text_file.hpp"
#include "engine/core/parameter_ranges.hpp"
#include "engine/core/time_table.hpp"

namespace ccm {
namespace {

namespace fs = std::filesystem;
using Keys = std::initializer_list<std::string_view>;

// One table of the scene file: the strict reader (config/strict_table.hpp) with the scene's
// vectors and the source references the builder's messages need.
class Table : public StrictTable {
 public:
  using StrictTable::StrictTable;
  explicit Table(StrictTable t) : StrictTable(std::move(t)) {}

  template <typename T>
  std::optional<T> get(std::string_view key) const {
    if constexpr (std::is_same_v<T, Vec3>) {
      const toml::node* n = node(key);
      if (!n) return std::nullopt;
      return vec3(*n, key_path(key));
    } else {
      return StrictTable::get<T>(key);
    }
  }
  template <typename T>
  T need(std::string_view key) const {
    if (auto v = get<T>(key)) return *v;
    fail(key, "required key is missing");
  }
  template <typename T>
  T get_or(std::string_view key, T fallback) const {
    return get<T>(key).value_or(fallback);
  }

  std::optional<Table> table(std::string_view key) const {
    if (auto t = StrictTable::table(key)) return Table(std::move(*t));
    return std::nullopt;
  }
  Table need_table(std::string_view key) const { return Table(StrictTable::need_table(key)); }
  // An array of tables ([[key]] or key = [{...}, ...]); empty when absent.
  std::vector<Table> tables(std::string_view key) const {
    std::vector<Table> out;
    for (StrictTable& t : StrictTable::tables(key)) out.emplace_back(std::move(t));
    return out;
  }

  // For the builder: the table's path and line, and the line of every key it sets.
  SourceRef ref() const { return SourceRef{path(), line(), key_lines()}; }

 private:
  Vec3 vec3(const toml::node& n, std::string_view path) const {
    const toml::array* a = n.as_array();
    if (!a || a->size() != 3) wrong_type(n, path, "an array of 3 numbers");
    Vec3 v;
    for (size_t i = 0; i < 3; ++i)
      v[static_cast<Eigen::Index>(i)] = number((*a)[i], fmt::format("{}[{}]", path, i));
    return v;
  }
};

// ---------------------------------------------------------------------------------------------
// Value checks

double positive(const Table& t, std::string_view key, double v) {
  if (!(v > 0.0)) t.fail(key, fmt::format("must be > 0 (got {})", v));
  return v;
}

Vec3 non_zero(const Table& t, std::string_view key, const Vec3& v) {
  if (!(v.norm() > 0.0)) t.fail(key, "must be a non-zero vector");
  return v;
}

std::string checked_name(const Table& t, std::string_view key) {
  std::string name = t.need<std::string>(key);
  const bool ok = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  });
  if (!ok)
    t.fail(key, fmt::format("'{}' is not a valid name (use letters, digits, _ and -)", name));
  return name;
}

// Adds name to names, failing when it is already there.
void require_unique(const Table& t, std::string_view key, const std::string& name,
                    std::map<std::string, std::string>& names) {
  const auto [it, fresh] = names.emplace(name, t.path());
  if (!fresh) t.fail(key, fmt::format("duplicate name '{}' (also used by {})", name, it->second));
}

// Exactly one of `keys` is present; returns it.
std::string_view one_of(const Table& t, Keys keys) {
  std::vector<std::string_view> given;
  for (std::string_view k : keys)
    if (t.has(k)) given.push_back(k);
  if (given.size() == 1) return given[0];
  if (given.empty()) t.fail("", fmt::format("needs one of: {}", fmt::join(keys, ", ")));
  t.fail(given[1], fmt::format("give only one of: {}", fmt::join(keys, ", ")));
}

// ---------------------------------------------------------------------------------------------
// [time], [monitor], [gravity], title

void parse_title(const Table& root, Scene& scene) {
  scene.title = root.get_or<std::string>("title", "");
}

void parse_time(const Table& root, Scene& scene) {
  const Table t = root.need_table("time");
  t.allow_only(
      {"end", "output_interval", "dt_safety", "max_dt", "max_steps", "end_after_separation"});
  SceneTime& time = scene.time;
  time.end = positive(t, "end", t.need<double>("end"));
  time.output_interval =
      positive(t, "output_interval", t.get_or("output_interval", time.end / 100));
  time.dt_safety = t.get_or("dt_safety", kDefaultDtSafety);
  if (!kDtSafetyRange.contains(time.dt_safety))
    t.fail("dt_safety", kDtSafetyRange.problem(time.dt_safety));
  if (time.dt_safety > 1.0)
    scene.warnings.push_back(fmt::format(
        "{}: {} > 1 exceeds the stable time step; use it only for stability experiments",
        t.where("dt_safety"), time.dt_safety));
  if (auto v = t.get<double>("max_dt")) time.max_dt = positive(t, "max_dt", *v);
  if (auto v = t.get<long>("max_steps")) {
    if (*v <= 0) t.fail("max_steps", fmt::format("must be > 0 (got {})", *v));
    time.max_steps = *v;
  }
  if (auto v = t.get<double>("end_after_separation")) {
    if (!(*v >= 0.0) || *v >= time.end)
      t.fail("end_after_separation",
             fmt::format("must lie in [0, end = {}) (got {})", time.end, *v));
    time.end_after_separation = *v;
  }
}

void parse_monitor(const Table& root, Scene& scene) {
  const auto t = root.table("monitor");
  if (!t) return;
  t->allow_only({"energy_tolerance", "check_interval", "dt_collapse_ratio"});
  MonitorSettings& m = scene.monitor;
  m.energy_tolerance =
      positive(*t, "energy_tolerance", t->get_or("energy_tolerance", m.energy_tolerance));
  const long interval = t->get_or("check_interval", static_cast<long>(m.check_interval));
  if (interval < 1 || interval > 1'000'000'000)
    t->fail("check_interval", fmt::format("must be >= 1 (got {})", interval));
  m.check_interval = static_cast<int>(interval);
  m.dt_collapse_ratio =
      positive(*t, "dt_collapse_ratio", t->get_or("dt_collapse_ratio", m.dt_collapse_ratio));
  if (m.dt_collapse_ratio >= 1.0)
    t->fail("dt_collapse_ratio", fmt::format("must be < 1 (got {})", m.dt_collapse_ratio));
}

void parse_gravity(const Table& root, Scene& scene) {
  const auto t = root.table("gravity");
  if (!t) return;
  t->allow_only({"acceleration"});
  scene.gravity = t->need<Vec3>("acceleration");
}

// ---------------------------------------------------------------------------------------------
// [[bodies]]

MaterialParams parse_material(const Table& t) {
  t.allow_only({"model", "E", "nu", "rho"});
  MaterialParams m;
  const std::string model = t.get_or<std::string>("model", "neo_hookean");
  if (!parse_material_model(model, m.model))
    t.fail("model", fmt::format("must be neo_hookean or linear_elastic (got '{}')", model));
  m.E = t.need<double>("E");
  m.nu = t.need<double>("nu");
  m.rho = t.need<double>("rho");
  // validate() answers "<field> <problem>"; report the problem at that field's key.
  const std::string problem = validate(m);
  if (!problem.empty()) {
    const size_t space = problem.find(' ');
    t.fail(problem.substr(0, space), problem.substr(space + 1));
  }
  return m;
}

struct ShapeInfo {
  Shape shape;
  std::string_view name;
  std::vector<std::string_view> keys;  // the keys that apply, besides "shape"
};

const std::array<ShapeInfo, 5> kShapes{{
    {Shape::sphere, "sphere", {"radius", "mesh_size", "refine"}},
    {Shape::box, "box", {"size", "centered", "mesh_size", "refine"}},
    {Shape::cylinder, "cylinder", {"radius", "length", "centered", "mesh_size", "refine"}},
    {Shape::pipe, "pipe", {"radius", "inner_radius", "length", "centered", "mesh_size", "refine"}},
    {Shape::mesh, "mesh", {"file", "scale"}},
}};

const ShapeInfo& shape_info(const Table& t) {
  const std::string name = t.need<std::string>("shape");
  for (const ShapeInfo& s : kShapes)
    if (s.name == name) return s;
  t.fail("shape", fmt::format("must be one of sphere, box, cylinder, pipe, mesh (got '{}')", name));
}

PrimitiveKind primitive_kind(Shape s) {
  switch (s) {
    case Shape::sphere:
      return PrimitiveKind::sphere;
    case Shape::cylinder:
      return PrimitiveKind::cylinder;
    case Shape::pipe:
      return PrimitiveKind::pipe;
    case Shape::box:
    case Shape::mesh:
      break;
  }
  return PrimitiveKind::box;
}

// refine = { center = [x, y, z], radius = r, mesh_size = h, transition = w }: local coordinates
// of the shape; the size grows linearly to the body's over w (default r).
LocalRefinement parse_refinement(const Table& t, double mesh_size) {
  t.allow_only({"center", "radius", "mesh_size", "transition"});
  LocalRefinement r;
  r.center = t.need<Vec3>("center");
  r.radius = positive(t, "radius", t.need<double>("radius"));
  r.mesh_size = positive(t, "mesh_size", t.need<double>("mesh_size"));
  if (t.has("transition")) r.transition = positive(t, "transition", t.need<double>("transition"));
  if (r.mesh_size > mesh_size)
    t.fail("mesh_size",
           fmt::format("must not exceed the body's mesh_size ({} > {})", r.mesh_size, mesh_size));
  return r;
}

PrimitiveSpec parse_primitive(const Table& t, Shape shape) {
  PrimitiveSpec p{primitive_kind(shape)};
  if (t.has("radius")) p.radius = positive(t, "radius", t.need<double>("radius"));
  if (t.has("length")) p.length = positive(t, "length", t.need<double>("length"));
  if (t.has("size")) {
    p.size = t.need<Vec3>("size");
    if (!(p.size.minCoeff() > 0.0))
      t.fail("size", fmt::format("every extent must be > 0 (got [{}])", fmt::join(p.size, ", ")));
  }
  if (t.has("inner_radius")) {
    p.inner_radius = positive(t, "inner_radius", t.need<double>("inner_radius"));
    if (!(p.inner_radius < p.radius))
      t.fail("inner_radius",
             fmt::format("must be < radius (got {} >= {})", p.inner_radius, p.radius));
  }
  p.centered = t.get_or("centered", false);
  p.mesh_size = positive(t, "mesh_size", t.need<double>("mesh_size"));
  if (const auto r = t.table("refine")) p.refinement = parse_refinement(*r, p.mesh_size);
  return p;
}

GeometrySpec parse_geometry(const Table& t) {
  t.allow_only({"shape", "size", "radius", "inner_radius", "length", "centered", "mesh_size",
                "refine", "file", "scale"});
  const ShapeInfo& info = shape_info(t);
  for (std::string_view k : {"size", "radius", "inner_radius", "length", "centered", "mesh_size",
                             "refine", "file", "scale"})
    if (t.has(k) && std::find(info.keys.begin(), info.keys.end(), k) == info.keys.end())
      t.fail(k, fmt::format("key '{}' does not apply to shape '{}'", k, info.name));
  for (std::string_view k : info.keys)
    if (k != "centered" && k != "refine" && k != "scale" && !t.has(k))
      t.fail(k, fmt::format("required for shape '{}'", info.name));

  GeometrySpec g;
  g.shape = info.shape;
  if (info.shape != Shape::mesh) {
    g.primitive = parse_primitive(t, info.shape);
    return g;
  }
  const fs::path file = t.need<std::string>("file");
  if (file.empty()) t.fail("file", "must not be empty");
  g.file = file.is_relative() ? t.file().parent_path() / file : file;
  g.scale = positive(t, "scale", t.get_or("scale", 1.0));
  return g;
}

Placement parse_placement(const Table& t) {
  t.allow_only({"translate", "rotate_axis", "rotate_deg"});
  Placement p;
  p.translation = t.get_or<Vec3>("translate", Vec3::Zero());
  p.rotation_axis = non_zero(t, "rotate_axis", t.get_or<Vec3>("rotate_axis", Vec3::UnitZ()));
  p.rotation_deg = t.get_or("rotate_deg", 0.0);
  return p;
}

// element = "tet4" (default) or "nodal_pressure" (Neo-Hookean only; docs/elements.md).
ElementKind parse_element(const Table& t, const MaterialParams& material) {
  ElementKind kind = kDefaultElementKind;
  if (!t.has("element")) return kind;
  const std::string name = t.need<std::string>("element");
  if (!parse_element_kind(name, kind))
    t.fail("element", unknown_value_problem(name, kElementKindNames));
  if (kind == ElementKind::nodal_pressure && material.model != MaterialModel::neo_hookean)
    t.fail("element", fmt::format("nodal_pressure needs material model neo_hookean (got '{}')",
                                  to_string(material.model)));
  return kind;
}

// [t, x, y, z] points of a vector history: at least one, finite, t strictly increasing.
std::vector<std::array<double, 4>> parse_vector_history(const Table& t, std::string_view key) {
  const toml::node* n = t.node(key);
  const std::string path = t.key_path(key);
  const toml::array* a = n ? n->as_array() : nullptr;
  if (!a) t.wrong_type(*n, path, "an array of [t, x, y, z] points");
  std::vector<std::array<double, 4>> points;
  std::vector<std::pair<double, double>> times;
  for (size_t i = 0; i < a->size(); ++i) {
    const std::string item = fmt::format("{}[{}]", path, i);
    const toml::array* p = (*a)[i].as_array();
    if (!p || p->size() != 4) t.wrong_type((*a)[i], item, "a [t, x, y, z] point of numbers");
    std::array<double, 4> v{};
    for (size_t c = 0; c < 4; ++c) v[c] = t.number((*p)[c], fmt::format("{}[{}]", item, c));
    points.push_back(v);
    times.emplace_back(v[0], v[1] + v[2] + v[3]);
  }
  const std::string problem = TimeTable::validate(times);
  if (!problem.empty()) t.fail(key, problem);
  return points;
}

// A pin's Coulomb friction: mu_s >= 0 (default 0) and mu_k in [0, mu_s] (default mu_s).
void parse_pin_friction(const Table& t, double& mu_s, double& mu_k) {
  mu_s = t.get_or("mu_s", 0.0);
  if (!kFrictionRange.contains(mu_s)) t.fail("mu_s", kFrictionRange.problem(mu_s));
  mu_k = t.get_or("mu_k", mu_s);
  if (!kFrictionRange.contains(mu_k)) t.fail("mu_k", kFrictionRange.problem(mu_k));
  if (mu_k > mu_s) t.fail("mu_k", fmt::format("must be at most mu_s ({})", mu_s));
}

// motion = "pinned": [bodies.pin] (docs/rigid-bodies.md, "Pinned"); an initial angular velocity
// must turn the body about the pin.
void parse_pin(const Table& body, BodySpec& b) {
  if (!body.has("pin")) body.fail("motion", "pinned needs a [bodies.pin] table (point, axis)");
  const Table t = body.need_table("pin");
  t.allow_only({"point", "axis", "mu_s", "mu_k", "radius"});
  RigidPin& pin = b.pin;
  pin.point = t.need<Vec3>("point");
  pin.axis = non_zero(t, "axis", t.need<Vec3>("axis"));
  parse_pin_friction(t, pin.mu_s, pin.mu_k);
  pin.radius = t.get_or("radius", pin.radius);
  if (!(pin.radius >= 0.0)) t.fail("radius", fmt::format("must be >= 0 (got {})", pin.radius));
  if ((pin.mu_s > 0.0) != (pin.radius > 0.0))
    t.fail(pin.radius > 0.0 ? "radius" : "mu_s",
           "the pin's friction needs both a coefficient and a radius (its arm)");
  const Vec3 w = b.initial_angular_velocity;
  const Vec3 e = pin.axis.normalized();
  if ((w - w.dot(e) * e).norm() > 1e-12 * w.norm())
    body.fail("initial_angular_velocity", "must be along the pin's axis");
}

// A rigid body's inertia given instead of computed (docs/rigid-bodies.md, "Given mass
// properties"): inertia = [Ixx, Iyy, Izz, Ixy, Ixz, Iyz] about the centre of mass [kg m^2], world
// axes in the placed reference configuration, and optionally center_of_mass [m]. The tensor must
// be that of a body: symmetric positive definite with principal moments obeying the triangle
// inequality (I_1 + I_2 >= I_3: every mass distribution does).
void parse_given_inertia(const Table& t, BodySpec& b) {
  for (std::string_view key : {"inertia", "center_of_mass"})
    if (!b.rigid && t.has(key)) t.fail(key, "applies only to kind = \"rigid\"");
  if (t.has("center_of_mass") && !t.has("inertia"))
    t.fail("center_of_mass", "applies with a given inertia (inertia = [...])");
  if (!t.has("inertia")) return;
  const toml::node* n = t.node("inertia");
  const toml::array* a = n->as_array();
  const std::string path = t.key_path("inertia");
  if (!a || a->size() != 6) t.wrong_type(*n, path, "[Ixx, Iyy, Izz, Ixy, Ixz, Iyz] (6 numbers)");
  std::array<double, 6> c{};
  for (size_t k = 0; k < 6; ++k) c[k] = t.number((*a)[k], fmt::format("{}[{}]", path, k));
  Mat3 I;
  I << c[0], c[3], c[4], c[3], c[1], c[5], c[4], c[5], c[2];
  const Vec3 m = Eigen::SelfAdjointEigenSolver<Mat3>(I).eigenvalues();  // ascending
  if (!(m.minCoeff() > 0.0))
    t.fail("inertia", fmt::format("must be positive definite (principal moments {:.4g}, {:.4g}, "
                                  "{:.4g} kg m^2)",
                                  m[0], m[1], m[2]));
  if (m[0] + m[1] < m[2] * (1.0 - 1e-12))
    t.fail("inertia",
           fmt::format("no body has these principal moments ({:.4g} + {:.4g} < {:.4g}: the "
                       "triangle inequality of a mass distribution)",
                       m[0], m[1], m[2]));
  b.inertia = I;
  if (t.has("center_of_mass")) b.center_of_mass = t.need<Vec3>("center_of_mass");
}

// kind = "rigid" and its keys (docs/rigid-bodies.md); the keys of a rigid body's motion are
// refused on a deformable body, and the keys of one motion under another.
void parse_rigid(const Table& t, BodySpec& b) {
  const std::string kind = t.get_or<std::string>("kind", "deformable");
  if (kind != "deformable" && kind != "rigid")
    t.fail("kind",
           unknown_value_problem(kind, std::array<std::string_view, 2>{"deformable", "rigid"}));
  b.rigid = kind == "rigid";
  for (std::string_view key :
       {"motion", "initial_angular_velocity", "velocity", "angular_velocity", "pin"})
    if (!b.rigid && t.has(key)) t.fail(key, "applies only to kind = \"rigid\"");
  if (!b.rigid) return;
  const std::string motion = t.get_or<std::string>("motion", "free");
  static constexpr std::array<std::string_view, 4> kMotions = {"free", "fixed", "prescribed",
                                                               "pinned"};
  if (motion == "free")
    b.motion = RigidMotion::free;
  else if (motion == "fixed")
    b.motion = RigidMotion::fixed;
  else if (motion == "prescribed")
    b.motion = RigidMotion::prescribed;
  else if (motion == "pinned")
    b.motion = RigidMotion::pinned;
  else
    t.fail("motion", unknown_value_problem(motion, kMotions));
  const bool prescribed = b.motion == RigidMotion::prescribed;
  const bool pinned = b.motion == RigidMotion::pinned;
  for (std::string_view key : {"velocity", "angular_velocity"})
    if (!prescribed && t.has(key)) t.fail(key, "applies only to motion = \"prescribed\"");
  if (!pinned && t.has("pin")) t.fail("pin", "applies only to motion = \"pinned\"");
  if (b.motion != RigidMotion::free && t.has("initial_velocity"))
    t.fail("initial_velocity",
           fmt::format("applies only to motion = \"free\" (this body's is \"{}\")", motion));
  if (!pinned && b.motion != RigidMotion::free && t.has("initial_angular_velocity"))
    t.fail("initial_angular_velocity",
           fmt::format("applies only to motion = \"free\" or \"pinned\" (this body's is \"{}\")",
                       motion));
  b.initial_angular_velocity = t.get_or<Vec3>("initial_angular_velocity", Vec3::Zero());
  if (pinned) return parse_pin(t, b);
  if (!prescribed) return;
  if (!t.has("velocity") && !t.has("angular_velocity"))
    t.fail("motion", "prescribed needs velocity = [[t, vx, vy, vz], ...] or angular_velocity");
  if (t.has("velocity")) b.prescribed_velocity = parse_vector_history(t, "velocity");
  if (t.has("angular_velocity"))
    b.prescribed_angular_velocity = parse_vector_history(t, "angular_velocity");
}

BodySpec parse_body(const Table& t, std::map<std::string, std::string>& names) {
  t.allow_only({"name", "kind", "motion", "initial_velocity", "initial_angular_velocity",
                "velocity", "angular_velocity", "pin", "mass", "inertia", "center_of_mass",
                "material", "element", "geometry", "placement"});
  BodySpec b;
  b.name = checked_name(t, "name");
  require_unique(t, "name", b.name, names);
  b.initial_velocity = t.get_or<Vec3>("initial_velocity", Vec3::Zero());
  if (t.has("mass")) b.mass = positive(t, "mass", t.need<double>("mass"));
  b.material = parse_material(t.need_table("material"));
  b.element = parse_element(t, b.material);
  parse_rigid(t, b);
  parse_given_inertia(t, b);
  const Table geometry = t.need_table("geometry");
  b.geometry = parse_geometry(geometry);
  if (auto p = t.table("placement")) b.placement = parse_placement(*p);
  b.where = t.ref();
  b.geometry_where = geometry.ref();
  return b;
}

void parse_bodies(const Table& root, Scene& scene) {
  const std::vector<Table> tables = root.tables("bodies");
  if (tables.empty()) root.fail("bodies", "at least one [[bodies]] table is required");
  std::map<std::string, std::string> names;
  for (const Table& t : tables) scene.bodies.push_back(parse_body(t, names));
}

// ---------------------------------------------------------------------------------------------
// Selections, [[fixed]], [[surface_loads]]

BoxSpec parse_box(const Table& t) {
  t.allow_only({"min", "max"});
  BoxSpec b{t.need<Vec3>("min"), t.need<Vec3>("max")};
  if (!(b.min.array() <= b.max.array()).all()) t.fail("max", "must be >= min in every component");
  return b;
}

PlaneSpec parse_plane(const Table& t) {
  t.allow_only({"point", "normal", "tolerance"});
  PlaneSpec p;
  p.point = t.need<Vec3>("point");
  p.normal = non_zero(t, "normal", t.need<Vec3>("normal"));
  p.tolerance = positive(t, "tolerance", t.get_or("tolerance", p.tolerance));
  return p;
}

std::optional<std::string> parse_body_ref(const Table& t) {
  if (!t.has("body")) return std::nullopt;
  return t.need<std::string>("body");
}

// One of node_set, box, plane: the nodes a [[fixed]] or [[joints]] table selects.
NodeSelection parse_node_selection(const Table& t) {
  const std::string_view kind = one_of(t, {"node_set", "box", "plane"});
  if (kind == "node_set") return NodeSetRef{t.need<std::string>("node_set")};
  if (kind == "box") return parse_box(t.need_table("box"));
  return parse_plane(t.need_table("plane"));
}

FixedSpec parse_fixed_one(const Table& t) {
  t.allow_only({"body", "node_set", "box", "plane"});
  FixedSpec f;
  f.body = parse_body_ref(t);
  f.selection = parse_node_selection(t);
  f.where = t.ref();
  return f;
}

void parse_fixed(const Table& root, Scene& scene) {
  for (const Table& t : root.tables("fixed")) scene.fixed.push_back(parse_fixed_one(t));
}

// A pin's clamp: stiffness and damping in kClampRange (default 0: no clamp).
double clamp_value(const Table& t, const char* key) {
  const double v = t.get_or(key, 0.0);
  if (!kClampRange.contains(v)) t.fail(key, kClampRange.problem(v));
  return v;
}

void check_column_prefix(const Table& t, std::string_view key, const std::string& name,
                         const Scene& scene);

// [[joints]]: kind = "pin" (point, axis, mu_s, mu_k, the clamp's stiffness and damping),
// "slide" (direction) or "track" (direction, normal_force, mu_s, mu_k, damping, from) on selected
// nodes.
JointSpec parse_joint(const Table& t) {
  const std::string kind = t.need<std::string>("kind");
  JointSpec j;
  if (kind == "pin") {
    t.allow_only({"name", "kind", "body", "node_set", "box", "plane", "point", "axis", "mu_s",
                  "mu_k", "stiffness", "damping"});
    j.point = t.need<Vec3>("point");
    j.axis = non_zero(t, "axis", t.need<Vec3>("axis"));
    parse_pin_friction(t, j.mu_s, j.mu_k);
    j.stiffness = clamp_value(t, "stiffness");
    j.damping = clamp_value(t, "damping");
  } else if (kind == "slide") {
    t.allow_only({"name", "kind", "body", "node_set", "box", "plane", "direction"});
    j.kind = JointKind::slide;
    j.axis = non_zero(t, "direction", t.need<Vec3>("direction"));
  } else if (kind == "track") {
    t.allow_only({"name", "kind", "body", "node_set", "box", "plane", "direction", "normal_force",
                  "mu_s", "mu_k", "damping", "from"});
    j.kind = JointKind::track;
    j.axis = non_zero(t, "direction", t.need<Vec3>("direction"));
    j.normal_force = t.need<double>("normal_force");
    if (!kNormalForceRange.contains(j.normal_force))
      t.fail("normal_force", kNormalForceRange.problem(j.normal_force));
    parse_pin_friction(t, j.mu_s, j.mu_k);
    j.damping = t.get_or("damping", 0.0);
    if (!kDampingRange.contains(j.damping)) t.fail("damping", kDampingRange.problem(j.damping));
    j.active_from = t.get_or("from", 0.0);
    if (!std::isfinite(j.active_from)) t.fail("from", "must be a finite time [s]");
  } else {
    t.fail("kind",
           unknown_value_problem(kind, std::array<std::string_view, 3>{"pin", "slide", "track"}));
  }
  j.body = parse_body_ref(t);
  j.selection = parse_node_selection(t);
  j.where = t.ref();
  return j;
}

void parse_joints(const Table& root, Scene& scene) {
  std::map<std::string, std::string> names;
  for (const Table& t : root.tables("joints")) {
    JointSpec j = parse_joint(t);
    j.name =
        t.has("name") ? checked_name(t, "name") : fmt::format("joint{}", scene.joints.size() + 1);
    require_unique(t, "name", j.name, names);
    check_column_prefix(t, "name", j.name, scene);
    scene.joints.push_back(std::move(j));
  }
}

std::vector<std::pair<double, double>> parse_force_table(const Table& t) {
  const toml::node* n = t.node("force");
  if (!n) t.fail("force", "required key is missing");
  const std::string path = t.key_path("force");
  const toml::array* a = n->as_array();
  if (!a) t.wrong_type(*n, path, "an array of [t, F] pairs");
  std::vector<std::pair<double, double>> points;
  for (size_t i = 0; i < a->size(); ++i) {
    const std::string item = fmt::format("{}[{}]", path, i);
    const toml::array* pair = (*a)[i].as_array();
    if (!pair || pair->size() != 2) t.wrong_type((*a)[i], item, "a [t, F] pair of numbers");
    points.emplace_back(t.number((*pair)[0], item + "[0]"), t.number((*pair)[1], item + "[1]"));
  }
  const std::string problem = TimeTable::validate(points);
  if (!problem.empty()) t.fail("force", problem);
  return points;
}

SurfaceLoadSpec parse_surface_load(const Table& t, size_t index) {
  t.allow_only({"name", "body", "surface", "plane", "direction", "force"});
  SurfaceLoadSpec s;
  s.name = t.has("name") ? checked_name(t, "name") : fmt::format("load{}", index);
  s.body = parse_body_ref(t);
  if (one_of(t, {"surface", "plane"}) == "surface")
    s.surface = SurfaceRef{t.need<std::string>("surface")};
  else
    s.surface = parse_plane(t.need_table("plane"));
  s.direction = non_zero(t, "direction", t.need<Vec3>("direction"));
  s.force = parse_force_table(t);
  s.where = t.ref();
  return s;
}

void parse_surface_loads(const Table& root, Scene& scene) {
  const std::vector<Table> tables = root.tables("surface_loads");
  for (size_t i = 0; i < tables.size(); ++i)
    scene.surface_loads.push_back(parse_surface_load(tables[i], i));
}

// ---------------------------------------------------------------------------------------------
// [output]

TrackSpec parse_track(const Table& t, std::map<std::string, std::string>& names) {
  t.allow_only({"name", "body", "point"});
  TrackSpec s;
  s.name = checked_name(t, "name");
  require_unique(t, "name", s.name, names);
  s.body = t.need<std::string>("body");
  s.point = t.need<Vec3>("point");
  s.where = t.ref();
  return s;
}

// fields = ["displacement", ...]: names of engine/observe/field_catalog.hpp, each once.
std::vector<FieldKind> parse_field_list(const Table& t) {
  const toml::node* n = t.node("fields");
  const toml::array* a = n->as_array();
  const std::string path = t.key_path("fields");
  if (!a) t.wrong_type(*n, path, "an array of field names");
  static constexpr auto kNames = field_names();
  std::vector<FieldKind> fields;
  for (size_t i = 0; i < a->size(); ++i) {
    const toml::node& e = (*a)[i];
    const std::string item = fmt::format("{}[{}]", path, i);
    if (!e.is_string()) t.wrong_type(e, item, "a string");
    const std::string& name = e.as_string()->get();
    const std::optional<FieldKind> kind = parse_field_name(name);
    if (!kind) t.fail_at(e, item, unknown_value_problem(name, kNames));
    if (std::find(fields.begin(), fields.end(), *kind) != fields.end())
      t.fail_at(e, item, fmt::format("field '{}' is listed twice", name));
    fields.push_back(*kind);
  }
  return fields;
}

// field_interval: > 0 and a whole multiple of the output interval, so that every field frame
// falls on an output sample (the step lands exactly on those).
double parse_field_interval(const Table& t, double output_interval) {
  if (!t.has("field_interval")) return output_interval;
  const double v = positive(t, "field_interval", t.need<double>("field_interval"));
  const std::string problem = field_interval_problem(v, output_interval);
  if (!problem.empty()) t.fail("field_interval", problem);
  return v;
}

void parse_output(const Table& root, Scene& scene) {
  OutputSpec& o = scene.output;
  o.field_interval = scene.time.output_interval;
  const auto t = root.table("output");
  if (!t) return;
  t->allow_only(
      {"kinetic_energy", "internal_energy", "displacement", "track", "fields", "field_interval"});
  o.kinetic_energy = t->get_or("kinetic_energy", o.kinetic_energy);
  o.internal_energy = t->get_or("internal_energy", o.internal_energy);
  o.displacement = t->get_or("displacement", o.displacement);
  std::map<std::string, std::string> names;
  for (const Table& track : t->tables("track")) o.track.push_back(parse_track(track, names));
  if (t->has("fields")) o.fields = parse_field_list(*t);
  if (t->has("field_interval") && !t->has("fields"))
    t->fail("field_interval", "applies only with fields = [...]");
  o.field_interval = parse_field_interval(*t, scene.time.output_interval);
}

// ---------------------------------------------------------------------------------------------
// [contact]

// The history columns of the sphere are "<name>.<quantity>", like a body's or a tracked
// point's: its name must not be one of theirs.
void check_column_prefix(const Table& t, std::string_view key, const std::string& name,
                         const Scene& scene) {
  for (const BodySpec& b : scene.bodies)
    if (b.name == name)
      t.fail(key, fmt::format("'{}' is also the name of a body (their history columns would clash)",
                              name));
  for (const TrackSpec& tr : scene.output.track)
    if (tr.name == name)
      t.fail(key,
             fmt::format(
                 "'{}' is also the name of a tracked point (their history columns would clash)",
                 name));
  for (const JointSpec& j : scene.joints)
    if (j.name == name)
      t.fail(key,
             fmt::format("'{}' is also the name of a joint (their history columns would clash)",
                         name));
}

RigidSphereSpec parse_sphere(const Table& t, const Scene& scene) {
  t.allow_only({"name", "radius", "mass", "density", "center", "velocity"});
  RigidSphereSpec s;
  if (t.has("name")) s.name = checked_name(t, "name");
  check_column_prefix(t, t.has("name") ? "name" : "", s.name, scene);
  s.radius = positive(t, "radius", t.need<double>("radius"));
  if (one_of(t, {"mass", "density"}) == "mass") {
    s.mass = positive(t, "mass", t.need<double>("mass"));
  } else {
    const double rho = positive(t, "density", t.need<double>("density"));
    s.mass = rho * 4.0 / 3.0 * std::numbers::pi * s.radius * s.radius * s.radius;
  }
  s.center = t.need<Vec3>("center");
  s.velocity = t.get_or<Vec3>("velocity", Vec3::Zero());
  return s;
}

// model = "dcr": the surfaces are checked against the meshes by the builder.
// An array of distinct strings (surface names) at key.
std::vector<std::string> surface_names(const Table& t, const std::string& key) {
  const toml::node* n = t.node(key);
  const toml::array* a = n ? n->as_array() : nullptr;
  const std::string path = t.key_path(key);
  if (!a) t.wrong_type(*n, path, "an array of strings");
  std::vector<std::string> names;
  for (size_t i = 0; i < a->size(); ++i) {
    const toml::node& e = (*a)[i];
    if (!e.is_string()) t.wrong_type(e, fmt::format("{}[{}]", path, i), "a string");
    std::string name = e.as_string()->get();
    if (std::find(names.begin(), names.end(), name) != names.end())
      t.fail_at(e, fmt::format("{}[{}]", path, i),
                fmt::format("surface '{}' is listed twice", name));
    names.push_back(std::move(name));
  }
  return names;
}

// The keys of each model's table; a pair of [[contact.pairs]] also has "name".
const std::vector<std::string_view> kDcrKeys = {
    "model", "surfaces", "self_contact", "restitution", "friction", "force_axis", "sensors"};
const std::vector<std::string_view> kPenaltyKeys = {
    "model",   "body",       "surface", "penalty_mode", "penalty",     "penalty_scale",
    "damping", "force_axis", "sphere",  "rigid",        "crease_angle"};

std::vector<std::string_view> with_name_key(std::vector<std::string_view> keys, bool pair) {
  if (pair) keys.emplace_back("name");
  return keys;
}

void parse_dcr(const Table& t, ContactSpec& c, bool pair) {
  t.allow_only(with_name_key(kDcrKeys, pair));
  c.kind = ContactKind::dcr;
  if (!t.node("surfaces")) t.fail("surfaces", "required key is missing");
  c.surfaces = surface_names(t, "surfaces");
  if (c.surfaces.empty()) t.fail("surfaces", "needs at least one surface");
  c.self_contact = t.get_or("self_contact", c.self_contact);
  c.restitution = t.get_or("restitution", c.restitution);
  if (!kRestitutionRange.contains(c.restitution))
    t.fail("restitution", kRestitutionRange.problem(c.restitution));
  c.friction = t.get_or("friction", c.friction);
  if (!kFrictionRange.contains(c.friction)) t.fail("friction", kFrictionRange.problem(c.friction));
  if (t.has("force_axis")) c.force_axis = non_zero(t, "force_axis", t.need<Vec3>("force_axis"));
  if (t.has("sensors")) c.sensors = surface_names(t, "sensors");
  c.where = t.ref();
}

// penalty_mode = "per_point" (K_P = penalty) or "element" (s = penalty_scale); each key of one
// mode is an error with the other.
void parse_penalty(const Table& t, ContactSpec& c) {
  if (t.has("penalty_mode")) {
    const std::string mode = t.need<std::string>("penalty_mode");
    if (!parse_penalty_mode(mode, c.penalty_mode))
      t.fail("penalty_mode", unknown_value_problem(mode, kPenaltyModeNames));
  }
  const bool element = c.penalty_mode == PenaltyMode::element;
  if (element && t.has("penalty"))
    t.fail("penalty",
           "applies only with penalty_mode = \"per_point\" (the element mode's springs are "
           "penalty_scale K A^2 / V)");
  if (!element && t.has("penalty_scale"))
    t.fail("penalty_scale", "applies only with penalty_mode = \"element\"");
  c.penalty = positive(t, "penalty", t.get_or("penalty", c.penalty));
  c.penalty_scale = positive(t, "penalty_scale", t.get_or("penalty_scale", c.penalty_scale));
}

// model = "rigid_penalty" (or "penalty"): a deformable surface against the analytic sphere or a
// meshed rigid body.
void parse_rigid_penalty(const Table& t, ContactSpec& c, const Scene& scene, bool pair) {
  t.allow_only(with_name_key(kPenaltyKeys, pair));
  c.kind = ContactKind::rigid_penalty;
  c.body = t.need<std::string>("body");
  if (t.has("surface")) c.surface = t.need<std::string>("surface");
  parse_penalty(t, c);
  c.damping = t.get_or("damping", c.damping);
  if (!kDampingRange.contains(c.damping)) t.fail("damping", kDampingRange.problem(c.damping));
  c.where = t.ref();
  // Against a meshed rigid body (docs/rigid-bodies.md, "Penalty") instead of the analytic sphere.
  if (one_of(t, {"sphere", "rigid"}) == "rigid") {
    c.rigid = t.need<std::string>("rigid");
    if (c.penalty_mode == PenaltyMode::element)
      t.fail("penalty_mode",
             "the element mode applies to the analytic sphere only; use "
             "\"per_point\" with rigid");
    if (t.has("force_axis"))
      t.fail("force_axis",
             "applies to the analytic sphere only (a rigid body's history has its "
             "contact force)");
    c.crease_angle = t.get_or("crease_angle", c.crease_angle);
    if (!kCreaseAngleRange.contains(c.crease_angle))
      t.fail("crease_angle", kCreaseAngleRange.problem(c.crease_angle));
    return;
  }
  if (t.has("crease_angle"))
    t.fail("crease_angle", "applies only to a meshed rigid body (rigid = \"<body>\")");
  if (t.has("force_axis")) c.force_axis = non_zero(t, "force_axis", t.need<Vec3>("force_axis"));
  const Table sphere = t.need_table("sphere");
  c.sphere = parse_sphere(sphere, scene);
  c.sphere_where = sphere.ref();
}

const std::vector<std::string_view> kContactModelNames = {"none", "dcr", "rigid_penalty",
                                                          "penalty"};

// One contact table: [contact] (pair = false) or one entry of [[contact.pairs]]. Empty for
// model = "none" (only in [contact]).
std::optional<ContactSpec> parse_contact_table(const Table& t, const Scene& scene, bool pair) {
  const std::string model = t.need<std::string>("model");
  ContactSpec c;
  if (model == "none" && !pair) {
    t.allow_only({"model"});
    return std::nullopt;
  }
  if (pair && t.has("name")) c.name = checked_name(t, "name");
  if (model == "dcr")
    parse_dcr(t, c, pair);
  else if (model == "rigid_penalty" || model == "penalty")
    parse_rigid_penalty(t, c, scene, pair);
  else
    t.fail("model",
           unknown_value_problem(model, std::span(kContactModelNames).subspan(pair ? 1 : 0)));
  return c;
}

// [[contact.pairs]]: one contact model per entry, acting in the order given (docs/scene-file.md,
// "Contact pairs"). Each entry's history columns start with its name (default "pair<k>").
void parse_contact_pairs(const Table& contact, Scene& scene) {
  contact.allow_only({"pairs"});
  const std::vector<Table> tables = contact.tables("pairs");
  if (tables.empty()) contact.fail("pairs", "needs at least one [[contact.pairs]] table");
  for (size_t k = 0; k < tables.size(); ++k) {
    const Table& t = tables[k];
    ContactSpec c = *parse_contact_table(t, scene, true);
    if (!t.has("name")) c.name = fmt::format("pair{}", k + 1);
    check_column_prefix(t, t.has("name") ? "name" : "", c.name, scene);
    for (const ContactSpec& other : scene.contacts)
      if (other.name == c.name)
        t.fail(t.has("name") ? "name" : "",
               fmt::format("pair name '{}' is used twice (it starts the pair's history columns)",
                           c.name));
    scene.contacts.push_back(std::move(c));
  }
}

void parse_contact(const Table& root, Scene& scene) {
  const auto t = root.table("contact");
  if (!t) return;
  if (t->has("pairs")) return parse_contact_pairs(*t, scene);
  if (auto c = parse_contact_table(*t, scene, false)) scene.contacts.push_back(std::move(*c));
}

// ---------------------------------------------------------------------------------------------
// The top level: one row per table or key. A new section is one more row.

struct Section {
  std::string_view key;
  void (*parse)(const Table& root, Scene& scene);
};

const std::array<Section, 10> kSections = {{
    {"title", parse_title},
    {"time", parse_time},
    {"monitor", parse_monitor},
    {"gravity", parse_gravity},
    {"bodies", parse_bodies},
    {"fixed", parse_fixed},
    {"surface_loads", parse_surface_loads},
    {"output", parse_output},
    {"joints", parse_joints},  // after bodies and output: a pin's names must not clash with theirs
    {"contact", parse_contact},  // after bodies and output: its names must not clash with theirs
}};

void check_top_level_keys(const toml::table& root, const Table& t) {
  for (auto&& [k, v] : root) {
    const std::string_view key = k.str();  // (clang 14 cannot capture a structured binding)
    const auto known = [&](const Section& s) { return s.key == key; };
    if (std::none_of(kSections.begin(), kSections.end(), known)) {
      std::vector<std::string_view> allowed;
      for (const Section& s : kSections) allowed.push_back(s.key);
      t.fail(k.str(), unknown_key_problem(k.str(), allowed));
    }
  }
}

}  // namespace

Scene parse_scene(std::string_view text, const std::filesystem::path& source) {
  const toml::table root = parse_toml(text, source);
  Scene scene;
  scene.source = source;
  const Table t(root, "", source);
  check_top_level_keys(root, t);
  for (const Section& s : kSections) s.parse(t, scene);
  return scene;
}

Scene parse_scene_file(const std::filesystem::path& file) {
  return parse_scene(read_config_text(file), file);
}

}  // namespace ccm
