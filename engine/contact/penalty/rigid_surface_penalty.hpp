// Penalty contact between a deformable surface and a meshed rigid body (docs/rigid-bodies.md,
// "Penalty"): the thesis's penalty (eq. 2.5-2.6, section 2.8) with the analytic sphere replaced by
// any closed rigid surface.
//
// The deformable surface carries the symmetric 3-point rule of rigid_sphere_penalty.hpp. A
// quadrature point x_q inside the rigid body, by depth delta below its surface (closest point p,
// outward normal n of the smoothed surface, curved_surface.hpp; the nearest flat triangle from
// surface_distance.hpp, in the body's reference frame), takes
//   f_q = max(0, K_P delta - c_q u_n) n,   u_n = n . (v_q - v_B(x_q)),
//   c_q = 2 zeta sqrt(K_P m_q)                                         (PS.1)
// handed to the triangle's nodes by its shape functions, and -f_q goes to the rigid body where the
// line through x_q along n meets the closest rigid triangle's plane, handed to that triangle's
// nodes by the point's barycentric weights: the rigid body gathers them as a force and a moment
// (engine/body/rigid_bodies.hpp). The two forces act along one line, so momentum and angular
// momentum are exchanged exactly.
// K_P is per point (the thesis's per_point mode; the element mode is the sphere model's alone).
//
// Work: trapezoidal over each step on the nodes that take forces, deformable and (for a free body)
// rigid; a fixed or prescribed body's share is its driver's. Step bound: the springs' stiffness
// on the nodes, omega^2 = max_a K_P s_a / m_a + K_P n_near / m (s_a: node a's triangles; n_near:
// the points near the body; m the body's mass when free), times the damped-oscillator factor
// sqrt(1 + zeta^2) - zeta; and a kinematic bound so that no point moves by more than half the
// rigid surface's grid cell relative to the body in one step (it cannot pass through unseen).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "engine/contact/contact_model.hpp"
#include "engine/contact/penalty/curved_surface.hpp"
#include "engine/contact/penalty/surface_distance.hpp"
#include "engine/core/penalty_mode.hpp"
#include "engine/mesh/model_mesh.hpp"
#include "engine/observe/history.hpp"

namespace ccm {

struct RigidSurfacePenaltyParams {
  std::string name = "penalty";               // history column prefix
  double penalty = kDefaultPointPenalty;      // K_P [N/m] per quadrature point
  double damping = 0.0;                       // zeta >= 0, fraction of critical per point
  double crease_angle = kDefaultCreaseAngle;  // [degrees] sharper edges stay sharp (NG.1)
};

class RigidSurfacePenalty : public ContactModel, public HistorySource {
 public:
  // surface: the deformable body's triangles (global ids); rigid_body: the mesh body (marked
  // rigid) whose boundary is the rigid surface. Throws std::invalid_argument for an empty
  // surface, a body that is not rigid, a rigid surface that is not closed, K_P <= 0, zeta < 0 or
  // a crease angle outside [0, 180).
  RigidSurfacePenalty(const ModelMesh& mesh, std::vector<Triangle> surface, int rigid_body,
                      RigidSurfacePenaltyParams params);

  void begin_step(const State& state, double dt) override;
  void add_forces(State& state) override;
  void correct(State& /*state*/, double /*dt*/) override {}  // a force model
  void end_step(const State& state, double dt) override;
  ContactStepBound step_bound(const State& state, double ceiling) const override;
  // Forces only: it moves no node.
  double corrected_elements_stable_dt() const override {
    return std::numeric_limits<double>::infinity();
  }

  // <name>.active_points, .penetration_max [m], .work [J], .rigid_force_x/y/z (the springs'
  // force on the rigid body at the sample [N])
  std::vector<std::string> history_columns() const override;
  void append_history(const State& state, std::vector<double>& row) const override;

  double work() const { return work_; }
  int active_points() const { return n_active_; }
  double penetration_max() const { return penetration_max_; }
  // Non-empty once a point has gone deeper than the rigid surface's grid cell (K_P far too soft).
  const std::string& failure() const { return failure_; }

 private:
  const RigidState* pose(const State& s) const;
  struct Frame {  // the body's pose, to take world points into its reference frame
    explicit Frame(const RigidState& r);
    Vec3 to_reference(const Vec3& x) const;
    Vec3 to_reference_fast(const Vec3& x) const;  // within rounding of to_reference()
    const RigidState& pose;
    Mat3 back;
  };
  const std::vector<int>& candidates(const State& s, const Frame& frame, double margin);
  double rounding_margin() const;
  double gap_bound(size_t point, const Vec3& x, double from_center, double beyond,
                   bool& loose) const;
  double sharp_gap(size_t point, const Vec3& x, double beyond, bool& exact) const;
  Vec3 reference_point(size_t point) const;
  double pin_lever(const State& s, const RigidState& r) const;
  void load_rigid(int triangle, const std::array<double, 3>& weights, const Vec3& f);

