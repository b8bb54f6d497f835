#include "engine/observe/history.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace ccm {

HistoryRecorder::HistoryRecorder(const ModelMesh& mesh, OutputRequest request)
    : mesh_(mesh), request_(std::move(request)) {
  columns_.push_back("time");
  for (const Body& b : mesh_.bodies) {
    if (request_.kinetic_energy) columns_.push_back(b.name + ".kinetic_energy");
    if (request_.internal_energy) columns_.push_back(b.name + ".internal_energy");
    if (request_.displacement) {
      columns_.push_back(b.name + ".u_mean");
      columns_.push_back(b.name + ".u_max");
    }
    if (!b.rigid && request_.kinetic_energy)  // a rigid body's are among its own columns
      for (const char* q : {"vx", "vy", "vz"}) columns_.push_back(b.name + "." + q);
    if (!b.rigid) continue;
    for (const char* q : kRigidColumns) columns_.push_back(b.name + "." + q);
    last_contact_impulse_.push_back(Vec3::Zero());
  }
  for (const TrackedNode& t : request_.tracked)
    for (const char* q : {"ux", "uy", "uz", "vx", "vy", "vz"}) columns_.push_back(t.name + "." + q);
}

void HistoryRecorder::add_source(const HistorySource& source) {
  if (!rows_.empty()) throw std::logic_error("HistoryRecorder::add_source after the first sample");
  sources_.push_back(&source);
  for (std::string& c : source.history_columns()) columns_.push_back(std::move(c));
}

double kinetic_energy(const State& s, int first, int count) {
  double ke = 0.0;
  for (int n = first; n < first + count; ++n) {
    const auto i = static_cast<size_t>(n);
    ke += s.m_lumped[i] * s.v[i].squaredNorm();
  }
  return 0.5 * ke;
}

// sum m_a v_a / sum m_a: the body's momentum over its mass.
Vec3 centre_of_mass_velocity(const State& s, int first, int count) {
  Vec3 p = Vec3::Zero();
  double m = 0.0;
  for (int n = first; n < first + count; ++n) {
    const auto i = static_cast<size_t>(n);
    p += s.m_lumped[i] * s.v[i];
    m += s.m_lumped[i];
  }
  return m > 0.0 ? Vec3(p / m) : Vec3::Zero();
}

void HistoryRecorder::sample_rigid(const State& s, const RigidState& r, std::vector<double>& row) {
  Vec3& last = last_contact_impulse_[static_cast<size_t>(&r - s.rigid.data())];
  const double interval = s.t - last_t_;
  const Vec3 F = interval > 0.0 ? Vec3((r.contact_impulse - last) / interval) : Vec3::Zero();
  last = r.contact_impulse;
  const Eigen::Quaterniond& q = r.rotation;
  row.insert(row.end(), {r.center.x(), r.center.y(), r.center.z(), q.w(), q.x(), q.y(), q.z(),
                         r.velocity.x(), r.velocity.y(), r.velocity.z(), r.angular_velocity.x(),
                         r.angular_velocity.y(), r.angular_velocity.z(), r.contact_impulse.x(),
                         r.contact_impulse.y(), r.contact_impulse.z(), F.x(), F.y(), F.z()});
}

void HistoryRecorder::sample_body(const State& s, const Body& b, double internal_energy,
                                  std::vector<double>& row) const {
  if (request_.kinetic_energy && b.rigid) {
    double ke = 0.0;
    const auto index = static_cast<int>(&b - mesh_.bodies.data());
    for (const RigidState& r : s.rigid)
      if (r.body == index) ke = r.kinetic_energy;
    row.push_back(ke);
  } else if (request_.kinetic_energy) {
    row.push_back(kinetic_energy(s, b.first_node, b.n_nodes));
  }
  if (request_.internal_energy) row.push_back(internal_energy);
  if (request_.displacement) {
    double sum = 0.0, max = 0.0;
    for (int n = b.first_node; n < b.first_node + b.n_nodes; ++n) {
      const auto i = static_cast<size_t>(n);
      const double u = (s.x[i] - s.X[i]).norm();
      sum += u;
      max = std::max(max, u);
    }
    row.push_back(sum / b.n_nodes);
    row.push_back(max);
  }
  if (!b.rigid && request_.kinetic_energy) {
    const Vec3 v = centre_of_mass_velocity(s, b.first_node, b.n_nodes);
    row.insert(row.end(), {v.x(), v.y(), v.z()});
  }
}

void HistoryRecorder::sample(const State& s, std::span<const double> body_internal_energy) {
  std::vector<double> row{s.t};
  row.reserve(columns_.size());
  for (size_t b = 0; b < mesh_.bodies.size(); ++b) {
    sample_body(s, mesh_.bodies[b], request_.internal_energy ? body_internal_energy[b] : 0.0, row);
    if (!mesh_.bodies[b].rigid) continue;
    for (const RigidState& r : s.rigid)
      if (r.body == static_cast<int>(b)) sample_rigid(s, r, row);
  }
  last_t_ = s.t;
  for (const TrackedNode& t : request_.tracked) {
    const auto i = static_cast<size_t>(t.node);
    const Vec3 u = s.x[i] - s.X[i];
    row.insert(row.end(), {u.x(), u.y(), u.z(), s.v[i].x(), s.v[i].y(), s.v[i].z()});
  }
  for (const HistorySource* source : sources_) source->append_history(s, row);
  rows_.push_back(std::move(row));
}

void write_history_csv(const std::filesystem::path& file, const HistoryRecorder& history) {
  const std::filesystem::path tmp = file.string() + ".partial";
  {
    std::ofstream out(tmp);
    if (!out) throw std::runtime_error(fmt::format("{}: cannot open for writing", tmp.string()));
    const auto& cols = history.columns();
    for (size_t c = 0; c < cols.size(); ++c) out << (c ? "," : "") << cols[c];
    out << '\n';
    for (const auto& row : history.rows()) {
      for (size_t c = 0; c < row.size(); ++c)
        out << (c ? "," : "") << fmt::format("{:.17g}", row[c]);
      out << '\n';
    }
    if (!out) throw std::runtime_error(fmt::format("{}: write failed", tmp.string()));
  }
  std::filesystem::rename(tmp, file);
}

}  // namespace ccm
