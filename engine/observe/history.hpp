// Sampled time histories of what a scene asked for, and nothing else.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "engine/core/state.hpp"
#include "engine/mesh/model_mesh.hpp"

namespace ccm {

struct TrackedNode {
  std::string name;
  int node = -1;
};

// Every rigid body (engine/body/) adds, after its body's columns, its pose and motion and the
// contact's action on it: <body>.x y z (centre of mass [m]), qw qx qy qz (rotation since the
// reference), vx vy vz [m/s], wx wy wz [rad/s], contact_impulse_x y z (momentum the contact has
// given it since t = 0 [N s]) and contact_force_x y z (that impulse over the output interval
// that ends at the sample [N]: its integral over the samples is the momentum exchanged). Its
// kinetic_energy column is the body's.
inline constexpr const char* kRigidColumns[] = {"x",
                                                "y",
                                                "z",
                                                "qw",
                                                "qx",
                                                "qy",
                                                "qz",
                                                "vx",
                                                "vy",
                                                "vz",
                                                "wx",
                                                "wy",
                                                "wz",
                                                "contact_impulse_x",
                                                "contact_impulse_y",
                                                "contact_impulse_z",
                                                "contact_force_x",
                                                "contact_force_y",
                                                "contact_force_z"};

struct OutputRequest {
  // per body: 1/2 sum m |v|^2 [J]; and a deformable body's centre-of-mass velocity
  // sum m v / sum m (<body>.vx, vy, vz [m/s]; a rigid body's are among its own columns)
  bool kinetic_energy = false;
  bool internal_energy = false;      // per body: sum V0 W [J]
  bool displacement = false;         // per body: mean and max |u| over its nodes [m]
  std::vector<TrackedNode> tracked;  // u and v of single nodes [m, m/s]
};

// Anything else that contributes columns to the history (e.g. a contact model's force and
// pressure, a rigid impactor's state). Sampled after the engine's own columns, in the order
// the sources were added.
class HistorySource {
 public:
  virtual ~HistorySource() = default;
  virtual std::vector<std::string> history_columns() const = 0;
  virtual void append_history(const State& s, std::vector<double>& row) const = 0;
};

class HistoryRecorder {
 public:
  HistoryRecorder(const ModelMesh& mesh, OutputRequest request);

  // Adds the source's columns; must be called before the first sample. Not owned.
  void add_source(const HistorySource& source);

  bool needs_internal_energy() const { return request_.internal_energy; }
  const std::vector<std::string>& columns() const { return columns_; }
  const std::vector<std::vector<double>>& rows() const { return rows_; }

  // body_internal_energy: one entry per body, read only when internal energy was requested.
  void sample(const State& s, std::span<const double> body_internal_energy);

 private:
  void sample_body(const State& s, const Body& b, double internal_energy,
                   std::vector<double>& row) const;
  void sample_rigid(const State& s, const RigidState& r, std::vector<double>& row);

  const ModelMesh& mesh_;
  OutputRequest request_;
  std::vector<const HistorySource*> sources_;
  std::vector<std::string> columns_;
  std::vector<std::vector<double>> rows_;
  std::vector<Vec3> last_contact_impulse_;  // per rigid body, at the last sample
  double last_t_ = 0.0;
};

// Kinetic energy 1/2 sum m |v|^2 of nodes [first, first + count).
double kinetic_energy(const State& s, int first, int count);
// sum m v / sum m over the nodes [first, first + count) [m/s].
Vec3 centre_of_mass_velocity(const State& s, int first, int count);

// Writes the history as CSV (header line of column names, then one line per sample, full
// precision). Written to a temporary file and renamed, so a reader never sees half a file.
void write_history_csv(const std::filesystem::path& file, const HistoryRecorder& history);

}  // namespace ccm
