// What the DCR contact reports when a scene asks (thesis 3.3.3): the total contact force between
// each pair of bodies, and the pressure over named sensor surfaces (eq. 3.8).
//
// DCR acts through velocity updates, not forces, so forces are impulses over time. A reported
// force is the mean over the output interval that ends at the sample: the impulse of every step
// since the previous sample divided by the interval's length. Its integral over the samples is
// therefore exactly the momentum the contact gave (a single step's impulse / dt, sampled, would
// alias: the impulses of a persistent contact arrive in some steps and not in others):
//   pair impulse   J_AB = sum over the contacts between A and B of their impulse on B
//                         + the restitution impulse on B when an episode ends,
//                  the impulse of a contact on its node a being lambda_n grad_a g
//                  + beta_a (lambda_t1 t1 + lambda_t2 t2) (contact_impulses.hpp; friction
//                  included); the position projection moves nodes without changing momentum;
//   pair force     F_AB = sum_{steps in the interval} J_AB / (t_k - t_{k-1});
//   sensor force   F_c = sum_{steps} sum_{i in sensor nodes} m_i dv_i / (t_k - t_{k-1}), dv_i
//                  the velocity change the contact step made at node i ("differentiated across
//                  the time step and multiplied by the node's lumped mass", 3.3.3);
//   pressure       P_raw = |F_c . axis| / A_p   (eq. 3.8; A_p the sensor's reference area;
//                  |F_c| when no axis is given).
// The sample at t = 0 closes an empty interval and reads 0. Only what is asked is computed:
// pair forces when an axis is given, pressures for the listed sensors.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/contact/dcr/contact_impulses.hpp"
#include "engine/contact/dcr/pair_restitution.hpp"
#include "engine/core/state.hpp"
#include "engine/core/types.hpp"
#include "engine/mesh/model_mesh.hpp"

namespace ccm::dcr {

struct ContactOutputRequest {
  std::optional<Vec3> force_axis;    // pair forces projected on it (normalised)
  std::vector<std::string> sensors;  // named surfaces, e.g. "artifact/sensor"
};

class ContactOutput {
 public:
  // bodies: the bodies whose surfaces take part (sorted, unique). Throws std::invalid_argument
  // for an unknown sensor surface, a zero axis or a sensor of zero area.
  ContactOutput(const ModelMesh& mesh, const std::vector<int>& bodies,
                ContactOutputRequest request);

  bool wants_anything() const { return axis_.has_value() || !sensors_.empty(); }
  // Before the contact step: the sensor nodes' velocities.
  void begin(const State& s);
  // The impulses of the step's contacts (rows[k] acts on the nodes of row k) and of the ending
  // restitution episodes; node_body maps a node to its body.
  void add_impulses(const std::vector<ContactRow>& rows,
                    const std::vector<PairImpulse>& restitution, const std::vector<int>& node_body);
  // After the contact step of size dt: adds its impulses to the open output interval.
  void finish(const State& s, double dt);

  std::vector<std::string> columns() const;
  // The interval means since the previous call (one call per output sample: it closes the
  // interval, hence the mutable cursors below).
  void append(std::vector<double>& row) const;

 private:
  struct Pair {
    int a, b;                                      // body indices, a < b
    std::string prefix;                            // "contact.<A>.<B>"
    Vec3 impulse_on_b = Vec3::Zero();              // of the current step [N s]
    mutable Vec3 interval_impulse = Vec3::Zero();  // since the previous sample [N s]
  };
  struct Sensor {
    std::string name;
    std::vector<int> nodes;
    std::vector<Vec3> v_before;
    double area = 0.0;                              // reference area A_p [m^2]
    mutable Vec3 interval_momentum = Vec3::Zero();  // sum m dv since the previous sample [N s]
  };
  Pair* pair_of(int a, int b);

  std::optional<Vec3> axis_;
  mutable double interval_ = 0.0;  // time since the previous sample [s]
  std::vector<Pair> pairs_;
  std::vector<Sensor> sensors_;
};

}  // namespace ccm::dcr