  RigidSurfacePenaltyParams params_;
  int rigid_body_ = 0;
  bool free_body_ = false;            // set at the first step, from the state
  std::vector<Triangle> tris_;        // the deformable surface (global ids)
  std::vector<Triangle> rigid_tris_;  // the rigid surface (global ids)
  SurfaceDistance distance_;          // of the rigid surface, reference frame
  CurvedSurface smooth_;              // the same surface smoothed (NG.1)
  double reach_ = 0.0;                // how far outside the flat surface a point can touch
  std::vector<int> nodes_;            // every node that can take a force, sorted
  std::vector<int> tri_local_;        // per deformable triangle corner: index into nodes_
  std::vector<int> rigid_local_;      // per rigid triangle corner: index into nodes_
  std::vector<char> rigid_node_;      // per entry of nodes_: a rigid body's node
  std::vector<double> triangles_at_;  // per entry of nodes_: the deformable triangles at it
  std::vector<int> hint_;             // per quadrature point: its last nearest rigid triangle
  std::vector<int> lens_hint_;        // per quadrature point: the triangle of its last clearance
  // Per quadrature point, a place in the body's frame and a radius: while the point stays within
  // it, it is outside the rigid surface (CL.1, rigid_surface_penalty.cpp); radius 0: unknown.
  struct Clearance {
    Vec3 at = Vec3::Zero();
    double radius = 0.0;
  };
  std::vector<Clearance> clear_;
  // Per quadrature point, its foot on the curved surface at its last evaluation (triangle -1:
  // none), where the next starts.
  struct Foot {
    int triangle = -1;
    std::array<double, 2> weights{};
  };
  std::vector<Foot> foot_;
  bool tracked(size_t point, const Vec3& X, SurfacePoint& hit);
  // Per quadrature point, where its depth was last evaluated (body frame; by add_forces(), or by
  // the step bound's closer look) and the depth there (NG.3; outside, minus its clearance): a
  // lower bound of its gap nearby that the step bound reads.
  struct Evaluated {
    Vec3 at = Vec3::Zero();
    double depth = 0.0;
    bool valid = false;
    bool exact = false;  // its depth, not a looser lower bound (a clearance)
  };
  std::vector<Evaluated> evaluated_;
  struct Gap {  // step_bound's scratch, per point near the body
    double gap;
    size_t point;
    bool loose;  // a lower bound that sharp_gap() can raise
  };
  std::vector<Gap> gaps_;       // the points outside within reach of a step
  std::vector<size_t> inside_;  // the points inside
  const std::vector<size_t>& gather_gaps(const State& s, const RigidState& r, double travel);
  const std::vector<size_t>& sort_near(double travel);
  // The points add_forces() found within near_margin_ of the surface (or inside), with their gap
  // bounds, and the state and margin they were recorded at: the step bound that follows at the
  // same state reads them instead of visiting every point again.
  std::vector<Gap> near_;
  struct Recorded {
    const State* state = nullptr;
    double t = 0.0, margin = 0.0;
  } near_of_;
  double near_margin_ = 0.0;  // [m] chosen by the last step bound
  bool locate(size_t point, const Vec3& X, SurfacePoint& hit);
  void spring(const State& s, const RigidState& r, size_t t, int k, const Vec3& x,
              const SurfacePoint& hit);
  void record_near(size_t point, const Vec3& X, double from_center);
  void sharpen(Gap& g, double travel);
  void remember_clearance(size_t point, const Vec3& X, const SurfacePoint& outside);
  std::vector<int> deformable_local_;        // the entries of nodes_ on the deformable surface
  std::vector<int> rigid_now_, rigid_prev_;  // rigid entries with a force, now and at the start
  std::vector<char> rigid_touched_;          // per entry: in rigid_now_
  bool has_pose_prev_ = false;               // the body's pose at the step's start:
  Vec3 center_prev_ = Vec3::Zero();
  Eigen::Quaterniond rotation_prev_ = Eigen::Quaterniond::Identity();
  std::vector<unsigned char> outcode_;  // per entry of nodes_: candidates()'s outcode
  std::vector<Vec3> x_ref_;             // per entry of nodes_: candidates()'s body-frame place
  std::vector<int> candidates_;         // deformable triangles near the body (scratch)
  std::vector<Vec3> f_now_, f_prev_, x_prev_;
  double work_ = 0.0, penetration_max_ = 0.0, damping_factor_ = 1.0;
  double bound2_ = 0.0;  // squared radius about the centre of mass within which a point can touch
  int n_active_ = 0;
  std::string failure_;
};

}  // namespace ccm
