// Field output of one run for ParaView (docs/fields.md): `fields.h5` (HDF5: the mesh once, then
// one group of datasets per frame) and `fields.xdmf` (XDMF 3: a temporal collection that points
// into it), in one folder. A frame is written at t = 0, at the first output sample at or after
// each multiple of the field interval, and at the last sample of the run.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/observe/field_catalog.hpp"
#include "engine/solver/explicit_integrator.hpp"
#include "engine/solver/model.hpp"
#include "io/fields/contact_impulse_probe.hpp"
#include "io/fields/field_h5.hpp"

namespace ccm::fields {

inline constexpr const char* kXdmfFile = "fields.xdmf";
inline constexpr const char* kH5File = "fields.h5";

struct FieldRequest {
  std::vector<FieldKind> fields;  // each once; empty: the recorder writes nothing
  double interval = 0.0;          // [s] > 0
  std::string title;              // copied into the XDMF file
};

// All fields of the catalogue, in its order (`ccm run --fields`, `ccm rig run --fields`).
std::vector<FieldKind> all_fields();

class FieldRecorder {
 public:
  // Creates the folder's HDF5 file (under a temporary name until finish()) and writes the mesh.
  // `model` must stay alive until the run has ended (finish() does not read it).
  FieldRecorder(const Model& model, FieldRequest request, const std::filesystem::path& dir);
  ~FieldRecorder();
  FieldRecorder(const FieldRecorder&) = delete;
  FieldRecorder& operator=(const FieldRecorder&) = delete;

  // Before the run: chains options.on_sample and, when contact pressure is asked and there is a
  // contact model, wraps options.contact in a ContactImpulseProbe (forwarding every hook).
  void attach(RunOptions& options);
  // At an output sample (attach() arranges the call).
  void sample(const State& s);
  // After the run: the last sample's frame if it was not written, the time table, then the HDF5
  // file renamed into place and fields.xdmf written (atomically).
  void finish();

  int frames_written() const { return static_cast<int>(times_.size()); }

 private:
  struct Frame {
    double t = 0.0;
    std::vector<double> displacement, velocity, J, von_mises, contact_pressure;
  };
  bool wants(FieldKind kind) const;
  void write_mesh();
  Frame compute(const State& s) const;
  void write(const Frame& f);

  const Model& model_;
  FieldRequest request_;
  std::filesystem::path dir_, h5_partial_;
  std::unique_ptr<FieldH5> h5_;
  std::vector<Triangle> faces_;  // every body's boundary (contact pressure only)
  std::vector<int> face_body_;
  std::unique_ptr<ContactImpulseProbe> probe_;
  long n_nodes_ = 0, n_tets_ = 0;
  std::vector<double> times_;     // of the frames written
  long next_index_ = 0;           // the next frame is due at next_index_ * interval
  std::optional<Frame> pending_;  // the last sample, when it was not written
  bool finished_ = false;
};

}  // namespace ccm::fields
