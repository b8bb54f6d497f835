#include "run/compare/compare_impact.hpp"

#include <vector>

#include "study/metrics/impact_metrics.hpp"

namespace ccm {
namespace {

// The run's histories as a study run record keeps them; none when a column is missing.
std::optional<study::RunRecord> as_record(const ComparedRun& run, const std::string& impactor,
                                          const std::string& artifact, double mass) {
  const auto t = run.column("time"), u = run.column(artifact + ".u_max");
  const auto vx = run.column(impactor + ".vx"), vy = run.column(impactor + ".vy"),
             vz = run.column(impactor + ".vz");
  if (!t || !u || !vx || !vy || !vz) return std::nullopt;
  study::RunRecord r;
  r.impactor.mass = mass;
  for (const std::vector<double>& row : run.rows) {
    r.artifact.time.push_back(row[*t]);
    r.artifact.u_max.push_back(row[*u]);
    r.impactor.vx.push_back(row[*vx]);
    r.impactor.vy.push_back(row[*vy]);
    r.impactor.vz.push_back(row[*vz]);
  }
  return r;
}

}  // namespace

std::optional<CompareImpact> compare_impact(const ComparedRun& deformable, const ComparedRun& rigid,
                                            const std::string& impactor,
                                            const std::string& artifact, double impactor_mass) {
  const auto d = as_record(deformable, impactor, artifact, impactor_mass);
  const auto r = as_record(rigid, impactor, artifact, impactor_mass);
  if (!d || !r) return std::nullopt;
  const auto qd = study::impact_quantities(*d), qr = study::impact_quantities(*r);
  if (!qd || !qr) return std::nullopt;
  return CompareImpact{*qd, *qr, study::impact_errors(*qd, *qr)};
}

}  // namespace ccm
