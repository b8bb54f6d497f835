#include "io/fields/field_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <system_error>

#include "io/fields/element_fields.hpp"
#include "io/fields/surface_pressure.hpp"
#include "io/fields/xdmf_text.hpp"

namespace ccm::fields {
namespace {

namespace fs = std::filesystem;

std::vector<double> flat(const std::vector<Vec3>& v) {
  std::vector<double> out;
  out.reserve(3 * v.size());
  for (const Vec3& p : v) out.insert(out.end(), {p.x(), p.y(), p.z()});
  return out;
}

std::vector<double> flat_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  std::vector<double> out;
  out.reserve(3 * a.size());
  for (size_t i = 0; i < a.size(); ++i) {
    const Vec3 d = a[i] - b[i];
    out.insert(out.end(), {d.x(), d.y(), d.z()});
  }
  return out;
}

void write_text_atomic(const fs::path& file, const std::string& text) {
  const fs::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out.good()) throw FieldFileError(tmp.string() + ": cannot write");
  }
  std::error_code ec;
  fs::rename(tmp, file, ec);
  if (ec) throw FieldFileError(file.string() + ": cannot rename into place: " + ec.message());
}

}  // namespace

std::vector<FieldKind> all_fields() {
  std::vector<FieldKind> out;
  for (const FieldInfo& f : kFieldCatalog) out.push_back(f.kind);
  return out;
}

FieldRecorder::FieldRecorder(const Model& model, FieldRequest request, const fs::path& dir)
    : model_(model),
      request_(std::move(request)),
      dir_(dir),
      h5_partial_(dir / (std::string(kH5File) + ".partial")),
      n_nodes_(model.mesh.n_nodes()),
      n_tets_(model.mesh.n_elements()) {
  if (!(request_.interval > 0.0)) throw std::invalid_argument("field interval must be > 0");
  if (request_.fields.empty()) return;
  if (wants(FieldKind::contact_pressure))
    for (size_t b = 0; b < model.mesh.bodies.size(); ++b)
      for (const Triangle& t : model.mesh.bodies[b].boundary) {
        faces_.push_back(t);
        face_body_.push_back(static_cast<int>(b));
      }
  h5_ = std::make_unique<FieldH5>(h5_partial_);
  write_mesh();
}

FieldRecorder::~FieldRecorder() = default;

bool FieldRecorder::wants(FieldKind kind) const {
  return std::find(request_.fields.begin(), request_.fields.end(), kind) != request_.fields.end();
}

void FieldRecorder::write_mesh() {
  const ModelMesh& mesh = model_.mesh;
  h5_->write(kNodesDataset, flat(mesh.X), mesh.X.size(), 3);
  std::vector<int> tets;
  tets.reserve(4 * mesh.tets.size());
  for (const Tet& t : mesh.tets) tets.insert(tets.end(), t.begin(), t.end());
  h5_->write(kTetsDataset, tets, mesh.tets.size(), 4);
  if (wants(FieldKind::body_id)) h5_->write(kBodyIdDataset, mesh.element_body, mesh.tets.size(), 1);
  if (faces_.empty()) return;
  std::vector<int> faces;
  faces.reserve(3 * faces_.size());
  for (const Triangle& t : faces_) faces.insert(faces.end(), t.begin(), t.end());
  h5_->write(kFacesDataset, faces, faces_.size(), 3);
  if (wants(FieldKind::body_id)) h5_->write(kFaceBodyIdDataset, face_body_, faces_.size(), 1);
}

void FieldRecorder::attach(RunOptions& options) {
  if (request_.fields.empty()) return;
  if (wants(FieldKind::contact_pressure) && options.contact) {
    probe_ = std::make_unique<ContactImpulseProbe>(*options.contact, nodes_of(faces_));
    options.contact = probe_.get();
  }
  SampleFn previous = options.on_sample;
  options.on_sample = [this, previous](const State& s) {
    if (previous) previous(s);
    sample(s);
  };
}

FieldRecorder::Frame FieldRecorder::compute(const State& s) const {
  Frame f;
  f.t = s.t;
  if (wants(FieldKind::displacement)) f.displacement = flat_difference(s.x, s.X);
  if (wants(FieldKind::velocity)) f.velocity = flat(s.v);
  if (wants(FieldKind::J)) f.J = tet_volume_ratio(model_.elements, s.x);
  if (wants(FieldKind::von_mises)) f.von_mises = tet_von_mises(model_.elements, s.x);
  if (!wants(FieldKind::contact_pressure)) return f;
  // The mean contact force of each node over the frame interval: impulse / interval.
  std::vector<Vec3> force(s.x.size(), Vec3::Zero());
  const double interval = times_.empty() ? 0.0 : s.t - times_.back();
  if (probe_ && interval > 0.0)
    for (size_t k = 0; k < probe_->nodes().size(); ++k)
      force[static_cast<size_t>(probe_->nodes()[k])] = probe_->impulses()[k] / interval;
  f.contact_pressure = face_contact_pressure(faces_, s.x, force);
  return f;
}

void FieldRecorder::write(const Frame& f) {
  const int k = frames_written();
  const auto put = [&](FieldKind kind, const std::vector<double>& values, size_t rows,
                       size_t cols) {
    if (wants(kind)) h5_->write(frame_dataset(k, kind), values, rows, cols);
  };
  const auto nodes = static_cast<size_t>(n_nodes_);
  const auto tets = static_cast<size_t>(n_tets_);
  put(FieldKind::displacement, f.displacement, nodes, 3);
  put(FieldKind::velocity, f.velocity, nodes, 3);
  put(FieldKind::J, f.J, tets, 1);
  put(FieldKind::von_mises, f.von_mises, tets, 1);
  put(FieldKind::contact_pressure, f.contact_pressure, faces_.size(), 1);
  times_.push_back(f.t);
  if (probe_) probe_->reset();
  pending_.reset();
}

void FieldRecorder::sample(const State& s) {
  if (request_.fields.empty() || finished_) return;
  const double due = static_cast<double>(next_index_) * request_.interval;
  if (!times_.empty() && s.t < due * (1.0 - 1e-9)) {
    pending_ = compute(s);
    return;
  }
  write(compute(s));
  next_index_ = static_cast<long>(std::floor(s.t / request_.interval * (1.0 + 1e-9))) + 1;
}

void FieldRecorder::finish() {
  if (request_.fields.empty() || finished_) return;
  finished_ = true;
  if (pending_) write(*pending_);
  h5_->write(kTimeDataset, times_, times_.size(), 1);
  h5_->close();
  std::error_code ec;
  const fs::path h5 = dir_ / kH5File;
  fs::rename(h5_partial_, h5, ec);
  if (ec) throw FieldFileError(h5.string() + ": cannot rename into place: " + ec.message());
  XdmfLayout layout;
  layout.h5_name = kH5File;
  layout.n_nodes = n_nodes_;
  layout.n_tets = n_tets_;
  layout.n_faces = static_cast<long>(faces_.size());
  layout.fields = request_.fields;
  layout.times = times_;
  layout.title = request_.title;
  write_text_atomic(dir_ / kXdmfFile, xdmf_text(layout));
}

}  // namespace ccm::fields
