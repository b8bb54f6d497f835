// Hertz impact of two identical elastic spheres (docs/contact-method.md §6(a); Johnson 1985, 11.4)
// and its DCR simulation, shared by the default-suite and the [validation] tests.
#pragma once

#include <cmath>
#include <vector>

#include "engine/contact/dcr/dcr_contact.hpp"
#include "engine/solver/lumped_mass.hpp"
#include "tests/support/contact_scenes.hpp"
#include "tests/support/models.hpp"
#include "tests/support/refined_sphere.hpp"

namespace ccm::test {

struct HertzCase {
  double R = 0.01;            // sphere radius [m]
  double E = 1e6;             // Young's modulus [Pa]
  double nu = 0.3;            // Poisson's ratio (0.3: far from locking of linear tets)
  double rho = 1000.0;        // density [kg/m^3]
  double v = 0.4;             // approach speed (each sphere moves at v / 2) [m/s]
  double mesh_size = 0.002;   // element size (away from the contact, when refined)
  double contact_size = 0.0;  // > 0: element size at the contact poles (refined_sphere.hpp)
};

// The sphere with its contact pole at centre + R (0, 0, pole_sign), uniform or refined there.
inline TetMesh hertz_sphere(const HertzCase& c, const Vec3& centre, int pole_sign) {
  if (!(c.contact_size > 0.0)) return gmsh_sphere(c.R, c.mesh_size, centre);
  RefinedSphere spec;
  spec.radius = c.R;
  spec.h_max = c.mesh_size;
  spec.h_min = c.contact_size;
  spec.refined_radius = 0.25 * c.R;  // 1.5 a_max at the default speed
  spec.transition = 0.3 * c.R;
  return refined_sphere(spec, centre, pole_sign);
}

// Closed form for two identical spheres: R* = R / 2, E* = E / (2 (1 - nu^2)), m* = m / 2.
struct HertzPrediction {
  double delta_max, force_max, contact_radius, duration;
  double wave_time;  // 2R / c_d, to be much smaller than the duration (quasi-static)
};

inline HertzPrediction hertz_prediction(const HertzCase& c, double sphere_mass) {
  const double R_eff = c.R / 2, E_eff = c.E / (2 * (1 - c.nu * c.nu)), m_eff = sphere_mass / 2;
  HertzPrediction p{};
  p.delta_max = std::pow(15 * m_eff * c.v * c.v / (16 * E_eff * std::sqrt(R_eff)), 0.4);
  p.force_max = 4.0 / 3.0 * E_eff * std::sqrt(R_eff) * std::pow(p.delta_max, 1.5);
  p.contact_radius = std::sqrt(R_eff * p.delta_max);
  p.duration = 2.943 * p.delta_max / c.v;
  const double lambda = c.E * c.nu / ((1 + c.nu) * (1 - 2 * c.nu)), mu = c.E / (2 * (1 + c.nu));
  p.wave_time = 2 * c.R / std::sqrt((lambda + 2 * mu) / c.rho);
  return p;
}

struct HertzRun {
  HertzPrediction hertz{};
  double duration = 0.0;   // first to last sample with a contact impulse between the spheres
  double force_max = 0.0;  // largest m dV/dt of the upper sphere (central differences)
  double mass = 0.0;       // lumped mass of one sphere (the mesh's volume, not 4/3 pi R^3)
  double momentum_error = 0.0;
  int elements = 0;
  dcr::DcrContact::WorkParts work_parts;  // the contact's work by mechanism [J]
  double injected = 0.0;                  // the contact's injected_energy() at the end [J]
  double initial_kinetic = 0.0;           // m v^2 / 4 of the pair [J]
  RunSummary summary;
};

// Two spheres, the upper one falling at v/2 and the lower one rising at v/2, 1e-4 R apart.
// The contact force is the rate of change of the upper sphere's momentum (only the contact acts
// on it), by central differences over samples 1/400 of the Hertz duration apart.
inline HertzRun run_hertz(const HertzCase& c) {
  const double gap = 1e-4 * c.R;
  const MaterialParams mat{MaterialModel::neo_hookean, c.E, c.nu, c.rho};
  ModelMesh mesh;
  add_body(mesh, "low", mat, hertz_sphere(c, Vec3(0, 0, -c.R), 1));
  add_body(mesh, "up", mat, hertz_sphere(c, Vec3(0, 0, c.R + gap), -1));
  Model model = make_model(std::move(mesh));
  set_body_velocity(model, 0, Vec3(0, 0, c.v / 2));
  set_body_velocity(model, 1, Vec3(0, 0, -c.v / 2));

  dcr::DcrSettings settings;
  settings.surfaces = {"low/boundary", "up/boundary"};
  settings.restitution = 1.0;
  dcr::DcrContact contact(model.mesh, settings, model.bcs.fixed_nodes);
  HertzRun out;
  out.elements = model.mesh.n_elements();
  {
    State probe;
    probe.m_lumped = lumped_mass(model.mesh, model.elements);
    for (int n = 0; n < model.mesh.bodies[1].n_nodes; ++n)
      out.mass += probe.m_lumped[static_cast<size_t>(model.mesh.bodies[1].first_node + n)];
  }
  out.hertz = hertz_prediction(c, out.mass);
  const double interval = out.hertz.duration / 400;
  RunOptions opt;
  opt.contact = &contact;
  opt.time.end_time = gap / c.v + 1.3 * out.hertz.duration;
  opt.time.output_interval = interval;
  std::vector<double> t, vz;
  double first = -1.0, last = -1.0;
  Vec3 p0 = Vec3::Zero();
  opt.on_sample = [&](const State& s) {
    const Vec3 p = linear_momentum(s);
    if (t.empty()) p0 = p;
    out.momentum_error = std::max(out.momentum_error, (p - p0).norm() / (out.mass * c.v));
    t.push_back(s.t);
    vz.push_back(mean_velocity(s, model.mesh.bodies[1]).z());
    if (contact.active_contacts() > 0) {
      if (first < 0) first = s.t;
      last = s.t;
    }
  };
  out.summary = run_explicit(model, opt);
  out.work_parts = contact.work_parts();
  out.injected = contact.injected_energy();
  out.initial_kinetic = 0.25 * out.mass * c.v * c.v;
  out.duration = last - first;
  for (size_t i = 1; i + 1 < t.size(); ++i)
    out.force_max =
        std::max(out.force_max, out.mass * (vz[i + 1] - vz[i - 1]) / (t[i + 1] - t[i - 1]));
  return out;
}

}  // namespace ccm::test
